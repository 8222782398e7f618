"""Half-space reference of the wheel-rail contact patch (Kalker's exact theory).

Solves the Hertzian wheel-rail case of SPEC 8, or a non-Hertzian one from a
gap file (--gap), on a grid of rectangles (the numerics are in
scripts/wheelrail_post/bem.py, rolling3d.py, gap.py): the normal problem at a
given load, then steady rolling at given creepages xi, eta, phi or at a given
longitudinal force (--Fx) or lateral force (--fy, over F_N), with Coulomb
friction or the exponential law of SPEC 4, and writes

  DIR/fields.csv      one row per element: x, y [m], p, q_x, q_y [Pa], slip
                      velocity s_x, s_y, |s| [m/s], f, state (stick, slip, out)
  DIR/centreline.csv  the same along the middle row of elements (y = 0 in the
                      Hertzian case), for overlays
  DIR/totals.csv      quantity, value, unit: F_N, F_x, F_y, xi, eta, slip-area
                      fraction, p0, a, b, contact area, approach, the Hertz
                      values, iteration counts and residuals; with --phi, --fy
                      or --gap also phi, F_y/F_N and the spin moment M_z

Signs: x is the rolling direction (the wheel moves towards +x, the leading edge
is at x > 0), y lateral, z = x cross y the normal into the wheel;
xi = (v_axle - omega r) / V (wheelrail's creepage), eta = v_y / V,
phi = Omega_z / V [1/m] (Kalker's: rigid slip (xi - phi y, eta + phi x));
q, F_x, F_y are the traction and force the rail exerts on the wheel
(wheelrail's F_L; a driving wheel has F_x > 0 and xi < 0), M_z =
sum (x q_y - y q_x) dA about the origin; s is the velocity of the wheel surface
relative to the rail surface, s = V (w - du/dx).

--gap FILE: h [m] on a grid, an .npz with keys x, s, h (h[i, j] at x[i] along
the rolling direction and s[j] lateral, m; what profiles.py writes) or a CSV
with the columns x, s, h, one row per grid point; --nx, --ny, --margin set
the grid, which is placed over the contact automatically (gap.py).

--check NAME runs a verification (fixed settings, independent of the other
options) and exits with status 1 if it fails: hertz, carter, c11, fullslip,
exponential, memory (the relaxing friction state), c22, c23, spin_fullslip,
symmetry, gap or all. See doc/manual/halfspace.md.
"""
import argparse
import math
import os
import sys
import time

import numpy as np

from . import bem
from .halfspace import (SPEC, InputError, elliptic_case, fields, gap_file_case, line_case,
                        make_law, moduli, rolling, semi_axes, write_csv)
from .halfspace_checks import CHECKS as CHECKS_2D
from .halfspace_checks_rolling import CHECKS as CHECKS_3D
from .rolling3d import creep_totals

CHECKS = dict(CHECKS_2D, **CHECKS_3D)


