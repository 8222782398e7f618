#!/usr/bin/env bash
# ctest driver of the stop by signal on NP ranks. bar.prm (2007 steps)
# writes a VTU snapshot every 500 steps (uncompressed, larger than a
# pipe's buffer); the file of rank 0's piece of
# snapshot 1 is a named pipe that this script holds open, so that the run
# waits in step 500 until the script has sent SIGTERM, and then drains it:
# the run must stop after step 500, write a checkpoint there, say so and
# exit with status 143 (128 + SIGTERM), leaving no *.tmp and no
# checkpoint.new; resumed with --resume it must end with statistics,
# probe.csv and series.h5's tables identical to an uninterrupted run. On 1
# rank the signal goes to the process; on 2 ranks to rank 1 alone (rank 0,
# which never sees it, must stop after the same step), and in a long run
# to mpirun, which passes it on to every rank. Last, a signal
# during the static start of a rolling case stops it before the time loop
# with status 143 and no checkpoint.
# Arguments: the wheelrail executable, the source directory, the number of
# MPI ranks.
set -euo pipefail
exe=$1 src=$2 np=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
# Open MPI's mpirun passes a SIGTERM on to the ranks after
# odls_base_sigkill_timeout seconds and kills them as long after: the
# default, 1 s, here
unset OMPI_MCA_odls_base_sigkill_timeout
run() {
  if [ "$np" -gt 1 ]; then mpirun -np "$np" "$exe" "$@"; else "$exe" "$@"; fi
}
# the same in the background, $! the pid of wheelrail or of mpirun (not of
# a subshell, which would take the signal itself); $1 the log's stem
start() {
  local log=$1
  shift
  if [ "$np" -gt 1 ]; then
    mpirun -np "$np" "$exe" "$@" > $log.log 2> $log.err &
  else
    "$exe" "$@" > $log.log 2> $log.err &
  fi
}
fail() {
  echo "FAILED: $*"
  exit 1
}
# no temporary file or directory anywhere in $1
no_temporaries() {
  local left
  left=$(find "$1" -name '*.tmp' -o -name 'checkpoint.new' -o -name 'checkpoint.old')
  [ -z "$left" ] || fail "left in $1: $left"
}

{ echo "include $src/tests/output_files/bar.prm"
  printf 'subsection Problem\n  set Test mode = false\nend\n'
  printf 'subsection Output\n  set VTU interval = 500\n  set VTU compression = none\n  set Report interval = 500\nend\n'
} > whole.prm
{ echo 'include whole.prm'; printf 'subsection Problem\n  set Output directory = split\nend\n'; } > split.prm
rm -rf run split
run whole.prm > whole.log

# $1: what gets the signal (process, rank1, mpirun)
stop_and_resume() {
  rm -rf split
  mkdir split
  # an output directory of wheelrail's (it refuses one that holds other files)
  touch split/.wheelrail.lock
  local pipe=split/solution_00001.0.vtu.tmp
  mkfifo "$pipe"
  exec 3<> "$pipe"
  start split split.prm
  local pid=$!
  # the first bytes of snapshot 1: the run is in step 500
  timeout 60 head -c 16 <&3 > /dev/null || fail "the run did not write snapshot 1 into $pipe"
  local target=$pid
  if [ "$np" -gt 1 ]; then
    for child in $(pgrep -P $pid); do
      grep -qz '^OMPI_COMM_WORLD_RANK=1$' /proc/$child/environ && target=$child
    done
    [ "$target" != "$pid" ] || fail "no rank 1 among the children of mpirun $pid"
  fi
  kill -TERM "$target"
  # let the run go on: read the rest of the snapshot
  cat "$pipe" > /dev/null 2>&1 &
  local drain=$!
  exec 3>&-
  local status=0
  wait $pid || status=$?
  kill $drain 2> /dev/null || true
  cat split.err
  [ $status -eq 143 ] || fail "exit status $status after SIGTERM to $1, not 143"
  grep -q "stopped by SIGTERM at step 500, t = " split.err || fail "no message naming the signal and step 500"
  grep -q "checkpoint written in split/checkpoint, resume with: wheelrail CASE.prm --resume" split.err ||
    fail "no message on the checkpoint"
  test -f split/checkpoint/info || fail "no checkpoint"
  grep -q "step 500," split/checkpoint/info || fail "the checkpoint is not at step 500: $(cat split/checkpoint/info)"
  no_temporaries split
  rm -f split/solution_00001.0.vtu  # the drained pipe, renamed
  run split.prm --resume > resume.log
  grep "^Resumed from split/checkpoint at step 500" resume.log
  local f
  for f in statistics probe.csv; do
    cmp "run/$f" "split/$f" || fail "$f differs from the uninterrupted run's (signal to $1)"
  done
  /usr/bin/python3 - run/series.h5 split/series.h5 << 'PY' || fail "series.h5 differs (signal to $1)"
import sys, h5py, numpy
a, b = (h5py.File(n, "r") for n in sys.argv[1:])
for key in ["statistics", "probes/probe"]:
    assert numpy.array_equal(a[key][()], b[key][()], equal_nan=True), key
PY
  no_temporaries split
  echo "SIGTERM to $1: stopped after step 500 with status 143, resumed: statistics, probe.csv, series.h5 identical"
}

