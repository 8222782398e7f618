"""The half-space reference of a profile run (Geometry/Profiles with profile
files): Kalker's exact theory on the undeformed distance of the two profiles
over each patch's tangent plane (SPEC 10), at the run's load and creepages.

Geometry. The run's parameters.prm gives the wheel and rail profile files
(relative names are taken from the case file's directory, as the program
does; parameters.prm does not record it, so case_dir, by default the
current directory, then the run directory's parent), the inclination 1:N,
the lateral shift y_w, the taping line position (profiles.Pair's offset),
Geometry/Wheel/Radius (R0) and the Second contact tolerance. profiles.py
finds the rigid contact points; check_printed() compares them with what the
program printed ("contact point at y ... mm, separation ..., contact angle
..., rolling radius ..., radius across ..."): the program's y is measured from
O (the main point), its contact angle is atan(dz_rail/dy) = -delta of
profiles.py, its radius across is the local curvature of the distance
(profiles.py's B is fitted over +-2 mm: the two differ where the curvature
varies), and it reads the profiles through smoothing splines.

Normal problem. The points are grouped (clusters): points whose contact
angles differ by less than MERGE_ANGLE share one tangent plane, that of the
first (lowest) point of the group, and are solved as ONE normal problem on
the combined gap over it (gap.gap_case): the load is shared through the
common approach by the solver itself, and the contact may be one patch or
two. Groups further apart in angle are separate problems with a common
vertical approach dz: group i, at vertical separation g_i before loading
and contact angle delta_i, is pressed by (dz - g_i) cos(delta_i) along its
normal, and dz is found so that sum N_i cos(delta_i) = F_N (the tangential
forces' vertical components neglected). One group carries N = F_N /
cos(delta).

Tangential problem. Steady rolling (rolling3d / bem.solve_rolling) at the
run's creepages with the run's friction law (compare.law_of). The rigid slip
per unit speed at (x, s) of a group's tangent plane, from the wheel's
rotation omega about its axle (+y, rolling towards +x) and the run's xi at
O:
    w_x = xi - (r(s) - r_P) / r_P,      w_y = eta + phi x,
    phi = sin(delta_P) / r_P  [1/m]
with r(s) the wheel's rolling radius at the tangent-plane point s, r_P and
delta_P those at the group's reference point (delta > 0: the normal tilts
towards +y, the flange side; positive phi is Kalker's, a counter-clockwise
rotation of the wheel relative to the rail seen from the wheel, rolling3d).
To first order in s, w_x = xi - phi s: Kalker's spin; the exact radius is
kept because a merged two-point patch spans radii that a linear term
misses. eta is the run's lateral creepage at O at instant t (statistics
'lateral creepage': the axle's lateral velocity, with yaw, along s), 0 where
the run does not report it (no lateral creepage, no yaw); every group takes
it (at a second point of another contact angle that neglects the axle's
vertical velocity along its s). A side without its file is the paper's
analytic one (analytic_side), so the paper's pair is a profile pair here too.
xi at O is the run's creepage at instant t (statistics), (V - omega r_eff) / V
with the program's effective radius r_eff (printed as "rolling radius" under
Rolling); a separate group's xi is shifted by -(r_P - r_O) / r_O. r_eff
differs from the undeformed r_O by up to about 0.15 mm (xi by 3e-4, F_x / F_N
by about 0.04 on these patches): the xi of the undeformed radius,
1 - omega r_O / V, is reported beside it.
"""
import math
import os
import re

import numpy as np

from . import bem
from . import compare as hc
from . import gap as gp
from . import profiles as pf

MM = 1e-3
# groups of contact points whose contact angles differ less than this share
# one tangent plane (rad)
MERGE_ANGLE = math.radians(5.0)
# the gap table: x within +-HALF_X, s over the group's points +-HALF_S, steps
HALF_X, HALF_S, STEP_X, STEP_S = 20 * MM, 22 * MM, 0.25 * MM, 0.1 * MM
DEFAULT_GRID = (32, 33)
# the area and extents count the elements (and FE nodes) with at least this
# share of the patch's p_max: the FE's penalty contact gives edge nodes that
# touch the master faces a few per cent of it (profile_compare.py)
P_SHARE = 0.05
MARGIN = 1.1


