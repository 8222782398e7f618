"""Kalker's exact theory of steady rolling on a half-space (boundary elements).

The reference for the contact patch of wheelrail (SPEC 4 and 8): two identical
elastic half-spaces (quasi-identity, so the normal and the tangential problems
decouple), a grid of equal rectangles carrying uniform tractions, and

  normal problem      undeformed gap h = x^2/(2 R_x) + y^2/(2 R_y), total load
                      F_N; p >= 0, gap >= 0, p gap = 0 by the constrained
                      conjugate gradients of Polonsky & Keer (1999);
  tangential problem  steady rolling towards +x at speed V; relative slip
                      velocity of the wheel surface over the rail surface
                      s = V (w - du/dx), w = (xi, eta) the rigid creepages,
                      u = u(wheel) - u(rail) the tangential displacement
                      difference, du/dx the upwind difference
                      (u(x + dx) - u(x)) / dx (the material enters at the
                      leading edge x > 0); stick where s = 0 and |q| <= f p,
                      slip where q = -f p s / |s|; Kalker's TANG active-set
                      iteration: GMRES on the stick equations, the slip
                      elements' traction directions from their local
                      problems (the others fixed), sets updated until
                      nothing changes; a slip-velocity dependent f by an
                      under-relaxed fixed point around it.

Signs: xi = (v_axle - omega r) / V as in wheelrail's statistics (the rigid
slip of the wheel over the rail per unit speed); q and F_x are the traction and
the force the rail exerts on the wheel (F_x > 0 drives the wheel, then xi < 0),
the same force as wheelrail's F_L; the rail carries -q.

Influence coefficients (combined for the two bodies, E* = E / (2 (1 - nu^2)),
G = E / (2 (1 + nu))): Love's closed form for the normal displacement from a
uniform pressure on a rectangle, the Cerruti closed forms for the tangential
ones, applied by FFT convolution zero-padded against wrap-around. Line2D runs
the same tangential theory on a 2-D plane-strain strip (dense matrices), the
setting of Carter's closed form.

The command-line tool and the verification checks are scripts/halfspace.py.
Needs Debian's python3-numpy only.
"""
import math

import numpy as np

# ----------------------------------------------------------------------------
# Hertz theory


def elliptic_ke(m):
    """Complete elliptic integrals K(m), E(m), parameter m = k^2 (AGM)."""
    a, b, c = 1.0, math.sqrt(1.0 - m), math.sqrt(m)
    total, power = 0.5 * c * c, 0.5
    while abs(c) > 1e-16:
        a, b, c = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
        power *= 2.0
        total += power * c * c
    k = math.pi / (2.0 * a)
    return k, k * (1.0 - total)


def hertz_elliptic(load, rx, ry, e_star):
    """Hertz ellipse for the gap x^2/(2 rx) + y^2/(2 ry), rx >= ry.

    Returns a (along x), b, p0, mean pressure, area and approach."""
    if rx < ry:
        raise ValueError("hertz_elliptic needs R_x >= R_y (a along x)")
    A, B = 0.5 / rx, 0.5 / ry

    def ratio(m):  # B/A of the ellipse with e^2 = m, b/a = sqrt(1 - m)
        k, e = elliptic_ke(m)
        return (e / (1.0 - m) - k) / (k - e)

    lo, hi = 1e-12, 1.0 - 1e-15
    if B / A <= 1.0 + 1e-12:
        m = 0.0
    else:
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if ratio(mid) < B / A else (lo, mid)
        m = 0.5 * (lo + hi)
    if m == 0.0:
        a = (3.0 * load * rx / (4.0 * e_star)) ** (1.0 / 3.0)
        b, p0 = a, 3.0 * load / (2.0 * math.pi * a * a)
        approach = a * a / rx
    else:
        k, e = elliptic_ke(m)
        a = (3.0 * load * (k - e) / (2.0 * math.pi * A * e_star * m)) ** (1.0 / 3.0)
        b = a * math.sqrt(1.0 - m)
        p0 = 3.0 * load / (2.0 * math.pi * a * b)
        approach = p0 * b * k / e_star
    return dict(a=a, b=b, p0=p0, p_mean=2.0 * p0 / 3.0, area=math.pi * a * b,
                approach=approach)


