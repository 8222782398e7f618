#!/usr/bin/env bash
# ctest driver: how parameter files are read, where one file cannot show it.
# - a directory given as the case file is refused;
# - a relative include is read next to the including file, not from the
#   working directory (a decoy of the same name sits in the working directory);
# - a UTF-8 byte-order mark and Windows line ends are accepted;
# - on 2 ranks a rejected input prints one message, without an MPI_ABORT.
# Arguments: the wheelrail executable. Runs in its own build directory.
set -uo pipefail
exe=$1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
rm -rf work && mkdir -p work/case && cd work
status=0
check() { # NAME CONDITION...
  local name=$1; shift
  if "$@"; then echo "$name: ok"; else echo "$name: FAILED"; status=1; fi
}

# a directory as the case file
mkdir -p dir.prm
"$exe" dir.prm > dir.log 2>&1; rc=$?
check "directory as case file refused" test $rc -ne 0
check "directory message" grep -q "'dir.prm' is a directory, not a parameter file" dir.log

# the include next to the case file wins over the working directory's
printf 'subsection Problem\n  set Geometry = bar\n  set Dry run = true\nend\n' > case/base.prm
printf 'subsection Problem\n  set Geometry = no such geometry\nend\n' > base.prm
printf 'include base.prm\nsubsection Problem\n  set Test mode = true\nend\n' > case/case.prm
"$exe" case/case.prm > include.log 2>&1; rc=$?
check "include read next to the including file" test $rc -eq 0
check "include gave the bar" grep -q "geometry 'bar'" include.log

# byte-order mark and CRLF line ends
printf '\xef\xbb\xbfsubsection Problem\r\n  set Geometry = bar\r\n  set Dry run = true\r\n  set Test mode = true\r\nend\r\n' > bom.prm
"$exe" bom.prm > bom.log 2>&1; rc=$?
check "byte-order mark and CRLF accepted" test $rc -eq 0
check "CRLF values read" grep -q "geometry 'bar'" bom.log

# one message on 2 ranks
printf 'include self.prm\n' > self.prm
mpirun -np 2 "$exe" self.prm > mpi.log 2>&1; rc=$?
check "2 ranks: refused" test $rc -ne 0
check "2 ranks: one message" test "$(grep -c 'closes a cycle of includes' mpi.log)" -eq 1
check "2 ranks: no MPI_ABORT" bash -c '! grep -q MPI_ABORT mpi.log'
if [ $status -ne 0 ]; then
  for f in *.log; do echo "--- $f"; cat "$f"; done
fi
exit $status