if [ "$np" -gt 1 ]; then
  stop_and_resume rank1
else
  stop_and_resume process
fi

# on 2 ranks, SIGTERM to mpirun, which passes it on to the ranks a second
# later (the run above would be past step 500 by then): a long run (133780
# steps) gets it once it has printed step 2000, and must stop long before
# its end with a checkpoint at the step it names, which resumes (for 100
# steps: that a resume ends as the uninterrupted run is shown above).
# mpirun's own exit status is 1 (it does not pass on the ranks').
if [ "$np" -gt 1 ]; then
  { echo "include $src/tests/output_files/bar.prm"
    printf 'subsection Problem\n  set Output directory = split\nend\n'
    printf 'subsection Time integration\n  set End time = 0.2\nend\n'
    printf 'subsection Output\n  set Report interval = 1000\nend\n'
  } > long.prm
  rm -rf split
  start split long.prm
  pid=$!
  for i in $(seq 1 600); do
    grep -qs "^step *2000 " split.log && break
    sleep 0.05
  done
  kill -TERM $pid
  status=0
  wait $pid || status=$?
  cat split.err
  [ $status -ne 0 ] || fail "exit status 0 after SIGTERM to mpirun"
  step=$(sed -n 's/.*stopped by SIGTERM at step \([0-9]*\), t = .*checkpoint written in split\/checkpoint.*/\1/p' split.err | head -1)
  [ -n "$step" ] || fail "no message naming the signal, the step and the checkpoint"
  [ "$step" -ge 2000 ] && [ "$step" -lt 133000 ] || fail "stopped at step $step"
  grep -q "step $step," split/checkpoint/info || fail "the checkpoint is not at step $step"
  no_temporaries split
  { echo 'include long.prm'; printf 'subsection Output\n  set Stop after step = %d\nend\n' $((step + 100)); } > more.prm
  run more.prm --resume > resume.log
  grep "^Resumed from split/checkpoint at step $step" resume.log
  grep "^Stopped after step $((step + 100))" resume.log
  no_temporaries split
  echo "SIGTERM to mpirun: stopped after step $step with a checkpoint that resumes"
fi

# a rolling case with a static start: SIGTERM once the Newton iterations
# have begun stops the run there (or, on a fast machine, after the static
# start), before the time loop, with no checkpoint and no temporary
sed "s#@SOURCE_DIR@#$src/tests/restart#" "$src/tests/restart/restart_01.prm.in" > rolling.prm
rm -rf run
start rolling rolling.prm
pid=$!
for i in $(seq 1 600); do
  grep -qs "Newton  0" rolling.log && break
  sleep 0.1
done
grep -qs "Newton  0" rolling.log || fail "no Newton iteration printed"
if [ "$np" -gt 1 ]; then kill -TERM $(pgrep -P $pid | head -1); else kill -TERM $pid; fi
status=0
wait $pid || status=$?
cat rolling.err
[ $status -eq 143 ] || fail "exit status $status after SIGTERM in the static start, not 143"
grep -Eq "stopped by SIGTERM (during the static solve|before the time loop)" rolling.err ||
  fail "no message naming the signal and the static start"
test ! -e run/checkpoint || fail "a checkpoint written before the time loop"
no_temporaries run
echo "SIGTERM in the static start: status 143, no checkpoint, no temporary"