def hertz_line(load, r, e_star):
    """Hertz 2-D line contact (load per unit length): semi-width a, p0."""
    a = math.sqrt(4.0 * load * r / (math.pi * e_star))
    return a, 2.0 * load / (math.pi * a)


# ----------------------------------------------------------------------------
# Influence coefficients
#
# Corner functions F with d2F/dx dy = kernel, so that the integral over the
# rectangle [x-hx, x+hx] x [y-hy, y+hy] of the point-load kernel is
# F(x+hx, y+hy) - F(x-hx, y+hy) - F(x+hx, y-hy) + F(x-hx, y-hy).
#   x^2/r^3 : y asinh(x/|y|)      y^2/r^3 : x asinh(y/|x|)      xy/r^3 : -r
# (terms of one variable alone, like y ln|y|, cancel in the difference).


def _xlog(x, y):
    """x asinh(y / |x|), 0 at x = 0."""
    ax = np.abs(x)
    with np.errstate(divide="ignore", invalid="ignore"):
        v = x * np.arcsinh(y / np.where(ax > 0, ax, 1.0))
    return np.where(ax > 0, v, 0.0)


def _rect(func, x, y, hx, hy):
    return func(x + hx, y + hy) - func(x - hx, y + hy) - func(x + hx, y - hy) + func(x - hx, y - hy)


def influence_3d(x, y, hx, hy, e_star, g_mod, nu):
    """Combined surface displacements at offsets (x, y) from uniform unit
    tractions on a rectangle of half-sides hx, hy: dict zz, xx, yy, xy."""
    fxx = _rect(lambda a, b: _xlog(b, a), x, y, hx, hy)  # integral of x^2/r^3
    fyy = _rect(_xlog, x, y, hx, hy)                     # integral of y^2/r^3
    fxy = _rect(lambda a, b: -np.hypot(a, b), x, y, hx, hy)
    return dict(zz=(fxx + fyy) / (math.pi * e_star),
                xx=(fxx + (1.0 - nu) * fyy) / (math.pi * g_mod),
                yy=(fyy + (1.0 - nu) * fxx) / (math.pi * g_mod),
                xy=nu * fxy / (math.pi * g_mod))


class Grid3D:
    """nx x ny rectangles centred on the origin, FFT-convolution operators.

    zz(p): normal displacement difference; dudx(q), q of shape (2, nx, ny):
    the upwind x-difference of the tangential displacement difference."""

    nc = 2

    def __init__(self, nx, ny, lx, ly, e_star, g_mod, nu):
        self.shape = (nx, ny)
        self.dx, self.dy = 2.0 * lx / nx, 2.0 * ly / ny
        self.dA = self.dx * self.dy
        self.x = (np.arange(nx) - 0.5 * (nx - 1)) * self.dx
        self.y = (np.arange(ny) - 0.5 * (ny - 1)) * self.dy
        ix = np.arange(2 * nx)
        ix = np.where(ix < nx + 1, ix, ix - 2 * nx)  # offsets -(nx-1) .. nx
        iy = np.arange(2 * ny)
        iy = np.where(iy < ny + 1, iy, iy - 2 * ny)
        ox, oy = np.meshgrid(ix * self.dx, iy * self.dy, indexing="ij")
        hx, hy = 0.5 * self.dx, 0.5 * self.dy
        k0 = influence_3d(ox, oy, hx, hy, e_star, g_mod, nu)
        k1 = influence_3d(ox + self.dx, oy, hx, hy, e_star, g_mod, nu)
        self._zz = np.fft.rfft2(k0["zz"])
        self._d = {c: np.fft.rfft2((k1[c] - k0[c]) / self.dx) for c in ("xx", "yy", "xy")}
        self.diag = np.array([(k1["xx"][0, 0] - k0["xx"][0, 0]) / self.dx,
                              (k1["yy"][0, 0] - k0["yy"][0, 0]) / self.dx])
        self.self_zz = k0["zz"][0, 0]

    def _conv(self, kernel_hat, f_hat):
        nx, ny = self.shape
        return np.fft.irfft2(kernel_hat * f_hat, s=(2 * nx, 2 * ny))[:nx, :ny]

    def _fft(self, f):
        nx, ny = self.shape
        return np.fft.rfft2(f, s=(2 * nx, 2 * ny))

    def zz(self, p):
        return self._conv(self._zz, self._fft(p))

    def dudx(self, q):
        nx, ny = self.shape
        qh = np.fft.rfft2(q, s=(2 * nx, 2 * ny))  # both components in one call
        d = self._d
        uh = np.stack([d["xx"] * qh[0] + d["xy"] * qh[1], d["xy"] * qh[0] + d["yy"] * qh[1]])
        return np.fft.irfft2(uh, s=(2 * nx, 2 * ny))[:, :nx, :ny]


