#!/usr/bin/env bash
# Same bits: run two wheelrail executables on every test input and compare
# everything they write, byte for byte. For refactoring, where the outputs
# must not change at all (numdiff's tolerances would hide a change).
#
#   scripts/same_bits.sh OLD_EXE NEW_EXE [--only REGEX] [--bench] [--keep DIR]
#
# Inputs: tests/NAME.prm and tests/NAME.prm.in (@SOURCE_DIR@ replaced) on 1
# rank, and on 2 ranks where tests/NAME.mpirun=2.output exists;
# tests/bad_input/NAME.prm (message and exit status). --bench adds
# prm/bench_paper.prm on 2 ranks (its 350 steps). Compared: the screen
# output, the exit status and every file of the output directory except
# timing.csv (wall-clock times) and the lock file (process id). Exit status 1
# if anything differs.
set -uo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 2 ] || { sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
old=$(readlink -f "$1"); new=$(readlink -f "$2"); shift 2
only=.; bench=0; work=""
while [ $# -gt 0 ]; do
  case $1 in
    --only) only=$2; shift 2 ;;
    --bench) bench=1; shift ;;
    --keep) work=$2; shift 2 ;;
    *) echo "same_bits.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
[ -x "$old" ] && [ -x "$new" ] || { echo "same_bits.sh: executables '$old', '$new'?" >&2; exit 2; }
[ -n "$work" ] || work=$(mktemp -d /tmp/same_bits.XXXXXX)
mkdir -p "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# one job: KIND NAME NP INPUT; runs both executables into $work/{old,new}/NAME.npNP
run_one() {
  local kind=$1 name=$2 np=$3 input=$4 which exe dir
  for which in old new; do
    [ $which = old ] && exe=$old || exe=$new
    dir=$work/$which/$name.np$np
    rm -rf "$dir"; mkdir -p "$dir"
    (
      cd "$dir"
      if [ $np -eq 1 ]; then "$exe" "$input" > screen 2>&1
      else mpirun --allow-run-as-root --oversubscribe -np $np "$exe" "$input" > screen 2>&1; fi
      echo $? > exit_status
    )
    # the screen of a full run (not test mode) has wall-clock times
    [ "$kind" = bench ] && rm -f "$dir/screen"
    find "$dir" \( -name timing.csv -o -name .wheelrail.lock \) -delete
  done
  if diff -r -q "$work/old/$name.np$np" "$work/new/$name.np$np" > "$work/$name.np$np.diff" 2>&1; then
    echo "same    $name (np $np)"; rm -f "$work/$name.np$np.diff"
  else
    echo "DIFFER  $name (np $np): $(head -3 "$work/$name.np$np.diff" | tr '\n' ' ')"
  fi
}
export -f run_one; export old new work

jobs=$work/jobs
: > "$jobs"; : > "$jobs.2"
mkdir -p "$work/inputs"
for f in "$top"/tests/*.prm "$top"/tests/*.prm.in; do
  name=$(basename "$f"); name=${name%.in}; name=${name%.prm}
  echo "$name" | grep -Eq "$only" || continue
  input=$f
  if [[ $f == *.in ]]; then
    input=$work/inputs/$name.prm
    sed "s|@SOURCE_DIR@|$top/tests|g" "$f" > "$input"
  fi
  echo "prm $name 1 $input" >> "$jobs"
  [ -f "$top/tests/$name.mpirun=2.output" ] && echo "prm $name 2 $input" >> "$jobs.2"
done
for f in "$top"/tests/bad_input/*.prm; do
  name=bad_input.$(basename "$f" .prm)
  echo "$name" | grep -Eq "$only" || continue
  echo "bad $name 1 $f" >> "$jobs"
done
[ $bench -eq 1 ] && echo "bench bench_paper 2 $top/prm/bench_paper.prm" >> "$jobs.2"

echo "same_bits.sh: $(wc -l < "$jobs") one-rank and $(wc -l < "$jobs.2") two-rank inputs, in $work"
xargs -P 2 -L 1 bash -c 'run_one "$@"' _ < "$jobs" > "$work/report"
xargs -P 1 -L 1 bash -c 'run_one "$@"' _ < "$jobs.2" >> "$work/report"
sort "$work/report"
n_diff=$(grep -c '^DIFFER' "$work/report")
echo "same_bits.sh: $(grep -c '^same' "$work/report") same, $n_diff different"
[ "$n_diff" -eq 0 ]
