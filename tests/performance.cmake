# --- Cost of the surface-diffusion packings (issue 16; doc/performance.md)
# performance_study runs a scene a few steps and writes its cost per step
# and per phase (wall and CPU, TimerOutput) as one CSV row; the packings of
# 8, 27, 64 and 154 particles share the paper's radii (uniform in
# [0.0633, 0.0797] um), the generator's settings and the resolution of
# packing_154_surface_diffusion_3d.prm (h_min = 0.3 / 2^5 = 0.0094 um,
# R/h = 6.7-8.5): only the particle count and the box differ (the box
# scales with N^(1/3), in whole coarse cells of 0.3 um). 3 steps each: the
# cost per step is taken over steps 2-3 (one adaptation, one metrics
# call). Long runs on a shared machine: label benchmark.
add_executable(performance_study performance_study.cc)
target_link_libraries(performance_study levelsinter_study)
deal_ii_setup_target(performance_study)
set(PERF_SCENE
  ${CMAKE_SOURCE_DIR}/parameter_files/packing_154_surface_diffusion_3d.prm)
set(PERF_STEPS 3)
set(PERF_CSVS)
set(PERF_FIXTURES)
# performance_run(N SIDE CELLS RANKS): N particles in [0, SIDE]^3 (CELLS
# coarse cells per axis) on RANKS ranks.
function(performance_run n side cells ranks)
  set(name performance_sd_${n}_np${ranks})
  if(n EQUAL 154)
    set(particles ${CMAKE_SOURCE_DIR}/parameter_files/packing_154_3d.csv)
    set(setup "")
  else()
    set(particles ${CMAKE_CURRENT_BINARY_DIR}/performance_packing_${n}.csv)
    set(setup performance_pack_${n})
  endif()
  add_test(NAME ${name} COMMAND ${MPIRUN} ${MPIRUN_FLAGS} -np ${ranks}
    $<TARGET_FILE:performance_study> ${PERF_SCENE} ${PERF_STEPS}
    --csv ${CMAKE_CURRENT_BINARY_DIR}/${name}.csv
    --set "Domain/Upper corner=${side},${side},${side}"
    --set "Domain/Subdivisions=${cells},${cells},${cells}"
    --set "Geometry/Particle file=${particles}"
    --set "Output/Directory=${CMAKE_CURRENT_BINARY_DIR}/${name}"
    --set "Output/Field formats=none" --set "Output/Progress interval=1")
  set_tests_properties(${name} PROPERTIES LABELS benchmark
    FIXTURES_SETUP ${name} FIXTURES_REQUIRED "${setup}")
  set(PERF_CSVS ${PERF_CSVS} ${CMAKE_CURRENT_BINARY_DIR}/${name}.csv
    PARENT_SCOPE)
  set(PERF_FIXTURES ${PERF_FIXTURES} ${name} PARENT_SCOPE)
endfunction()
# The smaller packings, made as packing_154_3d.csv was (its '#' lines) in
# a box scaled by (N / 154)^(1/3) and rounded up to whole 0.3 um cells.
foreach(spec 8:0.6:2 27:0.9:3 64:0.9:3)
  string(REPLACE ":" ";" spec ${spec})
  list(GET spec 0 n)
  list(GET spec 1 side)
  list(GET spec 2 cells)
  add_test(NAME performance_pack_${n} COMMAND $<TARGET_FILE:levelsinter-pack>
    --particles ${n} --radius-distribution uniform --radius-min 0.0633
    --radius-max 0.0797 --region 0,0,0:${side},${side},${side}
    --domain 0,0,0:${side},${side},${side} --seed 1 --overwrite
    --output ${CMAKE_CURRENT_BINARY_DIR}/performance_packing_${n}.csv)
  set_tests_properties(performance_pack_${n} PROPERTIES LABELS benchmark
    FIXTURES_SETUP performance_pack_${n})
  performance_run(${n} ${side} ${cells} 2)
endforeach()
performance_run(154 1.2 4 2)
# Strong scaling 1 -> 2 ranks on the 8 particles and on the 154 (740 k
# level-set DoFs, the issue's "at least 500 k"; 3.3 GB on 1 rank).
performance_run(8 0.6 2 1)
performance_run(154 1.2 4 1)
# Run as its #! says: Debian's python3 has matplotlib.
add_test(NAME performance_table COMMAND
  ${CMAKE_SOURCE_DIR}/scripts/plot_performance.py
  --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/performance_packings.csv
  --png ${CMAKE_SOURCE_DIR}/doc/validation_data/performance_packings.png
  ${PERF_CSVS})
