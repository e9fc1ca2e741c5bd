# Studies of surface diffusion behind doc/validation.md ("Surface
# diffusion"). Label validation-long, not in CI; each writes the CSV named
# by --csv.

# --- Mullins decay (2D) --------------------------------------------------------
# h = 1/64, 1/128, 1/256 times 10, 20, 40, 80 steps per e-folding
# (convergence in h and dt, and the error against CPU time), with and
# without v^c; modes 3 and 4.
add_test(NAME study_mullins_n2_2d COMMAND ${SD_VALIDATE} mullins
  ${PERTURBED} 4,5,6 10,20,40,80 --csv mullins_n2_2d.csv)
add_test(NAME study_mullins_n2_vc_2d COMMAND ${SD_VALIDATE} mullins
  ${PERTURBED} 4,5,6 10,20,40,80 --set ${VC} --csv mullins_n2_vc_2d.csv)
# h = 1/256 with the filter thickness of h = 1/128 (E = 0.047 = 12 h).
add_test(NAME study_mullins_n2_E047_2d COMMAND ${SD_VALIDATE} mullins
  ${PERTURBED} 6 10,20,40,80 --filter-thickness 0.047
  --csv mullins_n2_E047_2d.csv)
set(SD_STUDIES study_mullins_n2_2d study_mullins_n2_vc_2d
  study_mullins_n2_E047_2d)
foreach(n 3 4)
  add_test(NAME study_mullins_n${n}_2d COMMAND ${SD_VALIDATE} mullins
    ${PERTURBED} 5,6 40 --mode ${n} --csv mullins_n${n}_2d.csv)
  add_test(NAME study_mullins_n${n}_vc_2d COMMAND ${SD_VALIDATE} mullins
    ${PERTURBED} 5,6 40 --mode ${n} --set ${VC} --csv mullins_n${n}_vc_2d.csv)
  list(APPEND SD_STUDIES study_mullins_n${n}_2d study_mullins_n${n}_vc_2d)
endforeach()
# Stiffness: the largest stable step of the mixed (Eq. 82) and the
# decoupled (kappa then v_s) scheme for n = 2, h = 1/32 to 1/256, 20 steps
# per trial, bracketed to a factor 1.2 by scripts/largest_stable_step.py.
foreach(coupled 1 0)
  if(coupled)
    set(scheme mixed)
    set(start 1e-3)
  else()
    set(scheme decoupled)
    set(start 1e-5)
  endif()
  add_test(NAME study_mullins_stiffness_${scheme}_2d
    COMMAND ${CMAKE_SOURCE_DIR}/scripts/largest_stable_step.py ${SD_VALIDATE}
      ${PERTURBED} --levels 3,4,5,6 --coupled ${coupled} --start ${start}
      --csv mullins_stiffness_${scheme}_2d.csv)
  list(APPEND SD_STUDIES study_mullins_stiffness_${scheme}_2d)
endforeach()
# The mixed scheme with the filter fixed at E = 0.047 (band 0.031) at
# h = 1/128 and 1/256: does its limit follow h or E?
add_test(NAME study_mullins_stiffness_mixed_E047_2d
  COMMAND ${CMAKE_SOURCE_DIR}/scripts/largest_stable_step.py ${SD_VALIDATE}
    ${PERTURBED} --levels 5,6 --coupled 1 --start 1e-2
    --filter-thickness 0.047 --band-width 0.03125
    --csv mullins_stiffness_mixed_E047_2d.csv)
list(APPEND SD_STUDIES study_mullins_stiffness_mixed_E047_2d)

# --- Two grains (2D) -------------------------------------------------------------
# The paper's Table 3 setting (C_s = 1e-6, dt = 1e-3, h = 1/128, 1000
# steps) from nearly tangent grains (initial neck 2 h), without and with v^c.
add_test(NAME study_sd_two_grains_table3_2d COMMAND ${SD_VALIDATE} neck
  ${TWO_GRAINS} 1000 --set "${TANGENT}" --csv sd_two_grains_table3_2d.csv)
add_test(NAME study_sd_two_grains_table3_vc_2d COMMAND ${SD_VALIDATE} neck
  ${TWO_GRAINS} 1000 --set "${TANGENT}" --set ${VC}
  --csv sd_two_grains_table3_vc_2d.csv)
list(APPEND SD_STUDIES study_sd_two_grains_table3_2d
  study_sd_two_grains_table3_vc_2d)