class ReferenceError(ValueError):
    pass


def is_profile_run(prm):
    """Whether the run's geometry came from profile files."""
    return bool(prm.get("Geometry/Profiles/Wheel profile file", "").strip()
                or prm.get("Geometry/Profiles/Rail profile file", "").strip())


def resolve(name, case_dir, run):
    """The profile file NAME as the program opened it: absolute, or relative
    to case_dir (default: the current directory, then RUN's parent)."""
    if os.path.isabs(name):
        return name
    dirs = [case_dir] if case_dir else [os.getcwd(), os.path.dirname(os.path.abspath(run))]
    for d in dirs:
        path = os.path.normpath(os.path.join(d, name))
        if os.path.exists(path):
            return path
    raise ReferenceError("profile file %r not found relative to %s (give the case file's "
                         "directory)" % (name, " or ".join(dirs)))


def analytic_side(prm, side, n=2001, beyond=0.02):
    """The paper's analytic side of a run without its profile file, as points
    in the file's conventions [m]: the wheel a cylinder (a flat tread), the
    rail the circular crown of Geometry/Rail/Profile radius (turned by the
    inclination in Pair, as the program turns it), over the modelled window
    (Tread width about Wheel window centre, Head width about Rail window
    centre) and @p beyond further on each side, so that the gap table of a
    patch near the window's edge is defined (the program's body ends at the
    window: a patch that reaches it is not the half-space's)."""
    g = "Geometry/Profiles/%s window centre" % side
    c = float(prm.get(g, "0"))
    if side == "Wheel":
        half = 0.5 * float(prm["Geometry/Wheel/Tread width"]) + beyond
        y = np.linspace(c - half, c + half, n)
        return np.column_stack((y, 0.0 * y))
    R = float(prm["Geometry/Rail/Profile radius"])
    half = min(0.5 * float(prm["Geometry/Rail/Head width"]) + beyond, 0.5 * R)
    y = np.linspace(c - half, c + half, n)
    return np.column_stack((y, np.sqrt(R * R - y * y) - R))


def pair_of(prm, run, case_dir=None):
    """profiles.Pair of the run; a side without its file is the paper's
    analytic one (analytic_side), as in the program."""
    g = "Geometry/Profiles/"
    sides = []
    for side in ("Wheel", "Rail"):
        name = prm.get(g + side + " profile file", "").strip()
        if name:
            p = pf.read_profile(resolve(name, case_dir, run))
            taping = float(prm.get(g + "Wheel profile taping line", "0")) if side == "Wheel" else 0.0
            sides.append(as_written(p, prm, side, taping))
        else:
            sides.append(analytic_side(prm, side))
    return pf.Pair(sides[0], sides[1], float(prm.get(g + "Rail inclination", "0")),
                   float(prm.get(g + "Lateral shift", "0")),
                   float(prm.get(g + "Taping line position", "0")),
                   float(prm["Geometry/Wheel/Radius"]))


def as_written(p, prm, side, taping_line):
    """Profile points P in the program's conventions from the file's, by the
    entries the program has since main's edb29a2 (absent: unchanged):
    '<side> profile flip y' mirrors y, '<side> profile z down' turns z, and
    the wheel's taping line (its y as written, mirrored with the file) goes
    to y = 0."""
    g = "Geometry/Profiles/%s profile " % side
    p = np.array(p, dtype=float)
    flip = prm.get(g + "flip y", "false") == "true"
    if flip:
        p[:, 0] = -p[:, 0]
    if prm.get(g + "z down", "false") == "true":
        p[:, 1] = -p[:, 1]
    p[:, 0] -= -taping_line if flip else taping_line
    return p


def rigid_points(pair, prm):
    """The rigid contact points within the run's Second contact tolerance."""
    tol = float(prm.get("Geometry/Profiles/Second contact tolerance", "1e-4"))
    return pf.contact_points(pair, tol=max(tol, 1e-9))


_POINT = re.compile(r"contact point at y (\S+) mm, separation (\S+) mm, contact angle (\S+) deg,"
                    r" rolling radius (\S+) mm, radius across (\S+) mm")


