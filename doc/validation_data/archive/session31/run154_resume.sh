#!/bin/bash
# Session 31: resume session 30's 154-grain coupled packing (Extrapolation =
# limited, frozen build bin_lim of 0ca2e69) from its last checkpoint in
# /work/runs/s30/p154_lim, NP ranks (1), to at most STEPS steps, checkpoints
# every 20 min; the resident set is sampled every 10 s into p154_rss.txt.
cd /work/runs/s31
export LD_LIBRARY_PATH=/work/runs/s30/bin_lim
mpirun --allow-run-as-root -np ${NP:-1} /work/runs/s30/bin_lim/levelsinter \
  --resume /work/runs/s30/p154_lim \
  --set "Time/Maximum steps=${STEPS:-1000}" \
  --set "Output/Checkpoint minutes=20" >> p154_resume.log 2>&1 &
pid=$!
echo $pid > mpirun.pid
max=0
while kill -0 $pid 2>/dev/null; do
  for p in $(pgrep -P $pid); do
    r=$(awk '/VmRSS/{print $2}' /proc/$p/status 2>/dev/null)
    [ -n "$r" ] && [ "$r" -gt "$max" ] && max=$r &&
      echo "$(date +%T) $max kB" > p154_rss.txt
  done
  sleep 10
done
wait $pid
