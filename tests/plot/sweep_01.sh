#!/usr/bin/env bash
# ctest driver of the sweep test: scripts/sweep.py over mu_n = 0.1, 0.4 for
# both laws on a short coarse rolling case, with --check on its figures.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
sed "s#@SOURCE_DIR@#$src/tests/plot#" "$src/tests/plot/sweep_01.prm.in" > sweep_01.prm
rm -rf sweep
/usr/bin/python3 "$src/scripts/sweep.py" sweep_01.prm --mu 0.1,0.4 --laws constant,exponential \
  --out sweep --wheelrail "$exe" --check
test -s sweep/sweep.csv
# the runs are too short for the traction to build up (the traction and
# saturation tests check mu_a); each run's mean F_N must be the static load
/usr/bin/python3 - <<'PY'
import csv
rows = list(csv.DictReader(open("sweep/sweep.csv")))
assert len(rows) == 4, "expected 4 runs, got %d" % len(rows)
for r in rows:
    fn = float(r["mean_F_N_second_half_N"])
    err = abs(fn - 140283.) / 140283.
    print("%s mu_n %s: mean F_N %.1f kN, %.2g from the static load" % (r["law"], r["mu_n"], fn * 1e-3, err))
    assert err < 0.02, "F_N off the static load"
PY
