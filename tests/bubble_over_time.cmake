# --- Static bubble over time (issue 17, "Bubble over time") -----------------
# (doc/validation.md, "Static bubble over time"). Driver:
# levelsinter_viscous_validation bubble-time. C = |v|_max eta / gamma and
# the bubble's area error after every step on a uniform mesh, h = 1/40,
# 1/80, 1/160 at levels 3, 4, 5 (R/h = 8, 16, 32), filter and band 6 h, the
# explicit capillary step eta h / gamma.
set(BUBBLE_TIME ${CMAKE_SOURCE_DIR}/parameter_files/static_bubble_over_time_2d.prm)

# CI: 50 steps (the first 50 of the studies below, step for step).
# csf-curvature at R/h = 16, measured: C 6.44e-5 at the first step and
# never above it (it falls to 1.55e-5), largest area error 3.6e-5 (with
# v^c: 8.8e-10). Limits: C at most 1.05 times the first step's and below
# 1e-4, area 7e-5 (v^c: 2e-9).
add_test(NAME bubble_over_time_csf_curvature_2d COMMAND ${VISCOUS} bubble-time
  ${BUBBLE_TIME} 4 --set "Time/Maximum steps=50" --max-C-growth 1.05
  --max-C 1e-4 --max-area-drift 7e-5)
add_test(NAME bubble_over_time_csf_curvature_vc_2d COMMAND ${VISCOUS}
  bubble-time ${BUBBLE_TIME} 4 --set "Time/Maximum steps=50"
  --set "Volume correction/Enabled=true" --max-C-growth 1.05 --max-C 1e-4
  --max-area-drift 2e-9)
# sharp at R/h = 8, measured: C 1.31e-2 at the first step and never above
# it; the area falls by 1.1e-3 per step, 5.4 % after 50 steps (the
# tensorial form's loss, doc/validation.md): the limit 6.5 % guards that
# it grows no further. With v^c: C the same, area error at most 2.3e-5;
# limit 5e-5.
add_test(NAME bubble_over_time_sharp_2d COMMAND ${VISCOUS} bubble-time
  ${BUBBLE_TIME} 3 --set "Time/Maximum steps=50"
  --set "Viscous flow/Surface tension form=sharp" --max-C-growth 1.05
  --max-area-drift 0.065)
add_test(NAME bubble_over_time_sharp_vc_2d COMMAND ${VISCOUS} bubble-time
  ${BUBBLE_TIME} 3 --set "Time/Maximum steps=50"
  --set "Viscous flow/Surface tension form=sharp"
  --set "Volume correction/Enabled=true" --max-C-growth 1.05
  --max-area-drift 5e-5)

# Studies (validation-long): 1000 steps, csf-curvature at R/h = 8 and 16
# (12 min on the shared machine), sharp at R/h = 8. R/h = 32 (the scene
# itself, about 11 CPU minutes from 19 s for 30 steps, 38 min on the
# shared machine) and sharp at
# R/h = 32 were measured by hand (doc/validation.md).
foreach(case "csf-curvature;3,4" "sharp;3")
  list(GET case 0 form)
  list(GET case 1 levels)
  string(REPLACE "-" "_" name ${form})
  add_test(NAME study_bubble_over_time_${name}_2d COMMAND ${VISCOUS}
    bubble-time ${BUBBLE_TIME} ${levels}
    --set "Viscous flow/Surface tension form=${form}"
    --csv study_bubble_over_time_${name}.csv)
  add_test(NAME study_bubble_over_time_${name}_vc_2d COMMAND ${VISCOUS}
    bubble-time ${BUBBLE_TIME} ${levels}
    --set "Viscous flow/Surface tension form=${form}"
    --set "Volume correction/Enabled=true"
    --csv study_bubble_over_time_${name}_vc.csv)
  set_tests_properties(study_bubble_over_time_${name}_2d
    study_bubble_over_time_${name}_vc_2d PROPERTIES LABELS validation-long)
endforeach()
