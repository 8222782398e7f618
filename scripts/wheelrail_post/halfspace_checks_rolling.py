"""Verification checks of lateral creepage, spin and the non-Hertzian normal
problem (scripts/halfspace.py --check NAME): c22, c23, spin_fullslip,
symmetry, gap. Each prints its figures and returns whether it passed; the
conventions are rolling3d.py's, the coefficients kalker_table.py's.
"""
import math

import numpy as np

from . import bem, gap, kalker_table, rolling3d
from .halfspace import SPEC, elliptic_case, moduli, semi_axes
from .halfspace_checks import report


def _case(n):
    """The SPEC 8 Hertz case on n x (n + 1) elements over 1.1 (a, b)."""
    grid, p, *_ = elliptic_case(n, n + 1, 1.1, SPEC["load"], SPEC["rx"], SPEC["ry"],
                                SPEC["E"], SPEC["nu"])
    return grid, p


def _hertz():
    e_star, g_mod = moduli(SPEC["E"], SPEC["nu"])
    return bem.hertz_elliptic(SPEC["load"], SPEC["rx"], SPEC["ry"], e_star), g_mod


def _table():
    hz, _ = _hertz()
    lin = kalker_table.interpolate(hz["a"] / hz["b"], SPEC["nu"])
    ref = kalker_table.interpolate_contact(hz["a"] / hz["b"], SPEC["nu"])
    print("  Kalker (1990, Table E.3, as CONTACT's linrol), b/a %.4f, nu 0.3: C11 %.3f, C22 %.3f, "
          "C23 %.3f (CONTACT's interpolation in nu; linear between 0.25 and 0.5: %.3f, %.3f, %.3f)"
          % (hz["b"] / hz["a"], ref["C11"], ref["C22"], ref["C23"], lin["C11"], lin["C22"],
             lin["C23"]))
    return ref


def _coefficients(n):
    """C22, C23 (from F_y and from M_z), C33 with c_d^2 = A_d / pi, and
    |F_x| / |F_y| at eta = 1e-5 and at c_d phi = 1e-5 (no slip)."""
    _, g_mod = _hertz()
    grid, p = _case(n)
    c2 = (p > 0).sum() * grid.dA / math.pi
    c = math.sqrt(c2)
    law = bem.Coulomb(0.5)
    lat = rolling3d.solve_spin(grid, p, law, SPEC["speed"], eta=1e-5)
    phi = 1e-5 / c
    spin = rolling3d.solve_spin(grid, p, law, SPEC["speed"], phi=phi)
    slips = int((lat["contact"] & ~lat["stick"]).sum() + (spin["contact"] & ~spin["stick"]).sum())
    return dict(C22=-lat["F_y"] / (g_mod * c2 * 1e-5),
                C23=-spin["F_y"] / (g_mod * c2 * c * phi),
                C23_M=lat["M_z"] / (g_mod * c ** 3 * 1e-5),
                C33=-spin["M_z"] / (g_mod * c2 * c2 * phi),
                coupling=max(abs(lat["F_x"] / lat["F_y"]), abs(spin["F_x"] / spin["F_y"])),
                slips=slips)


def _coefficient_check(name, limit):
    """The coefficient `name` on 24 x 25 and 48 x 49 against the table."""
    ref = _table()
    rows = {}
    for n in (24, 48):
        rows[n] = k = _coefficients(n)
        print("  grid %2d x %2d (c_d^2 = A_d / pi): C22 %.4f, C23 from F_y %.4f, from M_z %.4f, "
              "C33 %.4f; |F_x / F_y| %.0e; slip elements %d"
              % (n, n + 1, k["C22"], k["C23"], k["C23_M"], k["C33"], k["coupling"], k["slips"]))
    e24, e48 = (abs(rows[n][name] / ref[name] - 1.0) for n in (24, 48))
    ok = report("%s (c_d^2, 48 x 49)" % name, rows[48][name], ref[name], limit)
    ok &= e48 < e24 and rows[48]["slips"] == 0
    print("  error shrinking with the grid (%.1e -> %.1e), no slip: %s"
          % (e24, e48, "ok" if ok else "FAILED"))
    return ok, rows


