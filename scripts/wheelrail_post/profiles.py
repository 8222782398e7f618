"""Wheel and rail profiles: reading 2-column files, placing the pair in the
track's cross-section, the rigid contact search and the undeformed distance
(gap) of a contact point over its tangent plane (scripts/profile_contact.py).

Frames (mesh/profiles/README.md). Every function here works in metres.

  rail profile   y = 0 on the rail's centre line, z = 0 at the top of the
                 uninclined head, y positive towards the gauge side (the track
                 centre), z up
  wheel profile  y = 0 at the taping line, z = 0 at the nominal rolling
                 circle, y positive towards the flange, z up; rolling radius
                 r(y) = R0 - z(y)
  track frame    the rail's frame after the inclination: the rail profile
                 rotated about the head's top (0, 0) by alpha = atan(1/N) so
                 that its head leans towards the track centre (+y): a point
                 (y, z) goes to (y cos a + z sin a, -y sin a + z cos a), the
                 gauge side goes down, the top's normal tilts towards +y.
                 The wheel's y axis points the same way (its flange is on the
                 gauge side); a wheel point y_wheel lies at
                     y = y_wheel + offset - y_w
                 with offset the taping line's lateral position over the rail
                 centre line at y_w = 0 and y_w the wheelset's lateral shift
                 towards this wheel's flange contact: y_w > 0 brings the
                 flange to its rail (the contact point moves towards the
                 flange, r grows; flange contact near y_w = 5..6 mm on a
                 standard track). The wheel itself then moves towards its
                 field side, -y: a shift of the wheel towards +y (towards the
                 track centre, where its flange points) would draw the flange
                 away from the rail, not bring it into flange contact.

The standard track's offset (standard_offset): gauge G = 1435 mm between the
rails' gauge faces 14 mm below the rail top, flange-back spacing 1360 mm,
taping line 70 mm from the flange back. The taping line lies 1360/2 + 70 =
750 mm from the track centre, the rail's gauge point G/2 = 717.5 mm from it;
with g the gauge point's y in the (inclined) rail frame, the rail centre line
lies 717.5 + g from the track centre and the taping line at
    offset = g - (750 - 717.5) mm = g - 32.5 mm
(60E1 upright: g = 35.98 mm, offset +3.48 mm; at 1:40: g = 35.53, +3.03 mm).

Contact search (contact_points): on a common lateral grid over the overlap of
the two profiles, d(y) = z_wheel(y) - z_rail(y); the wheel is lowered by
min d so that min d = 0, and every local minimum of d with d <= tol is a
contact point (more than one: two-point contact). Each point: its y (track
frame and wheel frame), the contact angle delta = -atan(dz_rail/dy) (positive
when the normal tilts towards +y: the flange side), the rolling radius
r = R0 - z_wheel_profile(y_wheel).

Gap (gap_grid): at a contact point P the local frame x (rolling, along the
track), s = n x x (lateral in the tangent plane, the direction of the rail
profile's tangent (cos th, sin th), th = -delta) and n = (-sin th, cos th)
(normal, out of the rail). gap(x, s) is the distance along n between the rail
surface (straight along x) and the wheel surface (the profile revolved about
the axle, along y, at height R0 + lowering: a profile point of radius r lies
at z_axle - sqrt(r^2 - x^2)) through the tangent-plane point P + x ex + s es:
positive, d(P) (zero up to tol) at x = s = 0. For a cylinder on a crown of
radius R it is x^2/(2 R0) + s^2/(2 R) to second order.
"""
import math
import re

import numpy as np

MM = 1e-3
R0_DEFAULT = 0.46  # nominal rolling radius [m]

# the standard track (mm)
TRACK_GAUGE = 1435.0
GAUGE_DEPTH = 14.0
FLANGE_BACK_SPACING = 1360.0
TAPING_FROM_BACK = 70.0

_SPLIT = re.compile(r"[\s,;]+")


def read_profile(path):
    """(n, 2) array y, z [m] of a 2-column profile file in mm.

    Text or CSV: the first two numbers of each line (separated by blanks,
    commas or semicolons); lines starting with '#' or '%', and whatever follows
    a '#' or '%' on a line, are comments; empty lines are skipped; a line whose
    first two fields are not numbers (a column header) is skipped only before
    the first data line. The points keep the file's order."""
    pts = []
    with open(path) as f:
        for k, line in enumerate(f, 1):
            line = re.split(r"[#%]", line, maxsplit=1)[0].strip()
            if not line:
                continue
            fields = [v for v in _SPLIT.split(line) if v]
            try:
                y, z = float(fields[0]), float(fields[1])
            except (ValueError, IndexError):
                if not pts:
                    continue
                raise ValueError("%s:%d: expected two numbers y z, got %r" % (path, k, line))
            if not (math.isfinite(y) and math.isfinite(z)):
                raise ValueError("%s:%d: not a finite number: %r" % (path, k, line))
            pts.append((y, z))
    if len(pts) < 3:
        raise ValueError("%s: %d points; a profile needs at least 3" % (path, len(pts)))
    return np.array(pts) * MM


