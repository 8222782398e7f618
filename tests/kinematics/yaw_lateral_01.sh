#!/usr/bin/env bash
# Wheelset kinematics (Wheelset/Lateral creepage, Yaw angle): a yaw angle of
# 2 mrad is the run with lateral creepage -2e-3 (eta = -psi, small-angle
# kinematics): statistics, probes and contact nodes identical to the byte;
# the statistics' lateral creepage column is -2e-3 (v_y / v_x) and the spin
# 0 (the cylinder on the crown); stopped after step 100 and resumed, the
# lateral run ends as the uninterrupted one (the checkpoint carries the
# axle's lateral velocity and position). Arguments: the wheelrail
# executable, the source directory.
set -euo pipefail
exe=$1 src=$2
sed "s#@SOURCE_DIR@#$src/tests/kinematics#" "$src/tests/kinematics/yaw_lateral_01.prm.in" > eta.prm
{ echo 'include eta.prm'
  printf 'subsection Problem\n  set Output directory = yaw\nend\n'
  printf 'subsection Wheelset\n  set Lateral creepage = 0\n  set Yaw angle = 2e-3\nend\n'; } > yaw.prm
{ echo 'include eta.prm'
  printf 'subsection Problem\n  set Output directory = split\nend\n'
  printf 'subsection Output\n  set Stop after step = 100\nend\n'; } > split.prm
rm -rf eta yaw split
"$exe" eta.prm > eta.log
"$exe" yaw.prm > yaw.log
grep "lateral creepage eta" eta.log
grep "lateral creepage eta" yaw.log
"$exe" split.prm > split.log
grep -q "^Stopped after step 100" split.log
"$exe" split.prm --resume > resume.log
status=0
for f in statistics probe.csv wheel_probe.csv contact_nodes.csv; do
  for run in yaw split; do
    if cmp -s "eta/$f" "$run/$f"; then
      echo "$run/$f: identical"
    else
      echo "$run/$f: DIFFERENT"; status=1
    fi
  done
done
/usr/bin/python3 - "$src/scripts" eta/statistics <<'PY' || status=1
import sys
sys.path.insert(0, sys.argv[1])
from wheelrail_post.compare import read_statistics, column
import os
names, data = read_statistics(os.path.dirname(sys.argv[2]) or ".")
eta = column(names, data, "lateral creepage")
spin = column(names, data, "spin creepage")
assert eta is not None and spin is not None, names
# v_y / v_x: v_y held, v_x changes by F_L / M over the run (1e-6 of it)
err = abs(eta / -2e-3 - 1).max()
print("lateral creepage column: largest |eta / -2e-3 - 1| %.1g (limit 1e-5; 8 digits in the file)" % err)
print("spin creepage column: largest |phi| %g 1/m (cylinder on the crown: 0)" % abs(spin).max())
sys.exit(0 if err < 1e-5 and abs(spin).max() == 0 else 1)
PY
exit $status