def check_c22():
    """F_y = -G c^2 C22 eta at eta = 1e-5 against Kalker's C22."""
    print("c22: eta = 1e-5, Coulomb f 0.5, grid over 1.1 a x 1.1 b; C22 = -F_y / (G c_d^2 eta)")
    return _coefficient_check("C22", 0.01)[0]


def check_c23():
    """The spin-lateral coupling at small creepages against Kalker's C23:
    F_y = -G c^3 C23 phi (spin alone) and M_z = G c^3 C23 eta (eta alone)
    agree (reciprocity); F_x stays 0 (no coupling in a patch symmetric about
    y = 0, linear theory); C33 = -M_z / (G c^4 phi) is printed, not checked
    (it is not in the table used)."""
    print("c23: c_d phi = 1e-5 and eta = 1e-5, Coulomb f 0.5, grid over 1.1 a x 1.1 b")
    ok, rows = _coefficient_check("C23", 0.04)
    k = rows[48]
    recip = abs(k["C23_M"] / k["C23"] - 1.0)
    print("  C23 from M_z(eta) against from F_y(phi): rel. difference %.1e (limit 1e-6); "
          "F_x / F_y %.0e (limit 1e-9); C33 %.4f -> %.4f (24 -> 48)"
          % (recip, k["coupling"], rows[24]["C33"], k["C33"]))
    return ok and recip < 1e-6 and k["coupling"] < 1e-9


def check_spin_fullslip():
    """Full slip: with the spin pole off the patch every element slips and
    sum |q| dA = f F_N; F -> the rigid full-slip values as the creepages
    grow. Pure spin: F_y -> 0, M_z -> -f int p rho dA (full_slip_ellipse)."""
    print("spin_fullslip: grid 24 x 25 over 1.1 a x 1.1 b, Coulomb f 0.5")
    hz, _ = _hertz()
    grid, p = _case(24)
    load, f, law = p.sum() * grid.dA, 0.5, bem.Coulomb(0.5)
    ok, gaps = True, []
    for scale in (1.0, 4.0, 16.0):
        cr = dict(xi=-0.05 * scale, eta=0.02 * scale, phi=3.0 * scale)
        sol = rolling3d.solve_spin(grid, p, law, SPEC["speed"], **cr)
        full = rolling3d.full_slip_grid(grid, p, f, **cr)
        q_abs = np.linalg.norm(sol["q"], axis=0).sum() * grid.dA / (f * load)
        gaps.append(max(abs(sol["F_x"] - full[0]), abs(sol["F_y"] - full[1])) / (f * load))
        all_slip = not (sol["stick"] & sol["contact"]).any()
        print("  xi %.2f eta %.2f phi %.0f 1/m: all slip %s, sum |q| dA / (f F_N) - 1 = %.0e, "
              "F_x %.0f N, F_y %.0f N, M_z %.2f N m; rigid full slip %.0f, %.0f N, %.2f N m; "
              "max |F - F_rigid| / (f F_N) %.1e" % (cr["xi"], cr["eta"], cr["phi"], all_slip,
                                                   q_abs - 1, sol["F_x"], sol["F_y"], sol["M_z"],
                                                   full[0], full[1], full[2], gaps[-1]))
        ok &= all_slip and abs(q_abs - 1.0) < 1e-9
    ok &= gaps[2] < gaps[1] < gaps[0] and gaps[2] < 5e-3
    m_full = rolling3d.full_slip_ellipse(hz["a"], hz["b"], load, f, phi=1.0)[2]
    print("  pure spin, full-slip limit on the Hertz ellipse: F_y 0, M_z %.3f N m = -f int p rho dA"
          % m_full)
    fy, mz = [], []
    for phi in (10.0, 100.0, 1000.0):
        sol = rolling3d.solve_spin(grid, p, law, SPEC["speed"], phi=phi)
        fy.append(abs(sol["F_y"]) / (f * load))
        mz.append(abs(sol["M_z"] / m_full - 1.0))
        print("  phi %5.0f 1/m: F_y / (f F_N) %.4f, M_z %.3f N m (rel. to the limit %.1e), "
              "slip-area fraction %.3f" % (phi, sol["F_y"] / (f * load), sol["M_z"], mz[-1],
                                           (sol["contact"] & ~sol["stick"]).sum()
                                           / sol["contact"].sum()))
    ok &= fy[2] < fy[1] < fy[0] and mz[2] < mz[1] < mz[0] and fy[2] < 3e-3 and mz[2] < 2e-3
    print("  differences from the full-slip limits shrinking, below 5e-3 (combined), F_y / (f F_N) "
          "< 3e-3 and M_z within 2e-3 at phi 1000: %s" % ("ok" if ok else "FAILED"))
    return ok


