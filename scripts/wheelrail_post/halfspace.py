#!/usr/bin/python3
"""Half-space reference of the wheel-rail contact patch (Kalker's exact theory).

Solves the Hertzian wheel-rail case of SPEC 8 on a grid of rectangles (the
numerics are in scripts/wheelrail_post/bem.py): the normal problem at a given load,
then steady rolling at a given longitudinal creepage or longitudinal force,
with Coulomb friction or the exponential law of SPEC 4, and writes

  DIR/fields.csv      one row per element: x, y [m], p, q_x, q_y [Pa], slip
                      velocity s_x, s_y, |s| [m/s], f, state (stick, slip, out)
  DIR/centreline.csv  the same along y = 0 (the middle row), for overlays
  DIR/totals.csv      quantity, value, unit: F_N, F_x, F_y, xi, eta, slip-area
                      fraction, p0, a, b, contact area, approach, the Hertz
                      values, iteration counts and residuals

Signs: x is the rolling direction (the wheel moves towards +x, the leading edge
is at x > 0), xi = (v_axle - omega r) / V (wheelrail's creepage); q, F_x, F_y
are the traction and force the rail exerts on the wheel (wheelrail's F_L; a
driving wheel has F_x > 0 and xi < 0); s is the velocity of the wheel surface
relative to the rail surface, s = V (xi - du_x/dx) in x.

--check NAME runs a verification (fixed settings, independent of the other
options) and exits with status 1 if it fails: hertz, carter, c11, fullslip,
exponential, memory (the relaxing friction state) or all. See doc/manual/halfspace.md.
"""
import argparse
import math
import os
import sys
import time

import numpy as np

from . import atomic_file
from . import bem

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


