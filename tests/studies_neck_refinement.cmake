# Studies of curvature refinement near necks behind doc/validation.md
# ("Curvature refinement near necks"), viscous (Hopper) and surface
# diffusion. Label validation-long, not in CI; each writes the CSV named by
# --csv (hopper runs also CSV.levelN.csv, the neck against time).

# --- Hopper's cylinders ---------------------------------------------------------
# Hopper from y_n = 0.1 R (the scene) and from 0.01 R, R/h = 10-40 in the
# band, with 0, 1, 2 extra levels at the neck.
set(NECK_001R "Geometry/Particles=-0.2499875, 0, 0.25; 0.2499875, 0, 0.25")
foreach(k 0 1 2)
  add_test(NAME study_neckref_hopper_k${k}_2d COMMAND ${VISCOUS} hopper
    ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 4,5,6
    --set "Mesh refinement/Curvature refinement levels=${k}"
    --csv neckref_hopper_k${k}.csv)
  list(APPEND NECKREF_HOPPER study_neckref_hopper_k${k}_2d)
endforeach()
foreach(k 0 2)
  add_test(NAME study_neckref_hopper_001R_k${k}_2d COMMAND ${VISCOUS} hopper
    ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 5,6 --set "${NECK_001R}"
    --set "Mesh refinement/Curvature refinement levels=${k}"
    --csv neckref_hopper_001R_k${k}.csv)
  list(APPEND NECKREF_HOPPER study_neckref_hopper_001R_k${k}_2d)
endforeach()
# The Stokes solution alone: one tiny step from Hopper's exact shape at
# y_n = 0.01, 0.05, 0.1, 0.2 R, R/h = 20 in the band plus k = 0-10 extra
# levels at the neck; the driver's initial_neck_speed_error is the neck
# point's speed against Hopper's dy_n/dt.
foreach(y 0.01 0.05 0.1 0.2)
  if(y STREQUAL "0.01")
    set(c 0.2499874997)
  elseif(y STREQUAL "0.05")
    set(c 0.2496873044)
  elseif(y STREQUAL "0.1")
    set(c 0.2487468593)
  else()
    set(c 0.2449489743)
  endif()
  foreach(k 0 2 4 6 8 10)
    add_test(NAME study_hopper_neck_speed_y${y}_k${k}_2d COMMAND ${VISCOUS}
      hopper ${VISCOUS_SCENES}/two_cylinders_circles_2d.prm 5
      --set "Geometry/Particles=-${c}, 0, 0.25; ${c}, 0, 0.25"
      --set "Mesh refinement/Curvature refinement levels=${k}"
      --set "Time/End time=1.25e-6" --dt-factor 1e-4
      --csv hopper_neck_speed_y${y}_k${k}.csv)
    list(APPEND NECKREF_HOPPER study_hopper_neck_speed_y${y}_k${k}_2d)
  endforeach()
endforeach()
set_tests_properties(${NECKREF_HOPPER} PROPERTIES LABELS validation-long
  RESOURCE_LOCK viscous_hopper_output)
# --- Two grains under surface diffusion ---------------------------------------
# Surface-diffusion two-grain neck (Table 3 setting, 1000 steps) with 0 to
# 4 extra levels, with the finest cell's reinitialisation (FINEST_REINIT).
foreach(k 0 1 2 3 4)
  add_test(NAME study_neckref_sd_two_grains_k${k}_2d COMMAND ${SD_VALIDATE}
    neck ${TWO_GRAINS} 1000 --set "${TANGENT}" --set "${FINEST_REINIT}"
    --set "Mesh refinement/Curvature refinement levels=${k}"
    --csv neckref_sd_two_grains_k${k}.csv)
  set_tests_properties(study_neckref_sd_two_grains_k${k}_2d PROPERTIES
    LABELS validation-long)
endforeach()
# The early neck with 2-4 extra levels at steps of 1e-5 and 1e-4 (400
# steps: t* to 2.5e-6 and 2.5e-5); with 3 levels also 2000 steps of 1e-4
# (t* = 1.25e-4, x/R = 0.3), and from the initial neck 2 h / 8 (2 cells of
# the finest level) at dt = 1e-5, 1100 steps (t* = 6.9e-6).
foreach(k 2 3 4)
  foreach(dt 1e-5 1e-4)
    add_test(NAME study_neckref_sd_two_grains_k${k}_dt${dt}_2d
      COMMAND ${SD_VALIDATE} neck ${TWO_GRAINS} 400 --set "${TANGENT}"
      --set "${FINEST_REINIT}"
      --set "Mesh refinement/Curvature refinement levels=${k}"
      --set "Time/Time step=${dt}"
      --csv neckref_sd_two_grains_k${k}_dt${dt}.csv)
    list(APPEND NECKREF_SD_DT study_neckref_sd_two_grains_k${k}_dt${dt}_2d)
  endforeach()
endforeach()
add_test(NAME study_neckref_sd_two_grains_k3_dt1e-4_long_2d
  COMMAND ${SD_VALIDATE} neck ${TWO_GRAINS} 2000 --set "${TANGENT}"
  --set "${FINEST_REINIT}"
  --set "Mesh refinement/Curvature refinement levels=3"
  --set "Time/Time step=1e-4" --sample-interval 20
  --csv neckref_sd_two_grains_k3_dt1e-4_long.csv)