class Line2D:
    """2-D plane-strain strip of n segments on [-lx, lx], dense operators:
    combined u(x) = -(2 / (pi E*)) int q(s) ln|x - s| ds for both directions."""

    nc = 1

    def __init__(self, nx, lx, e_star):
        self.shape = (nx,)
        self.dx = self.dA = 2.0 * lx / nx
        self.x = (np.arange(nx) - 0.5 * (nx - 1)) * self.dx

        def infl(d):
            def prim(t):
                at = np.abs(t)
                return np.where(at > 0, t * np.log(np.where(at > 0, at, 1.0)) - t, 0.0)
            h = 0.5 * self.dx
            return -(2.0 / (math.pi * e_star)) * (prim(d + h) - prim(d - h))

        off = self.x[:, None] - self.x[None, :]
        self.a_zz = infl(off)
        self.d_x = (infl(off + self.dx) - self.a_zz) / self.dx
        self.diag = np.array([self.d_x[0, 0]])

    def zz(self, p):
        return self.a_zz @ p

    def dudx(self, q):
        return (self.d_x @ q[0])[None, :]


# ----------------------------------------------------------------------------
# Solvers


def gmres(matvec, b, x0, precond, tol=1e-11, restart=80, maxiter=4000):
    """Restarted GMRES with right diagonal preconditioning; returns x, its."""
    x = x0.copy()
    bnorm = np.linalg.norm(b) or 1.0
    its = 0
    while its < maxiter:
        r = b - matvec(x)
        beta = np.linalg.norm(r)
        if beta <= tol * bnorm:
            return x, its
        V = np.zeros((restart + 1, b.size))
        H = np.zeros((restart + 1, restart))
        V[0] = r / beta
        cs, sn = np.zeros(restart), np.zeros(restart)
        e1 = np.zeros(restart + 1)
        e1[0] = beta
        for j in range(restart):
            its += 1
            w = matvec(precond * V[j])
            # classical Gram-Schmidt, twice (as orthogonal as modified
            # Gram-Schmidt, in two products with the basis)
            h = V[:j + 1] @ w
            w = w - h @ V[:j + 1]
            h2 = V[:j + 1] @ w
            w = w - h2 @ V[:j + 1]
            H[:j + 1, j] = h + h2
            H[j + 1, j] = np.linalg.norm(w)
            if H[j + 1, j] > 0:
                V[j + 1] = w / H[j + 1, j]
            for i in range(j):
                H[i, j], H[i + 1, j] = (cs[i] * H[i, j] + sn[i] * H[i + 1, j],
                                        -sn[i] * H[i, j] + cs[i] * H[i + 1, j])
            rho = math.hypot(H[j, j], H[j + 1, j])
            cs[j], sn[j] = H[j, j] / rho, H[j + 1, j] / rho
            H[j, j], H[j + 1, j] = rho, 0.0
            e1[j + 1] = -sn[j] * e1[j]
            e1[j] = cs[j] * e1[j]
            if abs(e1[j + 1]) <= tol * bnorm or its >= maxiter:
                break
        y = np.linalg.solve(np.triu(H[:j + 1, :j + 1]), e1[:j + 1])
        x = x + precond * (V[:j + 1].T @ y)
    return x, its