def printed_points(log):
    """The program's printed contact points from its log (None if no log):
    dicts y (from O), separation, angle (program's sign), r, across [m, rad]."""
    if not log or not os.path.exists(log):
        return None
    with open(log) as f:
        rows = _POINT.findall(f.read())
    return [dict(y=float(a) * MM, separation=float(b) * MM, angle=math.radians(float(c)),
                 r=float(d) * MM, across=float(e) * MM) for a, b, c, d, e in rows]


def check_printed(pair, points, printed):
    """Rows (k, dy, dsep, dangle, dr, across_profiles, across_printed, sign) of
    the differences profiles.py - program [m, rad]. The program printed its
    contact angle as atan(dz_rail/dy) = -delta before main's 24c91e7 and as
    delta since: the sign that fits the printed angles better is taken
    (sign -1: the former) and reported."""
    rows = []
    y0 = points[0]["y"]
    pairs = list(zip(points, printed))
    sign = 1 if sum(abs(c["delta"] - q["angle"]) for c, q in pairs) <= \
        sum(abs(c["delta"] + q["angle"]) for c, q in pairs) else -1
    for k, (c, q) in enumerate(zip(points, printed)):
        try:
            B = pf.gap_curvatures(pair, c)[1]
            across = 1 / (2 * B) if B > 0 else float("inf")
        except ValueError:
            across = float("nan")
        rows.append(dict(k=k, dy=(c["y"] - y0) - q["y"], dsep=c["gap"] - q["separation"],
                         dangle=sign * c["delta"] - q["angle"], dr=c["r"] - q["r"],
                         across=across, across_printed=q["across"], sign=sign))
    return rows


def groups(points):
    """Indices of the points grouped by contact angle (module docstring)."""
    out = []
    for k, c in enumerate(points):
        for g in out:
            if abs(c["delta"] - points[g[0]]["delta"]) < MERGE_ANGLE:
                g.append(k)
                break
        else:
            out.append([k])
    return out


def s_of(point, ref):
    """s of POINT in the tangent plane of REF (along its lateral direction)."""
    th = -ref["delta"]
    return (point["y"] - ref["y"]) * math.cos(th) + (point["z"] - ref["z"]) * math.sin(th)


def divide(pair, a, b, n=401):
    """The point of the rail profile between the contact points a and b where
    the profiles' vertical distance is largest: the ridge that parts their
    contacts (dict y, z as a contact point's)."""
    y = np.linspace(a["y"], b["y"], n)
    d = pair.wheel_z(y) - pair.rail_z(y)
    yd = float(y[int(np.argmax(d))])
    return dict(y=yd, z=float(pair.rail_z(np.array([yd]))[0]))


def ridge_gap(pair, a, b):
    """The vertical distance of the profiles at the ridge between points a and b."""
    y = np.array([divide(pair, a, b)["y"]])
    return float((pair.wheel_z(y) - pair.rail_z(y))[0] + pair.dz)


def group_gap(pair, points, group):
    """gap.Gap table over the tangent plane of the group's first point,
    covering its points (module constants); the s axis clipped to where both
    profiles are single-valued and, towards another group's point, at the
    ridge between them (divide: each separate problem sees its own contact)."""
    ref = points[group[0]]
    ss = [s_of(points[k], ref) for k in group]
    window = max(abs(v) for v in ss) + HALF_S + 5 * MM
    lo, hi = pf.s_coverage(pair, ref, window)
    for k, c in enumerate(points):
        if k not in group:
            d = s_of(divide(pair, ref, c), ref)
            lo, hi = (lo, min(hi, d)) if d > 0 else (max(lo, d), hi)
    s0, s1 = max(min(ss) - HALF_S, lo + 0.5 * MM), min(max(ss) + HALF_S, hi - 0.5 * MM)
    x = np.arange(-HALF_X, HALF_X + 0.5 * STEP_X, STEP_X)
    s = np.arange(s0, s1, STEP_S)
    return gp.Gap(pf.gap_grid(pair, ref, x, s, window), x, s)


