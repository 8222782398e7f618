#!/usr/bin/env bash
# ctest driver of the resume checks on NP ranks: a bar run stopped after
# step 100 (restart_02.prm) is resumed with damaged rank files (one flipped
# byte, cut short, the older formats' magic numbers), with a changed
# physics entry and with an End time before the checkpoint: each must be
# refused naming the file or the entries, with a non-zero exit status and
# the output directory unchanged; then with a changed End time and
# Statistics interval, which is accepted and listed. Arguments: the
# wheelrail executable, the source directory, the number of MPI ranks.
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
# every file of the output directory with its checksum (but the lock
# file, which names the last run that held the lock)
snapshot() { (cd run && find . -type f ! -name .wheelrail.lock | sort | xargs md5sum); }
# $1: prm file; $2: the expected message (fixed string); the resume must fail
refused() {
  if run "$1" --resume > refused.log 2>&1; then
    cat refused.log
    fail "$1 --resume was not refused"
  fi
  grep -F -m1 -- "$2" refused.log || { cat refused.log; fail "no message '$2'"; }
  snapshot > after.md5
  cmp -s before.md5 after.md5 || fail "the refused resume changed the output directory"
}

cp "$src/tests/restart/restart_02.prm" base.prm
rm -rf run saved
run base.prm > split.log
grep -q "^Stopped after step 100" split.log
cp -a run/checkpoint saved
snapshot > before.md5
last=run/checkpoint/rank_$((np - 1)).bin

# one flipped bit in the middle of the last rank's file
python3 -c "
import os, sys
with open(sys.argv[1], 'r+b') as f:
    f.seek(os.path.getsize(sys.argv[1]) // 2); b = f.read(1)
    f.seek(-1, 1); f.write(bytes([b[0] ^ 0x08]))" "$last"
snapshot > before.md5
refused base.prm "the checkpoint file '$last' is damaged: its CRC-32 checksum does not match"
cp saved/* run/checkpoint/

# the last rank's file cut short
truncate -s -100 "$last"
snapshot > before.md5
refused base.prm "the checkpoint file '$last' is truncated or incomplete"
cp saved/* run/checkpoint/

# rank 0's file with the magic number of the format before checksums
printf '1phcrlhw' | dd of=run/checkpoint/rank_0.bin conv=notrunc status=none
snapshot > before.md5
refused base.prm "the checkpoint file 'run/checkpoint/rank_0.bin' has an older format"
cp saved/* run/checkpoint/

# ... and of the format before the contact patch's window means
printf '2phcrlhw' | dd of=run/checkpoint/rank_0.bin conv=notrunc status=none
snapshot > before.md5
refused base.prm "has an older format (no contact-patch window means)"
cp saved/* run/checkpoint/

# ... and of the format before the friction state of the contact nodes
printf '3phcrlhw' | dd of=run/checkpoint/rank_0.bin conv=notrunc status=none
snapshot > before.md5
refused base.prm "has an older format (no friction state)"
cp saved/* run/checkpoint/
snapshot > before.md5

# physics edited: every differing entry named with both values
{ echo 'include base.prm'
  printf "subsection Material\n  set Young's modulus = 2.0e11\nend\n"
  printf "subsection Contact\n  set Static friction coefficient = 0.4\nend\n"
  printf "subsection Time integration\n  set Time step = 1.4e-6\n  set End time = 4e-4\nend\n"
} > physics.prm
refused physics.prm "other values of 3 entries that change the computed state"
grep -F "Material/Young's modulus: 2.1e11 -> 2.0e11" refused.log
grep -F "Contact/Static friction coefficient: 0.5 -> 0.4" refused.log
grep -F "Time integration/Time step: 0 -> 1.4e-6" refused.log
if grep -F "End time" refused.log | grep -qv "Only these"; then fail "End time listed as refused"; fi

# an End time before the checkpoint
{ echo 'include base.prm'; printf "subsection Time integration\n  set End time = 1e-4\nend\n"; } > early.prm
refused early.prm "is reached at step 67, and the checkpoint in 'run/checkpoint' is at step 100"

# the same values written otherwise are no change; End time and the
# statistics interval may change, and are listed
{ echo 'include base.prm'
  printf "subsection Material\n  set Young's modulus = 210e9\nend\n"
  printf "subsection Time integration\n  set End time = 4.0e-4\nend\n"
  printf "subsection Output\n  set Statistics interval = 20\nend\n"
} > later.prm
run later.prm --resume > later.log
grep -A2 "^Resumed with changed entries:" later.log
grep -qF "  Output/Statistics interval: 10 -> 20" later.log
grep -qF "  Time integration/End time: 3e-4 -> 4.0e-4" later.log
grep "^Explicit run finished: 268 steps" later.log
