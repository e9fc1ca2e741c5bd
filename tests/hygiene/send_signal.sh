#!/bin/sh
# send_signal.sh DELAY SIGNAL TARGET MPIRUN ARGS...: run "MPIRUN ARGS...",
# send SIGNAL after DELAY seconds to TARGET: "launcher" (mpirun itself) or
# "rank" (one rank only: mpirun's last child process), and exit with
# mpirun's exit code.
delay=$1 signal=$2 target=$3
shift 3
"$@" &
launcher=$!
sleep "$delay"
if [ "$target" = launcher ]; then
  kill -s "$signal" $launcher
else
  kill -s "$signal" "$(ps -o pid= --ppid $launcher | tail -n 1)"
fi
wait $launcher