def check_symmetry():
    """Reflection y -> -y of a patch symmetric about y = 0 maps (xi, eta,
    phi) to (xi, -eta, -phi) and (F_x, F_y, M_z) to (F_x, -F_y, -M_z):
    F_y odd in eta, M_z odd in phi, F_x even in both; at partial slip."""
    print("symmetry: grid 24 x 25, Coulomb f 0.5, partial slip")
    grid, p = _case(24)
    law, V = bem.Coulomb(0.5), SPEC["speed"]
    ok = True
    for xi, eta, phi in ((-1e-3, 1e-3, 0.0), (0.0, 0.0, 0.3), (-1e-3, 1e-3, 0.3)):
        a = rolling3d.solve_spin(grid, p, law, V, xi=xi, eta=eta, phi=phi)
        b = rolling3d.solve_spin(grid, p, law, V, xi=xi, eta=-eta, phi=-phi)
        scale = 0.5 * p.sum() * grid.dA
        d = [abs(a["F_x"] - b["F_x"]) / scale, abs(a["F_y"] + b["F_y"]) / scale,
             abs(a["M_z"] + b["M_z"]) / (scale * grid.x.max())]
        slip = (a["contact"] & ~a["stick"]).sum() / a["contact"].sum()
        print("  (xi, eta, phi) = (%g, %g, %g) and (%g, %g, %g): F_x %.1f N, F_y %.1f N, M_z "
              "%.3f N m, slip %.2f; |F_x - F_x'|, |F_y + F_y'| / (f F_N) %.0e %.0e, "
              "|M_z + M_z'| / (f F_N x_max) %.0e" % (xi, eta, phi, xi, -eta, -phi, a["F_x"],
                                                    a["F_y"], a["M_z"], slip, d[0], d[1], d[2]))
        ok &= max(d) < 1e-8 and 0.0 < slip < 1.0
        if xi == 0.0 and eta == 0.0:  # reflection with q -> -q: pure spin maps to itself
            print("  pure spin: F_x / (f F_N) %.0e (0 by symmetry)" % (a["F_x"] / scale))
            ok &= abs(a["F_x"]) < 1e-9 * scale
    base = rolling3d.solve_spin(grid, p, law, V, xi=1e-5)["F_x"]
    spun = rolling3d.solve_spin(grid, p, law, V, xi=1e-5, eta=1e-5, phi=1e-3)["F_x"]
    print("  small creepages (no slip, linear theory: F_x = -G c^2 C11 xi, no coupling to eta, phi "
          "in a symmetric patch): F_x(1e-5, 0, 0) %.4f N, F_x(1e-5, 1e-5, 1e-3) %.4f N"
          % (base, spun))
    ok &= abs(spun / base - 1.0) < 1e-8
    print("  F_y odd in eta, M_z odd in phi, F_x even, F_x unchanged by eta, phi: %s"
          % ("ok" if ok else "FAILED"))
    return ok


