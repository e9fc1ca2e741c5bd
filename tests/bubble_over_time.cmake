# --- Static bubble over time (issue 17, "Bubble over time") -----------------
# (doc/validation.md, "Static bubble over time"). Driver:
# levelsinter_viscous_validation bubble-time. C = |v|_max eta / gamma and
# the bubble's area error after every step on a uniform mesh, h = 1/40,
# 1/80, 1/160 at levels 3, 4, 5 (R/h = 8, 16, 32), filter and band 6 h, the
# explicit capillary step eta h / gamma.
set(BUBBLE_TIME ${CMAKE_SOURCE_DIR}/parameter_files/static_bubble_over_time_2d.prm)

# CI: 50 steps (the first 50 of the studies below, step for step), with
# the scene's Reinitialisation tolerance 4.
# csf-curvature at R/h = 16, measured: C 6.44e-5 at the first step and
# never above it (it falls to 5.7e-6), largest area error 1.3e-7 (with
# v^c: 7.9e-12). Limits: C at most 1.05 times the first step's and below
# 1e-4, area 3e-7 (v^c: 2e-9, the volume correction's solver tolerance).
add_test(NAME bubble_over_time_csf_curvature_2d COMMAND ${VISCOUS} bubble-time
  ${BUBBLE_TIME} 4 --set "Time/Maximum steps=50" --max-C-growth 1.05
  --max-C 1e-4 --max-area-drift 3e-7)
add_test(NAME bubble_over_time_csf_curvature_vc_2d COMMAND ${VISCOUS}
  bubble-time ${BUBBLE_TIME} 4 --set "Time/Maximum steps=50"
  --set "Volume correction/Enabled=true" --max-C-growth 1.05 --max-C 1e-4
  --max-area-drift 2e-9)
# csf-curvature at R/h = 32, the shipped scene's resolution, 30 steps:
# the first-step level is kept (measured over 100 steps: the largest C is
# the first step's, 1.6526e-5; it falls to 6.5e-6). With the default
# tolerance 0.25 C rose to 2.39 times the first step's at step 17, which
# the limit 1.01 catches.
add_test(NAME bubble_over_time_csf_curvature_rh32_2d COMMAND ${VISCOUS}
  bubble-time ${BUBBLE_TIME} 5 --set "Time/Maximum steps=30"
  --max-C-growth 1.01 --max-C 2e-5 --max-area-drift 1e-6)
# sharp at R/h = 8, measured: C 1.31e-2 at the first step and never above
# it; the area falls by about 1.2e-3 per step, 5.8 % after 50 steps (the
# tensorial form's loss, doc/validation.md): the limit 6.5 % guards that
# it grows no further. With v^c (the default 'auto' turns it on with the
# sharp form; the scene sets it off): C the same, area error at most
# 7.1e-5; limit 1.5e-4.
add_test(NAME bubble_over_time_sharp_2d COMMAND ${VISCOUS} bubble-time
  ${BUBBLE_TIME} 3 --set "Time/Maximum steps=50"
  --set "Viscous flow/Surface tension form=sharp" --max-C-growth 1.05
  --max-area-drift 0.065)
add_test(NAME bubble_over_time_sharp_vc_2d COMMAND ${VISCOUS} bubble-time
  ${BUBBLE_TIME} 3 --set "Time/Maximum steps=50"
  --set "Viscous flow/Surface tension form=sharp"
  --set "Volume correction/Enabled=auto" --max-C-growth 1.05
  --max-area-drift 1.5e-4)
# Without --csv the driver writes and reads back
# viscous_validation_output/bubble_time__levelN/metrics.csv: runs at the
# same level must not overlap.
set_tests_properties(bubble_over_time_csf_curvature_2d
  bubble_over_time_csf_curvature_vc_2d bubble_over_time_sharp_2d
  bubble_over_time_sharp_vc_2d bubble_over_time_csf_curvature_rh32_2d
  PROPERTIES RESOURCE_LOCK bubble_time_output)

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
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/study_bubble_over_time_${name}.csv)
  add_test(NAME study_bubble_over_time_${name}_vc_2d COMMAND ${VISCOUS}
    bubble-time ${BUBBLE_TIME} ${levels}
    --set "Viscous flow/Surface tension form=${form}"
    --set "Volume correction/Enabled=true"
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/study_bubble_over_time_${name}_vc.csv)
  set_tests_properties(study_bubble_over_time_${name}_2d
    study_bubble_over_time_${name}_vc_2d PROPERTIES LABELS validation-long)
endforeach()
