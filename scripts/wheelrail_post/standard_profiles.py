"""The standard wheel and rail profiles from their published geometric
definitions, written as 2-column point files into mesh/profiles/, and the
checks of their characteristic dimensions (scripts/make_profiles.py).

Files (two columns y z in mm, '#' header lines; mesh/profiles/README.md):

    s1002.txt       S1002 wheel (EN 13715, UIC 510-2), sections A..H
    60e1.txt        60E1 rail head top (EN 13674-1), R300/R80/R13 and the 1:20 flanks
    cylinder.txt    the paper's idealised wheel: flat tread z = 0, |y| <= 35 mm
    crown_r300.txt  the paper's idealised rail: circular crown R 300 mm, |y| <= 35 mm
    cone_phi005.txt, cone_phi02.txt  coned treads for spin 0.05 and 0.2 1/m on it

Conventions. Rail: y = 0 on the rail's centre line, z = 0 at the top of the
(uninclined) head, y positive towards the gauge side (track centre), z up.
Wheel: y = 0 at the taping line, z = 0 at the nominal rolling circle, y
positive towards the flange, z up (the flange lies below, z < 0; the rolling
radius is r(y) = R0 - z(y)).

S1002 definition: the section functions F(S) of H. Netter (DLR
Oberpfaffenhofen), as distributed with the exercise code of Lund University's
numerical analysis course (e.g. the Python function s1002(S) in
NUMA41 exercise copies on GitHub); S is the lateral coordinate
in mm, positive towards the field side, F the depth below the taping-line
level, positive towards the flange tip. Here y = -S and z = -F. The
coefficients were not available from a second, independent source; they are
checked against the dimensions that EN 13715 prescribes for S1002 (flange
height 28 mm, flange thickness 32.5 mm, qR 10.8 mm) and for value and slope
continuity at every section boundary (--check).

60E1 definition: the head construction of André Rohrbeck's EN13674 Swift
package (github.com/rohrbecka/EN13674, Sources/EN13674/Profiles/P60E1.swift):
crown arc R 300 centred on (0, -300) up to the chord width 20.456 mm, R 80
tangent to it up to the chord width 52.053 mm, R 13 tangent to that down to
the 1:20 flank; these chord widths are those of the EN 13674-1 drawing. The
head width 72 mm of the standard then follows as a check.
"""
import argparse
import math
import os

import numpy as np

# lateral sampling step along the curve [mm]
STEP = 0.1
IDEAL_STEP = 0.25

# --- S1002 (Netter's sections, in S and F; y = -S, z = -F) ----------------
S1002_COEFF = {
    "A": (1.364323640, 0.066666667),
    "B": (0.0, 3.358537058e-02, 1.565681624e-03, 2.810427944e-05, 5.844240864e-08,
          1.562379023e-08, 5.309217349e-15, 5.957839843e-12, 2.646656573e-13),
    "C": (4.320221063e+03, 1.038384026e+03, 1.065501873e+02, 6.051367875,
          2.054332446e-01, 4.169739389e-03, 4.687195829e-05, 2.252755540e-07),
    "D": (16.446, 13.0, 26.210665),
    "E": (93.576667419, 2.747477419),
    "F": (8.834924130, 20.0, 58.558326413),
    "G": (16.0, 12.0, 55.0),
    "H": (9.519259302, 20.5, 49.5),
}
# section bounds in S, from the flange back (-70) to the field side (+60)
S1002_BOUNDS = [("H", -70.0, -62.764705882), ("G", -62.764705882, -49.662510381),
                ("F", -49.662510381, -39.764473993), ("E", -39.764473993, -38.426669071),
                ("D", -38.426669071, -35.0), ("C", -35.0, -26.0),
                ("B", -26.0, 32.15796), ("A", 32.15796, 60.0)]