# Equal grains R = 0.1 and 0.15 in the same setting (R = 0.2 is the Table 3
# run): the same h = 1/128, C_s dt and initial neck 2 h; t* = C_s t / R^4
# then covers 16x (R = 0.1) and 3.2x (R = 0.15) more per step, as in the
# paper's Fig. 26.
foreach(spec "0.1:0.401228:0.598772:300" "0.15:0.350816:0.649184:500")
  string(REPLACE ":" ";" spec "${spec}")
  list(GET spec 0 R)
  list(GET spec 1 X1)
  list(GET spec 2 X2)
  list(GET spec 3 STEPS)
  add_test(NAME study_sd_neck_R${R}_2d COMMAND ${SD_VALIDATE} neck
    ${TWO_GRAINS} ${STEPS}
    --set "Geometry/Particles=${X1}, 0.5, ${R}; ${X2}, 0.5, ${R}"
    --csv sd_neck_R${R}_2d.csv)
  list(APPEND SD_STUDIES study_sd_neck_R${R}_2d)
endforeach()
# R = 0.2 at h = 1/256 (E = 6 h, band 4 h), x0 = 2 h: the early stage
# (0.05 <= x/R <= 0.3, Nichols-Mullins) at twice the resolution.
add_test(NAME study_sd_neck_R0.2_h256_2d COMMAND ${SD_VALIDATE} neck
  ${TWO_GRAINS} 200 --set "Geometry/Particles=0.300153, 0.5, 0.2; 0.699847, 0.5, 0.2"
  --set "Mesh refinement/Maximum level=6" --set "Mesh refinement/Minimum level=2"
  --set "Level set/Filter thickness=0.0234375"
  --set "Mesh refinement/Band width=0.015625" --csv sd_neck_R0.2_h256_2d.csv)
list(APPEND SD_STUDIES study_sd_neck_R0.2_h256_2d)
# Unequal grains 0.1 / 0.2 and equal grains of Rbar = 0.1333 (Fig. 27).
add_test(NAME study_sd_unequal_grains_2d COMMAND ${SD_VALIDATE} neck
  ${UNEQUAL} 2000 --csv sd_unequal_grains_2d.csv)
add_test(NAME study_sd_equivalent_grains_2d COMMAND ${SD_VALIDATE} neck
  ${UNEQUAL} 2000 --set
  "Geometry/Particles=0.367585, 0.5, 0.133333333333; 0.632415, 0.5, 0.133333333333"
  --csv sd_equivalent_grains_2d.csv)
list(APPEND SD_STUDIES study_sd_unequal_grains_2d study_sd_equivalent_grains_2d)
# Far-end-to-far-end length to x/R = 0.57: R = 0.1, 500 steps, without and
# with v^c.
add_test(NAME study_sd_length_R0.1_2d COMMAND ${SD_VALIDATE} neck
  ${TWO_GRAINS} 500 --set "${GRAINS_R01}" --csv sd_length_R0.1_2d.csv)
add_test(NAME study_sd_length_R0.1_vc_2d COMMAND ${SD_VALIDATE} neck
  ${TWO_GRAINS} 500 --set "${GRAINS_R01}" --set ${VC}
  --csv sd_length_R0.1_vc_2d.csv)
list(APPEND SD_STUDIES study_sd_length_R0.1_2d study_sd_length_R0.1_vc_2d)
set_tests_properties(${SD_STUDIES} PROPERTIES LABELS validation-long)
# The mullins mode names its output directories by level and steps only.
set_tests_properties(study_mullins_n2_2d study_mullins_n2_vc_2d
  study_mullins_n2_E047_2d study_mullins_n3_2d study_mullins_n3_vc_2d
  study_mullins_n4_2d study_mullins_n4_vc_2d PROPERTIES
  RESOURCE_LOCK sd_mullins_output)

# --- Perturbed sphere (3D) and the refined band at 0.8 E -------------------
# Studies at R/h = 16 (doc/validation.md, "3D: perturbed sphere"): the
# filter E = 12 h, E = 6 h with v^c, and the refined band at 0.8 E (the
# kappa / v_s system's band) with E = 6 h and 12 h; 2D Mullins at
# h = 1/256 with the refined band at 0.8 E.
set(SPHERE_16 mullins ${SPHERE} 4 20 --time-fraction 0.5 --signs 2)
add_test(NAME study_sd_sphere_E12h_3d COMMAND ${SD_VALIDATE} ${SPHERE_16}
  --filter-thickness 0.1875 --csv sd_sphere_E12h_3d.csv)
add_test(NAME study_sd_sphere_vc_h16_3d COMMAND ${SD_VALIDATE} ${SPHERE_16}
  --set ${VC} --csv sd_sphere_vc_h16_3d.csv)
add_test(NAME study_sd_sphere_band08E_h16_3d COMMAND ${SD_VALIDATE}
  ${SPHERE_16} --band-width 0.075 --csv sd_sphere_band08E_h16_3d.csv)
add_test(NAME study_sd_sphere_E12h_band08E_3d COMMAND ${SD_VALIDATE}
  ${SPHERE_16} --filter-thickness 0.1875 --band-width 0.15
  --csv sd_sphere_E12h_band08E_3d.csv)
