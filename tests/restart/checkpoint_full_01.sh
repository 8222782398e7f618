#!/usr/bin/env bash
# ctest driver of a full disk on NP ranks: the bar of restart_02.prm, stopped
# after step 100, is copied onto a small tmpfs and resumed there with a
# checkpoint every 50 steps. (a) With room for the records but not for a
# second checkpoint, the run must stop at step 150 naming the checkpoint and
# the full disk, with a non-zero status, the checkpoint of step 100
# unchanged, and no checkpoint.new or *.tmp left; that checkpoint, copied
# back, must resume to the end. (b) With no room for parameters.prm.tmp,
# the resume must stop naming that file, leaving no *.tmp. Needs root to
# mount the tmpfs: without it the test prints why and is skipped (77).
# Arguments: the wheelrail executable, the source directory, the number of
# MPI ranks.
set -euo pipefail
exe=$1 src=$2 np=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
run() {
  if [ "$np" -gt 1 ]; then mpirun -np "$np" "$exe" "$@"; else "$exe" "$@"; fi
}
fail() {
  echo "FAILED: $*"
  exit 1
}
no_temporaries() {
  local left
  left=$(find "$1" -name '*.tmp' -o -name 'checkpoint.new')
  [ -z "$left" ] || fail "left in $1: $left"
}

mkdir -p full
mountpoint -q full && umount full
if ! mount -t tmpfs -o size=4m tmpfs full 2> mount.err; then
  echo "SKIPPED: cannot mount a tmpfs to fill ($(cat mount.err)); run as root to test a full disk"
  exit 77
fi
trap 'umount full' EXIT

cp "$src/tests/restart/restart_02.prm" base.prm
sed -i 's#Output directory = run#Output directory = full/run#' base.prm
{ echo 'include base.prm'; printf 'subsection Output\n  set Checkpoint interval = 50\nend\n'; } > every50.prm
rm -rf run whole saved
# the uninterrupted run, and the run stopped after step 100 (off the tmpfs)
{ echo 'include base.prm'; printf 'subsection Problem\n  set Output directory = whole\nend\nsubsection Output\n  set Stop after step = 0\nend\n'; } > whole.prm
run whole.prm > whole.log
sed 's#full/run#run#' base.prm > local.prm
run local.prm > split.log
grep -q "^Stopped after step 100" split.log
cp -a run/checkpoint saved

# $1: bytes left free on the tmpfs besides the copy of run/
fill_leaving() {
  rm -rf full/run full/filler
  cp -a run full/run
  sync
  local avail
  avail=$(df -B1 --output=avail full | tail -1)
  [ "$avail" -gt "$1" ] || fail "the tmpfs is too small"
  fallocate -l $((avail - $1)) full/filler
  df -B1 --output=avail full | tail -1
}

# (a) room for the records, not for a checkpoint
checkpoint=$(du -cb run/checkpoint/rank_*.bin | tail -1 | cut -f1)
largest=$(ls -l run/parameters.prm run/statistics run/probe.csv run/series.h5 | awk '{print $5}' | sort -n | tail -1)
slack=$((largest + 5 * 4096))
[ "$slack" -lt $((checkpoint - 8192)) ] || fail "slack $slack not below the checkpoint's $checkpoint bytes"
fill_leaving $slack
status=0
run every50.prm --resume > full.log 2>&1 || status=$?
cat full.log
[ $status -ne 0 ] || fail "the run on the full disk ended with status 0"
grep -q "Cannot write the checkpoint in 'full/run/checkpoint.new' (disk full or no permission); the previous checkpoint is kept" full.log ||
  fail "no message naming the checkpoint and the full disk"
grep -q "^Resumed from full/run/checkpoint at step 100" full.log
no_temporaries full/run
diff -r saved full/run/checkpoint || fail "the checkpoint of step 100 was changed"
grep -q "step 100," full/run/checkpoint/info
# the kept checkpoint resumes to the end as the uninterrupted run
rm -rf run
cp -a full/run run
run local.prm --resume > resume.log
cmp whole/statistics run/statistics || fail "statistics differ after the resume of the kept checkpoint"
echo "full disk at the checkpoint of step 150: refused, checkpoint of step 100 kept and resumable, no temporary"

# (b) no room for parameters.prm.tmp
rm -rf run
run local.prm > split.log
fill_leaving 4096
status=0
run every50.prm --resume > full.log 2>&1 || status=$?
cat full.log
[ $status -ne 0 ] || fail "the run on the full disk ended with status 0"
grep -q "Cannot write 'full/run/parameters.prm.tmp' (disk full or no permission)" full.log ||
  fail "no message naming parameters.prm.tmp and the full disk"
no_temporaries full/run
echo "full disk at parameters.prm: refused, no temporary"