def rolling(grid, p, law, speed, creep=None, fx=None, eta=0.0):
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
        grid, p, normal, hz, X, Y, _ = elliptic_case(args.nx, args.ny, args.margin, args.load,
                                                     args.rx, args.ry, args.E, args.nu)
        a_p, b_p = semi_axes(grid, p, X, Y)
    sol = rolling(grid, p, law, args.speed, creep=args.creepage, fx=args.fx, eta=args.eta)
    fl = fields(grid, p, sol, args.speed)
    F = sol["q"].reshape(grid.nc, -1).sum(axis=1) * grid.dA
    contact = sol["contact"]
    n_c = int(contact.sum())
    unit_f = "N/m" if args.line else "N"
    totals = [
        ("F_N", p.sum() * grid.dA, unit_f), ("F_x", F[0], unit_f),
        ("F_y", F[1] if grid.nc == 2 else 0.0, unit_f),
        ("F_x/F_N", F[0] / (p.sum() * grid.dA), "-"),
        ("xi", sol["xi"], "-"), ("eta", args.eta if grid.nc == 2 else 0.0, "-"),
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


# ----------------------------------------------------------------------------
# Verification


def report(name, value, reference, tol, unit=""):
    err = abs(value / reference - 1.0)
    ok = err <= tol
    print("  %-34s %12.6g %-4s reference %12.6g  rel. error %.2e (limit %.0e) %s"
          % (name, value, unit, reference, err, tol, "ok" if ok else "FAILED"))
    return ok


def check_hertz():
    """Normal problem against the exact Hertz solution of SPEC 8, 3 grids."""
    print("hertz: F_N 140.3 kN, R_x 0.46 m, R_y 0.30 m, E 210 GPa, nu 0.3; "
          "grid over 1.15 a x 1.15 b")
    e_star, _ = moduli(SPEC["E"], SPEC["nu"])
    hz = bem.hertz_elliptic(SPEC["load"], SPEC["rx"], SPEC["ry"], e_star)
    ok = report("Hertz a [mm] (SPEC 8)", hz["a"] * 1e3, 8.017, 1e-4)
    ok &= report("Hertz b [mm]", hz["b"] * 1e3, 6.031, 1e-4)
    ok &= report("Hertz p0 [MPa]", hz["p0"] * 1e-6, 1385., 1e-3)
    ok &= report("Hertz approach [um]", hz["approach"] * 1e6, 130.5, 1e-3)
    errors = []
    for n in (16, 32, 64):
        grid, p, info, _, X, Y, _ = elliptic_case(n + 1, n + 1, 1.15, SPEC["load"], SPEC["rx"],
                                                  SPEC["ry"], SPEC["E"], SPEC["nu"])
        a, b = semi_axes(grid, p, X, Y)
        e = [abs(p.max() / hz["p0"] - 1), abs(a / hz["a"] - 1), abs(b / hz["b"] - 1),
             abs(info["approach"] / hz["approach"] - 1)]
        errors.append(e)
        print("  grid %3d x %3d: p0 %.2f MPa, a %.4f mm, b %.4f mm, approach %.3f um; rel. errors "
              "p0 %.1e a %.1e b %.1e approach %.1e; %d CG iterations, gap residual %.0e"
              % (n + 1, n + 1, p.max() * 1e-6, a * 1e3, b * 1e3, info["approach"] * 1e6,
                 e[0], e[1], e[2], e[3], info["iterations"], info["gap_residual"]))
        ok &= info["gap_residual"] < 1e-9
    ok &= max(errors[-1]) < 5e-4
    ok &= errors[2][0] < errors[1][0] < errors[0][0] and errors[2][3] < errors[1][3] < errors[0][3]
    print("  finest grid errors below 5e-4 and p0, approach errors shrinking: %s"
          % ("ok" if ok else "FAILED"))
    return ok


def check_carter():
    """2-D strip: Carter's traction and adhesion length at F_x = 0.6 f F_N."""
    print("carter: 2-D strip, R 0.46 m, Hertz line pressure p0 1385 MPa, f 0.5, "
          "F_x = 0.6 f F_N; 200 elements over 2.2 a")
    e_star, _ = moduli(SPEC["E"], SPEC["nu"])
    f, r, ratio = 0.5, SPEC["rx"], 0.6
    load = math.pi * r * 1385e6 ** 2 / e_star
    grid, p, a, p0 = line_case(200, 1.1, load, r, SPEC["E"], SPEC["nu"])
    sol = bem.solve_rolling_force(grid, p, ratio * f * p.sum() * grid.dA, bem.Coulomb(f),
                                  SPEC["speed"])
    a_stick = sol["stick"].sum() * grid.dx / 2.0
    a_c = math.sqrt(1.0 - ratio) * a
    d = a - a_c
    q_c = f * p - f * p0 * (a_c / a) * np.sqrt(np.clip(1 - ((grid.x - d) / a_c) ** 2, 0, None))
    q_err = np.abs(sol["q"][0] - q_c).max() / (f * p0)
    lead = grid.x[sol["stick"]].max() + grid.dx / 2
    ok = report("adhesion length a'/a", a_stick / a, math.sqrt(1.0 - ratio), 0.01)
    ok &= report("creepage xi = -f (a - a') / R", sol["xi"], -f * d / r, 0.01)
    print("  adhesion zone ends at the leading edge: x_max %.4f a; largest |q - q_Carter| "
          "%.2e f p0 (limit 2e-2)" % (lead / a, q_err))
    ok &= abs(lead / a - 1.0) < 0.02 and q_err < 2e-2
    return ok


def check_c11():
    """Small-creepage slope F_x / (G c^2 xi) against Kalker's C11.

    The staircase contact area A_d of a grid differs from pi a b by up to a
    few per cent and F_x scales with it, so C11 is shown both with the Hertz
    c^2 = a b and with c_d^2 = A_d / pi; the check is on the latter."""
    print("c11: xi = 1e-5, Coulomb f 0.5, grid over 1.1 a x 1.1 b; C11 = -F_x / (G c^2 xi)")
    e_star, g_mod = moduli(SPEC["E"], SPEC["nu"])
    hz = bem.hertz_elliptic(SPEC["load"], SPEC["rx"], SPEC["ry"], e_star)
    errors, ok = [], True
    for n in (24, 48):
        grid, p, *_ = elliptic_case(n, n + 1, 1.1, SPEC["load"], SPEC["rx"], SPEC["ry"],
                                    SPEC["E"], SPEC["nu"])
        sol = bem.solve_rolling(grid, p, [1e-5, 0.0], bem.Coulomb(0.5), SPEC["speed"])
        fx = sol["q"][0].sum() * grid.dA
        area = sol["contact"].sum() * grid.dA
        c11_hertz = -fx / (g_mod * hz["a"] * hz["b"] * 1e-5)
        c11 = -fx / (g_mod * area / math.pi * 1e-5)
        print("  grid %3d x %3d: A_d / (pi a b) %.4f, C11 with c^2 = a b %.4f, with c_d^2 %.4f; "
              "slip elements %d of %d" % (n, n + 1, area / hz["area"], c11_hertz, c11,
                                          (sol["contact"] & ~sol["stick"]).sum(),
                                          sol["contact"].sum()))
        errors.append(abs(c11 / 4.62 - 1.0))
    ok &= report("C11 (c_d^2, 48 x 49; Kalker b/a 0.752)", c11, 4.62, 0.01)
    ok &= report("C11 (c^2 = a b, 48 x 49)", c11_hertz, 4.62, 0.03)
    ok &= errors[1] < errors[0]
    print("  error shrinking with the grid: %s" % ("ok" if errors[1] < errors[0] else "FAILED"))
    return ok


def check_fullslip():
    """Large creepage: F_x -> f F_N (Coulomb), -> f(V |xi|) F_N (exponential)."""
    print("fullslip: grid 24 x 25 over 1.1 a x 1.1 b, V 38.89 m/s, driving (xi < 0)")
    grid, p, *_ = elliptic_case(24, 25, 1.1, SPEC["load"], SPEC["rx"], SPEC["ry"],
                                SPEC["E"], SPEC["nu"])
    load = p.sum() * grid.dA
    sol = bem.solve_rolling(grid, p, [-0.05, 0.0], bem.Coulomb(0.5), SPEC["speed"])
    F = sol["q"].reshape(2, -1).sum(axis=1) * grid.dA
    slip = (sol["contact"] & ~sol["stick"]).sum() / sol["contact"].sum()
    print("  Coulomb f 0.5, xi -0.05: slip-area fraction %.3f, F_y/F_N %.1e" % (slip, F[1] / load))
    q_abs = np.linalg.norm(sol["q"], axis=0).sum() * grid.dA
    ok = report("Coulomb sum |q| dA / (f F_N)", q_abs / (0.5 * load), 1.0, 1e-9)
    ok &= report("Coulomb F_x / (f F_N)", F[0] / (0.5 * load), 1.0, 1e-4) and slip == 1.0
    law = bem.Exponential(SPEC["f_s"], SPEC["f_d"], SPEC["k"])
    gaps = []
    for xi in (-0.01, -0.02, -0.05, -0.1):
        sol = bem.solve_rolling(grid, p, [xi, 0.0], law, SPEC["speed"])
        ratio = sol["q"][0].sum() * grid.dA / load
        f_rigid = float(law(np.array(SPEC["speed"] * abs(xi))))
        gaps.append(abs(ratio / f_rigid - 1.0))
        print("  exponential xi %6.3f: F_x/F_N %.5f, f(V|xi|) %.5f, rel. difference %.1e, "
              "%d fixed-point iterations, residual %.0e"
              % (xi, ratio, f_rigid, gaps[-1], sol["iterations"], sol["f_residual"]))
    ok_exp = gaps[-1] < 1e-4 and all(g1 < g0 for g0, g1 in zip(gaps, gaps[1:]))
    print("  exponential: difference shrinking with |xi|, below 1e-4 at xi -0.1: %s"
          % ("ok" if ok_exp else "FAILED"))
    return ok and ok_exp


def check_exponential():
    """The exponential law converges; F_x/F_N at a few creepages for the record."""
    print("exponential: f = 0.32 + 0.18 exp(-6 |s|), V 38.89 m/s, grid 16 x 17 over "
          "1.1 a x 1.1 b, relaxation 0.7")
    grid, p, *_ = elliptic_case(16, 17, 1.1, SPEC["load"], SPEC["rx"], SPEC["ry"],
                                SPEC["E"], SPEC["nu"])
    load = p.sum() * grid.dA
    law = bem.Exponential(SPEC["f_s"], SPEC["f_d"], SPEC["k"])
    ok = True
    for xi in (-0.001, -0.003, -0.006):
        sol = bem.solve_rolling(grid, p, [xi, 0.0], law, SPEC["speed"])
        c = sol["contact"]
        slipping = c & ~sol["stick"]
        s = SPEC["speed"] * np.linalg.norm(sol["W"], axis=0)
        q = np.linalg.norm(sol["q"], axis=0)
        law_err = np.abs(q - law(s) * p)[slipping].max() / p.max() if slipping.any() else 0.0
        print("  xi %7.4f: F_x/F_N %.5f, slip-area fraction %.3f, mean slip velocity in slip "
              "%.3f m/s, %d iterations, residual max|f_new - f| %.1e, max| |q| - f(s) p | / p0 %.1e"
              % (xi, sol["q"][0].sum() * grid.dA / load, slipping.sum() / c.sum(),
                 s[slipping].mean() if slipping.any() else 0.0, sol["iterations"],
                 sol["f_residual"], law_err))
        ok &= sol["f_residual"] < 1e-9 and law_err < 1e-8
    print("  converged, |q| = f(s) p in the slip zone: %s" % ("ok" if ok else "FAILED"))
    return ok


def check_memory():
    """The relaxing state: its limits and its transport equation."""
    print("memory: the exponential law with a state relaxing over the slip distance L, xi -0.003, "
          "grid 16 x 17")
    grid, p, *_ = elliptic_case(16, 17, 1.1, SPEC["load"], SPEC["rx"], SPEC["ry"],
                                SPEC["E"], SPEC["nu"])
    load = p.sum() * grid.dA
    V, creep = SPEC["speed"], [-0.003, 0.0]
    law = bem.Exponential(SPEC["f_s"], SPEC["f_d"], SPEC["k"])

    def ratio(sol):
        return sol["q"][0].sum() * grid.dA / load

    plain = ratio(bem.solve_rolling(grid, p, creep, law, V))
    static = ratio(bem.solve_rolling(grid, p, creep, bem.Coulomb(SPEC["f_s"]), V))
    ok = True
    # L far below the slip distance over an element (s dx / V, 1e-7 to 1e-5 m in the
    # slip zone): the law itself, to O(L)
    short = ratio(bem.solve_rolling(grid, p, creep, bem.RelaxingState(law, 1e-7, 0.0), V))
    # L far beyond the patch's slip distance: theta stays at f(0) = f_S, Coulomb f_S
    long_ = ratio(bem.solve_rolling(grid, p, creep, bem.RelaxingState(law, 1e3, 0.0), V))
    print("  F_x/F_N: L 1e-7 m %.5f, the law %.5f; L 1e3 m %.7f, Coulomb f_S %.7f"
          % (short, plain, long_, static))
    ok &= abs(short - plain) < 1e-4 and abs(long_ - static) < 1e-7
    previous = plain
    for length in (5e-6, 1e-5, 2e-5):
        rl = bem.RelaxingState(law, length, 0.0)
        sol = bem.solve_rolling(grid, p, creep, rl, V)
        c = sol["contact"]
        slipping = c & ~sol["stick"]
        s = V * np.linalg.norm(sol["W"], axis=0)
        q = np.linalg.norm(sol["q"], axis=0)
        # |q| = theta p in slip, theta the state transported for the solution's own s
        bound_err = np.abs(q - rl.along(s, c, grid.dx, V) * p)[slipping].max() / p.max()
        r = ratio(sol)
        print("  L %.0e m: F_x/F_N %.5f, slip-area fraction %.3f, max||q| - theta(s) p| / p0 %.1e, "
              "%d iterations, residual max|f_new - f| %.1e"
              % (length, r, slipping.sum() / c.sum(), bound_err, sol["iterations"], sol["f_residual"]))
        ok &= bound_err < 1e-8 and sol["f_residual"] < 1e-9 and r > previous
        previous = r
    print("  limits of L, |q| = theta p, F_x growing with L: %s" % ("ok" if ok else "FAILED"))
    return ok


CHECKS = dict(hertz=check_hertz, carter=check_carter, c11=check_c11, fullslip=check_fullslip,
              exponential=check_exponential, memory=check_memory)


# ----------------------------------------------------------------------------
# Command line


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