def incline_rail(p, n):
    """The rail profile P (m) inclined 1:N about (0, 0), head towards +y (N <= 0: upright)."""
    if not n or n <= 0:
        return np.array(p, dtype=float)
    a = math.atan(1.0 / n)
    c, s = math.cos(a), math.sin(a)
    return np.column_stack((p[:, 0] * c + p[:, 1] * s, -p[:, 0] * s + p[:, 1] * c))


def gauge_point(rail, depth=GAUGE_DEPTH * MM):
    """y [m] of the rail's gauge point: the outermost point towards +y at DEPTH below its top."""
    p = rail[np.argsort(rail[:, 0], kind="stable")]
    top = np.argmax(p[:, 1])
    level = p[top, 1] - depth
    side = p[top:]
    below = np.nonzero(side[:, 1] <= level)[0]
    if len(below) == 0:
        raise ValueError("the rail profile does not reach %.1f mm below its top on the gauge side"
                         % (depth / MM))
    j = below[0]
    (y0, z0), (y1, z1) = side[j - 1], side[j]
    return y0 + (level - z0) * (y1 - y0) / (z1 - z0)


def standard_offset(rail, gauge=TRACK_GAUGE * MM, depth=GAUGE_DEPTH * MM,
                    flange_back=FLANGE_BACK_SPACING * MM, taping=TAPING_FROM_BACK * MM):
    """Taping line over the rail centre line at y_w = 0 [m], rail in the track frame."""
    return gauge_point(rail, depth) - (flange_back / 2 + taping - gauge / 2)


def _as_function(p):
    """y ascending, z: a profile as a function of y (points of equal y merged)."""
    o = np.argsort(p[:, 0], kind="stable")
    y, z = p[o, 0], p[o, 1]
    keep = np.concatenate(([True], np.diff(y) > 1e-12))
    return y[keep], z[keep]


def _interp2(xq, x, y, derivative=False):
    """Quadratic (3-point Lagrange) interpolation of y(x), x ascending; and its slope."""
    xq = np.asarray(xq, dtype=float)
    i = np.clip(np.searchsorted(x, xq), 1, len(x) - 2)
    x0, x1, x2 = x[i - 1], x[i], x[i + 1]
    y0, y1, y2 = y[i - 1], y[i], y[i + 1]
    l0 = (xq - x1) * (xq - x2) / ((x0 - x1) * (x0 - x2))
    l1 = (xq - x0) * (xq - x2) / ((x1 - x0) * (x1 - x2))
    l2 = (xq - x0) * (xq - x1) / ((x2 - x0) * (x2 - x1))
    v = l0 * y0 + l1 * y1 + l2 * y2
    if not derivative:
        return v
    d0 = (2 * xq - x1 - x2) / ((x0 - x1) * (x0 - x2))
    d1 = (2 * xq - x0 - x2) / ((x1 - x0) * (x1 - x2))
    d2 = (2 * xq - x0 - x1) / ((x2 - x0) * (x2 - x1))
    return v, d0 * y0 + d1 * y1 + d2 * y2


class Pair:
    """A wheel profile over a rail profile in the track frame (all in m)."""

    def __init__(self, wheel, rail, inclination=40.0, y_w=0.0, offset=None, R0=R0_DEFAULT):
        self.rail = incline_rail(rail, inclination)
        self.wheel = np.array(wheel, dtype=float)
        self.inclination = inclination
        self.offset = standard_offset(self.rail) if offset is None else offset
        self.y_w = y_w
        self.R0 = R0
        self.wy, self.wz = _as_function(self.wheel)
        self.ry, self.rz = _as_function(self.rail)
        self.shift = self.offset - self.y_w  # track y = wheel y + shift
        self.dz = 0.0  # the wheel's lowering, set by contact_points

    def wheel_z(self, y):
        """Wheel profile height in the track frame at track y (before lowering)."""
        return _interp2(np.asarray(y) - self.shift, self.wy, self.wz)

    def rolling_radius(self, y):
        """The wheel's rolling radius R0 - z_wheel at track y."""
        return self.R0 - _interp2(np.asarray(y, dtype=float) - self.shift, self.wy, self.wz)

    def rail_z(self, y, derivative=False):
        return _interp2(y, self.ry, self.rz, derivative)

    def overlap(self):
        return max(self.wy[0] + self.shift, self.ry[0]), min(self.wy[-1] + self.shift, self.ry[-1])


