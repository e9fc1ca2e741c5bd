# --- Volume diffusion: the mechanism (Algorithm 3) ------------------------
set(VD_GRAINS ${CMAKE_SOURCE_DIR}/parameter_files/two_grains_volume_diffusion_2d.prm)

# Two equal grains R = 0.2 (paper Sect. 6.6, Table 7), h = 1/128, the CFL
# number 0.5 choosing dt, with the volume correction (Eq. 116), 40 steps.
# Measured: neck 0.04614 -> 0.08952 (x 1.94) by t = 9.5e-3 s, |dV/V| at
# most 2.4e-4 over the samples (9.2e-5 at the end); ~11 s. Limits: growth
# x 1.6 (a wrong sign of v shrinks the neck), |dV/V| 5e-4 (2x the largest
# sampled value). Without the correction the area fell by 4.4 % in the
# same 40 steps (measured), which this limit rejects.
# A check of the wiring, not of the rate: for a circle (xi = 0 exactly) the
# mechanism measured a spurious speed C_v |xi| up to 0.56 um/s at h = 1/128
# and 2.3 at h = 1/256 (Stabilisation constant 0.1; 0.49 and 1.2 at 1), so
# the neck speed is not yet the paper's.
add_test(NAME volume_diffusion_two_grains_2d COMMAND ${SD_VALIDATE} neck
  ${VD_GRAINS} 40 --sample-interval 5 --min-neck-growth 1.6
  --max-volume-change 5e-4)

# 1 and 2 ranks, 10 steps: the elastic solve (AMG/ILU per rank, relative
# 1e-10) differs with the partition, the interface does not. Measured:
# neck, area and volume agree to 1.6e-8, max_velocity to 4.5e-5 (where the
# largest nodal speed sits is not traced: not compared, nor iterations,
# times and mesh counts); checked at 1e-6.
foreach(np 1 2)
  add_test(NAME volume_diffusion_np${np}
    COMMAND ${MPIRUN} ${MPIRUN_FLAGS} -np ${np} $<TARGET_FILE:levelsinter>
      --overwrite --set "Time/Maximum steps=10" --set "Output/Metrics interval=1"
      --set "Output/Directory=vd_np${np}" --set "Output/Field formats=none"
      ${VD_GRAINS})
  set_tests_properties(volume_diffusion_np${np} PROPERTIES
    FIXTURES_SETUP vd_np${np})
endforeach()
add_test(NAME volume_diffusion_1_vs_2_ranks
  COMMAND compare_metrics vd_np1/metrics.csv vd_np2/metrics.csv 1e-6
    wall_time transport_iterations cells dofs volume_change max_velocity
    volume_diffusion_mechanics_iterations volume_diffusion_xi_iterations)
set_tests_properties(volume_diffusion_1_vs_2_ranks PROPERTIES
  FIXTURES_REQUIRED "vd_np1;vd_np2")

# The combinations SceneParameters refuses.
bad_input_test(volume_diffusion_with_viscous_flow "Volume diffusion/Enabled"
  --set "Viscous flow/Enabled=true" ${VD_GRAINS})
bad_input_test(volume_diffusion_newtonian "Phase law/Law"
  --set "Phase law/Law=newtonian" ${VD_GRAINS})