def solve_normal(grid, h, load, tol=1e-12, maxit=5000):
    """Polonsky-Keer constrained CG for p >= 0, gap >= 0 at total load."""
    dA = grid.dA
    p = np.full(h.shape, load / (h.size * dA))
    t = np.zeros_like(p)
    g_old, conj = 1.0, 0.0
    for it in range(1, maxit + 1):
        g = grid.zz(p) + h
        ic = p > 0
        g = g - g[ic].mean()
        g_sum = np.sum(g[ic] ** 2)
        t = np.where(ic, g + conj * (g_sum / g_old) * t, 0.0)
        g_old = g_sum
        r = grid.zz(t)
        r = r - r[ic].mean()
        tau = np.sum(g[ic] * t[ic]) / np.sum(r[ic] * t[ic])
        p_old = p.copy()
        p = np.where(ic, p - tau * t, p)
        p[p < 0] = 0.0
        overlap = (p == 0) & (g < 0)
        conj = 0.0 if overlap.any() else 1.0
        p[overlap] -= tau * g[overlap]
        p *= load / (p.sum() * dA)
        change = dA * np.abs(p - p_old).sum() / load
        if change < tol:
            break
    u = grid.zz(p)
    ic = p > 0
    approach = np.mean(u[ic] + h[ic])
    gap = h + u - approach
    resid = max(np.abs(gap[ic]).max(), max(0.0, -gap[~ic].min()) if (~ic).any() else 0.0)
    return p, dict(approach=approach, iterations=it, change=change,
                   gap_residual=resid / approach)


class Coulomb:
    velocity_dependent = False

    def __init__(self, f):
        self.f_static = f

    def __call__(self, s):
        return np.full_like(s, self.f_static)


class Exponential:
    """f = f_D + (f_S - f_D) exp(-k |s|), |s| the slip velocity [m/s]."""
    velocity_dependent = True

    def __init__(self, f_s, f_d, k):
        self.f_s, self.f_d, self.k = f_s, f_d, k
        self.f_static = f_s

    def __call__(self, s):
        return self.f_d + (self.f_s - self.f_d) * np.exp(-self.k * np.abs(s))


class RelaxingState:
    """A law with a friction state (wheelrail's Friction relaxation length L
    and time tau): the local coefficient theta of a material point follows
    d theta/dt = -(|s| / L + 1 / tau)(theta - f(|s|)), f the underlying law,
    and starts at f(0) where the point comes into contact. In steady rolling
    the points cross the patch at the speed V from the leading edge (x > 0)
    backwards, so theta is integrated along x, exactly over each element for
    the element's own s: the element's value is theta at its centre. L or
    tau zero: that part of the relaxation is off (both zero: the law)."""
    velocity_dependent = True

    def __init__(self, law, length, time):
        if length < 0 or time < 0:
            raise ValueError("relaxation length and time must not be negative")
        self.law, self.length, self.time = law, length, time
        self.f_static = law.f_static

    def __call__(self, s):
        return self.law(s)

    def along(self, s, contact, dx, speed):
        """theta of each element, for the slip velocities s [m/s] (grid
        shape, axis 0 along x), the contact mask and the element length dx."""
        if self.length == 0 and self.time == 0:
            return self.law(s)
        fresh = float(self.law(np.zeros(1))[0])
        theta = np.zeros(s.shape)
        state = np.full(s.shape[1:], fresh)
        for i in reversed(range(s.shape[0])):
            target = self.law(s[i])
            rate = (np.abs(s[i]) / self.length if self.length > 0 else 0.0) \
                + (1.0 / self.time if self.time > 0 else 0.0)
            decay = np.exp(-rate * 0.5 * dx / speed)
            centre = target + (state - target) * decay
            theta[i] = np.where(contact[i], centre, 0.0)
            state = np.where(contact[i], target + (centre - target) * decay, fresh)
        return theta


