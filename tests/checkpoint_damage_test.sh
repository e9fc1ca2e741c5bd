#!/bin/bash
# checkpoint_damage_test.sh LEVELSINTER COMPARE_METRICS MPIRUN "MPIRUN_FLAGS"
#                           SCENE NP WORK FILE [--set ...]...
# A run of 10 steps on NP ranks with checkpoints at steps 5 and 10; then, for
# each damage to FILE of a checkpoint (truncated to half its size, missing,
# one byte inverted), on a copy of the run:
#  - FILE damaged in step_000010 only: --resume must name the checkpoint,
#    FILE and the fault, set the checkpoint aside as step_000010.damaged,
#    say it resumes from step_000005, exit 0, keep step_000005, and its
#    metrics.csv must agree with the undamaged run's (to 1e-8, as the
#    restart tests);
#  - FILE damaged in both checkpoints: --resume must exit 1 naming both
#    and change nothing (checkpoints and metrics.csv as they were).
# For FILE = counters.txt also: random bytes with a manifest that matches
# them (a format mismatch, not damage) must stop with exit 1 naming the
# file.
set -u
levelsinter=$1 compare=$2 mpirun=$3 flags=${4//;/ } scene=$5 np=$6 work=$7
file=$8
shift 8
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
launch() { # levelsinter on NP ranks
  # shellcheck disable=SC2086
  $mpirun $flags -np "$np" "$levelsinter" "$@"
}
fail() {
  echo "FAIL ($case): $*"
  cat "$case.log"
  exit 1
}

launch --set "Output/Directory=pristine" --set "Time/Maximum steps=10" \
  --set "Output/Checkpoint interval=5" --set "Output/Field formats=none" \
  --set "Output/Progress interval=0" "$@" "$scene" > pristine.log 2>&1 ||
  { cat pristine.log; exit 1; }
echo "files in step_000010: $(ls pristine/checkpoints/step_000010 | tr '\n' ' ')"
[ -f pristine/checkpoints/step_000010/"$file" ] ||
  { echo "FAIL: a checkpoint has no $file"; exit 1; }

damage() { # KIND PATH
  local size
  size=$(stat -c %s "$2")
  case $1 in
    truncate) truncate -s $((size / 2)) "$2" ;;
    missing) rm "$2" ;;
    flip)
      local offset=$((size / 2)) byte
      byte=$(od -An -tu1 -j $offset -N1 "$2" | tr -d ' ')
      # shellcheck disable=SC2059
      printf "$(printf '\\%03o' $((byte ^ 255)))" |
        dd of="$2" bs=1 seek=$offset conv=notrunc status=none
      ;;
  esac
}
fault() { # KIND PATH (undamaged): what levelsinter must say
  local size
  size=$(stat -c %s "$2")
  case $file:$1 in
    manifest.txt:truncate)
      echo "manifest.txt is incomplete (it has no final 'end' line)" ;;
    manifest.txt:missing)
      echo "it has no manifest.txt (it was written by a levelsinter older than checkpoint manifests, or the manifest was lost), so it cannot be verified" ;;
    manifest.txt:flip)
      echo "manifest.txt is damaged (its content does not match its own CRC-32)" ;;
    *:truncate) echo "'$file' has $((size / 2)) bytes, the manifest lists $size" ;;
    *:missing) echo "'$file' is missing" ;;
    *:flip) echo "'$file' is damaged: its CRC-32 is " ;;
  esac
}

for kind in truncate missing flip; do
  # The newest checkpoint damaged: the previous one is used.
  case=fallback_$kind
  cp -r pristine $case
  expected=$(fault $kind $case/checkpoints/step_000010/"$file")
  damage $kind $case/checkpoints/step_000010/"$file"
  launch --resume $case > $case.log 2>&1 || fail "exit code $?, expected 0"
  grep -qF "warning: checkpoint '$case/checkpoints/step_000010' cannot be used: $expected" $case.log ||
    fail "no warning '... $expected'"
  grep -qF "set aside as 'step_000010.damaged'" $case.log ||
    fail "not said that the checkpoint is set aside"
  grep -qF "resuming from the previous checkpoint '$case/checkpoints/step_000005' instead" $case.log ||
    fail "not said that step_000005 is used"
  grep -qF "resumed at step 5," $case.log || fail "not resumed at step 5"
  [ "$(ls $case/checkpoints | tr '\n' ' ')" = \
    "step_000005 step_000010 step_000010.damaged " ] ||
    fail "checkpoints left: $(ls $case/checkpoints | tr '\n' ' ')"
  # shellcheck disable=SC2086
  "$compare" pristine/metrics.csv $case/metrics.csv 1e-8 wall_time \
    volume_change transport_iterations > $case.compare ||
    { cat $case.compare; fail "metrics.csv differs from the undamaged run"; }
  echo "$case: $(grep -F "cannot be used" $case.log)"

  # Both checkpoints damaged: nothing to resume from, nothing changed.
  case=none_$kind
  cp -r pristine $case
  expected10=$(fault $kind $case/checkpoints/step_000010/"$file")
  expected5=$(fault $kind $case/checkpoints/step_000005/"$file")
  damage $kind $case/checkpoints/step_000010/"$file"
  damage $kind $case/checkpoints/step_000005/"$file"
  launch --resume $case > $case.log 2>&1
  code=$?
  [ $code = 1 ] || fail "exit code $code, expected 1"
  grep -qF "levelsinter: error: no checkpoint in '$case/checkpoints' can be used: step_000010: $expected10" $case.log ||
    fail "no error naming step_000010 and '$expected10'"
  grep -qF "; step_000005: $expected5" $case.log ||
    fail "no error naming step_000005 and '$expected5'"
  [ "$(ls $case/checkpoints | tr '\n' ' ')" = "step_000005 step_000010 " ] ||
    fail "checkpoints changed: $(ls $case/checkpoints | tr '\n' ' ')"
  cmp -s pristine/metrics.csv $case/metrics.csv || fail "metrics.csv changed"
done

if [ "$file" = counters.txt ]; then
  # Random bytes that the manifest vouches for: not damage but a file that
  # is not levelsinter's counters; the error names it.
  case=counters_unreadable
  cp -r pristine $case
  python3 - $case/checkpoints/step_000010 << 'PYTHON' || exit 1
import random, sys, zlib, pathlib
folder = pathlib.Path(sys.argv[1])
random.seed(29)
(folder / "counters.txt").write_bytes(bytes(random.randrange(256) for _ in range(200)))
lines = ["levelsinter checkpoint manifest 1"]
for f in sorted(folder.iterdir()):
    if f.name != "manifest.txt":
        data = f.read_bytes()
        lines.append(f"{f.name} {len(data)} {zlib.crc32(data):08x}")
body = "\n".join(lines) + "\n"
(folder / "manifest.txt").write_text(body + f"end {zlib.crc32(body.encode()):08x}\n")
PYTHON
  launch --resume $case > $case.log 2>&1
  code=$?
  [ $code = 1 ] || fail "exit code $code, expected 1"
  grep -qF "levelsinter: error: cannot read '$case/checkpoints/step_000010/counters.txt' (" $case.log ||
    fail "no error naming counters.txt"
  echo "$case: $(grep -F "error:" $case.log)"
fi
echo "all cases passed"
