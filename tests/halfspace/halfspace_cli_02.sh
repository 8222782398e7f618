#!/usr/bin/env bash
# ctest driver of the command line of scripts/halfspace.py with lateral
# creepage, spin and a gap file: a spin case writes phi, F_y/F_N and M_z and
# its M_z is the fields' sum of (x q_y - y q_x) dA; a given F_y/F_N with spin
# is reached; a Hertzian gap as .npz and as CSV gives the same fields and
# Hertz's p0, a, b; bad input ends with exit status 2, a message naming the
# option and no output directory. The same gap 2 mm aside keeps its a, b
# and puts its pressure centroid at y = 2 mm.
# Argument: the source directory.
set -euo pipefail
src=$1
hs="/usr/bin/python3 $src/scripts/halfspace.py"
rm -rf spin force gap_npz gap_csv gap_shift bad hz.npz hz.csv shift.npz nokey.npz
$hs --nx 16 --ny 17 --creepage -0.001 --phi 0.5 --out spin
$hs --nx 16 --ny 17 --fy 0.2 --phi 0.5 --out force
/usr/bin/python3 - <<'PY'
import numpy as np
x = np.linspace(-0.02, 0.02, 161)
s = np.linspace(-0.015, 0.015, 121)
X, S = np.meshgrid(x, s, indexing="ij")
h = X * X / (2 * 0.46) + S * S / (2 * 0.30)  # the SPEC 8 gap, R_x 0.46 m, R_y 0.30 m
np.savez("hz.npz", x=x, s=s, h=h)
np.savez("nokey.npz", x=x, y=s, h=h)
np.savez("shift.npz", x=x, s=s, h=X * X / (2 * 0.46) + (S - 2e-3) ** 2 / (2 * 0.30))
with open("hz.csv", "w") as out:
    out.write("x,s,h\n")
    for i in range(x.size):
        for j in range(s.size):
            out.write("%r,%r,%r\n" % (x[i], s[j], h[i, j]))
PY
$hs --nx 24 --ny 25 --gap hz.npz --creepage -0.001 --out gap_npz
$hs --nx 24 --ny 25 --gap hz.csv --creepage -0.001 --out gap_csv
cmp gap_npz/fields.csv gap_csv/fields.csv
$hs --nx 24 --ny 25 --gap shift.npz --out gap_shift
/usr/bin/python3 - <<'PY'
import csv
import numpy as np

def totals(d):
    return {r["quantity"]: float(r["value"]) for r in csv.DictReader(open(d + "/totals.csv"))}

t = totals("spin")
rows = list(csv.DictReader(open("spin/fields.csv")))
x, y, qx, qy = (np.array([float(r[k]) for r in rows]) for k in ("x", "y", "q_x", "q_y"))
dA = np.diff(np.unique(x))[0] * np.diff(np.unique(y))[0]
mz = ((x * qy - y * qx) * dA).sum()
assert t["phi"] == 0.5 and abs(mz / t["M_z"] - 1) < 1e-6, (mz, t["M_z"])
assert abs(t["F_y/F_N"] - t["F_y"] / t["F_N"]) < 1e-9 and t["F_y"] < 0, t
f = totals("force")
assert abs(f["F_y/F_N"] - 0.2) < 1e-6 and f["eta"] < 0, f
g = totals("gap_npz")
assert abs(g["p0"] / 1385.43e6 - 1) < 3e-3 and abs(g["a"] / 8.0174e-3 - 1) < 3e-3, g
assert abs(g["b"] / 6.0309e-3 - 1) < 3e-3 and abs(g["approach"] / 130.487e-6 - 1) < 3e-3, g
assert abs(g["F_y"]) < 1e-6 * g["F_N"] and abs(g["M_z"]) < 1e-9 * g["F_N"], g
sh = totals("gap_shift")  # the same patch 2 mm aside: a, b about its centroid
assert abs(sh["a"] / 8.0174e-3 - 1) < 3e-3 and abs(sh["b"] / 6.0309e-3 - 1) < 3e-3, sh
rows = list(csv.DictReader(open("gap_shift/fields.csv")))
p, y = (np.array([float(r[k]) for r in rows]) for k in ("p", "y"))
assert abs((p * y).sum() / p.sum() - 2e-3) < 2e-5, (p * y).sum() / p.sum()
print("spin: M_z %.3f N m = sum (x q_y - y q_x) dA; F_y/F_N 0.2 at eta %.5f; gap file: p0 %.1f MPa,"
      " a %.4f mm, b %.4f mm" % (t["M_z"], f["eta"], g["p0"] * 1e-6, g["a"] * 1e3, g["b"] * 1e3))
PY
expect_error() {  # expected message part, then the options
  local msg=$1; shift
  set +e
  out=$($hs "$@" --out bad 2>&1); rc=$?
  set -e
  echo "$* -> exit $rc: $out"
  [ "$rc" -eq 2 ] && grep -q -- "$msg" <<<"$out" && [ ! -e bad ]
}
expect_error "--fy excludes" --fy 0.1 --Fx 1000
expect_error "--fy excludes" --fy 0.1 --eta 0.001
expect_error "--fy = 1.5" --fy 1.5
expect_error "--phi" --phi 2000
expect_error "--phi: not with --line" --line --phi 1
expect_error "--gap = missing.npz" --gap missing.npz
expect_error "lacks the key" --gap nokey.npz
expect_error "--fy: |F| = 84180 N must be below" --fy 0.6
echo "bad input rejected"