class ConvergenceError(RuntimeError):
    pass


def local_slip(w_star, a, bound, mask):
    """Slip traction of one element with the others fixed: q = -lam W,
    W = W* + a q, |q| = bound, i.e. q = -W* / (mu + a) with mu = 1/lam > 0
    and |W* / (mu + a)| = bound (Newton on mu, vectorised)."""
    w = np.where(mask, w_star, 0.0)
    g = np.where(mask, bound, 1.0)
    # Newton on psi(mu) = 1 / |W* / (mu + a)| - 1 / g, linear in mu where
    # the components' a are equal and nearly so here, from below (psi is
    # increasing and concave, so the iterates rise monotonically to the
    # root): a few steps to round-off instead of a bisection's 80 (the same
    # q to 6e-16 on random elements)
    wn = np.linalg.norm(w, axis=0)
    solve = mask & (wn > 0)
    mu = np.where(solve, np.maximum(0.0, wn / g - a.max(axis=0)), 0.0)
    for _ in range(50):
        r = w / (mu + a)
        n = np.linalg.norm(r, axis=0)
        n = np.where(solve, n, 1.0)
        psi = 1.0 / n - 1.0 / g
        dpsi = np.where(solve, np.sum(r * r / (mu + a), axis=0) / n ** 3, 1.0)
        step = np.where(solve, -psi / dpsi, 0.0)
        mu = np.maximum(mu + step, 0.0)
        if np.all(np.abs(step) <= 1e-15 * (mu + a.min())):
            break
    return np.where(mask, -w / (mu + a), 0.0)


def tang(grid, bound, creep, q, stick, tol=1e-10, maxit=300, beta=0.5):
    """Kalker's TANG for fixed traction bounds g = f p (> 0 in contact).

    creep: the rigid slip w, nc constants (uniform) or an array (nc,) +
    grid shape (with spin: rolling3d.rigid_slip). Stick set H:
    w - du/dx = 0; slip set S: q = g t, t = -W/|W|.
    Returns q, W (dimensionless slip s/V), stick mask, iterations."""
    nc = grid.nc
    contact = bound > 0
    creep = np.asarray(creep, dtype=float)
    qn = np.linalg.norm(q, axis=0)
    t = np.where(qn > 0, q / np.where(qn > 0, qn, 1.0), 0.0)
    if creep.size == nc:
        creep = creep.reshape((nc,) + (1,) * len(grid.shape))
        t[0][(qn == 0) & contact] = -1.0 if creep.flat[0] > 0 else 1.0
    else:  # a field: the first slip directions opposite to the rigid slip
        wn = np.linalg.norm(creep, axis=0)
        fresh = (qn == 0) & contact & (wn > 0)
        t[:, fresh] = -creep[:, fresh] / wn[fresh]
    a = -grid.diag.reshape((nc,) + (1,) * len(grid.shape))
    history = []  # of the slip directions while the sets stay the same
    for it in range(1, maxit + 1):
        slip = contact & ~stick
        q_slip = np.where(slip, bound * t, 0.0)
        rhs_full = creep - grid.dudx(q_slip)
        nh = int(stick.sum())
        if nh:
            precond = np.repeat(1.0 / grid.diag, nh)

            def matvec(v):
                full = np.zeros_like(q)
                full[:, stick] = v.reshape(nc, nh)
                return grid.dudx(full)[:, stick].ravel()

            x, _ = gmres(matvec, rhs_full[:, stick].ravel(), q[:, stick].ravel(), precond,
                         tol=tol)
            q = q_slip.copy()
            q[:, stick] = x.reshape(nc, nh)
        else:
            q = q_slip
        W = creep - grid.dudx(q)
        # local problem of each contact element with the others fixed:
        # W = W* + a q, a = -diag(du/dx of its own traction) > 0
        w_star = W - a * q
        q_stick = -w_star / a
        qn = np.linalg.norm(q, axis=0)
        to_slip = stick & (qn > bound * (1.0 + 1e-9))
        to_stick = slip & (np.linalg.norm(q_stick, axis=0) <= bound)
        keep = slip & ~to_stick
        q_local = local_slip(w_star, a, bound, keep)
        t_new = np.where(keep, q_local / np.where(keep, bound, 1.0), t)
        dt = np.abs(t_new - t)[:, keep].max() if keep.any() else 0.0
        changed = to_slip.any() or to_stick.any()
        if not changed and dt < 1e-9:
            return q, W, stick, it
        # the slip directions: damped update t + beta (t_new - t) (the undamped
        # block-Jacobi step can diverge through the elements' mutual
        # influence), Anderson-accelerated while the sets stay the same
        # (in 2-D the local problems give the directions, +-1, exactly)
        if nc > 1 and keep.any():
            pair = (t[:, keep].ravel(), t_new[:, keep].ravel())
            history = [] if changed else history + [pair]
            t_mix = t_new.copy()
            t_mix[:, keep] = anderson(history[-6:] or [pair], beta).reshape(nc, -1)
            norm = np.linalg.norm(t_mix, axis=0)
            # a reversed direction (norm near 0) takes the undamped step
            good = keep & (norm > 0.1)
            t_new = np.where(good, t_mix / np.where(good, norm, 1.0), t_new)
        t = np.where(to_slip, q / np.where(qn > 0, qn, 1.0), t_new)
        stick = (stick & ~to_slip) | to_stick
    raise ConvergenceError("TANG: stick/slip sets or slip directions not converged in "
                           "%d iterations (last direction change %.1e)" % (maxit, dt))