set_tests_properties(performance_table PROPERTIES LABELS benchmark
  FIXTURES_REQUIRED "${PERF_FIXTURES}")

# --- The paper's 154-particle packings (doc/performance.md, "The
# 154-particle runs"): the run itself with a checkpoint every 5 steps (it
# can be resumed with levelsinter --resume), then its history: necks x/R,
# density, shrinkage, pores and volume change (scripts/packing_history.py).
# Surface diffusion to t = 0.13, where the mean neck has passed 0.5 R (the
# paper's "necks at 0.5 R"; measured at step 130, t = 0.128 s, about 1.4 h
# on 2 idle cores); the
# coupled packing for its first 12 steps (about 30 min; the paper's run has
# 550: resume the run with a larger limit to go on).
function(packing_154_run name scene limit)
  string(REPLACE "_" " " title "154 particles, ${name}")
  add_test(NAME packing_154_${name}_run COMMAND ${MPIRUN} ${MPIRUN_FLAGS}
    -np 2 $<TARGET_FILE:levelsinter> --overwrite
    --set "Output/Directory=${CMAKE_CURRENT_BINARY_DIR}/packing_154_${name}"
    --set "Output/Checkpoint interval=5" --set "${limit}"
    ${CMAKE_SOURCE_DIR}/parameter_files/${scene})
  set_tests_properties(packing_154_${name}_run PROPERTIES LABELS benchmark
    TIMEOUT 14400 FIXTURES_SETUP packing_154_${name})
  add_test(NAME packing_154_${name}_history COMMAND
    ${CMAKE_SOURCE_DIR}/scripts/packing_history.py
    ${CMAKE_CURRENT_BINARY_DIR}/packing_154_${name}
    ${CMAKE_SOURCE_DIR}/parameter_files/packing_154_3d.csv
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/packing_154_${name}.csv
    --png ${CMAKE_SOURCE_DIR}/doc/validation_data/packing_154_${name}.png
    --title "${title}")
  set_tests_properties(packing_154_${name}_history PROPERTIES
    LABELS benchmark FIXTURES_REQUIRED packing_154_${name})
endfunction()
packing_154_run(surface_diffusion packing_154_surface_diffusion_3d.prm
  "Time/End time=0.13")
packing_154_run(coupled packing_154_coupled_3d.prm "Time/Maximum steps=12")

# The wall and CPU time of every scene in parameter_files/ on 1 and 2 ranks
# as shipped (doc/user_guide.md, "Scenes"): short scenes to the end, long
# ones projected from their first 20 s, or from their first steps with an
# ETA where a step takes longer (the 3D packings: up to 10 min;
# scripts/measure_scenes.py). The 154-particle packings and the 1.4 M-DoF
# transport benchmark are left out (hours, 16 GB; doc/performance.md and
# doc/validation.md give their cost). About 60 minutes on idle cores.
add_test(NAME benchmark_scene_times
  COMMAND ${CMAKE_SOURCE_DIR}/scripts/measure_scenes.py
    $<TARGET_FILE:levelsinter> --budget 20 --max-budget 600
    --skip packing_154_surface_diffusion_3d.prm packing_154_coupled_3d.prm
    transport_benchmark_3d.prm
    --work ${CMAKE_CURRENT_BINARY_DIR}/scene_times
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/scene_times.csv)
set_tests_properties(benchmark_scene_times PROPERTIES LABELS benchmark)

