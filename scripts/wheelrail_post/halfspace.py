"""Half-space reference of the wheel-rail contact patch (Kalker's exact theory):
the cases and the solve.

The Hertzian wheel-rail case of SPEC 8 on a grid of rectangles: the normal
problem at a given load (elliptic_case, or line_case for Carter's strip), then
steady rolling at given creepages (xi, eta, spin phi) or a given longitudinal
or lateral force (rolling) with Coulomb friction or the exponential law
(make_law), the per-element fields and CSV files of them (write_csv); a
non-Hertzian case from a gap file (gap_file_case, gap.py).
The numerics are in bem.py (spin: rolling3d.py, general gaps: gap.py), the
verification checks in halfspace_checks.py and halfspace_checks_rolling.py,
the command line (scripts/halfspace.py) in halfspace_cli.py. Signs and
conventions: halfspace_cli.py's docstring, doc/manual/halfspace.md.
"""
import math

import numpy as np

from . import atomic_file
from . import bem
from . import gap
from . import rolling3d

SPEC = dict(load=140.3e3, rx=0.46, ry=0.30, E=2.1e11, nu=0.3, speed=38.89,
            f=0.5, f_s=0.5, f_d=0.32, k=6.0)


class InputError(Exception):
    pass


def moduli(E, nu):
    """Combined modulus E* of two identical bodies and the shear modulus G."""
    return E / (2.0 * (1.0 - nu * nu)), E / (2.0 * (1.0 + nu))


def make_law(name, f, f_s, f_d, k, length=0.0, time=0.0):
    """The law; the exponential one with a relaxing state if length or time > 0."""
    if name == "coulomb":
        return bem.Coulomb(f)
    law = bem.Exponential(f_s, f_d, k)
    return bem.RelaxingState(law, length, time) if length > 0 or time > 0 else law


def elliptic_case(nx, ny, margin, load, rx, ry, E, nu):
    """Grid around the Hertz ellipse and the normal solution on it."""
    e_star, g_mod = moduli(E, nu)
    hz = bem.hertz_elliptic(load, rx, ry, e_star)
    grid = bem.Grid3D(nx, ny, margin * hz["a"], margin * hz["b"], e_star, g_mod, nu)
    X, Y = np.meshgrid(grid.x, grid.y, indexing="ij")
    p, info = bem.solve_normal(grid, X * X / (2 * rx) + Y * Y / (2 * ry), load)
    edge = np.zeros_like(p, dtype=bool)
    edge[[0, -1], :] = edge[:, [0, -1]] = True
    if (p[edge] > 0).any():
        raise InputError("--margin: the contact reaches the edge of the grid; raise --margin")
    return grid, p, info, hz, X, Y, g_mod


def line_case(nx, margin, load, r, E, nu):
    """2-D strip with the Hertz line pressure sampled at the element centres."""
    e_star, g_mod = moduli(E, nu)
    a, p0 = bem.hertz_line(load, r, e_star)
    grid = bem.Line2D(nx, margin * a, e_star)
    p = p0 * np.sqrt(np.clip(1.0 - (grid.x / a) ** 2, 0.0, None))
    return grid, p, a, p0


def semi_axes(grid, p, X, Y):
    """a, b of the Hertz ellipse with the pressure's second moments:
    <x^2>_p = a^2 / 5 for an ellipsoidal pressure."""
    w = p.sum()
    return math.sqrt(5.0 * (p * X * X).sum() / w), math.sqrt(5.0 * (p * Y * Y).sum() / w)


def gap_file_case(path, nx, ny, margin, load, E, nu):
    """The non-Hertzian case of a gap file (gap.load_gap): the grid placed
    over the contact (gap.gap_case), the normal solution, Hertz values NaN."""
    try:
        grid, p, info = gap.gap_case(gap.load_gap(path), load, nx, ny, E, nu, margin)
    except (OSError, gap.GapError) as e:
        raise InputError("--gap: %s" % e)
    X, Y = np.meshgrid(grid.x, grid.y, indexing="ij")
    nan = float("nan")
    hz = dict(a=nan, b=nan, p0=nan, area=nan, approach=nan)
    return grid, p, info, hz, X, Y, moduli(E, nu)[1]


def rolling(grid, p, law, speed, creep=None, fx=None, eta=0.0, phi=0.0, fy=None):
    """Steady rolling at the creepages, or at a given F_x or F_y [N] (one of
    them). Without spin and F_y the solve of the earlier versions (bem.py),
    otherwise rolling3d's (the solution then carries F_x, F_y, M_z)."""
    if phi != 0.0 or fy is not None:
        try:
            if fx is not None:
                return rolling3d.solve_force(grid, p, law, speed, fx, "xi", eta=eta, phi=phi)
            if fy is not None:
                return rolling3d.solve_force(grid, p, law, speed, fy, "eta", xi=creep, phi=phi)
        except ValueError as e:
            raise InputError("%s: %s" % ("--fy" if fy is not None else "--Fx", e))
        return rolling3d.solve_spin(grid, p, law, speed, xi=creep, eta=eta, phi=phi)
    if fx is not None:
        try:
            return bem.solve_rolling_force(grid, p, fx, law, speed, eta=eta)
        except ValueError as e:
            raise InputError(str(e))
    c = [creep, eta] if grid.nc == 2 else [creep]
    sol = bem.solve_rolling(grid, p, c, law, speed)
    sol["xi"] = creep
    return sol


def fields(grid, p, sol, speed):
    """Per-element columns (3-D: arrays of grid shape)."""
    q, W = sol["q"], sol["W"]
    s = speed * W
    state = np.where(~sol["contact"], "out", np.where(sol["stick"], "stick", "slip"))
    qy = q[1] if grid.nc == 2 else np.zeros_like(p)
    sy = s[1] if grid.nc == 2 else np.zeros_like(p)
    smag = np.hypot(s[0], sy)
    return dict(p=p, q_x=q[0], q_y=qy, s_x=s[0], s_y=sy, s=smag, f=sol["f"],
                state=state)


def write_csv(path, header, rows):
    with atomic_file.replacing(path) as tmp, open(tmp, "w") as out:
        out.write(",".join(header) + "\n")
        for r in rows:
            out.write(",".join(v if isinstance(v, str) else "%.9g" % v for v in r) + "\n")
