#!/usr/bin/python3
"""ctest tests/profile_contact_py_01: scripts/wheelrail_post/profiles.py.

1. The paper's idealised pair (mesh/profiles/cylinder.txt on crown_r300.txt,
   rail upright, offset 0): one contact point at y = 0 with delta = 0 and
   r = R0, and gap(x, s) = x^2/(2 R0) + s^2/(2 * 0.3) over |x|, |s| <= 3 mm
   (to 0.1 % of its largest value; the next terms are of relative order 1e-5).
2. A cone 1:40 (z = -y/40: r = R0 + y/40 grows towards the flange) on the
   R 300 crown: d(y) = -y/40 - (sqrt(R^2 - y^2) - R) is least where the crown's
   slope is -1/40, at y = +R sin(atan(1/40)) = +7.4977 mm (towards the gauge
   side, where the cone's larger radius is), delta = +atan(1/40); on the crown
   inclined 1:40 at y = 0. Gap curvatures A = cos(delta) / (2 r), B = 1/0.6.
3. S1002 on 60E1 inclined 1:40 at y_w = 0 (the standard track's offset): one
   contact point, |delta| < 5 deg, |r - R0| < 2 mm; at y_w = 6 mm the contact
   has moved to the flange root (delta > 10 deg, r - R0 > 2 mm).
4. The reader: CSV with '%' comments and a header line gives the same points.
Argument: the source directory.
"""
import math
import os
import sys
import tempfile

import numpy as np

src = sys.argv[1]
sys.path.insert(0, os.path.join(src, "scripts"))
from wheelrail_post import profiles as P  # noqa: E402

prof = os.path.join(src, "mesh", "profiles")
R0 = P.R0_DEFAULT
failed = []


def check(what, ok, detail):
    print("%-4s %-60s %s" % ("ok" if ok else "FAIL", what, detail))
    if not ok:
        failed.append(what)


# 1. cylinder on the R300 crown
cyl = P.read_profile(os.path.join(prof, "cylinder.txt"))
crown = P.read_profile(os.path.join(prof, "crown_r300.txt"))
pair = P.Pair(cyl, crown, inclination=0, y_w=0.0, offset=0.0, R0=R0)
pts = P.contact_points(pair)
c = pts[0]
check("cylinder/R300: one contact point", len(pts) == 1, "%d" % len(pts))
check("  at y = 0", abs(c["y"]) < 1e-6, "y = %.2e mm (tolerance 1e-3 mm)" % (c["y"] * 1e3))
check("  delta = 0, r = R0", abs(c["delta"]) < 1e-5 and abs(c["r"] - R0) < 1e-9,
      "delta %.2e rad, r - R0 %.2e m" % (c["delta"], c["r"] - R0))
x = np.linspace(-3e-3, 3e-3, 13)
s = np.linspace(-3e-3, 3e-3, 13)
g = P.gap_grid(pair, c, x, s)
X, S = np.meshgrid(x, s, indexing="ij")
ga = X ** 2 / (2 * R0) + S ** 2 / (2 * 0.3)
err = np.abs(g - ga).max()
check("  gap = x^2/(2 R0) + s^2/(2*0.3) over |x|,|s| <= 3 mm", err <= 1e-3 * ga.max(),
      "largest difference %.3e m of %.3e m (tolerance 0.1 %%)" % (err, ga.max()))
check("  gap >= 0, zero at the point", g.min() >= -1e-12 and abs(g[6, 6]) < 1e-12,
      "min %.2e m, gap(0, 0) %.2e m" % (g.min(), g[6, 6]))

# 2. cone 1:40 on the R300 crown, upright and inclined 1:40
y = np.linspace(-35e-3, 35e-3, 701)
cone = np.column_stack((y, -y / 40))
a = math.atan(1 / 40)
for N, y_ref in ((0, 0.3 * math.sin(a)), (40, 0.0)):
    pair = P.Pair(cone, crown, inclination=N, y_w=0.0, offset=0.0, R0=R0)
    pts = P.contact_points(pair)
    c = pts[0]
    tag = "cone 1:40 on R300 %s" % ("upright" if N == 0 else "inclined 1:40")
    check(tag + ": one contact point", len(pts) == 1, "%d" % len(pts))
    check("  at y = %+.4f mm" % (y_ref * 1e3), abs(c["y"] - y_ref) < 1e-6,
          "y = %+.4f mm (tolerance 1e-3 mm)" % (c["y"] * 1e3))
    check("  delta = +atan(1/40) = %.4f deg" % math.degrees(a), abs(c["delta"] - a) < 1e-5,
          "%.4f deg" % math.degrees(c["delta"]))
    check("  r = R0 + y_wheel/40", abs(c["r"] - (R0 + c["y_wheel"] / 40)) < 1e-8,
          "r - R0 = %.4f mm" % ((c["r"] - R0) * 1e3))
    A, B = P.gap_curvatures(pair, c)
    A_ref = math.cos(a) / (2 * c["r"])
    check("  gap curvatures A = cos(delta)/(2r), B = 1/(2*0.3)",
          abs(A / A_ref - 1) < 1e-3 and abs(B * 0.6 - 1) < 1e-3,
          "A %.5f (%.5f), B %.5f (%.5f) 1/m" % (A, A_ref, B, 1 / 0.6))

# 3. S1002 on 60E1 1:40
wheel = P.read_profile(os.path.join(prof, "s1002.txt"))
rail = P.read_profile(os.path.join(prof, "60e1.txt"))
pair = P.Pair(wheel, rail, inclination=40, y_w=0.0, R0=R0)
print("     standard offset (taping line over the rail centre line): %.3f mm" % (pair.offset * 1e3))
check("  offset = gauge point - 32.5 mm, 2.5 .. 3.5 mm", 2.5e-3 < pair.offset < 3.5e-3,
      "%.3f mm" % (pair.offset * 1e3))
pts = P.contact_points(pair)
c = pts[0]
check("S1002/60E1 1:40, y_w = 0: one contact point", len(pts) == 1,
      "%d at y = %.3f mm (wheel %.3f mm)" % (len(pts), c["y"] * 1e3, c["y_wheel"] * 1e3))
check("  |delta| < 5 deg", abs(math.degrees(c["delta"])) < 5, "%.3f deg" % math.degrees(c["delta"]))
check("  |r - R0| < 2 mm", abs(c["r"] - R0) < 2e-3, "r - R0 = %.3f mm" % ((c["r"] - R0) * 1e3))
pair = P.Pair(wheel, rail, inclination=40, y_w=6e-3, R0=R0)
c = P.contact_points(pair)[0]
check("S1002/60E1 1:40, y_w = 6 mm: flange root", math.degrees(c["delta"]) > 10
      and c["r"] - R0 > 2e-3, "delta %.2f deg, r - R0 %.3f mm, y_wheel %.2f mm"
      % (math.degrees(c["delta"]), (c["r"] - R0) * 1e3, c["y_wheel"] * 1e3))

# 4. the reader
with tempfile.TemporaryDirectory() as d:
    path = os.path.join(d, "p.csv")
    with open(path, "w") as f:
        f.write("% exported profile\ny_mm,z_mm\n")
        for yy, zz in P.read_profile(os.path.join(prof, "cylinder.txt"))[:5] * 1e3:
            f.write("%.6f, %.6f  # a point\n" % (yy, zz))
    q = P.read_profile(path)
    check("reader: CSV, % comments, header line", np.allclose(q, cyl[:5]), "%d points" % len(q))

print("%d check(s) failed" % len(failed) if failed else "all checks passed")
sys.exit(1 if failed else 0)