# --- What resolution and step the packing results need (issue 26;
# doc/validation.md, "Packings: resolution and step"): 27 spheres made like
# the 154 (packing_27_like_154_3d.csv: the paper's radii, nearly tangent,
# levelsinter-pack seed 1 in a box of (27/154)^(1/3) x 1.2 rounded up to
# 0.9 um) with the coupled 154 scene's settings, to t = 0.01 s: the CFL
# number 0.5 (the scene's), 1 and 2 (its band widened from 4.8 to 5.1
# cells, as the band must hold (Adapt interval x CFL + 1) cells). No other
# mesh: at 2 h no node lies lambda = 3 cells inside a sphere (the run is
# refused), and at h / 2 the volume-diffusion spikes cut the step to 2e-5 s
# (measured on 8 spheres, doc/performance.md: about 17 h to t = 0.005 s).
# Each case keeps a checkpoint
# every 5 steps and is resumed where it stopped; metrics at every step, so
# that the comparison at fixed times interpolates between close rows.
# Measured (27 Nov 2026, doc/validation.md): CFL 2 / 1 / 0.5 in 24 / 34 /
# 50 steps, 4.4e3 s wall for the reference on 1 rank of a shared machine.
# Added 28 Nov 2026: CFL 4 with an adaptation every step (the band then
# holds 1 x 4 + 1 cells at 0.048) and CFL 2 with `Elastic solve interval =
# 2`: 24 and 39 steps (those runs, like the first three, with the elastic
# solver tolerance 1e-6 the scene had then).
# The scene's elastic problem moved to the solid space with the recovered
# xi on 28 Nov 2026 (doc/performance.md, "Session 23"); this study keeps
# the space and xi it was measured with, so that its table stays true.
# packing_convergence_test(NAME SCENE BOX CELLS PARTICLES END TIMES
#   ARGS...): scripts/packing_convergence.py on SCENE with PARTICLES in
#   [0, BOX]^3 (CELLS coarse cells per axis) to END, compared at TIMES, its
#   table in doc/validation_data/NAME.csv; ARGS: the cases and options.
function(packing_convergence_test name scene box cells particles end times)
  add_test(NAME ${name} COMMAND
    ${CMAKE_SOURCE_DIR}/scripts/packing_convergence.py
    $<TARGET_FILE:levelsinter> ${CMAKE_SOURCE_DIR}/parameter_files/${scene}
    --work ${CMAKE_CURRENT_BINARY_DIR}/${name}
    --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/${name}.csv
    --end-time ${end} --times ${times}
    --set "Domain/Upper corner=${box},${box},${box}"
    --set "Domain/Subdivisions=${cells},${cells},${cells}"
    --set "Output/Metrics interval=1"
    --set "Geometry/Particle file=${CMAKE_SOURCE_DIR}/parameter_files/${particles}"
    ${ARGN})
  set_tests_properties(${name} PROPERTIES
    LABELS validation-long TIMEOUT 10800)
endfunction()
packing_convergence_test(packing_convergence_27 packing_154_coupled_3d.prm
  0.9 3 packing_27_like_154_3d.csv 0.01 0.0025,0.005,0.01
  --case "cfl4_adapt1:Time/CFL number=4\\;Mesh refinement/Adapt interval=1\\;Mesh refinement/Band width=0.048"
  --case "cfl2_interval2:Time/CFL number=2\\;Mesh refinement/Band width=0.048\\;Volume diffusion/Elastic solve interval=2"
  --case "cfl2:Time/CFL number=2\\;Mesh refinement/Band width=0.048"
  --case "cfl1:Time/CFL number=1"
  --case "reference"
  --reference reference
  --set "Viscous flow/Pressure space=continuous"
  --set "Volume diffusion/Pressure gradient=nodal"
  --set "Time/CFL number=0.5"
  --set "Volume diffusion/Extrapolation=linear")

# The coupled scene as shipped since session 23 (solid space, recovered xi)
# on the 27 spheres, to t = 0.005 s (issue 26; doc/validation.md,
# "Packings: the solid space's step and mesh"): CFL 1.5 with and without
# `Elastic solve interval = 2`, and 2 h (one level less, band and filter
# doubled), against the scene (CFL 0.5). Measured (28 Nov 2026) on a
# machine shared with two other sessions: 1-2 h of wall per case.
packing_convergence_test(packing_solid_27 packing_154_coupled_3d.prm
  0.9 3 packing_27_like_154_3d.csv 0.005 0.0025,0.005
  --case "coarse:Mesh refinement/Maximum level=4\\;Mesh refinement/Band width=0.09\\;Level set/Filter thickness=0.112"
  --case "cfl1.5_interval2:Time/CFL number=1.5\\;Volume diffusion/Elastic solve interval=2"
  --case "cfl1.5:Time/CFL number=1.5"
  --case "reference"
  --reference reference
  --set "Time/CFL number=0.5"
  --set "Volume diffusion/Extrapolation=linear")