def anderson(history, beta):
    """Anderson-accelerated iterate with mixing beta from pairs (x_k, g(x_k)),
    oldest first; with one pair the damped step x + beta (g - x)."""
    x, g = history[-1]
    f = [gk - xk for xk, gk in history]
    if len(history) < 2:
        return x + beta * f[-1]
    df = np.array([f[i + 1] - f[i] for i in range(len(f) - 1)]).T
    dx = np.array([history[i + 1][0] - history[i][0] for i in range(len(f) - 1)]).T
    gamma = np.linalg.lstsq(df, f[-1], rcond=None)[0]
    return x + beta * f[-1] - (dx + beta * df) @ gamma


def solve_rolling(grid, p, creep, law, speed, relax=0.7, ftol=1e-9, maxit=500, start=None,
                  depth=5):
    """Steady rolling at given creepages; f from the law at the local slip
    velocity V |W| (a RelaxingState law: its state transported along x):
    when it depends on it, a fixed point f = G(f) by steps under-relaxed
    with relax, Anderson-accelerated over the last depth + 1 iterates; an
    accelerated f is kept within the range of the f and G(f) it combines,
    and a residual that grows restarts the acceleration from a plain step.

    Without start (q, stick mask, f) the iteration begins in the all-stick
    state with f = f_S everywhere and so follows the branch reached from
    stick (velocity weakening may admit further solutions; this solver
    reports the one it reaches). solve_rolling_force starts each trial
    creepage from the previous trial's solution."""
    contact = p > 0
    nc = grid.nc
    if start is None:
        q = np.zeros((nc,) + p.shape)
        stick = contact.copy()
        f = np.where(contact, law.f_static, 0.0)
    else:
        q, stick, f = (np.array(a) for a in start)
        stick = stick | (contact & (np.linalg.norm(q, axis=0) == 0))
    history, pairs, it = [], [], 0
    for it in range(1, maxit + 1):
        q, W, stick, n_tang = tang(grid, f * p, creep, q, stick)
        s = speed * np.linalg.norm(W, axis=0)
        theta = law.along(s, contact, grid.dx, speed) if hasattr(law, "along") else law(s)
        f_new = np.where(contact, theta, 0.0)
        res = np.abs(f_new - f)[contact].max()
        history.append(res)
        if not law.velocity_dependent or res < ftol:
            f = f_new if law.velocity_dependent else f
            break
        if len(history) > 1 and res > history[-2]:
            pairs = []
        pairs = (pairs + [(f[contact], f_new[contact])])[-(depth + 1):]
        mixed = anderson(pairs, relax)
        lo = min(x.min() for pair in pairs for x in pair)
        hi = max(x.max() for pair in pairs for x in pair)
        f = f.copy()
        f[contact] = np.clip(mixed, lo, hi)
    else:
        raise ConvergenceError("friction law: fixed point not converged in %d iterations "
                               "(max |f_new - f| %.1e)" % (maxit, history[-1]))
    return dict(q=q, W=W, stick=stick & contact, f=f, f_residual=history[-1],
                iterations=it, history=history, contact=contact)


