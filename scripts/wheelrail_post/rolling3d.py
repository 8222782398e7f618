"""Steady rolling with lateral creepage and spin on the half-space (Kalker).

The rigid slip of the wheel surface over the rail surface per unit rolling
speed V, at the point (x, y) of the contact plane (origin: the patch's
reference point, x the rolling direction with the leading edge at x > 0,
y lateral, z = x cross y the normal pointing from the rail into the wheel):

    w_x = xi - phi y,        w_y = eta + phi x

xi = (v_x - omega r) / V and eta = v_y / V the longitudinal and lateral
creepages (the wheel's rigid velocity relative to the rail at the reference
point, over V; xi as bem.py and wheelrail's statistics), phi = Omega_z / V
[1/m] the spin creepage, Omega_z the wheel's angular velocity relative to
the rail about the normal (the rotation moves the point (x, y) at
(-Omega_z y, Omega_z x)). This is Kalker's convention (Kalker 1990,
Three-dimensional elastic bodies in rolling contact) as CONTACT computes it
(github eve70a/CONTACT, src/m_sdis.f90, set_tang_rhs: the rigid slip of
body 1 with respect to body 2 is (cksi - cphi y, ceta + cphi x)), and
SPEC 10's (phi = Omega . n / V). The slip velocity is
s = V (w - du/dx) as in bem.py; q, F are what the rail exerts on the wheel.

Kalker's linear theory in these conventions (small creepages, no slip):

    F_x = -G c^2 C11 xi
    F_y = -G c^2 (C22 eta + c C23 phi)
    M_z = -G c^3 (-C23 eta + c C33 phi),      c = sqrt(a b)

with C11, C22, C23, C33 > 0 (kalker_table.py); M_z = sum (x q_y - y q_x) dA
is the spin moment about the reference point. The checks confirm these
signs (halfspace_checks_rolling.py).

Without spin the rigid slip is uniform and is passed to bem.solve_rolling
as the two constants of today's runs (identical results); with spin it is
the field above.
"""
import math

import numpy as np

from . import bem


def mesh(grid):
    """Element centres X, Y (grid shape)."""
    return np.meshgrid(grid.x, grid.y, indexing="ij")


def rigid_slip(grid, xi, eta=0.0, phi=0.0):
    """Kalker's rigid slip w = (xi - phi y, eta + phi x), shape (2,) + grid."""
    X, Y = mesh(grid)
    return np.stack([xi - phi * Y, eta + phi * X])


def creep_totals(grid, q):
    """F_x, F_y [N] and the spin moment M_z = sum (x q_y - y q_x) dA [N m]."""
    X, Y = mesh(grid)
    fx, fy = q.reshape(2, -1).sum(axis=1) * grid.dA
    return fx, fy, float((X * q[1] - Y * q[0]).sum() * grid.dA)


def solve_spin(grid, p, law, speed, xi=0.0, eta=0.0, phi=0.0, start=None):
    """Steady rolling at the creepages (xi, eta, phi): bem.solve_rolling's
    solution with xi, eta, phi, F_x, F_y, M_z added."""
    creep = rigid_slip(grid, xi, eta, phi) if phi != 0.0 else [xi, eta]
    sol = bem.solve_rolling(grid, p, creep, law, speed, start=start)
    fx, fy, mz = creep_totals(grid, sol["q"])
    sol.update(xi=xi, eta=eta, phi=phi, F_x=fx, F_y=fy, M_z=mz)
    return sol


def _illinois(g, lo, g_lo, hi, g_hi, rtol, scale, maxit):
    """Root of g between lo and hi (g_lo < 0 < g_hi, or the reverse) by the
    Illinois variant of regula falsi; returns the root and its g's result."""
    side = 0
    for it in range(maxit):
        c = (lo * g_hi - hi * g_lo) / (g_hi - g_lo)
        val, sol = g(c)
        if abs(val) <= rtol * scale:
            return c, sol, it + 1
        if abs(hi - lo) < 1e-14 * max(abs(hi), abs(lo)):
            raise bem.ConvergenceError("the force jumps across the target at creepage %g" % c)
        if (val > 0) == (g_hi > 0):
            hi, g_hi = c, val
            if side == 1:
                g_lo *= 0.5
            side = 1
        else:
            lo, g_lo = c, val
            if side == -1:
                g_hi *= 0.5
            side = -1
    raise bem.ConvergenceError("creepage for the given force: not converged in %d iterations"
                               % maxit)