def run(args):
    law = make_law(args.law, args.f, args.f_s, args.f_d, args.k, args.relaxation_length,
                   args.relaxation_time)
    e_star, g_mod = moduli(args.E, args.nu)
    t0 = time.time()
    if args.line:
        load = args.line_load
        if load is None:
            p0 = bem.hertz_elliptic(args.load, args.rx, args.ry, e_star)["p0"]
            load = math.pi * args.rx * p0 * p0 / e_star
        grid, p, a, p0 = line_case(args.nx, args.margin, load, args.rx, args.E, args.nu)
        X, Y = grid.x, np.zeros_like(grid.x)
        hz = dict(a=a, b=float("nan"), p0=p0, area=2 * a, approach=float("nan"))
        normal = dict(approach=float("nan"), iterations=0, gap_residual=0.0)
        # <x^2>_p = a^2 / 4 for the semi-elliptic line pressure
        a_p, b_p = 2.0 * math.sqrt((p * X * X).sum() / p.sum()), float("nan")
    else:
        case = gap_file_case(args.gap, args.nx, args.ny, args.margin, args.load, args.E,
                             args.nu) if args.gap else \
            elliptic_case(args.nx, args.ny, args.margin, args.load, args.rx, args.ry, args.E,
                          args.nu)
        grid, p, normal, hz, X, Y, _ = case
        # a gap's patch need not be centred: its second moments about the centroid
        xc, yc = ((p * X).sum() / p.sum(), (p * Y).sum() / p.sum()) if args.gap else (0.0, 0.0)
        a_p, b_p = semi_axes(grid, p, X - xc, Y - yc) if args.gap else semi_axes(grid, p, X, Y)
    fy = None if args.fy is None else args.fy * p.sum() * grid.dA
    sol = rolling(grid, p, law, args.speed, creep=args.creepage, fx=args.fx, eta=args.eta,
                  phi=args.phi, fy=fy)
    fl = fields(grid, p, sol, args.speed)
    F = sol["q"].reshape(grid.nc, -1).sum(axis=1) * grid.dA
    contact = sol["contact"]
    n_c = int(contact.sum())
    unit_f = "N/m" if args.line else "N"
    totals = [
        ("F_N", p.sum() * grid.dA, unit_f), ("F_x", F[0], unit_f),
        ("F_y", F[1] if grid.nc == 2 else 0.0, unit_f),
        ("F_x/F_N", F[0] / (p.sum() * grid.dA), "-"),
        ("xi", sol["xi"], "-"), ("eta", sol.get("eta", args.eta) if grid.nc == 2 else 0.0, "-")] + \
        spin_rows(args, grid, sol, p) + [
        ("slip_area_fraction", (contact & ~sol["stick"]).sum() / max(n_c, 1), "-"),
        ("p0", p.max(), "Pa"), ("a", a_p, "m"), ("b", b_p, "m"),
        ("contact_area", n_c * grid.dA, "m" if args.line else "m^2"),
        ("approach", normal["approach"], "m"),
        ("hertz_p0", hz["p0"], "Pa"), ("hertz_a", hz["a"], "m"), ("hertz_b", hz["b"], "m"),
        ("hertz_approach", hz["approach"], "m"),
        ("normal_iterations", normal["iterations"], "-"),
        ("normal_gap_residual", normal["gap_residual"], "-"),
        ("friction_iterations", sol["iterations"], "-"),
        ("friction_residual", sol["f_residual"], "-"),
        ("creepage_iterations", sol.get("outer_iterations", 0), "-")] + [
        ("residual_" + k, v, "-") for k, v in sorted(bem.rolling_residuals(sol, p).items())] + [
        ("elements_x", grid.shape[0], "-"),
        ("elements_y", grid.shape[1] if grid.nc == 2 else 1, "-"),
        ("wall_time", time.time() - t0, "s")]
    names = ["p", "q_x", "q_y", "s_x", "s_y", "s", "f", "state"]
    header = ["x", "y"] + names
    XX = X if grid.nc == 2 else X[:, None]
    YY = Y if grid.nc == 2 else Y[:, None]
    cols = {k: (v if grid.nc == 2 else v[:, None]) for k, v in fl.items()}
    rows = [[XX[i, j], YY[i, j]] + [cols[k][i, j] for k in names]
            for i in range(XX.shape[0]) for j in range(XX.shape[1])]
    mid = XX.shape[1] // 2
    centre = [[XX[i, mid]] + [cols[k][i, mid] for k in names] for i in range(XX.shape[0])]
    for name, value, unit in totals:
        print("%-22s %14.6g %s" % (name, value, unit))
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        write_csv(os.path.join(args.out, "fields.csv"), header, rows)
        write_csv(os.path.join(args.out, "centreline.csv"), ["x"] + names, centre)
        write_csv(os.path.join(args.out, "totals.csv"), ["quantity", "value", "unit"],
                  [[n, v, u] for n, v, u in totals])
        print("wrote %s/{fields,centreline,totals}.csv" % args.out)
    return 0