def s1002_F(name, S):
    """Netter's F(S) of section NAME [mm] (depth, positive towards the flange tip)."""
    c = S1002_COEFF[name]
    S = np.asarray(S, dtype=float)
    if name == "A":
        return c[0] - c[1] * S
    if name == "B":  # AB - BB S + CB S^2 - DB S^3 + ... + IB S^8
        return sum(((-1) ** k) * c[k] * S ** k for k in range(9))
    if name == "C":  # -AC - BC S - ... - HC S^7
        return -sum(c[k] * S ** k for k in range(8))
    if name == "D":
        return c[0] - np.sqrt(np.maximum(c[1] ** 2 - (S + c[2]) ** 2, 0.0))
    if name == "E":
        return -c[0] - c[1] * S
    # F, G, H: arcs below their centres
    return c[0] + np.sqrt(np.maximum(c[1] ** 2 - (S + c[2]) ** 2, 0.0))


def s1002_dF(name, S):
    """dF/dS of section NAME."""
    c = S1002_COEFF[name]
    S = np.asarray(S, dtype=float)
    if name == "A":
        return -c[1] + 0 * S
    if name == "B":
        return sum(((-1) ** k) * k * c[k] * S ** (k - 1) for k in range(1, 9))
    if name == "C":
        return -sum(k * c[k] * S ** (k - 1) for k in range(1, 8))
    if name == "E":
        return -c[1] + 0 * S
    u = S + c[2]
    root = np.sqrt(c[1] ** 2 - u ** 2)
    return u / root if name == "D" else -u / root


def s1002_z(y):
    """z(y) of S1002 [mm] in this file's convention (y = -S, z = -F)."""
    S = -np.asarray(y, dtype=float)
    out = np.full(S.shape, np.nan)
    for name, a, b in S1002_BOUNDS:
        m = (S >= a) & (S <= b)
        out[m] = -s1002_F(name, S[m])
    return out


def _arc_center(name):
    """Centre (y, z) and radius of an arc section, in y, z."""
    A, R, C = S1002_COEFF[name]
    if name == "D":  # F = A - sqrt(..) -> z = -A + sqrt(..): above the centre
        return (C, -A, R, +1)
    return (C, -A, R, -1)  # z = -A - sqrt(..): below the centre


def _resample(points, step):
    """Points of a finely sampled curve at equal arc length <= step (incl. ends)."""
    p = np.asarray(points)
    seg = np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1]))
    s = np.concatenate(([0.0], np.cumsum(seg)))
    n = max(1, int(math.ceil(s[-1] / step - 1e-9)))
    t = np.linspace(0.0, s[-1], n + 1)
    return t, s


def _sample_section(name, Sa, Sb, step):
    """Points (y, z) of one S1002 section from S = Sa to S = Sb (y from -Sa to -Sb)."""
    ya, yb = -Sa, -Sb
    if name in ("D", "F", "G", "H"):  # arcs: by angle, equal arc length
        yc, zc, R, side = _arc_center(name)
        pa = math.atan2(side * math.sqrt(max(R * R - (ya - yc) ** 2, 0.0)), ya - yc)
        pb = math.atan2(side * math.sqrt(max(R * R - (yb - yc) ** 2, 0.0)), yb - yc)
        n = max(1, int(math.ceil(abs(pb - pa) * R / step - 1e-9)))
        phi = np.linspace(pa, pb, n + 1)
        return np.column_stack((yc + R * np.cos(phi), zc + R * np.sin(phi)))
    # polynomials and lines: by y on a fine grid, then equal arc length
    yf = np.linspace(ya, yb, 20001)
    zf = -s1002_F(name, -yf)
    t, s = _resample(np.column_stack((yf, zf)), step)
    y = np.interp(t, s, yf)
    y[0], y[-1] = ya, yb
    return np.column_stack((y, -s1002_F(name, -y)))