def measures(grid, p):
    """area, length (x extent), width (s extent) of the elements with
    p >= P_SHARE p_max, their sizes included; p_max [SI], the s of the centre
    of pressure, the load."""
    c = p >= P_SHARE * p.max()
    X, Y = np.meshgrid(grid.x, grid.y, indexing="ij")
    return dict(area=c.sum() * grid.dA, length=np.ptp(X[c]) + grid.dx,
                width=np.ptp(Y[c]) + grid.dy, p_max=float(p.max()),
                s_centre=float((p * Y).sum() / p.sum()), load=float(p.sum() * grid.dA))


def solve_group(gap, load, E, nu, grid_shape):
    """The normal solution of one group at normal load LOAD: grid, p, info."""
    try:
        return gp.gap_case(gap, load, grid_shape[0], grid_shape[1], E, nu, MARGIN)
    except gp.GapError as e:
        raise ReferenceError("normal problem: %s" % e)


def load_at_approach(gap, d, E, nu, grid_shape, guess, rtol=1e-4):
    """The normal load and solution at normal approach d (approach ~ load^(2/3))."""
    load = guess
    for _ in range(12):
        grid, p, info = solve_group(gap, load, E, nu, grid_shape)
        ratio = d / info["approach"]
        if abs(ratio - 1) < rtol:
            break
        load *= ratio ** 1.5
    return load, (grid, p, info)


def common_approach(gaps, pts, load, E, nu, grid_shape):
    """Separate groups pressed by a common vertical approach dz (module
    docstring): their (grid, p, info) and dz, by the secant method on dz."""
    cos = [math.cos(c["delta"]) for c in pts]
    sep = [c["gap"] for c in pts]
    guesses = [load / len(pts)] * len(pts)

    def total(dz):
        sols = []
        for i, g in enumerate(gaps):
            d = (dz - sep[i]) * cos[i]
            if d <= 0:
                sols.append((0.0, None))
                continue
            n, sol = load_at_approach(g, d, E, nu, grid_shape, guesses[i])
            guesses[i] = n
            sols.append((n, sol))
        return sum(n * c for (n, _), c in zip(sols, cos)) - load, sols

    grid, p, info = solve_group(gaps[0], load / len(pts) / cos[0], E, nu, grid_shape)
    z0 = info["approach"] / cos[0] + sep[0]
    z1 = 1.1 * z0
    f0, sols = total(z0)
    f1, sols = total(z1)
    for _ in range(30):
        if abs(f1) < 1e-4 * load:
            break
        step = -f1 * (z1 - z0) / (f1 - f0)
        while True:  # a step too far puts a contact on its table's edge
            try:
                z = max(z1 + step, 0.5 * z1)
                f, new = total(z)
                break
            except ReferenceError:
                step *= 0.5
                if abs(step) < 1e-3 * z1:
                    raise
        z0, f0, z1, f1, sols = z1, f1, z, f, new
    else:
        raise ReferenceError("common approach of the separate patches: not converged")
    return [s for _, s in sols], z1


def normal_reference(pair, points, load, E, nu, grid_shape=DEFAULT_GRID):
    """The normal solution of every group at the vertical load LOAD: a list of
    dicts (group, point, grid, p, info, measures, delta, gap)."""
    grps = groups(points)
    gaps = [group_gap(pair, points, g) for g in grps]
    refs = [points[g[0]] for g in grps]
    if len(grps) == 1:
        sols = [solve_group(gaps[0], load / math.cos(refs[0]["delta"]), E, nu, grid_shape)]
        dz = None
    else:
        try:
            sols, dz = common_approach(gaps, refs, load, E, nu, grid_shape)
        except ReferenceError as e:
            raise ReferenceError(
                "the separate patches (contact angles %s deg) did not solve: %s. A contact that "
                "reaches the ridge between the points (its vertical gap: %s um) makes one "
                "conformal contact across different angles, which half-space patches on tangent "
                "planes do not model" % (", ".join("%.1f" % math.degrees(c["delta"]) for c in refs),
                                         e, ", ".join("%.1f" % (ridge_gap(pair, a, b) * 1e6)
                                                      for a, b in zip(refs, refs[1:]))))
    out = []
    for g, ref, gap, sol in zip(grps, refs, gaps, sols):
        entry = dict(group=g, point=ref, gap=gap, vertical_approach=dz, grid=None)
        if sol is not None:
            grid, p, info = sol
            entry.update(grid=grid, p=p, info=info, measures=measures(grid, p))
        out.append(entry)
    return out


