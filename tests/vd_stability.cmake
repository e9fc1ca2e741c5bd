# --- Volume diffusion: explicit stability limit ---------------------------
# The largest stable step of v = -C_v xi N (explicit Euler) on the perturbed
# elastic cylinder of volume_diffusion_cylinder_mode2_2d (R = 0.25, Table 7
# moduli, lambda = 6 cells) at h = 1/128 and 1/256 (E = 0.12, band 0.118,
# as that test) and h = 1/64 (E = 0.16, band 0.158: lambda = 6 h = 0.094
# must stay below 0.8 E with two cells of sources to spare). Not h = 1/32:
# lambda = 6 h would need E >= 10 h > R. 20 steps per trial, bracketed to a
# factor 1.2 by scripts/largest_stable_step.py; the mechanism's own limit
# is switched off (Time step factor = 0). --rate is the driver's
# s_2 = (2/3)(1 + nu) 6 in t* = C_v gamma t / R^3, nu = 0.3235 from
# K = 390e3, G = 156e3.
add_test(NAME study_vd_stiffness_2d
  COMMAND ${CMAKE_SOURCE_DIR}/scripts/largest_stable_step.py ${SD_VALIDATE}
    ${PERTURBED} --levels 5,6 --rate 5.294117647058823
    --scheme volume-diffusion --start 1e-5
    --filter-thickness 0.12 --band-width 0.118 ${VD_CYLINDER}
    --set "Volume diffusion/Time step factor=0"
    --csv vd_stiffness_2d.csv)
add_test(NAME study_vd_stiffness_h64_2d
  COMMAND ${CMAKE_SOURCE_DIR}/scripts/largest_stable_step.py ${SD_VALIDATE}
    ${PERTURBED} --levels 4 --rate 5.294117647058823
    --scheme volume-diffusion --start 1e-3
    --filter-thickness 0.16 --band-width 0.158 ${VD_CYLINDER}
    --set "Volume diffusion/Time step factor=0"
    --csv vd_stiffness_h64_2d.csv)
set_tests_properties(study_vd_stiffness_2d study_vd_stiffness_h64_2d
  PROPERTIES LABELS validation-long)
# The same limit at h = 1/128 with the interior offset lambda = 3, 4, 5, 6
# cells (the packings run lambda = 3): how far the limit, measured at 6
# cells, holds for a smaller offset (doc/validation.md, "Volume diffusion:
# explicit stability limit").
foreach(lambda 3 4 5 6)
  add_test(NAME study_vd_stiffness_lambda${lambda}_2d
    COMMAND ${CMAKE_SOURCE_DIR}/scripts/largest_stable_step.py ${SD_VALIDATE}
      ${PERTURBED} --levels 5 --rate 5.294117647058823
      --scheme volume-diffusion-lambda${lambda} --start 1e-5
      --filter-thickness 0.12 --band-width 0.118 ${VD_CYLINDER}
      --set "Volume diffusion/Interior offset=${lambda}"
      --set "Volume diffusion/Time step factor=0"
      --csv vd_stiffness_lambda${lambda}_2d.csv)
  set_tests_properties(study_vd_stiffness_lambda${lambda}_2d
    PROPERTIES LABELS validation-long)
endforeach()

# --- The xi extension with hanging nodes inside the filter ramp ------------
# Refined to h = 1/128 only where |d| < 4 h, two levels coarser beyond,
# E = 10 h (the geometry band |d| < 8 h holds coarse cells). Before the fix
# GMRES stalled (residual 0.52 after 1000 iterations at E = 10 h, 1.7e-3
# at E = 6 h; measured): the band's edge in the solid had no data and the
# source test counted all of lambda in the coarse cells' h. Measured now:
# 32 iterations, no unsourced interface cell, RMS error 4.7e-3 (6.1e-5 on
# the uniform mesh: the sources next to coarse cells read a one-sided
# gradient). Limit 7e-3.
add_test(NAME xi_hanging_nodes_in_ramp_2d COMMAND ${XI} field 2 radial 7
  --band 4 --filter 10 --max-error 7e-3)
