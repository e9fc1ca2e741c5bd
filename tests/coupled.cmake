# --- Surface and volume diffusion together (Eq. 118, Algorithm 4) ----------
# One scene, three runs: coupled, surface only, volume only (the other
# mechanism switched off with --set).
set(COUPLED ${CMAKE_SOURCE_DIR}/parameter_files/two_grains_coupled_2d.prm)
set(COUPLED_SURFACE "Volume diffusion/Enabled=false")
set(COUPLED_VOLUME "Surface diffusion/Enabled=false")
set(COMPARE_NECKS ${CMAKE_SOURCE_DIR}/scripts/compare_neck_curves.py)

# Both sections in reduced time: one scene has one time.
bad_input_test(coupled_two_reduced_times "Volume diffusion/Time unit"
  --set "Surface diffusion/Time unit=reduced"
  --set "Surface diffusion/Reference radius=0.2"
  --set "Volume diffusion/Time unit=reduced"
  --set "Volume diffusion/Reference radius=0.2" ${COUPLED})

# CI_PLACEHOLDER

# --- Study: the coupled pair of the paper's Fig. 47 (label validation-long) --
# STUDY_PLACEHOLDER
