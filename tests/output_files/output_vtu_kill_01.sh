#!/usr/bin/env bash
# ctest driver of the atomic VTU output: bar.prm with a VTU snapshot every 50
# steps (uncompressed, about 230 kB each) is killed with SIGKILL while it
# writes the third snapshot. The file it writes into is made a named pipe
# that this script holds open and never drains, so that the kill lands in
# the middle of the snapshot every time. Afterwards no solution_*.vtu or
# .pvtu may be incomplete: every snapshot that solution.pvd lists is there,
# complete, with every piece it names, and the killed one is not there.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
fail() {
  echo "FAILED: $*"
  exit 1
}
{ echo "include $src/tests/output_files/bar.prm"
  printf 'subsection Problem\n  set Test mode = false\nend\n'
  printf 'subsection Output\n  set VTU interval = 50\n  set VTU compression = none\nend\n'
} > vtu.prm
rm -rf run
mkdir run
# an output directory of wheelrail's (it refuses one that holds other files)
touch run/.wheelrail.lock
# snapshot 2 (after 100 steps), piece of rank 0, under its temporary name
pipe=run/solution_00002.0.vtu.tmp
mkfifo "$pipe"
exec 3<> "$pipe"
"$exe" vtu.prm > vtu.log 2>&1 &
pid=$!
# the first bytes of the snapshot: the run is writing it
timeout 60 head -c 16 <&3 > /dev/null || fail "the run did not write snapshot 2 into $pipe"
kill -KILL $pid
if wait $pid; then fail "the run was not killed"; fi
exec 3>&-
rm "$pipe"

ls run
test -f run/solution.pvd || fail "no solution.pvd"
for pvtu in $(grep -o 'file="[^"]*"' run/solution.pvd | cut -d'"' -f2); do
  tail -1 "run/$pvtu" | grep -q "</VTKFile>" || fail "$pvtu is incomplete"
  for vtu in $(grep -o 'Source="[^"]*"' "run/$pvtu" | cut -d'"' -f2); do
    test -s "run/$vtu" && tail -1 "run/$vtu" | grep -q "</VTKFile>" || fail "$vtu is incomplete"
    echo "$pvtu: $vtu complete"
  done
done
grep -q 'file="solution_00001.pvtu"' run/solution.pvd || fail "snapshot 1 not listed"
if grep -q 'solution_00002' run/solution.pvd; then fail "the killed snapshot 2 is listed"; fi
for f in run/solution_*; do
  case $f in
    *.tmp) ;;
    *) test -s "$f" && tail -1 "$f" | grep -q "</VTKFile>" || fail "$f is incomplete" ;;
  esac
done
test ! -e run/solution_00002.0.vtu || fail "an incomplete solution_00002.0.vtu"
echo "killed while writing snapshot 2: snapshots 0 and 1 complete and listed, no incomplete file"
