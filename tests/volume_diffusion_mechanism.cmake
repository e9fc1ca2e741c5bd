# --- Volume diffusion: the mechanism (Algorithm 3) ------------------------
set(VD_GRAINS ${CMAKE_SOURCE_DIR}/parameter_files/two_grains_volume_diffusion_2d.prm)