def check_gap():
    """The normal problem on a general gap: a Hertzian array on elliptic_case's
    grid gives its p and F_x exactly; the automatic grid reproduces Hertz;
    h = x^2 / (2 R_x) + |y|^3 / k converges with the grid."""
    print("gap: F_N 140.3 kN, E 210 GPa, nu 0.3")
    rx, ry, load = SPEC["rx"], SPEC["ry"], SPEC["load"]
    hz, _ = _hertz()
    grid, p_ref = _case(24)
    X, Y = rolling3d.mesh(grid)
    p, info = gap.solve_gap(grid, X * X / (2 * rx) + Y * Y / (2 * ry), load)
    law, V = bem.Coulomb(0.5), SPEC["speed"]
    fx = [rolling3d.solve_spin(grid, q, law, V, xi=-2e-3)["F_x"] for q in (p_ref, p)]
    same = np.array_equal(p, p_ref) and fx[0] == fx[1]
    print("  Hertzian h as an array on elliptic_case's 24 x 25 grid: p identical %s, F_x at "
          "xi -2e-3 identical %s (%.3f N)" % (np.array_equal(p, p_ref), fx[0] == fx[1], fx[1]))
    ok = same
    hertz = gap.Gap(lambda X, Y: X * X / (2 * rx) + Y * Y / (2 * ry), extent=(-0.03, 0.03) * 2)
    grid, p, info = gap.gap_case(hertz, load, 48, 49, SPEC["E"], SPEC["nu"])
    a, b = semi_axes(grid, p, *rolling3d.mesh(grid))
    print("  Hertzian h, automatic grid 48 x 49 over x %.2f..%.2f mm, y %.2f..%.2f mm:"
          % (grid.x[0] * 1e3, grid.x[-1] * 1e3, grid.y[0] * 1e3, grid.y[-1] * 1e3))
    ok &= report("p0 [MPa]", p.max() * 1e-6, hz["p0"] * 1e-6, 1e-3)
    ok &= report("a [mm] (second moment)", a * 1e3, hz["a"] * 1e3, 1e-3)
    ok &= report("b [mm]", b * 1e3, hz["b"] * 1e3, 1e-3)
    ok &= report("approach [um]", info["approach"] * 1e6, hz["approach"] * 1e6, 1e-3)
    return ok & _check_cubic_gap()


def _check_cubic_gap():
    """h = x^2 / (2 R_x) + |y|^3 / k, k = 3.6e-3 m^2 (|y|^3 / k = y^2 / (2 R_y)
    at |y| = 6 mm): p_max, approach, area on 24 x 25 and 48 x 49."""
    k, rx = 3.6e-3, SPEC["rx"]
    cubic = gap.Gap(lambda X, Y: X * X / (2 * rx) + np.abs(Y) ** 3 / k, extent=(-0.03, 0.03) * 2)
    rows = []
    for n in (24, 48):
        grid, p, info = gap.gap_case(cubic, SPEC["load"], n, n + 1, SPEC["E"], SPEC["nu"])
        rows.append((p.max(), info["approach"], (p > 0).sum() * grid.dA))
        print("  h = x^2 / (2 R_x) + |y|^3 / k, grid %d x %d over %.2f x %.2f mm: p_max %.2f MPa, "
              "approach %.3f um, area %.2f mm^2, gap residual %.0e"
              % (n, n + 1, (grid.x[-1] - grid.x[0] + grid.dx) * 1e3,
                 (grid.y[-1] - grid.y[0] + grid.dy) * 1e3, rows[-1][0] * 1e-6,
                 rows[-1][1] * 1e6, rows[-1][2] * 1e6, info["gap_residual"]))
    d = [abs(rows[1][i] / rows[0][i] - 1.0) for i in range(3)]
    ok = d[0] < 5e-3 and d[1] < 1e-3 and d[2] < 2e-2
    print("  change 24 -> 48: p_max %.1e (limit 5e-3), approach %.1e (1e-3), area %.1e (2e-2): %s"
          % (d[0], d[1], d[2], "ok" if ok else "FAILED"))
    return ok


CHECKS = dict(c22=check_c22, c23=check_c23, spin_fullslip=check_spin_fullslip,
              symmetry=check_symmetry, gap=check_gap)