def contact_points(pair, tol=1e-6, dy=1e-5):
    """The rigid contact points of PAIR: a list of dicts, lowest gap first.

    Lowers the wheel to min d = 0 (pair.dz); every interior local minimum of d
    with d <= tol is a point: y (track frame), y_wheel, z (track frame), gap
    (d there), delta [rad], r (rolling radius), at_end (the minimum lies at an
    end of the overlap: an edge of a profile)."""
    lo, hi = pair.overlap()
    if hi - lo < 3 * dy:
        raise ValueError("the profiles do not overlap laterally (%.3f .. %.3f mm)"
                         % (lo / MM, hi / MM))
    n = int(math.floor((hi - lo) / dy)) + 1
    y = lo + dy * np.arange(n)
    d = pair.wheel_z(y) - pair.rail_z(y)
    pair.dz = -float(d.min())
    d = d + pair.dz
    cand = [i for i in range(1, n - 1) if d[i] <= d[i - 1] and d[i] < d[i + 1] and d[i] <= tol]
    ends = [i for i in (0, n - 1) if d[i] <= tol and
            (d[i] < d[1] if i == 0 else d[i] < d[n - 2])]
    out = []
    for i in cand + ends:
        yi, gi = y[i], d[i]
        if 0 < i < n - 1:  # parabola through the three grid points
            a, b, c = d[i - 1], d[i], d[i + 1]
            den = a - 2 * b + c
            if den > 0:
                t = 0.5 * (a - c) / den
                yi = y[i] + t * dy
                gi = b - 0.25 * (a - c) * t
        zr, slope = pair.rail_z(np.array([yi]), derivative=True)
        yw = yi - pair.shift
        zw = float(_interp2(np.array([yw]), pair.wy, pair.wz)[0])
        out.append({"y": float(yi), "y_wheel": float(yw), "z": float(zr[0]),
                    "gap": max(float(gi), 0.0), "delta": -math.atan(float(slope[0])),
                    "r": pair.R0 - zw, "at_end": not (0 < i < n - 1)})
    out.sort(key=lambda c: (c["gap"], c["y"]))
    return out


def _local_curve(y, z, P, t, nrm, window):
    """A profile (ascending y) as h(s) in the frame at P: the monotone run around P."""
    q = np.column_stack((y - P[0], z - P[1]))
    s = q @ t
    h = q @ nrm
    i0 = int(np.argmin(np.hypot(q[:, 0], q[:, 1])))
    a = i0
    while a > 0 and s[a - 1] < s[a] and s[a - 1] > -window:
        a -= 1
    b = i0
    while b < len(s) - 1 and s[b + 1] > s[b] and s[b + 1] < window:
        b += 1
    return s[a:b + 1], h[a:b + 1]


def gap_grid(pair, point, x, s, window=0.03):
    """gap[i, j] = gap(x[i], s[j]) [m] at the contact POINT (from contact_points(pair))."""
    x = np.asarray(x, dtype=float)
    s = np.asarray(s, dtype=float)
    th = -point["delta"]
    t = np.array([math.cos(th), math.sin(th)])
    nrm = np.array([-math.sin(th), math.cos(th)])
    P = np.array([point["y"], point["z"]])
    rs, rh = _local_curve(pair.ry, pair.rz, P, t, nrm, window)
    if rs[0] > s.min() or rs[-1] < s.max():
        raise ValueError("the rail profile does not cover s = %.2f .. %.2f mm around the point"
                         % (s.min() / MM, s.max() / MM))
    h_rail = _interp2(s, rs, rh)
    r = pair.R0 - pair.wz  # rolling radii of the wheel profile points
    z_axle = pair.R0 + pair.dz
    yw = pair.wy + pair.shift
    gap = np.empty((len(x), len(s)))
    for i, xi in enumerate(x):
        zw = z_axle - np.sqrt(r * r - xi * xi)
        ws, wh = _local_curve(yw, zw, P, t, nrm, window)
        if ws[0] > s.min() or ws[-1] < s.max():
            raise ValueError("the wheel profile does not cover s = %.2f .. %.2f mm around the"
                             " point" % (s.min() / MM, s.max() / MM))
        gap[i] = _interp2(s, ws, wh) - h_rail
    return gap


