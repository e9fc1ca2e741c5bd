#!/bin/sh
# signal_one_rank.sh DELAY MPIRUN ARGS...: run "MPIRUN ARGS...", send
# SIGTERM to one of its ranks only (its last child process) after DELAY
# seconds, and exit with mpirun's exit code.
delay=$1
shift
"$@" &
launcher=$!
sleep "$delay"
rank=$(ps -o pid= --ppid "$launcher" | tail -n 1)
kill -TERM $rank
wait $launcher