def s1002_points(step=STEP):
    """The S1002 curve from the flange back (y = 70) to the field side (y = -60)."""
    parts = []
    for i, (name, a, b) in enumerate(S1002_BOUNDS):
        p = _sample_section(name, a, b, step)
        parts.append(p if i == 0 else p[1:])  # a boundary point once
    return np.vstack(parts)


def s1002_boundaries():
    """At each section boundary: (left, right, S, value jump, slope jump) [mm, mm, -]."""
    out = []
    for (n1, _, b1), (n2, a2, _) in zip(S1002_BOUNDS[:-1], S1002_BOUNDS[1:]):
        S = b1
        dv = float(s1002_F(n1, S) - s1002_F(n2, S))
        ds = float(s1002_dF(n1, S) - s1002_dF(n2, S))
        # slope jump as an angle (the flange's slopes are steep)
        da = float(math.atan(s1002_dF(n1, S)) - math.atan(s1002_dF(n2, S)))
        out.append((n1, n2, S, dv, ds, da))
    return out


def _solve_y(f, lo, hi, target):
    """y in [lo, hi] with f(y) = target, f monotone there (bisection)."""
    flo = f(lo) - target
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        fm = f(mid) - target
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def s1002_dimensions():
    """Flange height, flange thickness (10 mm above the taping line), qR [mm]."""
    # flange crest: the lowest z of the profile (section G's arc: centre - 12)
    yc, zc, R, _ = _arc_center("G")
    crest_y, crest_z = yc, zc - R
    Sh = 0.0 - crest_z  # below the taping-line point (0, 0)
    # flange face (gauge side of the flange, y from the crest down to the root)
    face = lambda y: float(s1002_z(np.array([y]))[0])  # noqa: E731
    y10 = _solve_y(face, 26.0, crest_y, -10.0)  # 10 mm below the tread level
    Sd = 70.0 - y10  # from the flange back face y = 70
    y2 = _solve_y(face, 26.0, crest_y, crest_z + 2.0)  # 2 mm above the crest
    qR = y2 - y10
    return {"crest": (crest_y, crest_z), "Sh": Sh, "Sd": Sd, "qR": qR,
            "y10": y10, "y2": y2}


# --- 60E1 head (EN 13674-1) -------------------------------------------------
R_CROWN, R_MID, R_CORNER = 300.0, 80.0, 13.0
W_CROWN, W_MID = 20.456, 52.053  # chord widths of the R300 and R80 arcs [mm]
FLANK = 1.0 / 20.0  # the flanks' inclination to the vertical
FLANK_DEPTH = 30.0  # the flanks are written down to z = -30 mm


def e60_geometry():
    """Arc centres, radii and tangency points of the head's gauge half (y >= 0)."""
    c300 = np.array([0.0, -R_CROWN])
    th1 = math.asin(W_CROWN / 2 / R_CROWN)  # angle from the vertical at R300/R80
    t1 = c300 + R_CROWN * np.array([math.sin(th1), math.cos(th1)])
    c80 = c300 + (R_CROWN - R_MID) * np.array([math.sin(th1), math.cos(th1)])
    th2 = math.asin((W_MID / 2 - c80[0]) / R_MID)  # at R80/R13
    t2 = c80 + R_MID * np.array([math.sin(th2), math.cos(th2)])
    c13 = c80 + (R_MID - R_CORNER) * np.array([math.sin(th2), math.cos(th2)])
    a = math.atan(FLANK)  # the flank's outward normal: (cos a, sin a)
    th3 = math.pi / 2 - a
    t3 = c13 + R_CORNER * np.array([math.cos(a), math.sin(a)])
    z_end = -FLANK_DEPTH
    t4 = np.array([t3[0] + (t3[1] - z_end) * FLANK, z_end])
    return {"c300": c300, "c80": c80, "c13": c13, "th1": th1, "th2": th2, "th3": th3,
            "t1": t1, "t2": t2, "t3": t3, "t4": t4}