add_test(NAME study_neckref_sd_two_grains_k3_x0fine_2d
  COMMAND ${SD_VALIDATE} neck ${TWO_GRAINS} 1100 --set "${X0FINE}"
  --set "${FINEST_REINIT}"
  --set "Mesh refinement/Curvature refinement levels=3"
  --set "Time/Time step=1e-5" --sample-interval 20
  --csv neckref_sd_two_grains_k3_x0fine.csv)
set_tests_properties(${NECKREF_SD_DT}
  study_neckref_sd_two_grains_k3_dt1e-4_long_2d
  study_neckref_sd_two_grains_k3_x0fine_2d PROPERTIES LABELS validation-long)
# Steps that grow with t (Time/Relative time step r: dt = max(1e-7, r t),
# CFL off) from the initial neck 2 h / 8 (x0/R = 0.0099) to t* = 2.5e-4:
# convergence in r at 3 extra levels, and in the levels (4-6) at 2-3 r;
# samples every 0.2 / r steps (about 11 per decade of t for every r once
# the steps grow). The CFL step (CFL number 1, 3 levels) for comparison.
foreach(spec "3:0.1:2" "3:0.05:4" "3:0.025:8" "3:0.0125:16" "4:0.05:4"
             "4:0.025:8" "5:0.1:2" "5:0.05:4" "5:0.025:8" "6:0.1:2"
             "6:0.05:4" "6:0.025:8")
  string(REPLACE ":" ";" spec "${spec}")
  list(GET spec 0 k)
  list(GET spec 1 r)
  list(GET spec 2 interval)
  set(name study_neckref_sd_two_grains_k${k}_rel${r}_2d)
  add_neckref_relative_run(${name} neckref_sd_two_grains_k${k}_rel${r}.csv
    20000 ${k} ${r} ${interval} --set "${FINEST_REINIT}")
  list(APPEND NECKREF_SD_REL ${name})
endforeach()
# The same with `Solid reinitialisation from band cells`: the
# level set inside the neck is rebuilt at the band's h / dt, the
# atmosphere's wedge at the finest cell's (doc/validation.md, "Steps that
# grow with t"); samples every 4 steps.
set(SOLID_BAND "Level set/Solid reinitialisation from band cells=true")
foreach(spec "5:0.1" "5:0.05" "5:0.025" "6:0.1" "6:0.05" "6:0.025")
  string(REPLACE ":" ";" spec "${spec}")
  list(GET spec 0 k)
  list(GET spec 1 r)
  set(name study_neckref_sd_two_grains_k${k}_rel${r}_solid_band_2d)
  add_neckref_relative_run(${name}
    neckref_sd_two_grains_k${k}_rel${r}_solid_band.csv 20000 ${k} ${r} 4
    --set "${SOLID_BAND}")
  list(APPEND NECKREF_SD_REL ${name})
endforeach()
# The reinitialisation acts per step (lambda = strength h_min / dt): 5
# levels with strength = r and diffusion = 0.4 r (the scene's 0.05 / 0.02
# at r = 0.05), i.e. the same reinitialisation per unit time for every r.
# At r = 0.0125 the interface wrinkles from t* ~ 1.4e-5 on: that run
# stops after 832 steps.
foreach(spec "0.1:2:0.04:rel0.1_reinit_double:20000"
             "0.025:8:0.01:rel0.025_reinit_half:20000"
             "0.0125:16:0.005:rel0.0125_reinit_quarter:832")
  string(REPLACE ":" ";" spec "${spec}")
  list(GET spec 0 r)
  list(GET spec 1 interval)
  list(GET spec 2 diffusion)
  list(GET spec 3 name)
  list(GET spec 4 steps)
  add_neckref_relative_run(study_neckref_sd_two_grains_k5_${name}_2d
    neckref_sd_two_grains_k5_${name}.csv ${steps} 5 ${r} ${interval}
    --set "${FINEST_REINIT}"
    --set "Level set/Reinitialisation strength=${r}"
    --set "Level set/Reinitialisation diffusion=${diffusion}")
  list(APPEND NECKREF_SD_REL study_neckref_sd_two_grains_k5_${name}_2d)
endforeach()
add_test(NAME study_neckref_sd_two_grains_k3_cfl1_2d
  COMMAND ${SD_VALIDATE} neck ${TWO_GRAINS} 20000 --set "${X0FINE}"
  --set "${FINEST_REINIT}"
  --set "Mesh refinement/Curvature refinement levels=3"
  --set "Time/Time step=0" --set "Time/CFL number=1"
  --set "Time/End time=0.25" --sample-interval 5
  --csv neckref_sd_two_grains_k3_cfl1.csv)
set_tests_properties(${NECKREF_SD_REL} study_neckref_sd_two_grains_k3_cfl1_2d
  PROPERTIES LABELS validation-long)
# The reference: the same run with the whole band at h = 1/256, 400 steps.
add_test(NAME study_neckref_sd_two_grains_level6_2d COMMAND ${SD_VALIDATE}
  neck ${TWO_GRAINS} 400 --set "${TANGENT}"
  --set "Mesh refinement/Maximum level=6"
  --csv neckref_sd_two_grains_level6.csv)
set_tests_properties(study_neckref_sd_two_grains_level6_2d PROPERTIES
  LABELS validation-long)
