#!/usr/bin/env bash
# ctest driver: a refused resume leaves the output directory exactly as it
# was. The bar of restart_02.prm, stopped after step 100 on 2 ranks and on
# 1 rank, is resumed with a changed physics entry (and a changed Statistics
# interval, which alone would be accepted), on the other rank count, with a
# flipped byte in a rank file, and with the two rank files exchanged: each
# must fail with a message and a non-zero status, print no "Resumed", and
# leave every file and directory (names, sizes, mtimes, checksums) as
# before; only .wheelrail.lock is left out, as every run that takes the
# lock writes its pid into it. Arguments: the wheelrail executable, the
# source directory.
set -euo pipefail
exe=$1 src=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fail() {
  echo "FAILED: $*"
  exit 1
}
# $1 ranks, then the arguments
run() {
  local np=$1
  shift
  if [ "$np" -gt 1 ]; then mpirun -np "$np" "$exe" "$@"; else "$exe" "$@"; fi
}
# every entry of the directory: type, name, size, mtime (ns), checksum
snapshot() {
  (cd run && find . ! -name .wheelrail.lock -printf '%y %p %s %T@\n' | sort &&
    find . -type f ! -name .wheelrail.lock | sort | xargs md5sum)
}
# $1 ranks, $2 prm file, $3 the expected message (fixed string)
refused() {
  snapshot > before.txt
  sleep 0.01 # a rewrite would show in the mtimes
  if run "$1" "$2" --resume > refused.log 2>&1; then
    cat refused.log
    fail "$2 --resume on $1 rank(s) was not refused"
  fi
  grep -F -m1 -- "$3" refused.log || { cat refused.log; fail "no message '$3'"; }
  if grep "Resumed" refused.log; then fail "a refused resume printed 'Resumed'"; fi
  snapshot > after.txt
  diff before.txt after.txt || fail "the refused resume ($2 on $1 rank(s)) changed the output directory"
  echo "refused and unchanged: $2 on $1 rank(s)"
}

cp "$src/tests/restart/restart_02.prm" base.prm
{ echo 'include base.prm'
  printf "subsection Material\n  set Young's modulus = 2.0e11\nend\n"
  printf "subsection Output\n  set Statistics interval = 20\nend\n"
} > physics.prm

for np in 2 1; do
  rm -rf run
  run $np base.prm > split.log
  grep -q "^Stopped after step 100" split.log
  other=$((3 - np))
  refused $np physics.prm "other values of 1 entry that change the computed state"
  refused $other base.prm "was written by $np MPI rank(s); resume it with as many (this run has $other)"
  last=run/checkpoint/rank_$((np - 1)).bin
  cp "$last" saved.bin
  /usr/bin/python3 -c "
import os, sys
with open(sys.argv[1], 'r+b') as f:
    f.seek(os.path.getsize(sys.argv[1]) // 2); b = f.read(1)
    f.seek(-1, 1); f.write(bytes([b[0] ^ 0x08]))" "$last"
  refused $np base.prm "the checkpoint file '$last' is damaged"
  cp -p saved.bin "$last"
done

# rank 0's and rank 1's files exchanged: each holds the other's part
rm -rf run
run 2 base.prm > split.log
mv run/checkpoint/rank_0.bin run/checkpoint/rank.bin
mv run/checkpoint/rank_1.bin run/checkpoint/rank_0.bin
mv run/checkpoint/rank.bin run/checkpoint/rank_1.bin
refused 2 base.prm "the rank files were renamed or exchanged"