def _arc(c, R, th_a, th_b, step):
    """Arc points, th measured from the vertical towards +y."""
    n = max(1, int(math.ceil(abs(th_b - th_a) * R / step - 1e-9)))
    th = np.linspace(th_a, th_b, n + 1)
    return np.column_stack((c[0] + R * np.sin(th), c[1] + R * np.cos(th)))


def e60_points(step=STEP):
    """The head from the field-side flank (y < 0) over the top to the gauge-side flank."""
    g = e60_geometry()
    n = max(1, int(math.ceil(np.hypot(*(g["t4"] - g["t3"])) / step - 1e-9)))
    half = [_arc(g["c300"], R_CROWN, 0.0, g["th1"], step),
            _arc(g["c80"], R_MID, g["th1"], g["th2"], step)[1:],
            _arc(g["c13"], R_CORNER, g["th2"], g["th3"], step)[1:],
            (g["t3"] + np.outer(np.linspace(0, 1, n + 1), g["t4"] - g["t3"]))[1:]]
    right = np.vstack(half)
    left = right[:0:-1] * np.array([-1.0, 1.0])
    return np.vstack((left, right))


def e60_head_width_at(depth):
    """Head width [mm] at DEPTH mm below the top (on the R13 arc or the flank)."""
    g = e60_geometry()
    z = -depth
    if z >= g["t3"][1]:
        dz = z - g["c13"][1]
        return 2 * (g["c13"][0] + math.sqrt(R_CORNER ** 2 - dz ** 2))
    return 2 * (g["t3"][0] + (g["t3"][1] - z) * FLANK)


# --- the paper's idealised pair ---------------------------------------------
def cylinder_points():
    y = np.linspace(-35.0, 35.0, int(round(70.0 / IDEAL_STEP)) + 1)
    return np.column_stack((y, 0.0 * y))


def crown_points(R=300.0):
    y = np.linspace(-35.0, 35.0, int(round(70.0 / IDEAL_STEP)) + 1)
    return np.column_stack((y, np.sqrt(R * R - y * y) - R))


# Coned treads for spin without lateral creepage on the R300 crown: free
# rolling on a cone of half-angle gamma (radius growing towards the flange)
# gives the spin phi = sin(gamma) / r at the contact, no lateral creepage.
CONE_SPINS = (0.05, 0.2)     # phi [1/m] at the nominal radius R0
CONE_R0 = 460.0              # [mm]


def cone_angle(phi, r0=CONE_R0):
    """Half-angle [rad] of the cone whose spin at radius r0 [mm] is phi [1/m]."""
    return math.asin(phi * r0 * 1e-3)


def cone_points(phi):
    y = np.linspace(-35.0, 35.0, int(round(70.0 / IDEAL_STEP)) + 1)
    return np.column_stack((y, -y * math.tan(cone_angle(phi))))


def _cone_name(phi):
    return "cone_phi%s.txt" % ("%g" % phi).replace("0.", "0")


# --- the files --------------------------------------------------------------
RAIL_CONV = [
    "columns: y z [mm]; z up",
    "rail convention: y = 0 on the rail's centre line, z = 0 at the top of the",
    "  (uninclined) head, y positive towards the gauge side (track centre)",
]
WHEEL_CONV = [
    "columns: y z [mm]; z up",
    "wheel convention: y = 0 at the taping line, z = 0 at the nominal rolling",
    "  circle, y positive towards the flange; the flange lies below (z < 0);",
    "  rolling radius r(y) = R0 - z(y)",
]
GENERATOR = "generated by scripts/make_profiles.py (scripts/wheelrail_post/standard_profiles.py);" \
    " do not edit"


