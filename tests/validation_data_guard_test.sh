#!/bin/bash
# validation_data_guard_test.sh SOURCE_DIR WORK DRIVER: a study does not replace a
# longer history in a validation_data folder with a shorter one unless
# LEVELSINTER_REPLACE_SHORTER=1 (scripts/validation_data.py). Written
# through scripts/packing_history.py from a made-up run of 3 metrics rows
# over the committed 11-row packing_154_coupled.csv: refused (exit 1, a
# message naming the file and both lengths, the CSV unchanged, no plot
# written); replaced with the variable set; and in a folder not named
# validation_data replaced without it. Then the same rule for the C++
# drivers' --csv (tests/study_support.h, CsvFile), through DRIVER
# (pore_analysis, 2 rows): over 5 rows the file is kept and the rows go to
# FILE.partial; over 1 row it is replaced.
set -u
source_dir=$1 work=$2 driver=$3
rm -rf "$work" && mkdir -p "$work/run" "$work/validation_data" "$work/build" &&
  cd "$work" || exit 1
history=$source_dir/scripts/packing_history.py
long=$source_dir/doc/validation_data/packing_154_coupled.csv
printf 'x,y,z,r\n0.3,0.5,0.5,0.2\n0.7,0.5,0.5,0.2\n' > particles.csv
printf 'step,particle_i,particle_j,neck_radius\n' > run/necks.csv
printf 'step,time,relative_density,size_ratio_x,closed_pores,sub_cell_pockets,volume_change,wall_time\n' > run/metrics.csv
for step in 0 5 10; do
  echo "$step,0,1,0.1" >> run/necks.csv
  echo "$step,$step.0,0.6,1,0,0,0,1" >> run/metrics.csv
done
for folder in validation_data build; do
  cp "$long" $folder/history.csv
done
unset LEVELSINTER_REPLACE_SHORTER

"$history" run particles.csv --csv validation_data/history.csv \
  --png validation_data/history.png > refused.log 2>&1
code=$?
cat refused.log
[ $code = 1 ] || { echo "FAIL: exit code $code, expected 1"; exit 1; }
grep -qF "packing_history.py: error: 'validation_data/history.csv' holds 11 rows (the last: step 50); this run gives 3. A shorter history does not replace a longer one: nothing was written. Set LEVELSINTER_REPLACE_SHORTER=1 to replace it." refused.log ||
  { echo "FAIL: no refusal message"; exit 1; }
cmp -s "$long" validation_data/history.csv ||
  { echo "FAIL: the longer history was changed"; exit 1; }
[ ! -e validation_data/history.png ] ||
  { echo "FAIL: the plot was written"; exit 1; }

LEVELSINTER_REPLACE_SHORTER=1 "$history" run particles.csv \
  --csv validation_data/history.csv --png validation_data/history.png \
  > replaced.log 2>&1 || { cat replaced.log; exit 1; }
[ "$(wc -l < validation_data/history.csv)" = 4 ] ||
  { echo "FAIL: not replaced with LEVELSINTER_REPLACE_SHORTER=1"; exit 1; }

"$history" run particles.csv --csv build/history.csv --png build/history.png \
  > build.log 2>&1 || { cat build.log; exit 1; }
[ "$(wc -l < build/history.csv)" = 4 ] ||
  { echo "FAIL: a file outside validation_data not replaced"; exit 1; }

printf 'level,h\n1,1\n2,1\n3,1\n4,1\n5,1\n' > validation_data/table.csv
cp validation_data/table.csv long.csv
"$driver" holes 2 0 4,5 --csv validation_data/table.csv > driver.log 2>&1 ||
  { cat driver.log; exit 1; }
cmp -s long.csv validation_data/table.csv ||
  { echo "FAIL: the driver replaced the longer table"; exit 1; }
[ "$(wc -l < validation_data/table.csv.partial)" = 3 ] ||
  { echo "FAIL: no 2-row table.csv.partial"; exit 1; }
grep -qF "'validation_data/table.csv' kept: it holds 5 rows, this run gave 2" \
  driver.log || { cat driver.log; echo "FAIL: no message"; exit 1; }
printf 'level,h\n1,1\n' > validation_data/table.csv
"$driver" holes 2 0 4,5 --csv validation_data/table.csv > driver2.log 2>&1 ||
  { cat driver2.log; exit 1; }
[ "$(wc -l < validation_data/table.csv)" = 3 ] &&
  [ ! -e validation_data/table.csv.partial ] ||
  { echo "FAIL: the driver did not replace a shorter table"; exit 1; }
echo "refused, replaced when asked, and replaced outside validation_data;"
echo "the C++ drivers keep a longer table and replace a shorter one"
