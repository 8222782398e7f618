"""Verification checks of the half-space reference (scripts/halfspace.py --check
NAME): hertz, carter, c11, fullslip, exponential, memory. Each prints its
figures against the reference and returns whether it passed.
"""
import math

import numpy as np

from . import bem
from .halfspace import SPEC, elliptic_case, line_case, moduli, semi_axes


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