add_test(NAME study_mullins_n2_band08E_2d COMMAND ${SD_VALIDATE} mullins
  ${PERTURBED} 6 40 --band-width 0.01875 --csv mullins_n2_band08E_2d.csv)
add_test(NAME study_mullins_n2_E047_band08E_2d COMMAND ${SD_VALIDATE} mullins
  ${PERTURBED} 6 40 --filter-thickness 0.047 --band-width 0.0375
  --csv mullins_n2_E047_band08E_2d.csv)
set_tests_properties(study_sd_sphere_E12h_3d study_sd_sphere_vc_h16_3d
  study_sd_sphere_band08E_h16_3d study_sd_sphere_E12h_band08E_3d
  study_mullins_n2_band08E_2d study_mullins_n2_E047_band08E_2d PROPERTIES
  LABELS validation-long RESOURCE_LOCK sd_mullins_output)
# Why the refined band at 0.8 E makes the 2D n = 2 rate at 40 steps
# worse (doc/validation.md, "Mullins decay (2D)", "Band and rate"): the
# step series at h = 1/128, E = 0.047, with the band at 0.8 E and at 4 h;
# h = 1/256 with the reinitialisation off or without remeshing, each with
# both bands; the band at 0.8 E for n = 3, 4 and for wider filters.
set(E047 --filter-thickness 0.047)
set(NO_REINIT "Level set/Reinitialisation strength=0")
set(NO_REMESH "Mesh refinement/Adapt interval=1000")
add_test(NAME study_mullins_band08E_dt_2d COMMAND ${SD_VALIDATE} mullins
  ${PERTURBED} 5 10,20,40,80,160,320 --band-width 0.0375
  --csv mullins_band08E_dt_2d.csv)
add_test(NAME study_mullins_band4h_dt_2d COMMAND ${SD_VALIDATE} mullins
  ${PERTURBED} 5 10,20,40,80,160,320 --csv mullins_band4h_dt_2d.csv)
# Each band with the reinitialisation off and without remeshing.
foreach(band 4h 08E)
  set(band_args)
  if(band STREQUAL "08E")
    set(band_args --band-width 0.0375)
  endif()
  foreach(off noreinit noremesh)
    set(off_setting ${NO_REINIT})
    if(off STREQUAL "noremesh")
      set(off_setting ${NO_REMESH})
    endif()
    set(name mullins_E047_band${band}_${off}_2d)
    add_test(NAME study_${name} COMMAND ${SD_VALIDATE} mullins ${PERTURBED}
      6 40 ${E047} ${band_args} --set ${off_setting} --csv ${name}.csv)
    list(APPEND SD_BAND_RATE study_${name})
  endforeach()
endforeach()
add_test(NAME study_mullins_band08E_320_noreinit_2d COMMAND ${SD_VALIDATE}
  mullins ${PERTURBED} 5 320 --band-width 0.0375 --set ${NO_REINIT}
  --csv mullins_band08E_320_noreinit_2d.csv)
add_test(NAME study_mullins_E047_band08E_160_2d COMMAND ${SD_VALIDATE}
  mullins ${PERTURBED} 6 160 ${E047} --band-width 0.0375
  --csv mullins_E047_band08E_160_2d.csv)
foreach(n 3 4)
  add_test(NAME study_mullins_n${n}_band08E_2d COMMAND ${SD_VALIDATE} mullins
    ${PERTURBED} 5 40,160 --mode ${n} --band-width 0.0375
    --csv mullins_n${n}_band08E_2d.csv)
  add_test(NAME study_mullins_n${n}_E047_band08E_h256_2d COMMAND ${SD_VALIDATE}
    mullins ${PERTURBED} 6 40 --mode ${n} ${E047} --band-width 0.0375
    --csv mullins_n${n}_E047_band08E_h256_2d.csv)
  list(APPEND SD_BAND_RATE study_mullins_n${n}_E047_band08E_h256_2d)
endforeach()
foreach(spec "0.0625:0.05" "0.094:0.075")
  string(REPLACE ":" ";" spec "${spec}")
  list(GET spec 0 E)
  list(GET spec 1 W)
  add_test(NAME study_mullins_E${E}_band08E_2d COMMAND ${SD_VALIDATE} mullins
    ${PERTURBED} 5 40 --filter-thickness ${E} --band-width ${W}
    --csv mullins_E${E}_band08E_2d.csv)
  list(APPEND SD_BAND_RATE study_mullins_E${E}_band08E_2d)
endforeach()
set_tests_properties(study_mullins_band08E_dt_2d study_mullins_band4h_dt_2d
  study_mullins_band08E_320_noreinit_2d study_mullins_E047_band08E_160_2d
  study_mullins_n3_band08E_2d
  study_mullins_n4_band08E_2d ${SD_BAND_RATE} PROPERTIES
  LABELS validation-long RESOURCE_LOCK sd_mullins_output)

