"""The non-Hertzian normal problem: any undeformed gap h(x, y) on the half-space.

The gap h [m] is the distance between the two undeformed surfaces along the
normal, over the tangent plane of the patch (x rolling direction, y = s
lateral, as rolling3d.py), from

  a callable   h(X, Y) on arrays of element centres (with a search extent);
  a table      h[i, j] at x[i], y[j] (increasing axes, any spacing), read
               bilinearly; profiles.py writes it as an .npz with keys x, s
               (the lateral axis), h; load_gap reads that or a CSV.

The normal problem is bem.solve_normal's (Polonsky & Keer) on the values of
h at the element centres (solve_gap; an array of the grid's shape is used
as it is, so a Hertzian h gives today's elliptic_case arrays exactly).

place_grid finds where to put the grid. Since the combined normal
displacement u of a positive pressure is positive, the contact lies inside
{h <= h_min + delta}, delta the approach. An estimate of delta for the load
by the Hertz-like relation F_N = 0.943 E* L sqrt(A(L) / pi), A(L) the area
of {h <= h_min + L} (exact for a sphere), a coarse solve over the bounding
box of {h <= h_min + 1.5 L} (the level raised until the contact stays off
the edge), then the grid over the coarse contact's bounding box, widened by
one coarse element and scaled by margin about its centre. The grid is
Grid3D's, shifted by the box centre (influence coefficients depend on
offsets only); the coordinates keep the gap's origin, the reference point
of the creepages and of M_z.
"""
import csv
import math

import numpy as np

from . import bem


class GapError(ValueError):
    pass


class Gap:
    """h(X, Y) from a callable (extent (x0, x1, y0, y1) to search) or a
    table h[i, j] at x[i], y[j] (bilinear; outside the table an error)."""

    def __init__(self, h, x=None, y=None, extent=None):
        if callable(h):
            if extent is None:
                raise GapError("a gap function needs its extent (x0, x1, y0, y1)")
            self.func, self.extent = h, tuple(float(v) for v in extent)
            return
        self.x, self.y, self.h = (np.asarray(v, dtype=float) for v in (x, y, h))
        if self.h.shape != (self.x.size, self.y.size):
            raise GapError("gap table: h has shape %s, the axes %d x %d"
                           % (self.h.shape, self.x.size, self.y.size))
        if (np.diff(self.x) <= 0).any() or (np.diff(self.y) <= 0).any():
            raise GapError("gap table: the x and s axes must increase")
        if not np.isfinite(self.h).all():
            raise GapError("gap table: h has values that are not finite")
        self.func = self._bilinear
        self.extent = (self.x[0], self.x[-1], self.y[0], self.y[-1])

    def _bilinear(self, X, Y):
        x0, x1, y0, y1 = self.extent
        if X.min() < x0 or X.max() > x1 or Y.min() < y0 or Y.max() > y1:
            raise GapError("the contact reaches the edge of the gap table (x %.4g..%.4g, "
                           "s %.4g..%.4g m)" % self.extent)
        i = np.clip(np.searchsorted(self.x, X) - 1, 0, self.x.size - 2)
        j = np.clip(np.searchsorted(self.y, Y) - 1, 0, self.y.size - 2)
        tx = (X - self.x[i]) / (self.x[i + 1] - self.x[i])
        ty = (Y - self.y[j]) / (self.y[j + 1] - self.y[j])
        h = self.h
        return ((1 - tx) * (1 - ty) * h[i, j] + tx * (1 - ty) * h[i + 1, j]
                + (1 - tx) * ty * h[i, j + 1] + tx * ty * h[i + 1, j + 1])

    def __call__(self, X, Y):
        return self.func(np.asarray(X, dtype=float), np.asarray(Y, dtype=float))


def load_gap(path):
    """A gap table from an .npz (keys x, s, h: h[i, j] at x[i], s[j], m) or
    a CSV with a header x,s,h and one row per point of a full grid."""
    if path.endswith(".npz"):
        with np.load(path) as d:
            missing = [k for k in ("x", "s", "h") if k not in d]
            if missing:
                raise GapError("%s lacks the key(s) %s (x, s, h expected)"
                               % (path, ", ".join(missing)))
            return Gap(d["h"], d["x"], d["s"])
    with open(path) as f:
        rows = list(csv.DictReader(f))
    try:
        pts = np.array([[float(r["x"]), float(r["s"]), float(r["h"])] for r in rows])
    except (KeyError, TypeError, ValueError):
        raise GapError("%s: a CSV with the columns x, s, h (m) expected" % path)
    xs, ys = np.unique(pts[:, 0]), np.unique(pts[:, 1])
    if len(pts) != xs.size * ys.size:
        raise GapError("%s: the points do not form a full grid (%d points, %d x %d axes)"
                       % (path, len(pts), xs.size, ys.size))
    h = np.full((xs.size, ys.size), np.nan)
    h[np.searchsorted(xs, pts[:, 0]), np.searchsorted(ys, pts[:, 1])] = pts[:, 2]
    return Gap(h, xs, ys)