def s_coverage(pair, point, window=0.03):
    """(s_lo, s_hi) [m]: the range of s over which both profiles are single-valued
    around the contact POINT in its tangent plane (gap_grid's s may lie inside it)."""
    th = -point["delta"]
    t = np.array([math.cos(th), math.sin(th)])
    nrm = np.array([-math.sin(th), math.cos(th)])
    P = np.array([point["y"], point["z"]])
    rs, _ = _local_curve(pair.ry, pair.rz, P, t, nrm, window)
    ws, _ = _local_curve(pair.wy + pair.shift, pair.wz + pair.dz, P, t, nrm, window)
    return max(rs[0], ws[0]), min(rs[-1], ws[-1])


def gap_curvatures(pair, point, half=2e-3, n=9):
    """A, B [1/m] of gap ~ gap0 + A x^2 + B s^2 fitted over |x|, |s| <= HALF."""
    x = np.linspace(-half, half, n)
    s = np.linspace(-half, half, n)
    g = gap_grid(pair, point, x, s)
    X, S = np.meshgrid(x, s, indexing="ij")
    M = np.column_stack((np.ones(X.size), X.ravel() ** 2, S.ravel() ** 2, X.ravel() * S.ravel(),
                         S.ravel(), S.ravel() ** 3))
    coef, *_ = np.linalg.lstsq(M, g.ravel(), rcond=None)
    return float(coef[1]), float(coef[2])


# --- command line (scripts/profile_contact.py) ------------------------------
def _standard_track_lines(pair):
    g = gauge_point(pair.rail)
    return [
        "standard track: gauge %.0f mm at %.0f mm below the rail top, flange-back spacing %.0f mm,"
        " taping line %.0f mm from the flange back"
        % (TRACK_GAUGE, GAUGE_DEPTH, FLANGE_BACK_SPACING, TAPING_FROM_BACK),
        "  rail gauge point y = %.3f mm (inclined rail) -> taping line at %+.3f mm over the rail"
        " centre line (towards the gauge side) at y_w = 0" % (g / MM, standard_offset(pair.rail) / MM),
    ]


def survey(wheel, rail, inclination, shifts, offset=None, R0=R0_DEFAULT, tol=1e-6, near=1e-4):
    """Rows (y_w, kind, point, Pair) of the contacts ('contact') and near-contacts ('near')."""
    rows = []
    for y_w in shifts:
        pair = Pair(wheel, rail, inclination, y_w, offset, R0)
        pts = contact_points(pair, tol=near)
        mirror = Pair(wheel, rail, inclination, -y_w, offset, R0)
        r_other = contact_points(mirror, tol=tol)[0]["r"]
        for c in pts:
            c["dr"] = c["r"] - r_other
            rows.append((y_w, "contact" if c["gap"] <= tol else "near", c, pair))
    return rows