def solve_rolling_force(grid, p, fx_target, law, speed, eta=0.0, rtol=1e-8, maxit=100):
    """Creepage xi for a given F_x (force on the wheel) by the Illinois
    variant of regula falsi on a bracket grown from xi = 0."""
    load = p.sum() * grid.dA
    f_cap = law.f_static
    if abs(fx_target) >= f_cap * load:
        raise ValueError("--Fx: |F_x| = %g N must be below f_S F_N = %g N"
                         % (abs(fx_target), f_cap * load))
    sign = -1.0 if fx_target > 0 else 1.0  # F_x > 0 needs xi < 0

    last = {}

    def fx(xi):  # starts from the previous solution
        creep = [xi, eta] if grid.nc == 2 else [xi]
        sol = solve_rolling(grid, p, creep, law, speed, start=last.get("start"))
        last["start"] = (sol["q"], sol["stick"], sol["f"])
        return sol["q"][0].sum() * grid.dA, sol

    lo, f_lo = 0.0, -abs(fx_target)
    hi = 1e-4
    while True:
        val, sol = fx(sign * hi)
        f_hi = abs(val) - abs(fx_target)
        if f_hi >= 0:
            break
        lo, f_lo, hi = hi, f_hi, 2.0 * hi
        if hi > 1.0:
            raise ValueError("--Fx: F_x = %g N not reached for |xi| <= 1 (the largest "
                             "force with this law is lower)" % fx_target)
    side = 0
    for it in range(maxit):
        xi = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        val, sol = fx(sign * xi)
        fv = abs(val) - abs(fx_target)
        if abs(fv) <= rtol * abs(fx_target):
            break
        if hi - lo < 1e-14 * hi:
            raise ConvergenceError("creepage for F_x = %g: F_x(xi) jumps across the target "
                                   "at xi = %g" % (fx_target, sign * xi))
        if fv > 0:
            hi, f_hi = xi, fv
            if side == 1:
                f_lo *= 0.5
            side = 1
        else:
            lo, f_lo = xi, fv
            if side == -1:
                f_hi *= 0.5
            side = -1
    else:
        raise ConvergenceError("creepage for F_x = %g N: not converged in %d iterations"
                               % (fx_target, maxit))
    sol["xi"] = sign * xi
    sol["outer_iterations"] = it + 1
    return sol


def rolling_residuals(sol, p):
    """Conditions of the solution: in stick |W| and the excess of |q| over
    f p; in slip | |q| - f p | / (f p) and the misalignment |q/|q| + W/|W||."""
    q, W, f = sol["q"], sol["W"], sol["f"]
    stick, slip = sol["stick"], sol["contact"] & ~sol["stick"]
    qn, wn, g = np.linalg.norm(q, axis=0), np.linalg.norm(W, axis=0), f * p
    out = dict(stick_slip=0.0, stick_excess=0.0, slip_bound=0.0, slip_alignment=0.0)
    g = np.where(g > 0, g, 1.0)
    qn, wn = np.where(qn > 0, qn, 1.0), np.where(wn > 0, wn, 1.0)
    if stick.any():
        out["stick_slip"] = wn[stick].max()
        out["stick_excess"] = max(0.0, ((qn - g) / g)[stick].max())
    if slip.any():
        out["slip_bound"] = (np.abs(qn - g) / g)[slip].max()
        out["slip_alignment"] = np.linalg.norm(q / qn + W / wn, axis=0)[slip].max()
    return out