def _s1002_header():
    return [
        "S1002 wheel profile (EN 13715:2006+A1:2010 / UIC 510-2), new, flange height",
        "  28 mm, flange thickness 32.5 mm, taping line 70 mm from the flange back",
    ] + WHEEL_CONV + [
        "source: sections A..H (polynomials B, C; lines A, E; arcs D R13, F R20,",
        "  G R12, H R20.5) of H. Netter, DLR Oberpfaffenhofen, as distributed in the",
        "  function s1002(S) of Lund University's numerical analysis exercises",
        "  (public copies on GitHub, e.g. of the NUMA41 course, HT24);",
        "  y = -S, z = -F(S); coefficients in scripts/wheelrail_post/standard_profiles.py",
        "extent: from the flange back y = +70 (the end of arc H, where its tangent is",
        "  vertical, z = -9.519; the vertical back face above it is not written: it is",
        "  not single-valued in y, the FE model takes a window) across the flange and",
        "  the tread to the field side y = -60 (the end of the definition; the",
        "  chamfer to the outer face is not part of it)",
        "points every <= %.2f mm of arc length, ordered from the flange back" % STEP,
        GENERATOR,
    ]


def _e60_header():
    g = e60_geometry()
    return [
        "60E1 rail head (EN 13674-1:2011, the former UIC 60), top of the head",
    ] + RAIL_CONV + [
        "source: the head construction of the EN 13674-1 drawing as coded in",
        "  github.com/rohrbecka/EN13674, Sources/EN13674/Profiles/P60E1.swift:",
        "  crown R300 centre (0, -300) to |y| = 20.456/2; R80 tangent to it to",
        "  |y| = 52.053/2 (centre (+-%.4f, %.4f)); R13 tangent to that" % (g["c80"][0], g["c80"][1]),
        "  (centre (+-%.4f, %.4f)) down to the 1:20 flank, tangent at" % (g["c13"][0], g["c13"][1]),
        "  (+-%.4f, %.4f): head width %.3f mm there (72 mm in EN 13674-1)"
        % (g["t3"][0], g["t3"][1], 2 * g["t3"][0]),
        "extent: the flanks down to z = -%.0f mm; symmetric about y = 0" % FLANK_DEPTH,
        "points every <= %.2f mm of arc length, from the field side to the gauge side" % STEP,
        GENERATOR,
    ]


def _format(header, pts):
    lines = ["# " + h for h in header]
    lines += ["%.6f %.6f" % (0.0 if abs(y) < 5e-7 else y, 0.0 if abs(z) < 5e-7 else z)
              for y, z in pts]
    return "\n".join(lines) + "\n"


def file_texts():
    """{file name: text} of every generated file."""
    return {
        "s1002.txt": _format(_s1002_header(), s1002_points()),
        "60e1.txt": _format(_e60_header(), e60_points()),
        "cylinder.txt": _format([
            "the paper's idealised wheel: a cylinder, flat tread z = 0 over |y| <= 35 mm",
        ] + WHEEL_CONV + ["points every %.2f mm" % IDEAL_STEP, GENERATOR], cylinder_points()),
        "crown_r300.txt": _format([
            "the paper's idealised rail: a circular crown of radius 300 mm over",
            "  |y| <= 35 mm, z = sqrt(300^2 - y^2) - 300",
        ] + RAIL_CONV + ["points every %.2f mm" % IDEAL_STEP, GENERATOR], crown_points()),
        **{_cone_name(phi): _format([
            "a coned tread for spin without lateral creepage on the R300 crown: half-angle",
            "  gamma = asin(phi R0) = %.6f deg for phi = %g 1/m at R0 = %g mm (the spin" %
            (math.degrees(cone_angle(phi)), phi, CONE_R0),
            "  sin(gamma) / r at the contact, r = R0 - z there), z = -y tan(gamma)",
        ] + WHEEL_CONV + ["points every %.2f mm" % IDEAL_STEP, GENERATOR], cone_points(phi))
           for phi in CONE_SPINS},
    }


