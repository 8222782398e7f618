#!/usr/bin/env bash
# ctest driver of the restart test on NP ranks: the same case run
# uninterrupted, and stopped after step 100 (checkpoint) then resumed with
# --resume; statistics, probes and the contact-node state at the end must be
# identical to the byte. Arguments: the wheelrail executable, the source
# directory, the number of MPI ranks.
set -euo pipefail
exe=$1 src=$2 np=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
run() {
  if [ "$np" -gt 1 ]; then mpirun -np "$np" "$exe" "$@"; else "$exe" "$@"; fi
}
sed "s#@SOURCE_DIR@#$src/tests/restart#" "$src/tests/restart/restart_01.prm.in" > whole.prm
{ echo 'include whole.prm'; printf 'subsection Problem\n  set Output directory = split\nend\nsubsection Output\n  set Stop after step = 100\nend\n'; } > split.prm
rm -rf run split
run whole.prm > whole.log
run split.prm > split.log
grep -q "^Stopped after step 100" split.log
test -f split/checkpoint/info && test ! -e split/checkpoint.new
run split.prm --resume > resume.log
grep "^Resumed from" resume.log
status=0
for f in statistics probe.csv wheel_probe.csv contact_nodes.csv; do
  if cmp -s "run/$f" "split/$f"; then
    echo "$f: identical"
  else
    echo "$f: DIFFERENT"; status=1
  fi
done
grep "^Summary" whole.log
grep "^Summary" resume.log
exit $status
