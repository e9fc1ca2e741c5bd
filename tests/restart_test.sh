#!/bin/bash
# restart_test.sh LEVELSINTER COMPARE_METRICS MPIRUN "MPIRUN_FLAGS" SCENE
#                 NP_FIRST NP_RESUME WORK TOLERANCE "IGNORED;COLUMNS"
#                 [--set ...]...
# The scene run uninterrupted on NP_FIRST ranks, then again killed with
# SIGKILL once its checkpoint at step 10 exists and resumed on NP_RESUME
# ranks: the two metrics.csv must agree to TOLERANCE in every column but
# the IGNORED ones (see tests/restart.cmake), and so must the packing
# analysis' files if the scene writes them.
set -u
levelsinter=$1 compare=$2 mpirun=$3 flags=${4//;/ } scene=$5
np_first=$6 np_resume=$7 work=$8 tolerance=$9 ignored=${10//;/ }
shift 10
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
launch() { # NP ARGS...: levelsinter on NP ranks
  local np=$1
  shift
  # shellcheck disable=SC2086
  $mpirun $flags -np "$np" "$levelsinter" "$@"
}

launch "$np_first" --set "Output/Directory=reference" "$@" "$scene" \
  > reference.log 2>&1 || { cat reference.log; exit 1; }

# shellcheck disable=SC2086
$mpirun $flags -np "$np_first" "$levelsinter" --set "Output/Directory=killed" \
  "$@" "$scene" > killed.log 2>&1 &
launcher=$!
for _ in $(seq 1 6000); do
  [ -d killed/checkpoints/step_000010 ] && break
  kill -0 $launcher 2> /dev/null || break
  sleep 0.01
done
# SIGKILL to the ranks themselves (the launcher cannot pass it on).
ranks=$(ps -o pid= --ppid $launcher)
if [ -n "$ranks" ]; then
  # shellcheck disable=SC2086
  kill -9 $ranks 2> /dev/null
fi
wait $launcher
[ -d killed/checkpoints/step_000010 ] ||
  { echo "FAIL: no checkpoint at step 10"; cat killed.log; exit 1; }
echo "killed after $(($(wc -l < killed/metrics.csv) - 1)) metrics rows;" \
  "checkpoints: $(ls killed/checkpoints | tr '\n' ' ')"

launch "$np_resume" --resume killed > resumed.log 2>&1 ||
  { cat resumed.log; exit 1; }
grep -E "resumed|checkpoint" resumed.log | head -3
# shellcheck disable=SC2086
"$compare" reference/metrics.csv killed/metrics.csv "$tolerance" $ignored ||
  exit 1
# The packing analysis' files, if the scene has it: necks.csv and pores.csv
# to the same tolerance (not the pore centroids, which are round-off on a
# symmetry centre), pore_events.csv line by line (step, event, pore id).
for table in necks pores; do
  [ -f reference/$table.csv ] || continue
  echo "$table.csv:"
  "$compare" reference/$table.csv killed/$table.csv "$tolerance" \
    centroid_x centroid_y centroid_z || exit 1
done
if [ -f reference/pore_events.csv ]; then
  diff <(cut -d, -f2-4 reference/pore_events.csv) \
    <(cut -d, -f2-4 killed/pore_events.csv) ||
    { echo "FAIL: pore_events.csv differs"; exit 1; }
  echo "pore_events.csv: $(($(wc -l < killed/pore_events.csv) - 1)) events agree"
fi