# --- Two grains and a packing (3D) -----------------------------------------
# The packing to x/R = 0.5 (22 steps) for the far-end length.
add_test(NAME study_sd_packing_length_3d
  COMMAND ${MPIRUN} ${MPIRUN_FLAGS} -np 2 ${SD_VALIDATE} neck
    ${CMAKE_SOURCE_DIR}/parameter_files/packing_surface_diffusion_3d.prm 22
    --sample-interval 2 --csv sd_packing_length_3d.csv)
set_tests_properties(study_sd_packing_length_3d PROPERTIES
  LABELS validation-long)
# The two-sphere and packing runs with the refined band at 0.8 E (the
# kappa / v_s system's band; doc/validation.md, "3D: two grains", "3D:
# small packing"): R/h = 8 and 12 to t* = 1e-3, the packing to t = 2.4 on
# 2 ranks.
set(GRAINS_3D_H8 --set "Mesh refinement/Maximum level=2"
  --set "Level set/Filter thickness=0.15" --set "Time/Time step=0.01"
  --set "Time/End time=1.6")
add_test(NAME study_sd_two_grains_h8_band08E_3d COMMAND ${SD_VALIDATE} neck
  ${GRAINS_3D} 160 --sample-interval 5 ${GRAINS_3D_H8}
  --set "Mesh refinement/Band width=0.12"
  --csv sd_two_grains_h8_band08E_3d.csv)
add_test(NAME study_sd_two_grains_h12_band08E_3d COMMAND ${SD_VALIDATE} neck
  ${GRAINS_3D} 160 --sample-interval 5 --set "Domain/Subdivisions=27, 15, 15"
  --set "Mesh refinement/Maximum level=1"
  --set "Level set/Filter thickness=0.1" --set "Mesh refinement/Band width=0.08"
  --set "Time/Time step=0.01" --set "Time/End time=1.6"
  --csv sd_two_grains_h12_band08E_3d.csv)
add_test(NAME study_sd_packing_band08E_3d
  COMMAND ${MPIRUN} ${MPIRUN_FLAGS} -np 2 ${SD_VALIDATE} neck
    ${CMAKE_SOURCE_DIR}/parameter_files/packing_surface_diffusion_3d.prm 25
    --sample-interval 2 --set "Mesh refinement/Band width=0.12"
    --csv sd_packing_band08E_3d.csv)
set_tests_properties(study_sd_two_grains_h8_band08E_3d
  study_sd_two_grains_h12_band08E_3d study_sd_packing_band08E_3d PROPERTIES
  LABELS validation-long)
# The two spheres from nearly tangent (x0/R = 0.05, the neck a sub-cell
# cusp) with k curvature levels, steps relative to t and the solid
# reinitialised from band cells (the default for surface diffusion), to
# t* = 1e-3; k = 5 only to t* = 1e-6. Also k = 3 with the finest cell's
# reinitialisation and with v^c (doc/validation.md, "3D: two grains from
# nearly tangent").
set(TANGENT_3D "Geometry/Particles=0.30025, 0.5, 0.5, 0.2; 0.69975, 0.5, 0.5, 0.2")
set(GRAINS_3D_TANGENT --set "Mesh refinement/Maximum level=2"
  --set "Level set/Filter thickness=0.15" --set "Mesh refinement/Band width=0.12"
  --set "Time/Time step=1e-7" --set "Time/CFL number=0"
  --set "Time/End time=1.6")
foreach(spec "3:0.05:" "3:0.025:" "4:0.05:" "5:0.05:_to1e-6"
             "3:0.05:_finest_reinit" "3:0.05:_vc")
  string(REPLACE ":" ";" spec "${spec}")
  list(GET spec 0 k)
  list(GET spec 1 r)
  list(GET spec 2 variant)
  set(name sd_two_grains_tangent_k${k}_rel${r}${variant}_3d)
  set(extra)
  if(variant STREQUAL "_to1e-6")
    set(extra --set "Time/End time=0.0016")
  elseif(variant STREQUAL "_finest_reinit")
    set(extra --set "${FINEST_REINIT}")
  elseif(variant STREQUAL "_vc")
    set(extra --set "Volume correction/Enabled=true")
  endif()
  add_test(NAME study_${name} COMMAND ${SD_VALIDATE} neck ${GRAINS_3D} 3000
    --sample-interval 4 --set "${TANGENT_3D}" ${GRAINS_3D_TANGENT}
    --set "Mesh refinement/Curvature refinement levels=${k}"
    --set "Time/Relative time step=${r}" ${extra} --csv ${name}.csv)
  set_tests_properties(study_${name} PROPERTIES LABELS validation-long)
endforeach()