def write(directory):
    from . import atomic_file
    os.makedirs(directory, exist_ok=True)
    for name, text in file_texts().items():
        path = os.path.join(directory, name)
        with atomic_file.replacing(path) as tmp:
            with open(tmp, "w") as f:
                f.write(text)
        print("wrote %s (%d points)" % (path, sum(1 for l in text.splitlines()
                                                   if not l.startswith("#"))))


# --- the checks -------------------------------------------------------------
class Checks:
    def __init__(self):
        self.failed = 0

    def value(self, what, got, ref, tol, unit="mm"):
        ok = abs(got - ref) <= tol
        self.failed += not ok
        print("%-4s %-58s %12.6f %s  reference %g, tolerance %g"
              % ("ok" if ok else "FAIL", what, got, unit, ref, tol))
        return ok

    def true(self, what, ok, detail=""):
        self.failed += not ok
        print("%-4s %-58s %s" % ("ok" if ok else "FAIL", what, detail))
        return ok


def _read_points(text):
    return np.array([[float(v) for v in l.split()] for l in text.splitlines()
                     if l.strip() and not l.startswith("#")])


def _circle_fit(p):
    """Least-squares circle (Kasa) through points: centre, radius."""
    A = np.column_stack((2 * p[:, 0], 2 * p[:, 1], np.ones(len(p))))
    b = (p ** 2).sum(axis=1)
    (a, c, k), *_ = np.linalg.lstsq(A, b, rcond=None)
    return (a, c), math.sqrt(k + a * a + c * c)


def _largest_turn(p):
    """Largest change of direction between consecutive segments of a polyline [deg]."""
    seg = p[1:] - p[:-1]
    ang = np.unwrap(np.arctan2(seg[:, 1], seg[:, 0]))
    return float(np.degrees(np.abs(np.diff(ang)).max()))


