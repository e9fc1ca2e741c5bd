#!/bin/bash
# Every 20 s: the last progress line of the 154 run and the CPU seconds
# (utime + stime) and resident memory of its two ranks.
cd /work/runs/s23
tck=$(getconf CLK_TCK)
while true; do
  line=$(grep "^step" c154_solid_rec.log | tail -n 1)
  out="$(date +%s)"
  for p in $(pgrep -f "^./levelsinter_154 --overwrite"); do
    read -r ut st <<< $(awk '{print $14, $15}' /proc/$p/stat)
    rss=$(awk '/VmRSS/{print $2}' /proc/$p/status)
    hwm=$(awk '/VmHWM/{print $2}' /proc/$p/status)
    out="$out $p $(( (ut+st)/tck )) $rss $hwm"
  done
  echo "$out | $line" >> c154_monitor.txt
  sleep 20
done