def solve_gap(grid, h, load):
    """Normal problem on the grid for the gap h: an array of grid shape (used
    as it is) or a Gap/callable at the element centres. Returns p, info;
    info["at_edge"]: the contact reaches the grid's edge."""
    if not isinstance(h, np.ndarray):
        X, Y = np.meshgrid(grid.x, grid.y, indexing="ij")
        h = h(X, Y)
    p, info = bem.solve_normal(grid, h, load)
    edge = np.zeros_like(p, dtype=bool)
    edge[[0, -1], :] = edge[:, [0, -1]] = True
    info["at_edge"] = bool((p[edge] > 0).any())
    return p, info


def make_grid(nx, ny, box, e_star, g_mod, nu):
    """Grid3D over box = (x0, x1, y0, y1), shifted to the box's centre."""
    x0, x1, y0, y1 = box
    grid = bem.Grid3D(nx, ny, 0.5 * (x1 - x0), 0.5 * (y1 - y0), e_star, g_mod, nu)
    grid.x = grid.x + 0.5 * (x0 + x1)
    grid.y = grid.y + 0.5 * (y0 + y1)
    return grid


def _level_box(gap, level, n=257):
    """Bounding box of {h <= h_min + level} on an n x n sample of the extent
    (widened by one sample spacing); also the area of the set."""
    x0, x1, y0, y1 = gap.extent
    xs, ys = np.linspace(x0, x1, n), np.linspace(y0, y1, n)
    X, Y = np.meshgrid(xs, ys, indexing="ij")
    h = gap(X, Y)
    inside = h <= h.min() + level
    dx, dy = xs[1] - xs[0], ys[1] - ys[0]
    ix, iy = np.nonzero(inside.any(axis=1))[0], np.nonzero(inside.any(axis=0))[0]
    box = (max(x0, xs[ix[0]] - dx), min(x1, xs[ix[-1]] + dx),
           max(y0, ys[iy[0]] - dy), min(y1, ys[iy[-1]] + dy))
    return box, inside.sum() * dx * dy, h


def estimate_level(gap, load, e_star):
    """L with F_N = 0.943 E* L sqrt(A(L) / pi) (bisection in L)."""
    _, _, h = _level_box(gap, np.inf)
    lo, hi = 0.0, float(h.max() - h.min())
    if 0.943 * e_star * hi * math.sqrt(_level_box(gap, hi)[1] / math.pi) < load:
        raise GapError("the load needs an approach beyond the gap's extent")
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        area = _level_box(gap, mid, 129)[1]
        lo, hi = (mid, hi) if 0.943 * e_star * mid * math.sqrt(area / math.pi) < load else (lo, mid)
    return hi


def place_grid(gap, load, nx, ny, e_star, g_mod, nu, margin=1.1, coarse=24):
    """The grid over the contact of the load (module docstring); returns
    the grid and the coarse solve's approach."""
    level = 1.5 * estimate_level(gap, load, e_star)
    for _ in range(12):
        box = _level_box(gap, level)[0]
        grid = make_grid(coarse, coarse + 1, box, e_star, g_mod, nu)
        p, info = solve_gap(grid, gap, load)
        if not info["at_edge"]:
            break
        level *= 1.5
    else:
        raise GapError("no grid holds the contact within the gap's extent")
    X, Y = np.meshgrid(grid.x, grid.y, indexing="ij")
    c = p > 0
    xa, xb = X[c].min() - grid.dx, X[c].max() + grid.dx
    ya, yb = Y[c].min() - grid.dy, Y[c].max() + grid.dy
    xm, ym, hx, hy = 0.5 * (xa + xb), 0.5 * (ya + yb), 0.5 * (xb - xa), 0.5 * (yb - ya)
    box = (xm - margin * hx, xm + margin * hx, ym - margin * hy, ym + margin * hy)
    return make_grid(nx, ny, box, e_star, g_mod, nu), info["approach"]


def gap_case(gap, load, nx, ny, E, nu, margin=1.1):
    """Grid placed over the contact, the normal solution on it; the grid is
    widened by 1.2 until the contact stays off its edge. Returns grid, p,
    info (bem.solve_normal's, with at_edge)."""
    e_star, g_mod = E / (2.0 * (1.0 - nu * nu)), E / (2.0 * (1.0 + nu))
    grid, _ = place_grid(gap, load, nx, ny, e_star, g_mod, nu, margin)
    for _ in range(6):
        p, info = solve_gap(grid, gap, load)
        if not info["at_edge"]:
            return grid, p, info
        lx, ly = 0.6 * grid.dx * nx, 0.6 * grid.dy * ny
        xm, ym = grid.x.mean(), grid.y.mean()
        grid = make_grid(nx, ny, (xm - lx, xm + lx, ym - ly, ym + ly), e_star, g_mod, nu)
    raise GapError("the contact reaches the grid's edge after widening it")