def check(directory):
    c = Checks()
    texts = file_texts()
    print("S1002 (EN 13715):")
    d = s1002_dimensions()
    c.value("flange height Sh (crest below the taping-line point)", d["Sh"], 28.0, 1e-6)
    c.value("flange thickness Sd (10 mm above the taping line)", d["Sd"], 32.5, 0.01)
    c.value("qR (Sd point to the point 2 mm above the crest)", d["qR"], 10.8, 0.05)
    z0 = float(s1002_z(np.array([0.0]))[0])
    c.value("taping-line point z(0)", z0, 0.0, 1e-9)
    worst_v = worst_a = (None, 0.0)
    for n1, n2, S, dv, ds, da in s1002_boundaries():
        print("     boundary %s|%s at y = %+.6f: value jump %+.2e mm, slope jump %+.2e"
              " (%+.2e deg)" % (n1, n2, -S, -dv, -ds, math.degrees(-da)))
        if abs(dv) > abs(worst_v[1]):
            worst_v = ("%s|%s" % (n1, n2), dv)
        if abs(da) > abs(worst_a[1]):
            worst_a = ("%s|%s" % (n1, n2), da)
    # the coefficients are published to 10 significant digits: section C's
    # polynomial (terms up to 1e5 that cancel to ~10 mm) is good to ~1e-4 mm
    c.value("largest value jump at a section boundary (%s)" % worst_v[0],
            abs(worst_v[1]), 0.0, 1e-3)
    c.value("largest slope jump at a section boundary (%s)" % worst_a[0],
            math.degrees(abs(worst_a[1])), 0.0, 0.05, "deg")
    p = _read_points(texts["s1002.txt"])
    seg = np.hypot(np.diff(p[:, 0]), np.diff(p[:, 1]))
    c.value("largest point spacing along the curve", seg.max(), STEP, 1e-3)
    c.true("ends: flange back y = 70, field side y = -60",
           abs(p[0, 0] - 70) < 1e-9 and abs(p[-1, 0] + 60) < 1e-9,
           "(%.3f, %.3f) ... (%.3f, %.3f)" % (p[0, 0], p[0, 1], p[-1, 0], p[-1, 1]))
    c.true("y decreasing along the curve (single-valued z(y))", bool(np.all(np.diff(p[:, 0]) < 0)))
    c.value("largest turn between point pairs (0.1 mm on R13: 0.44 + D|C jump)",
            _largest_turn(p), 0.0, 0.5, "deg")

    print("60E1 (EN 13674-1):")
    g = e60_geometry()
    c.value("head width at the top of the 1:20 flanks", 2 * g["t3"][0], 72.0, 0.01)
    print("     (width 14 mm below the top, the gauge point: %.3f mm; the tangency"
          " R13/flank is %.3f mm below the top)" % (e60_head_width_at(14.0), -g["t3"][1]))
    # tangency: the centres on the common normals, the flank normal to R13's radius
    t1_80 = np.hypot(*(g["t1"] - g["c80"])) - R_MID
    t1_300 = np.hypot(*(g["t1"] - g["c300"])) - R_CROWN
    t2_13 = np.hypot(*(g["t2"] - g["c13"])) - R_CORNER
    c.value("R300/R80 tangency: |t1 - c80| - 80 (same normal)", abs(t1_80) + abs(t1_300), 0.0, 1e-9)
    c.value("R80/R13 tangency: |t2 - c13| - 13", abs(t2_13), 0.0, 1e-9)
    flank_dir = g["t4"] - g["t3"]
    c.value("R13/flank tangency: flank . radius (normal)",
            abs(float(np.dot(flank_dir, g["t3"] - g["c13"]))) / np.hypot(*flank_dir), 0.0, 1e-9)
    p = _read_points(texts["60e1.txt"])
    seg = p[1:] - p[:-1]
    c.value("largest turn between point pairs (no kink; 0.1 mm on R13: 0.44)",
            _largest_turn(p), 0.0, 0.45, "deg")
    top = p[np.argmax(p[:, 1])]
    c.value("top of the head at (0, 0): |(y, z)|", float(np.hypot(*top)), 0.0, 1e-9)
    crown = p[np.abs(p[:, 0]) <= W_CROWN / 2]
    (cy, cz), R = _circle_fit(crown)
    c.value("R300 crown fitted to the points |y| <= 10.228", R, 300.0, 0.5)
    c.value("  its centre's y", cy, 0.0, 1e-3)
    c.value("largest point spacing along the curve", np.hypot(seg[:, 0], seg[:, 1]).max(), STEP, 1e-3)

    print("idealised pair:")
    p = _read_points(texts["crown_r300.txt"])
    (cy, cz), R = _circle_fit(p)
    c.value("crown_r300 radius fitted to its points", R, 300.0, 1e-3)

    for phi in CONE_SPINS:
        p = _read_points(texts[_cone_name(phi)])
        slope = np.polyfit(p[:, 0], p[:, 1], 1)[0]
        c.value("%s: spin sin(atan(-slope)) / R0 [1/m]" % _cone_name(phi),
                math.sin(math.atan(-slope)) / (CONE_R0 * 1e-3), phi, 1e-6, unit="1/m")

    print("files in %s:" % directory)
    for name, text in texts.items():
        path = os.path.join(directory, name)
        same = os.path.isfile(path) and open(path).read() == text
        c.true("%s equals what the generator writes" % name, same,
               "" if same else "(regenerate: scripts/make_profiles.py --dir %s)" % directory)
    print("%d check(s) failed" % c.failed if c.failed else "all checks passed")
    return 1 if c.failed else 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dir", default=os.path.join(
        os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
        "mesh", "profiles"), help="folder of the profile files (default mesh/profiles)")
    ap.add_argument("--check", action="store_true",
                    help="verify the definitions' characteristic points and that the files"
                    " on disk are what the generator writes (exit status 1 if not); writes nothing")
    a = ap.parse_args(argv)
    if a.check:
        return check(a.dir)
    write(a.dir)
    return 0