def normal_case(prm, load, grid_shape, run=None):
    """compare.normal_case's tuple (grid, p, info, reference values, X, Y, G)
    for a profile run at the vertical LOAD: its first patch (one group, or
    the main group of several at their common approach); the reference values
    a, b (half the length and width), p0 (p_max), area, approach."""
    pair = pair_of(prm, run or os.getcwd())
    patch = normal_reference(pair, rigid_points(pair, prm), load,
                             float(prm["Material/Young's modulus"]),
                             float(prm["Material/Poisson's ratio"]), grid_shape)[0]
    grid, p, m = patch["grid"], patch["p"], patch["measures"]
    X, Y = np.meshgrid(grid.x, grid.y, indexing="ij")
    ref = dict(a=0.5 * m["length"], b=0.5 * m["width"], p0=m["p_max"], area=m["area"],
               approach=patch["info"]["approach"])
    E, nu = float(prm["Material/Young's modulus"]), float(prm["Material/Poisson's ratio"])
    return grid, p, patch["info"], ref, X, Y, E / (2.0 * (1.0 + nu))


def rolling_radius(pair, ref, s):
    """The wheel's rolling radius at the tangent-plane points s of REF's plane."""
    th = -ref["delta"]
    y = ref["y"] + np.asarray(s) * math.cos(th)
    return pair.rolling_radius(y)


def rigid_slip(pair, patch, xi, eta=0.0):
    """Kalker's rigid slip (w_x, w_y) of the module docstring on the patch's grid."""
    ref, grid = patch["point"], patch["grid"]
    X, Y = np.meshgrid(grid.x, grid.y, indexing="ij")
    r_p = ref["r"]
    phi = math.sin(ref["delta"]) / r_p
    wx = xi - (rolling_radius(pair, ref, Y) - r_p) / r_p
    return np.stack([wx, eta + phi * X]), phi


def tangential_reference(pair, patch, law, speed, xi_O, r_O, eta=0.0):
    """Steady rolling of a solved patch at the creepage xi_O at O (rolling
    radius r_O): xi = xi_O - (r_P - r_O) / r_O at the patch's point. The
    solution dict of bem.solve_rolling with xi, phi, F_x, F_y, M_z, F_N and
    slip_fraction."""
    from . import rolling3d
    xi = xi_O - (patch["point"]["r"] - r_O) / r_O
    w, phi = rigid_slip(pair, patch, xi, eta)
    grid, p = patch["grid"], patch["p"]
    try:
        sol = bem.solve_rolling(grid, p, w, law, speed)
    except bem.ConvergenceError as e:
        raise ReferenceError("tangential problem: %s" % e)
    fx, fy, mz = rolling3d.creep_totals(grid, sol["q"])
    c = sol["contact"]
    sol.update(xi=xi, eta=eta, phi=phi, F_x=fx, F_y=fy, M_z=mz, F_N=float(p.sum() * grid.dA),
               slip_fraction=float((c & ~sol["stick"]).sum() / c.sum()))
    return sol


def run_load(run, prm, t):
    """The vertical wheel load: the statistics' F_N at t, else Static
    solve/Axle load (the wheel load of the static start); and its source."""
    names, stats = hc.read_statistics(run)
    if stats is not None and math.isfinite(t):
        fn, time = hc.column(names, stats, "F_N"), hc.column(names, stats, "time")
        if fn is not None and time is not None:
            return float(np.interp(t, time, fn)), "statistics F_N at t = %.6g s" % t
    return float(prm["Static solve/Axle load"]), "Static solve/Axle load"


def run_creepage(run, t):
    """The run's rigid creepage, wheel angular velocity and lateral creepage
    at t (statistics; NaN without them)."""
    names, stats = hc.read_statistics(run)
    out = []
    for name in ("creepage", "omega", "lateral creepage"):
        col = hc.column(names, stats, name) if stats is not None else None
        out.append(float(np.interp(t, hc.column(names, stats, "time"), col))
                   if col is not None and math.isfinite(t) else float("nan"))
    return out


