#!/usr/bin/env bash
# ctest driver of the worked examples of doc/developer.md, built into their
# own wheelrail (tests/plugins/*.cc). Arguments: that executable, the source
# directory. Checked:
# - stribeck_friction.cc: with Stribeck exponent 1 the block sliding down
#   the inclined plane (contact_block_incline_03) gives the statistics of
#   the exponential law to the byte; with exponent 0.5 (f(v) about 7 %
#   above the exponential law's at the block's speed) the program's check of
#   the acceleration against g (sin theta - f(v) cos theta) holds with the
#   new law's f (test mode: a check outside its tolerance fails the run);
# - stick_fraction.cc: on the block dragged over the plate
#   (contact_block_sliding_02) with a statistics row every step, the column
#   'stick fraction [-]' is 1 - slip nodes / contact nodes of the same row;
#   with a row every 20 steps, a run stopped after step 1000 and resumed
#   ends with the uninterrupted run's statistics to the byte (the column's
#   sum and count of the row in progress are in the checkpoint).
set -euo pipefail
exe=$1 src=$2
rm -rf incline_* sliding_* *.prm *.log

case_file() { # NAME BASE then lines of overrides on stdin
  { echo "include $src/tests/$2.prm"; printf 'subsection Problem\n  set Output directory = %s\nend\n' "$1"; cat; } > "$1.prm"
}

printf 'subsection Contact\n  set Friction law = exponential\nend\n' | case_file incline_exp contact_block_incline_03
printf 'subsection Contact\n  set Friction law = stribeck\n  set Stribeck exponent = 1\nend\n' |
  case_file incline_s1 contact_block_incline_03
printf 'subsection Contact\n  set Friction law = stribeck\n  set Stribeck exponent = 0.5\nend\n' |
  case_file incline_s05 contact_block_incline_03
for name in incline_exp incline_s1 incline_s05; do "$exe" $name.prm > $name.log; done
cmp incline_exp/statistics incline_s1/statistics
echo "stribeck, exponent 1: statistics identical to the exponential law's"
grep "friction law" incline_s1.log
grep "friction law" incline_s05.log
sed -n '/^Check: inclined plane/,$p' incline_s05.log | grep -v "violations"
grep -q "within tolerance: yes" incline_s05.log

printf 'subsection Output\n  set Statistics interval = 1\n  set Postprocessors = stick fraction\nend\n' |
  case_file sliding_every contact_block_sliding_02
"$exe" sliding_every.prm > sliding_every.log
/usr/bin/python3 - sliding_every/statistics <<'PY'
import sys, numpy as np
names = [l.split(":", 1)[1].strip() for l in open(sys.argv[1]) if l[:1] == "#" and ":" in l[:5]]
rows = np.loadtxt(sys.argv[1], comments="#")
col = {n: rows[:, i] for i, n in enumerate(names)}
contact, slip, stick = col["contact nodes"], col["slip nodes"], col["stick fraction [-]"]
expected = np.where(contact > 0, 1 - slip / np.maximum(contact, 1), 0.0)
error = np.abs(stick - expected).max()
print("stick fraction: %d rows, %d with slip, largest |column - (1 - slip/contact)| %.1e"
      % (len(rows), int((slip > 0).sum()), error))
sys.exit(0 if error < 1e-7 and (slip > 0).any() and (slip < contact).any() else 1)
PY

printf 'subsection Output\n  set Postprocessors = stick fraction\nend\n' | case_file sliding_whole contact_block_sliding_02
printf 'subsection Output\n  set Postprocessors = stick fraction\n  set Stop after step = 1000\nend\n' |
  case_file sliding_split contact_block_sliding_02
"$exe" sliding_whole.prm > sliding_whole.log
"$exe" sliding_split.prm > sliding_split.log
"$exe" sliding_split.prm --resume > sliding_resume.log
grep "^Resumed from" sliding_resume.log
cmp sliding_whole/statistics sliding_split/statistics
echo "stick fraction: stopped after step 1000 and resumed = uninterrupted (statistics identical)"