def _plot(path, wheel, rail, inclination, shifts, rows, offset, R0):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    n = len(shifts)
    fig, axes = plt.subplots(1, n, figsize=(4.2 * n, 4.2), squeeze=False)
    for ax, y_w in zip(axes[0], shifts):
        pair = [r[3] for r in rows if r[0] == y_w][0]
        ax.plot(pair.rail[:, 0] / MM, pair.rail[:, 1] / MM, "k-", lw=1, label="rail")
        ax.plot((pair.wy + pair.shift) / MM, (pair.wz + pair.dz) / MM, "b-", lw=1, label="wheel")
        for yw2, kind, c, _ in rows:
            if yw2 == y_w:
                ax.plot(c["y"] / MM, c["z"] / MM, "ro" if kind == "contact" else "o",
                        mfc="r" if kind == "contact" else "none", mec="r")
        ax.set_xlim(-45, 50)
        ax.set_ylim(-35, 10)
        ax.set_aspect("equal")
        ax.set_title("y_w = %g mm" % (y_w / MM))
        ax.set_xlabel("y [mm] (towards the track centre)")
        ax.grid(True, lw=0.3)
    axes[0][0].set_ylabel("z [mm]")
    axes[0][0].legend(loc="lower left", fontsize=8)
    fig.suptitle("contact points (filled: contact, open: near-contact); rail 1:%g" % inclination
                 if inclination else "contact points; rail upright")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv=None):
    import argparse
    import os
    import sys
    from . import SCRIPTS_DIR
    prof = os.path.join(os.path.dirname(SCRIPTS_DIR), "mesh", "profiles")
    ap = argparse.ArgumentParser(
        description="Rigid contact points of a wheel profile on a rail profile"
        " (scripts/wheelrail_post/profiles.py: frames, signs, the gap).")
    ap.add_argument("--wheel", default=os.path.join(prof, "s1002.txt"), help="wheel profile file [mm]")
    ap.add_argument("--rail", default=os.path.join(prof, "60e1.txt"), help="rail profile file [mm]")
    ap.add_argument("--inclination", type=float, default=40.0,
                    help="rail inclination 1:N towards the track centre (0: upright; default 40)")
    ap.add_argument("--yw", default="0,3,6",
                    help="wheelset shifts y_w [mm], comma separated; > 0 brings the flange to the rail")
    ap.add_argument("--offset", type=float, default=None,
                    help="taping line over the rail centre line at y_w = 0 [mm]"
                    " (default: the standard track's, computed from the rail profile)")
    ap.add_argument("--R0", type=float, default=R0_DEFAULT, help="nominal rolling radius [m] (0.46)")
    ap.add_argument("--tol", type=float, default=1e-3,
                    help="gap [mm] within which a local minimum is a contact point (0.001)")
    ap.add_argument("--near", type=float, default=0.1,
                    help="also list local minima with a gap up to this [mm] as near-contacts (0.1)")
    ap.add_argument("--png", default=None, help="figure of the profiles with the points")
    a = ap.parse_args(argv)

    def bad(msg):
        print("profile_contact.py: error: %s" % msg, file=sys.stderr)
        return 2
    try:
        shifts = [float(v) * MM for v in a.yw.split(",") if v.strip()]
    except ValueError:
        return bad("--yw: comma-separated numbers [mm], got %r" % a.yw)
    if not shifts:
        return bad("--yw: no shift given")
    if a.inclination < 0 or a.R0 <= 0 or a.tol < 0 or a.near < a.tol:
        return bad("--inclination >= 0, --R0 > 0 and 0 <= --tol <= --near")
    try:
        wheel = read_profile(a.wheel)
        rail = read_profile(a.rail)
    except (OSError, ValueError) as e:
        return bad(str(e))
    offset = None if a.offset is None else a.offset * MM
    pair0 = Pair(wheel, rail, a.inclination, 0.0, offset, a.R0)
    print("wheel %s (%d points), rail %s (%d points), rail %s, R0 = %.4f m"
          % (a.wheel, len(wheel), a.rail, len(rail),
             "inclined 1:%g" % a.inclination if a.inclination else "upright", a.R0))
    if offset is None:
        for line in _standard_track_lines(pair0):
            print(line)
    else:
        print("taping line at %+.3f mm over the rail centre line at y_w = 0 (--offset)" % a.offset)
    print("y_w > 0: the wheelset shifted so that this wheel's flange approaches its rail;"
          " y: track frame (rail centre line, towards the track centre);")
    print("delta: contact angle (> 0: normal towards the track centre); dr = r(y_w) - r(-y_w);"
          " A, B: gap ~ A x^2 + B s^2 [1/m]")
    try:
        rows = survey(wheel, rail, a.inclination, shifts, offset, a.R0, a.tol * MM, a.near * MM)
    except ValueError as e:
        return bad(str(e))
    print("%7s %-8s %9s %9s %9s %8s %10s %9s %9s %8s %8s"
          % ("y_w mm", "kind", "y mm", "y_whl mm", "gap um", "delta", "r mm", "r-R0 mm",
             "dr mm", "A 1/m", "B 1/m"))
    for y_w, kind, c, pair in rows:
        try:
            A, B = gap_curvatures(pair, c)
            ab = "%8.3f %8.3f" % (A, B)
        except ValueError:
            ab = "%8s %8s" % ("-", "-")
        print("%7.2f %-8s %9.3f %9.3f %9.3f %7.2fd %10.3f %+9.3f %+9.3f %s%s"
              % (y_w / MM, kind, c["y"] / MM, c["y_wheel"] / MM, c["gap"] / 1e-6,
                 math.degrees(c["delta"]), c["r"] / MM, (c["r"] - a.R0) / MM, c["dr"] / MM, ab,
                 "  (at a profile's end)" if c["at_end"] else ""))
    for y_w in shifts:
        n = sum(1 for r in rows if r[0] == y_w and r[1] == "contact")
        print("y_w = %.2f mm: %d contact point%s" % (y_w / MM, n, "" if n == 1 else "s (two-point contact)"
                                                     if n == 2 else "s"))
    if a.png:
        _plot(a.png, wheel, rail, a.inclination, shifts, rows, offset, a.R0)
        print("wrote %s" % a.png)
    return 0