# Steps beyond CFL 1.5 and the scene's cap of 1e-3 s (issue 26; doc/validation.md,
# "Packings: steps beyond CFL 1.5 and the cap"): the scene as shipped on the
# 27 spheres, to t = 0.02 s, at CFL 1.5 (the scene) and CFL 3 with a cap of
# 2e-3 s (an adaptation every step, so that the band holds 1 x 3 + 1
# cells), against CFL 0.5. Measured (28 Nov 2026, session 26) with 1 rank
# per case, two cases at a time beside helpers' jobs: about 2.5 h of CPU.
packing_convergence_test(packing_step_27 packing_154_coupled_3d.prm
  0.9 3 packing_27_like_154_3d.csv 0.02 0.005,0.01,0.02
  --case "cfl3_cap2e-3:Time/CFL number=3\\;Time/Time step=2e-3\\;Mesh refinement/Adapt interval=1"
  --case "cfl1.5:Time/CFL number=1.5"
  --case "reference"
  --reference reference
  --ranks 1
  --set "Time/CFL number=0.5"
  --set "Volume diffusion/Extrapolation=linear")

# The coupled packing at h and h / 2 with the scene as shipped (solid
# space, recovered xi, CFL 1.5; issue 26, doc/validation.md, "Packings: the
# coupled scene at h and h / 2"): 8 spheres made like the 154 to t = 0.005
# s. h / 2 keeps the physics: xi's depth lambda h = 0.028 um (lambda = 6
# cells of h / 2), the band and the filter in um as the scene's; it starts
# from Minimum level 2 (see the surface-diffusion study below). Measured
# (29 Nov 2026, session 28): 1 rank beside other jobs, 5 steps at h (331 s
# of wall), 10 at h / 2 (4 237 s).
packing_convergence_test(packing_resolution_coupled_8
  packing_154_coupled_3d.prm 0.6 2 packing_8_like_154_3d.csv
  0.005 0.001,0.0025,0.005
  --case "h"
  --case "h2:Mesh refinement/Minimum level=2\\;Mesh refinement/Maximum level=6\\;Volume diffusion/Interior offset=6"
  --reference h2 --ranks 1
  --set "Volume diffusion/Extrapolation=linear")

# The same 8 spheres to t = 0.015 s, past the rise of the largest speed,
# with xi's extension limited (the scene since session 30) and linear, at h
# and h / 2, and at h with the step capped at 5e-4 s (issue 26;
# doc/validation.md, "Packings: the limited extrapolation"). The studies
# before session 30 ran the linear extension and keep it (--set above).
# Measured (29 Nov 2026, session 30): 1 rank beside two helpers' jobs,
# 2.5 min at h, 4.5 min with the shorter step, 25 min (limited) and 31 min
# (linear, its step cut to 2.3e-4 s by the ridge) at h / 2.
# h / 2 of the 8 spheres like the 154 with the physics fixed (xi's depth
# lambda h = 0.028 um: 6 cells of h / 2; band and filter in um).
set(PACKING_8_H2
  "Mesh refinement/Minimum level=2\\;Mesh refinement/Maximum level=6\\;Volume diffusion/Interior offset=6")
set(PACKING_8_TIMES 0.0025,0.005,0.0075,0.01,0.0125,0.015)
packing_convergence_test(packing_resolution_limited_8
  packing_154_coupled_3d.prm 0.6 2 packing_8_like_154_3d.csv
  0.015 ${PACKING_8_TIMES}
  --case "h_linear:Volume diffusion/Extrapolation=linear"
  --case "h2_linear:${PACKING_8_H2}\\;Volume diffusion/Extrapolation=linear"
  --case "h_dt5e-4:Time/Time step=5e-4"
  --case "h"
  --case "h2:${PACKING_8_H2}"
  --reference h2 --ranks 1)

