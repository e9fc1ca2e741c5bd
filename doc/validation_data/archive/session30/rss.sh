#!/bin/bash
# Largest resident set of process 19148, sampled every 10 s.
max=0
while kill -0 19148 2>/dev/null; do
  r=$(awk '/VmRSS/{print $2}' /proc/19148/status 2>/dev/null)
  [ -n "$r" ] && [ "$r" -gt "$max" ] && max=$r && echo "$(date +%T) $max kB" > p154_lim_rss.txt
  sleep 10
done
