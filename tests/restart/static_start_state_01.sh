#!/usr/bin/env bash
# ctest driver of Wheelset/Static start state on the short coarse rolling
# case of the sweep test (tests/plot/sweep_01.prm.in, 0.1 ms): a run that
# finds no state solves the static start and writes it; a run with another
# friction law (Coulomb instead of the exponential law), friction coefficient
# and traction reads it, and its
# statistics are those of the same run solving its own static start, to the
# byte; a run with another Sprung mass is refused naming the entry, as is a
# directory that holds something else, each with a non-zero exit status and
# the state left as it was. Arguments: the wheelrail executable, the source
# directory.
set -euo pipefail
exe=$1 src=$2
fail() {
  echo "FAILED: $*"
  exit 1
}
sed "s#@SOURCE_DIR@#$src/tests/plot#" "$src/tests/plot/sweep_01.prm.in" > base.prm
rm -rf state other write read solve refused
# $1: name (output directory, NAME.prm); the rest: lines after the include
case_file() {
  local name=$1
  shift
  {
    echo "include base.prm"
    printf 'subsection Problem\n  set Output directory = %s\nend\n' "$name"
    printf '%s\n' "$@"
  } > "$name.prm"
}
friction=("subsection Contact" "  set Friction law = constant" "  set Static friction coefficient = 0.4" "end")
case_file write "subsection Wheelset" "  set Static start state = state" "end"
case_file read "${friction[@]}" "subsection Wheelset" "  set Static start state = state" \
  "  set Nominal traction coefficient = 0.4" "end"
case_file solve "${friction[@]}" "subsection Wheelset" "  set Nominal traction coefficient = 0.4" "end"
case_file refused "subsection Wheelset" "  set Static start state = state" "  set Sprung mass = 12000" "end"
case_file other "subsection Wheelset" "  set Static start state = write" "end"

"$exe" write.prm > write.log
grep -F "static start written to state/" write.log || fail "write.prm: no state written"
test -s state/info && test -s state/rank_0.bin
ls -d state.new.* 2> /dev/null && fail "a partial state directory was left"
md5sum state/* > state.md5
"$exe" read.prm > read.log
grep -F "static start read from state/" read.log || fail "read.prm: the state was not read"
grep -q "Static contact solve" read.log && fail "read.prm solved the static start"
"$exe" solve.prm > solve.log
grep -q "Static contact solve" solve.log || fail "solve.prm did not solve the static start"
cmp read/statistics solve/statistics || fail "statistics with the state read differ from those solved"
cmp read/probe.csv solve/probe.csv || fail "probe.csv with the state read differs from the one solved"
echo "statistics with the static start read = solved: identical"
for name in refused other; do
  if "$exe" $name.prm > $name.log 2>&1; then
    cat $name.log
    fail "$name.prm was not refused"
  fi
done
grep -F -A1 "Wheelset/Static start state: the state in 'state' is of another static problem: 1 entry differs" \
  refused.log || { cat refused.log; fail "refused.log: no message"; }
grep -F "Wheelset/Sprung mass: 13400 -> 12000" refused.log || fail "refused.log: the entry is not named"
grep -F "Wheelset/Static start state: 'write' exists and holds no static start" other.log ||
  { cat other.log; fail "other.log: no message"; }
md5sum -c --quiet state.md5 || fail "the state changed"
echo "refused: another Sprung mass, a directory that is not a state"
