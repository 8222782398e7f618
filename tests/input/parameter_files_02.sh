#!/usr/bin/env bash
# ctest driver: hostile parameter files and command lines, where one .prm
# cannot show it.
# - a line longer than 65536 characters is refused with its file and line (a
#   1 MB line, in the case file and in an include); one of 65536 is read;
# - a read that fails (/proc/self/mem: EIO) is refused with file and line;
# - an include that is a symbolic link loop, or a link to itself, says so; a
#   dangling link names its target;
# - tabs between words (include, subsection, set) work like spaces;
# - CR-only line ends (old Mac) are read, with the right line numbers;
# - an entry set again by a file that includes the first setting is an
#   override; the same value twice in one file is accepted;
# - command-line errors name the argument, then print the usage text, and
#   control characters in an argument are escaped.
# Arguments: the wheelrail executable. Runs in its own build directory.
set -uo pipefail
exe=$1
rm -rf work && mkdir -p work && cd work
status=0
check() { # NAME CONDITION...
  local name=$1; shift
  if "$@"; then echo "$name: ok"; else echo "$name: FAILED"; status=1; fi
}
run() { # LOG ARGS...: runs wheelrail, leaves its exit status in rc
  local log=$1; shift
  "$exe" "$@" > "$log" 2>&1; rc=$?
}
bar='subsection Problem\n  set Geometry = bar\n  set Dry run = true\n  set Test mode = true\nend\n'

# a 1 MB line in the case file and in an include; a line of exactly 65536
{ printf 'subsection Problem\n  set Geometry = bar\n  set Output directory = '
  head -c 1000000 /dev/zero | tr '\0' a; printf '\nend\n'; } > long.prm
run long.log long.prm
check "1 MB line refused" test $rc -ne 0
check "1 MB line: file and line" \
  grep -q "Line <3> of file <long.prm>: the line is longer than 65536 characters" long.log
{ printf '# a long comment follows\n#'; head -c 1000000 /dev/zero | tr '\0' a; printf '\n'; } > long.inc
printf "$bar"'include long.inc\n' > long_include.prm
run long_include.log long_include.prm
check "1 MB line in an include refused" test $rc -ne 0
check "1 MB line in an include: file and line" \
  grep -q "Line <2> of file <long.inc>: the line is longer than 65536" long_include.log
{ printf "$bar#"; head -c 65535 /dev/zero | tr '\0' a; printf '\n'; } > limit.prm
run limit.log limit.prm
check "65536 characters read" test $rc -eq 0

# a read that fails
printf "$bar"'include /proc/self/mem\n' > eio.prm
run eio.log eio.prm
check "failed read refused" test $rc -ne 0
check "failed read: file and line" \
  grep -q "Line <1> of file </proc/self/mem>: reading the file failed" eio.log

# symbolic link loops and a dangling link
ln -s loop_b.inc loop_a.inc && ln -s loop_a.inc loop_b.inc && ln -s self.inc self.inc
ln -s missing.inc dangling.inc
for link in loop_a self dangling; do
  printf "$bar"'include %s.inc\n' $link > $link.prm
  run $link.log $link.prm
  check "include $link refused" test $rc -ne 0
done
check "link cycle named" grep -q "Line <6> of file <loop_a.prm>: 'include loop_a.inc': \
The included file 'loop_a.inc' is a symbolic link that leads back to itself" loop_a.log
check "link to itself named" grep -q "'self.inc' is a symbolic link that leads back to itself" self.log
check "dangling link named" \
  grep -q "'dangling.inc' is a symbolic link to 'missing.inc', which does not exist" dangling.log
run self_case.log self.inc
check "case file linked to itself named" \
  grep -q "The parameter file 'self.inc' is a symbolic link that leads back to itself" self_case.log

# tabs: include, subsection and set
printf 'subsection\tProblem\n\tset\tGeometry\t=\tbar\nend\n' > tabs.inc
printf 'include\ttabs.inc\nsubsection\tProblem\n\tset\tDry run\t=\ttrue\n\tset\tTest mode = true\nend\n' \
  > tabs.prm
run tabs.log tabs.prm
check "tabs accepted" test $rc -eq 0
check "tabs: include read" grep -q "geometry 'bar'" tabs.log
check "tabs: Dry run read" grep -q "Dry run: stopping" tabs.log

# CR-only line ends, read and with the right line numbers
printf 'subsection Problem\r  set Geometry = bar\r  set Dry run = true\r  set Test mode = true\rend\r' \
  > cr.prm
run cr.log cr.prm
check "CR-only accepted" test $rc -eq 0
check "CR-only values read" grep -q "geometry 'bar'" cr.log
printf '# old Mac\rsubsection Problem\r  set Geometry = bar\r  set Dry rn = true\rend\r' > cr_bad.prm
run cr_bad.log cr_bad.prm
check "CR-only: line number" \
  grep -q "Line <4> of file <cr_bad.prm>: No entry with name <Dry rn>" cr_bad.log

# an override of an included entry; the same value twice in one file
printf 'subsection Time integration\n  set End time = 1e-3\nend\n' > base.inc
printf "$bar"'include base.inc\nsubsection Time integration\n  set End time = 2e-3\nend\n' \
  > override.prm
run override.log override.prm
check "override of an include accepted" test $rc -eq 0
check "override: the includer's value" grep -q "to t = 2 ms" override.log
printf "$bar"'subsection Time integration\n  set End time = 2e-3\n  set End time = 2e-3\nend\n' \
  > same.prm
run same.log same.prm
check "same value twice accepted" test $rc -eq 0

# the command line
printf "$bar" > ok.prm
cli() { # NAME MESSAGE ARGS...
  local name=$1 message=$2; shift 2
  run cli.log "$@"
  check "$name refused" test $rc -ne 0
  check "$name named" grep -qF "Error: $message" cli.log
  check "$name: usage" grep -q "^Usage: wheelrail CASE.prm" cli.log
}
cli "unknown option" "unknown option '--resme'" ok.prm --resme
cli "unknown short option" "unknown option '-x'" -x ok.prm
cli "two case files" "two case files, 'ok.prm' and 'cr.prm': give one" ok.prm cr.prm
cli "--resume first" "'--resume' without a case file before it" --resume ok.prm
cli "no case file" "no case file given"
cli "empty argument" "argument 1 is empty, not a case file" ""
cli "escape in an argument" "unknown option '--\x1b[2J'" $'--\e[2J'
check "no raw ESC printed" bash -c "! grep -q $'\e' cli.log"
run help.log ok.prm --help
check "--help after the file: help" grep -q "^Parameters (defaults shown)" help.log

if [ $status -ne 0 ]; then
  for f in *.log; do echo "--- $f"; head -c 2000 "$f"; done
fi
exit $status