def reference(run, t, case_dir=None, grid_shape=DEFAULT_GRID, log=None, load=None, tangential=True):
    """The whole reference of RUN at time t: dict with pair, points, printed
    (None without a log), check rows, load and its source, patches (each with
    its normal solution, measures and, for a run with friction and
    tangential=True, 'rolling': the tangential solution), law (text)."""
    prm = hc.read_parameters(run)
    if not prm:
        raise ReferenceError("%s has no parameters.prm" % run)
    pair = pair_of(prm, run, case_dir)
    points = rigid_points(pair, prm)
    printed = printed_points(log)
    check = check_printed(pair, points, printed) if printed else None
    src = "given"
    if load is None:
        load, src = run_load(run, prm, t)
    E, nu = float(prm["Material/Young's modulus"]), float(prm["Material/Poisson's ratio"])
    patches = normal_reference(pair, points, load, E, nu, grid_shape)
    xi, omega, eta = run_creepage(run, t)
    xi = xi if math.isfinite(xi) else 0.0
    if not math.isfinite(eta):  # not reported: no lateral creepage, no yaw
        eta = 0.0
    speed, r_O = float(prm["Wheelset/Rolling speed"]), points[0]["r"]
    if not math.isfinite(omega):
        omega = speed * (1 - xi) / r_O
    out = dict(pair=pair, points=points, printed=printed, check=check, load=load, load_source=src,
               patches=patches, law="frictionless", xi=xi, eta=eta, omega=omega,
               xi_undeformed=1.0 - omega * r_O / speed, r_eff=speed * (1 - xi) / omega)
    if tangential and prm.get("Contact/Friction law", "none") != "none":
        law, _, out["law"] = hc.law_of(prm)
        for patch in patches:
            if patch["grid"] is not None:
                patch["rolling"] = tangential_reference(pair, patch, law, speed, xi, r_O, eta)
    return out


def creepage_for(run, target, case_dir=None, grid_shape=DEFAULT_GRID, load=None, eta=0.0):
    """The longitudinal creepage xi at O at which the reference of RUN's
    profiles, load (default Static solve/Axle load) and law gives
    F_x / F_N = target over all its patches (bisection over [-0.05, 0.05];
    driving: target > 0 at xi < 0), for a case that holds it
    (Wheelset/Initial creepage). RUN needs only its parameters.prm (a dry
    run). Returns (xi, achieved F_x / F_N)."""
    prm = hc.read_parameters(run)
    if not prm:
        raise ReferenceError("%s has no parameters.prm" % run)
    pair = pair_of(prm, run, case_dir)
    points = rigid_points(pair, prm)
    load = float(prm["Static solve/Axle load"]) if load is None else load
    E, nu = float(prm["Material/Young's modulus"]), float(prm["Material/Poisson's ratio"])
    patches = [p for p in normal_reference(pair, points, load, E, nu, grid_shape)
               if p["grid"] is not None]
    law, _, _ = hc.law_of(prm)
    speed, r_O = float(prm["Wheelset/Rolling speed"]), points[0]["r"]

    def ratio(xi):
        sols = [tangential_reference(pair, p, law, speed, xi, r_O, eta) for p in patches]
        return sum(s["F_x"] for s in sols) / sum(s["F_N"] for s in sols)

    lo, hi = -0.05, 0.05  # ratio falls with xi
    f_lo, f_hi = ratio(lo) - target, ratio(hi) - target
    if f_lo * f_hi > 0:
        raise ReferenceError("F_x / F_N = %g is not reached for |xi| <= 0.05 (from %.4f to %.4f)"
                             % (target, f_lo + target, f_hi + target))
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        f_mid = ratio(mid) - target
        if abs(hi - lo) < 1e-7:
            break
        lo, f_lo, hi = (mid, f_mid, hi) if f_mid * f_lo > 0 else (lo, f_lo, mid)
    return 0.5 * (lo + hi), ratio(0.5 * (lo + hi))
