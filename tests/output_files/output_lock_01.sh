#!/usr/bin/env bash
# ctest driver of the output-directory lock: a first run of bar.prm starts in
# the background and is paused (SIGSTOP) once it holds the lock; a second
# run into the same directory, on 1 and on 2 ranks, must stop at once naming
# the directory and the first run's pid, with a non-zero exit status and
# nothing in the directory changed; the first run, continued, must end as
# the same case run alone. Then a run rejected at setup (a time step above
# the stable step) must leave the directory's files as they were, and a
# run killed with SIGKILL must leave no stale lock.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
fail() {
  echo "FAILED: $*"
  exit 1
}
# every file of the directory with its checksum; with $2 = all, the lock
# file too (a run that takes the lock writes its pid into it)
snapshot() {
  if [ "${2:-}" = all ]; then
    (cd "$1" && find . -type f | sort | xargs md5sum)
  else
    (cd "$1" && find . -type f ! -name .wheelrail.lock | sort | xargs md5sum)
  fi
}

cp "$src/tests/output_files/bar.prm" first.prm
{ echo 'include first.prm'; printf 'subsection Problem\n  set Output directory = alone\nend\n'; } > alone.prm
{ echo 'include first.prm'; printf 'subsection Time integration\n  set End time = 1e-3\nend\n'; } > second.prm
{ echo 'include first.prm'; printf 'subsection Time integration\n  set Time step = 1.6e-6\nend\n'; } > rejected.prm
rm -rf run alone
"$exe" alone.prm > alone.log

"$exe" first.prm > first.log 2>&1 &
pid=$!
# the lock file names its holder once the lock is held
for i in $(seq 1 1000); do
  grep -qs "^pid $pid " run/.wheelrail.lock && break
  kill -0 $pid 2> /dev/null || break
  sleep 0.01
done
kill -STOP $pid 2> /dev/null || fail "the first run ended before it was paused (it wrote no lock note into run/.wheelrail.lock)"
grep -q "^pid $pid on host " run/.wheelrail.lock || fail "no lock note of the first run"
snapshot run all > before.md5

for np in 1 2; do
  if [ $np -gt 1 ]; then
    mpirun -np $np "$exe" second.prm > second.log 2>&1 && fail "a second run on $np ranks was not refused"
  else
    "$exe" second.prm > second.log 2>&1 && fail "a second run was not refused"
  fi
  grep -m1 -o "Error: Problem/Output directory 'run' is in use by another wheelrail run (pid $pid on host [^,]*," second.log ||
    { cat second.log; fail "no message naming the directory and the holder"; }
  snapshot run all > after.md5
  cmp -s before.md5 after.md5 || fail "the refused run on $np ranks changed the directory"
done

kill -CONT $pid
wait $pid || fail "the first run failed"
for f in statistics probe.csv; do
  cmp "run/$f" "alone/$f" && echo "$f: the same as the run alone"
done
grep -q "set End time *= 3e-3" run/parameters.prm || fail "parameters.prm is not the first run's"

# a run rejected at setup leaves the files as they were
snapshot run > before.md5
if "$exe" rejected.prm > rejected.log 2>&1; then fail "the time step above the stable step was accepted"; fi
grep -o "Error: Time integration/Time step = 1.6e-06 s exceeds the stable step" rejected.log
snapshot run > after.md5
cmp -s before.md5 after.md5 || fail "the rejected run changed the directory"
echo "rejected run: the directory unchanged"

# a run killed with SIGKILL leaves no stale lock: the next run goes ahead
{ echo 'include first.prm'; printf 'subsection Problem\n  set Output directory = killed\nend\n'; } > killed.prm
{ echo 'include killed.prm'; printf 'subsection Problem\n  set Dry run = true\nend\n'; } > after_kill.prm
rm -rf killed
"$exe" killed.prm > killed.log 2>&1 &
pid=$!
for i in $(seq 1 1000); do
  grep -qs "^pid $pid " killed/.wheelrail.lock && break
  kill -0 $pid 2> /dev/null || break
  sleep 0.01
done
kill -KILL $pid 2> /dev/null || fail "the run to be killed ended before"
if wait $pid; then fail "the run was not killed"; fi
"$exe" after_kill.prm > after_kill.log 2>&1 || { cat after_kill.log; fail "the run after a killed one was refused"; }
grep -q "^pid $pid " killed/.wheelrail.lock && fail "the lock note still names the killed run"
echo "after kill -9: the next run took the lock"

# a directory that holds files no wheelrail run wrote is refused, on 1 and 2
# ranks, before anything is written there (not even the lock file)
rm -rf foreign
mkdir -p foreign/src
echo "notes" > foreign/notes.txt
{ echo 'include first.prm'; printf 'subsection Problem\n  set Output directory = foreign\nend\n'; } > foreign.prm
snapshot foreign all > before.md5
for np in 1 2; do
  if [ $np -gt 1 ]; then
    mpirun -np $np "$exe" foreign.prm > foreign.log 2>&1 && fail "a foreign directory was accepted on $np ranks"
  else
    "$exe" foreign.prm > foreign.log 2>&1 && fail "a foreign directory was accepted"
  fi
  grep -o "Error: Problem/Output directory 'foreign' already holds files that no wheelrail run wrote (e.g. 'notes.txt')" foreign.log ||
    { cat foreign.log; fail "no message naming the directory and a foreign file"; }
  [ "$(grep -c "Error" foreign.log)" = 1 ] || { cat foreign.log; fail "more than one message on $np ranks"; }
  snapshot foreign all > after.md5
  cmp -s before.md5 after.md5 && [ ! -e foreign/.wheelrail.lock ] || fail "the refused run changed the directory"
done
echo "foreign directory: refused on 1 and 2 ranks, nothing written"