def solve_force(grid, p, law, speed, target, component="eta", xi=0.0, eta=0.0, phi=0.0,
                rtol=1e-8, maxit=100):
    """The creepage `component` ("xi" or "eta") for which F_x or F_y [N]
    equals target, the other creepages fixed (F_x falls with xi, F_y with
    eta): a bracket grown from the given value by steps 1e-4, 2e-4, ... in
    the direction that moves the force towards the target, then Illinois.
    Each trial starts from the previous trial's solution."""
    load = p.sum() * grid.dA
    if abs(target) >= law.f_static * load:
        raise ValueError("|F| = %g N must be below f_S F_N = %g N"
                         % (abs(target), law.f_static * load))
    k = {"xi": 0, "eta": 1}[component]
    creep = dict(xi=xi, eta=eta, phi=phi)
    last = {}

    def g(c):
        creep[component] = c
        sol = solve_spin(grid, p, law, speed, start=last.get("start"), **creep)
        last["start"] = (sol["q"], sol["stick"], sol["f"])
        return (sol["F_x"], sol["F_y"])[k] - target, sol

    c0 = creep[component]
    g0, sol = g(c0)
    if abs(g0) <= rtol * abs(target or load):
        sol["outer_iterations"] = 1
        return sol
    direction = 1.0 if g0 > 0 else -1.0  # the force falls with its creepage
    step, lo, g_lo = 1e-4, c0, g0
    while True:
        hi = c0 + direction * step
        g_hi, sol = g(hi)
        if (g_hi > 0) != (g0 > 0):
            break
        lo, g_lo, step = hi, g_hi, 2.0 * step
        if step > 2.0:
            raise ValueError("F = %g N not reached for creepage changes up to 1 (the largest "
                             "force with these creepages and this law is lower)" % target)
    c, sol, its = _illinois(g, lo, g_lo, hi, g_hi, rtol, abs(target) or load, maxit)
    sol["outer_iterations"] = its
    return sol


def full_slip_grid(grid, p, f, xi=0.0, eta=0.0, phi=0.0):
    """The rigid full-slip limit on the grid: q = -f p w / |w| (the elastic
    slip neglected against the rigid slip); returns F_x, F_y, M_z."""
    w = rigid_slip(grid, xi, eta, phi)
    wn = np.linalg.norm(w, axis=0)
    q = np.where(wn > 0, -f * p * w / np.where(wn > 0, wn, 1.0), 0.0)
    return creep_totals(grid, q)


def full_slip_ellipse(a, b, load, f, xi=0.0, eta=0.0, phi=0.0, n=200):
    """The same limit for the Hertz pressure p0 sqrt(1 - (x/a)^2 - (y/b)^2)
    on the ellipse, by the midpoint rule in x = a sin(u) cos t,
    y = b sin(u) sin t, u in (0, pi/2) (n x 4n points; p dA becomes
    p0 a b sin u cos^2 u du dt, smooth at the edge): F_x, F_y, M_z. For pure spin F_y = 0 (the slip
    direction field is odd in x) and M_z = -sign(phi) f int p rho dA,
    rho = sqrt(x^2 + y^2); on a circle of radius a that is
    -sign(phi) (3 pi / 16) f F_N a."""
    u = (np.arange(n) + 0.5) * (0.5 * math.pi / n)
    t = (np.arange(4 * n) + 0.5) * (2.0 * math.pi / (4 * n))
    U, T = np.meshgrid(u, t, indexing="ij")
    X, Y = a * np.sin(U) * np.cos(T), b * np.sin(U) * np.sin(T)
    p0 = 3.0 * load / (2.0 * math.pi * a * b)
    p_dA = p0 * a * b * np.sin(U) * np.cos(U) ** 2 * (0.5 * math.pi / n) * (2.0 * math.pi / (4 * n))
    wx, wy = xi - phi * Y, eta + phi * X
    wn = np.hypot(wx, wy)
    wn = np.where(wn > 0, wn, np.inf)
    g = f * p_dA / wn
    qx, qy = -g * wx, -g * wy
    return float(qx.sum()), float(qy.sum()), float((X * qy - Y * qx).sum())
