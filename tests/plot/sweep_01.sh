#!/usr/bin/env bash
# ctest driver of the sweep test: scripts/sweep.py over mu_n = 0.1, 0.4 for
# both laws on a short coarse rolling case, with --check on its figures
# (the creep curve's half-space curves included), then the CSV files and the
# printed creep-curve lines.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
sed "s#@SOURCE_DIR@#$src/tests/plot#" "$src/tests/plot/sweep_01.prm.in" > sweep_01.prm
rm -rf sweep
/usr/bin/python3 "$src/scripts/sweep.py" sweep_01.prm --mu 0.1,0.4 --laws constant,exponential \
  --out sweep --wheelrail "$exe" --check | tee sweep.log
test -s sweep/sweep.csv
test -s sweep/creep_curve.png
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
# the creep curve: one FE row per run, at its mean creepage with the half-space
# value there; one printed line per run. The half-space curves (32 x 17
# elements): the Coulomb one starts with Kalker's slope C11 = 4.62 (32 x 17
# gives 1.2 % more at |xi| = 2.5e-4) and saturates at f = 0.5; the exponential
# one rises to a largest value between f_D = 0.32 and f_S = 0.5 (0.363 near
# xi = -0.006), then falls towards f_D.
/usr/bin/python3 - <<'PY'
import csv, math, re
rows = list(csv.DictReader(open("sweep/creep_curve.csv")))
fe = [r for r in rows if r["source"] == "FE"]
assert len(fe) == 4, "expected 4 FE rows, got %d" % len(fe)
for r in fe:
    v = [float(r[k]) for k in ("creepage", "Fx_over_Fn", "halfspace_Fx_over_Fn")]
    assert all(map(math.isfinite, v)), "FE row not finite: %s" % r
log = open("sweep.log").read()
lines = re.findall(r"^creep curve: (\S+) mu_n (\S+): creepage (\S+), mu_a FE (\S+), half-space (\S+) ", log, re.M)
assert len(lines) == 4, "expected 4 printed creep-curve lines, got %d" % len(lines)
fn = {r["law"]: float(r["mean_F_N_second_half_N"]) for r in csv.DictReader(open("sweep/sweep.csv"))}
curve = lambda law: sorted((float(r["creepage"]), float(r["Fx_over_Fn"]))
                           for r in rows if r["source"] == "half-space" and r["law"] == law)
c = dict(curve("constant"))
# Kalker: F_x = -G c^2 C11 xi, c^2 = a b of Hertz (SPEC 8: 8.017 x 6.031 mm at 140.3 kN, ~ F_N^(2/3))
G, load = 2.1e11 / 2.6, fn["constant"]
slope = G * 8.017e-3 * 6.031e-3 * (load / 140.3e3) ** (2 / 3) * 4.62 / load
small = c[-2.5e-4] / (2.5e-4 * slope)
print("Coulomb half-space: F_x/F_N at xi -2.5e-4 %.5f, %.4f of Kalker's C11 slope (limit 0.05); "
      "at xi -0.016 %.4f (limit >= 0.495)" % (c[-2.5e-4], small, c[-0.016]))
assert abs(small - 1) < 0.05 and 0.495 <= c[-0.016] <= 0.5, "Coulomb creep curve off"
assert abs(c[2.5e-4] + c[-2.5e-4]) < 1e-12, "creep curve not odd in xi"
e = [v for xi, v in curve("exponential") if xi < 0]
top = max(e)
print("exponential half-space: largest F_x/F_N %.4f (between 0.32 and 0.5), at xi -0.016 %.4f "
      "(below the largest)" % (top, e[0]))
assert 0.32 < top < 0.5 and 0.32 < e[0] < top, "exponential creep curve off"
PY
