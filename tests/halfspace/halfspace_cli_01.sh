#!/usr/bin/env bash
# ctest driver of the command line of scripts/halfspace.py: a small case at a
# given longitudinal force writes its three CSV files with the force reached,
# and bad input ends with exit status 2, a message naming the option and no
# output directory.
# Argument: the source directory.
set -euo pipefail
src=$1
hs="/usr/bin/python3 $src/scripts/halfspace.py"
rm -rf case bad
$hs --nx 16 --ny 17 --Fx 42090 --out case
/usr/bin/python3 - <<'PY'
import csv
tot = {r["quantity"]: float(r["value"]) for r in csv.DictReader(open("case/totals.csv"))}
rows = list(csv.DictReader(open("case/fields.csv")))
line = list(csv.DictReader(open("case/centreline.csv")))
assert len(rows) == 16 * 17 and len(line) == 16, (len(rows), len(line))
assert abs(tot["F_x"] / 42090. - 1) < 1e-6, tot["F_x"]
assert abs(tot["F_N"] / 140.3e3 - 1) < 1e-9, tot["F_N"]
assert tot["xi"] < 0, "a driving force needs xi < 0"
assert tot["residual_stick_slip"] < 1e-9 and tot["residual_slip_alignment"] < 1e-6, tot
states = [r["state"] for r in rows]
slip = states.count("slip") / (states.count("slip") + states.count("stick"))
assert abs(slip - tot["slip_area_fraction"]) < 1e-8
for r in rows:  # Coulomb: |q| <= f p, |q| = f p where slipping (CSV: 9 digits)
    q = (float(r["q_x"]) ** 2 + float(r["q_y"]) ** 2) ** 0.5
    p = float(r["p"])
    assert q <= 0.5 * p * (1 + 1e-8)
    if r["state"] == "slip":
        assert abs(q - 0.5 * p) <= 1e-8 * p
    if r["state"] == "stick":
        assert float(r["s"]) < 1e-6, r
    if r["state"] == "out":
        assert p == 0 and q == 0
mid = [r for r in rows if float(r["y"]) == 0]  # the centreline is the row y = 0
assert [(r["x"], r["p"], r["q_x"]) for r in mid] == [(r["x"], r["p"], r["q_x"]) for r in line]
print("F_x %.1f N at xi %.5f, slip-area fraction %.3f: files consistent"
      % (tot["F_x"], tot["xi"], slip))
PY
expect_error() {  # expected message part, then the options
  local msg=$1; shift
  set +e
  out=$($hs "$@" --out bad 2>&1); rc=$?
  set -e
  echo "$* -> exit $rc: $out"
  [ "$rc" -eq 2 ] && grep -q -- "$msg" <<<"$out" && [ ! -e bad ]
}
expect_error "--ny" --ny 16
expect_error "--nu" --nu 0.6
expect_error "--Fx" --Fx 80000
expect_error "--Rx" --Rx 0.2
expect_error "--margin" --margin 0.95
expect_error "--fD" --law exponential --fD 0.6
expect_error "--Fx and --creepage" --Fx 1000 --creepage 0.001
echo "bad input rejected"