# Curvature refinement at the necks instead of h / 2 (issue 26: "and the
# curvature refinement at necks, if that is the cheaper route";
# doc/validation.md, "Packings: curvature levels at the necks, the
# density's start, the first closed pore"): the 8 spheres of packing_resolution_limited_8 at h
# with one curvature level (neck cells h / 2), lambda = 6 cells of h / 2
# (3.5 h in band cells, 3 h at the necks) or 5 (3 h and 2.5 h), 4 or 2
# cells per curvature radius, against h and h / 2 (the same cases as
# packing_resolution_limited_8). Measured (29 Nov 2026, session 31): 1 rank
# beside the 154 run and two helpers' jobs, 6.8-10.6 min per curvature
# case.
set(CURVATURE_LEVEL "Mesh refinement/Curvature refinement levels=1")
packing_convergence_test(packing_curvature_refinement_8
  packing_154_coupled_3d.prm 0.6 2 packing_8_like_154_3d.csv
  0.015 ${PACKING_8_TIMES}
  --case "h"
  --case "h_curv1_offset6:${CURVATURE_LEVEL}\\;Volume diffusion/Interior offset=6"
  --case "h_curv1_offset5:${CURVATURE_LEVEL}\\;Volume diffusion/Interior offset=5"
  --case "h_curv1_cpr2_offset5:${CURVATURE_LEVEL}\\;Mesh refinement/Cells per curvature radius=2\\;Volume diffusion/Interior offset=5"
  --case "h2:${PACKING_8_H2}"
  --reference h2 --ranks 1)

# The first closed pore (issue 26: "the time the first pore closes"
# within 10 % of the finest run; doc/validation.md, "Packings: curvature
# levels at the necks, the density's start, the first closed pore"): the
# central pore of
# eight tangent spheres like the 154's (pore_cubic_coupled_3d.prm, every
# setting of packing_154_coupled_3d.prm, an eighth) at 2 h, h (the scene)
# and h / 2 with lambda h and the filter fixed in um, and at h with a
# shorter step. 2 h needs an adaptation every step (its band of 0.05 um
# holds 1 x 1.5 + 1 cells). Measured (29 Nov 2026, session 31): 1 rank
# beside other jobs, about 2 min at 2 h, 7 min at h, 40 min at h / 2.
add_test(NAME packing_first_closure_cubic COMMAND
  ${CMAKE_SOURCE_DIR}/scripts/packing_convergence.py
  $<TARGET_FILE:levelsinter>
  ${CMAKE_SOURCE_DIR}/parameter_files/pore_cubic_coupled_3d.prm
  --work ${CMAKE_CURRENT_BINARY_DIR}/packing_first_closure_cubic
  --csv ${CMAKE_SOURCE_DIR}/doc/validation_data/packing_first_closure_cubic.csv
  --end-time 0.12 --times 0.01,0.02,0.04,0.06,0.08
  --case "2h:Mesh refinement/Maximum level=2;Volume diffusion/Interior offset=1.5;Mesh refinement/Adapt interval=1;Mesh refinement/Band width=0.05"
  --case "h"
  --case "h_dt5e-4:Time/Time step=5e-4"
  --case "h_cfl075:Time/CFL number=0.75"
  --case "h2:Mesh refinement/Maximum level=4;Volume diffusion/Interior offset=6"
  --reference h2 --ranks 1)
set_tests_properties(packing_first_closure_cubic PROPERTIES
  LABELS validation-long TIMEOUT 10800)

# The surface-diffusion packing at three meshes (issue 26; doc/validation.md,
# "Packings: resolution and step"): 8 spheres made like the 154 with the
# settings of packing_154_surface_diffusion_3d.prm to its end time t =
# 0.033 s, at h (the scene), 2 h and h / 2, the band and the filter scaled
# with h (lengths in cells kept); h / 2 starts from Minimum level 2, as at
# level 1 no node sees the spheres at a band of 0.02 um (the run would stop
# at its start). The step is the scene's cap of 1e-3 s at every mesh (not
# CFL-bound), so only h changes. Measured (27 Nov 2026): 1 rank on a shared
# machine, 98 s, 329 s and 1067 s.
packing_convergence_test(packing_resolution_sd_8
  packing_154_surface_diffusion_3d.prm 0.6 2 packing_8_like_154_3d.csv
  0.033 0.005,0.01,0.02,0.033
  --case "coarse:Mesh refinement/Maximum level=4\\;Mesh refinement/Band width=0.08\\;Level set/Filter thickness=0.112"
  --case "reference"
  --case "fine:Mesh refinement/Minimum level=2\\;Mesh refinement/Maximum level=6\\;Mesh refinement/Band width=0.02\\;Level set/Filter thickness=0.028"
  --reference fine --ranks 1)