def spin_rows(args, grid, sol, p):
    """Rows of totals.csv for spin, a given F_y or a gap file (only then, so
    that the files of the other options stay as they were)."""
    if args.phi == 0.0 and args.fy is None and not args.gap:
        return []
    fx, fy, mz = creep_totals(grid, sol["q"])
    return [("phi", args.phi, "1/m"), ("F_y/F_N", fy / (p.sum() * grid.dA), "-"),
            ("M_z", mz, "N m")]


def parse(argv):
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    g = ap.add_argument_group("grid")
    g.add_argument("--nx", type=int, default=48, help="elements along x (rolling), 4..512 "
                   "[default 48]")
    g.add_argument("--ny", type=int, default=49, help="elements along y, odd (a row on y = 0), "
                   "3..511 [default 49]")
    g.add_argument("--margin", type=float, default=1.1, help="grid half-sides / Hertz semi-axes, "
                   "1.01..5 [default 1.1]")
    g.add_argument("--line", action="store_true", help="2-D plane-strain strip along x (Carter's "
                   "setting): Hertz line pressure, --ny unused")
    g.add_argument("--gap", default=None, help="non-Hertzian case: the undeformed gap h [m] on a "
                   "grid, an .npz with keys x, s, h (h[i, j] at x[i], s[j], m) or a CSV with "
                   "columns x, s, h; the grid is placed over the contact (--Rx, --Ry unused)")
    g = ap.add_argument_group("geometry, load, material")
    g.add_argument("--load", type=float, default=SPEC["load"], help="normal load F_N [N], > 0 "
                   "[default 140.3e3]")
    g.add_argument("--line-load", type=float, default=None, help="--line: load per length [N/m], "
                   "> 0 [default: the one whose Hertz p0 is the elliptic case's p0]")
    g.add_argument("--Rx", dest="rx", type=float, default=SPEC["rx"], help="radius along x, "
                   "wheel rolling radius [m], >= R_y [default 0.46]")
    g.add_argument("--Ry", dest="ry", type=float, default=SPEC["ry"], help="radius along y, rail "
                   "profile [m], > 0 [default 0.30]")
    g.add_argument("--E", type=float, default=SPEC["E"], help="Young's modulus of both bodies "
                   "[Pa], > 0 [default 2.1e11]")
    g.add_argument("--nu", type=float, default=SPEC["nu"], help="Poisson's ratio, 0..0.49 "
                   "[default 0.3]")
    g = ap.add_argument_group("rolling and friction")
    g.add_argument("--creepage", type=float, default=0.0, help="longitudinal creepage xi, "
                   "-1..1 [default 0]")
    g.add_argument("--Fx", dest="fx", type=float, default=None, help="longitudinal force on the "
                   "wheel [N] (--line: N/m) instead of --creepage; |F_x| < f F_N (Coulomb), f_S F_N "
                   "(exponential)")
    g.add_argument("--eta", type=float, default=0.0, help="lateral creepage, -1..1 [default 0]")
    g.add_argument("--phi", type=float, default=0.0, help="spin creepage phi = Omega_z / V "
                   "[1/m], -1e3..1e3; rigid slip (xi - phi y, eta + phi x) [default 0]")
    g.add_argument("--fy", type=float, default=None, help="lateral force on the wheel over F_N "
                   "instead of --eta; |F_y/F_N| < f (Coulomb), f_S (exponential); not with --Fx")
    g.add_argument("--speed", type=float, default=SPEC["speed"], help="rolling speed V [m/s], "
                   "> 0 [default 38.89]")
    g.add_argument("--law", choices=["coulomb", "exponential"], default="coulomb",
                   help="friction law [default coulomb]")
    g.add_argument("--f", type=float, default=SPEC["f"], help="Coulomb coefficient, 0..2 "
                   "[default 0.5]")
    g.add_argument("--fS", dest="f_s", type=float, default=SPEC["f_s"], help="exponential: "
                   "static coefficient, f_D..2 [default 0.5]")
    g.add_argument("--fD", dest="f_d", type=float, default=SPEC["f_d"], help="exponential: "
                   "dynamic coefficient, 0..f_S [default 0.32]")
    g.add_argument("--k", type=float, default=SPEC["k"], help="exponential: decay [s/m], >= 0 "
                   "[default 6]")
    g.add_argument("--relaxation-length", type=float, default=0.0, help="exponential: the local "
                   "coefficient relaxes towards f(s) over this slip distance [m], 0..1 (wheelrail's "
                   "Contact/Friction relaxation length) [default 0: off]")
    g.add_argument("--relaxation-time", type=float, default=0.0, help="exponential: ... and over "
                   "this time [s], 0..1 [default 0: off]")
    g = ap.add_argument_group("output and checks")
    g.add_argument("--out", default=None, help="directory for the CSV files (created)")
    g.add_argument("--check", choices=sorted(CHECKS) + ["all"], default=None,
                   help="run a verification instead of a case; exit status 1 if it fails")
    args = ap.parse_args(argv)
    limits = [("--nx", args.nx, 4, 512), ("--ny", args.ny, 3, 511),
              ("--margin", args.margin, 1.01, 5.0), ("--nu", args.nu, 0.0, 0.49),
              ("--creepage", args.creepage, -1.0, 1.0), ("--eta", args.eta, -1.0, 1.0),
              ("--phi", args.phi, -1e3, 1e3),
              ("--f", args.f, 1e-6, 2.0), ("--fS", args.f_s, 1e-6, 2.0),
              ("--fD", args.f_d, 1e-6, 2.0), ("--k", args.k, 0.0, 1e6),
              ("--relaxation-length", args.relaxation_length, 0.0, 1.0),
              ("--relaxation-time", args.relaxation_time, 0.0, 1.0)]
    for name, value, lo, hi in limits:
        if not lo <= value <= hi or value != value:
            raise InputError("%s = %g is outside [%g, %g]" % (name, value, lo, hi))
    for name, value in (("--load", args.load), ("--Rx", args.rx), ("--Ry", args.ry),
                        ("--E", args.E), ("--speed", args.speed)):
        if not value > 0 or math.isinf(value):
            raise InputError("%s = %g must be positive and finite" % (name, value))
    if args.line_load is not None and not args.line_load > 0:
        raise InputError("--line-load = %g must be positive" % args.line_load)
    if args.ny % 2 == 0:
        raise InputError("--ny = %d must be odd (a row of elements on y = 0)" % args.ny)
    if args.rx < args.ry:
        raise InputError("--Rx = %g must be >= --Ry = %g (the semi-axis a lies along x)"
                         % (args.rx, args.ry))
    if args.f_d > args.f_s:
        raise InputError("--fD = %g must not exceed --fS = %g" % (args.f_d, args.f_s))
    if args.fx is not None and args.creepage != 0.0:
        raise InputError("--Fx and --creepage are exclusive; give one")
    new_3d = [n for n, v in (("--phi", args.phi != 0.0), ("--fy", args.fy is not None),
                             ("--gap", args.gap)) if v]
    if args.line and new_3d:
        raise InputError("%s: not with --line (the strip has no lateral direction)" % new_3d[0])
    if args.fy is not None and (args.fx is not None or args.eta != 0.0):
        raise InputError("--fy excludes --Fx and --eta (one prescribed force; --fy sets eta)")
    if args.fy is not None and not abs(args.fy) < 1.0:
        raise InputError("--fy = %g must lie in (-1, 1) (and below the friction limit)" % args.fy)
    if args.gap and not os.path.isfile(args.gap):
        raise InputError("--gap = %s is not a file" % args.gap)
    if args.out and os.path.exists(args.out) and not os.path.isdir(args.out):
        raise InputError("--out = %s exists and is not a directory" % args.out)
    return args


def main(argv):
    try:
        args = parse(argv)
        if args.check:
            names = sorted(CHECKS) if args.check == "all" else [args.check]
            failed = [n for n in names if not CHECKS[n]()]
            print("checks failed: %s" % ", ".join(failed) if failed else "all checks passed")
            return 1 if failed else 0
        return run(args)
    except InputError as e:
        print("halfspace.py: error: %s" % e, file=sys.stderr)
        return 2
    except bem.ConvergenceError as e:
        print("halfspace.py: error: %s; nothing written" % e, file=sys.stderr)
        return 3
