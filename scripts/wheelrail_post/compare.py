"""A wheelrail run's output read by column name, and its contact patch
compared with the half-space solution (scripts/halfspace.py, Kalker's exact
theory of steady rolling) of the same load and traction.

Shared by plot.py (overlays on Figs. 4 and 10, the RMS lines), sweep.py (the
creep curve) and convergence_study.py (the mesh and time-step study):

  read_parameters, read_statistics, column, read_csv, read_probe,
  read_patch, patch_header, axis_rows
                            the run's files: parameters.prm, statistics
                            (deal.II TableHandler text), the probes
                            (series.h5, or the CSV files), patch_*.csv
  fit_ellipse               the Hertzian ellipse fitted to a patch's pressures
  compare_patch             the patch at an instant against the half-space
                            solution at the patch's own F_N and F_x: the
                            solution along y = 0, the RMS differences of
                            pressure / p0 and shear_x / (f p0) there, the
                            slip-area fractions
  slip_halves               eq. 6 slip shares and mean s_n of the leading
                            and trailing halves of a patch (FE) or of the
                            half-space solution along y = 0
  creep_curve               half-space F_x / F_N against the creepage

The half-space case takes the run's wheel radius (R_x), rail profile radius
(R_y), E, nu, rolling speed and friction law (constant: Coulomb f = the static
coefficient; exponential: f_S, f_D, k). A patch force beyond what Coulomb
friction can carry, |F_x| >= f_S F_N, is capped at 0.995 f_S F_N; a force the
exponential law cannot reach in steady rolling (above its largest F_x / F_N,
about 0.37 for SPEC 4's coefficients) is replaced by rolling at the run's
rigid creepage at the patch's instant. Both are said in the result's 'note'.
"""
import math
import os
import time

import numpy as np

from . import halfspace as hs

# the grid of the comparisons: elements along x and y (odd: a row on y = 0)
# over 1.1 x the Hertz semi-axes
DEFAULT_GRID = (32, 17)
MARGIN = 1.1
# a patch force at or beyond the Coulomb limit is taken as this share of it
CAP = 0.995


def parse_grid(text, none_allowed=False):
    """'NXxNY' as (NX, NY) with 4 <= NX <= 512 and NY odd in 3..511 (as
    halfspace.py's --nx, --ny), '0x0' as (0, 0) if @p none_allowed; None if bad."""
    try:
        grid = tuple(int(v) for v in text.lower().split("x"))
    except ValueError:
        return None
    if len(grid) != 2:
        return None
    if grid == (0, 0):
        return grid if none_allowed else None
    return grid if 4 <= grid[0] <= 512 and 3 <= grid[1] <= 511 and grid[1] % 2 == 1 else None


# ----------------------------------------------------------------------------
# Reading a run


def read_parameters(run):
    """RUN/parameters.prm as {"Section/Sub/Entry": value} ({} if missing)."""
    values, path = {}, []
    name = os.path.join(run, "parameters.prm")
    if not os.path.exists(name):
        return values
    with open(name) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                path.append(line[len("subsection "):].strip())
            elif line == "end":
                if path:
                    path.pop()
            elif line.startswith("set ") and "=" in line:
                key, value = line[4:].split("=", 1)
                values["/".join(path + [key.strip()])] = value.strip()
    return values


def read_statistics(run):
    """RUN/statistics as (column names, array) or (None, None)."""
    name = os.path.join(run, "statistics")
    if not os.path.exists(name):
        return None, None
    names = []
    with open(name) as f:
        for line in f:
            if line.startswith("# ") and ":" in line and line[2].isdigit():
                names.append(line.split(":", 1)[1].strip())
    data = np.loadtxt(name, comments="#", ndmin=2)
    return names, data


def column(names, data, prefix):
    """The first column whose name starts with @p prefix, or None."""
    for i, n in enumerate(names):
        if n.startswith(prefix):
            return data[:, i]
    return None


def read_csv(name):
    """A CSV with '#' comment lines and one header line: dict of arrays."""
    if not os.path.exists(name):
        return None
    with open(name) as f:
        lines = [l for l in f if not l.startswith("#")]
    if len(lines) < 2:
        return None
    header = [h.strip() for h in lines[0].split(",")]
    data = np.array([[float(v) for v in l.split(",")] for l in lines[1:] if l.strip()])
    return {h: data[:, i] for i, h in enumerate(header)}


def read_probe(run, name):
    """The history of probe NAME ('probe', 'wheel_probe') as {column: array}:
    from RUN/series.h5 (/probes/NAME, h5py) if the run wrote it, else from
    RUN/NAME.csv; None if neither exists."""
    series = os.path.join(run, "series.h5")
    if os.path.exists(series):
        import h5py
        with h5py.File(series, "r") as f:
            if "probes/" + name in f:
                d = f["probes/" + name]
                columns = [c.decode() if isinstance(c, bytes) else c for c in d.attrs["columns"]]
                data = d[()]
                return {c: data[:, i] for i, c in enumerate(columns)}
    return read_csv(os.path.join(run, name + ".csv"))


def patch_file(run, instant):
    return os.path.join(run, "patch_%s.csv" % instant)


def read_patch(run, instant):
    return read_csv(patch_file(run, instant))


def patch_header(path):
    """(time [s], patch centre x [m]) from a patch file's first line."""
    with open(path) as f:
        head = f.readline()
    t = float(head.split("(t = ")[1].split(" s")[0]) if "(t = " in head else float("nan")
    return t, float(head.split("patch centre x = ")[1].split(" m")[0])


def axis_rows(patch):
    """Indices of the nodes on the longitudinal axis (smallest |y|), by x."""
    y = np.abs(patch["y"])
    on_axis = np.flatnonzero(np.isclose(y, y.min(), rtol=0, atol=1e-9))
    return on_axis[np.argsort(patch["x"][on_axis])]


# ----------------------------------------------------------------------------
# The half-space case of a run


def law_of(prm):
    """(half-space law, its static coefficient, description) of a run.

    The half-space reference has the library's laws, 'constant' and
    'exponential'; a run with another law (a plugin, doc/developer.md) has
    no reference here, and is refused rather than compared with the wrong
    law."""
    name = prm["Contact/Friction law"]
    if name == "none":
        raise ValueError("a frictionless run has no shear to compare with the rolling half-space "
                         "solution")
    if name not in ("constant", "exponential"):
        raise ValueError("the half-space reference has no friction law '%s' (it has 'constant' and "
                         "'exponential'): add it to wheelrail_post/bem.py and law_of() in "
                         "wheelrail_post/compare.py to compare this run" % name)
    if name == "constant":
        f = float(prm["Contact/Static friction coefficient"])
        return hs.make_law("coulomb", f, 0, 0, 0), f, "Coulomb f = %g" % f
    f_s = float(prm["Contact/Static friction coefficient"])
    f_d = float(prm["Contact/Dynamic friction coefficient"])
    k = float(prm["Contact/Decay coefficient"])
    # the friction state's relaxation (absent from the parameters of older runs)
    length = float(prm.get("Contact/Friction relaxation length", 0))
    time = float(prm.get("Contact/Friction relaxation time", 0))
    text = "exponential f_S = %g, f_D = %g, k = %g s/m" % (f_s, f_d, k)
    if length > 0 or time > 0:
        text += ", state relaxing over L = %g m, tau = %g s" % (length, time)
    return hs.make_law("exponential", 0, f_s, f_d, k, length, time), f_s, text


def normal_case(prm, Fn, grid=DEFAULT_GRID, run=None):
    """hs.elliptic_case at the run's geometry and material for the load Fn;
    a profile run's: the normal problem on the profiles' gap
    (profile_reference.normal_case; relative profile files from the current
    directory, then @p run's parent)."""
    from . import profile_reference
    if profile_reference.is_profile_run(prm):
        return profile_reference.normal_case(prm, Fn, grid, run)
    return hs.elliptic_case(grid[0], grid[1], MARGIN, Fn, float(prm["Geometry/Wheel/Radius"]),
                            float(prm["Geometry/Rail/Profile radius"]),
                            float(prm["Material/Young's modulus"]), float(prm["Material/Poisson's ratio"]))


def fit_ellipse(x, y, p, force):
    """Hertzian p^2 = p0^2 (1 - (x - xc)^2/a^2 - y^2/b^2) fitted to the pressures
    above 25 % of the largest (as the program's own fit; xc the force-weighted
    centre): (p0, a, b)."""
    inside = p > 0
    xc = np.sum(force[inside] * x[inside]) / np.sum(force[inside])
    use = inside & (p >= 0.25 * p[inside].max())
    A = np.column_stack([np.ones(use.sum()), (x[use] - xc) ** 2, y[use] ** 2])
    c = np.linalg.lstsq(A, p[use] ** 2, rcond=None)[0]
    return np.sqrt(c[0]), np.sqrt(-c[0] / c[1]), np.sqrt(-c[0] / c[2])


def patch_totals(P):
    """F_N, F_x (the rail's force on the wheel) and the slip-area fraction
    (eq. 5 as decided on the slave nodes) of the rail nodes in contact."""
    inc = P["in_contact"] > 0
    Fn = np.sum(P["F_n"][inc])
    Fx = np.sum(P["shear_x"][inc] * P["area"][inc])
    slip = inc & (P["adhesion_eq5"] == 0)
    return Fn, Fx, np.sum(P["area"][slip]) / np.sum(P["area"][inc])


def compare_patch(run, instant="t", grid=DEFAULT_GRID):
    """The patch of RUN at @p instant against the half-space solution at its
    own F_N and F_x; None without that patch file.

    Returns a dict: Fn, Fx (patch), fx_hs (the force the half-space solved
    for), xc (patch centre), t, creep_fe (rigid creepage at t from the
    statistics), creep_hs, slip_fe, slip_hs, p0_hs, f_ref (Coulomb f; the
    exponential law: the pressure-weighted mean f of the half-space slip area,
    f_S without slip), rms_p (over p0_hs), rms_q (over f_ref p0_hs), axis
    (the half-space solution along y = 0: x relative to the patch centre, p,
    q_x, s, contact), fe (the patch's axis rows: x relative, p, q_x),
    sol, grid, note (None or what was capped), seconds, law (description)."""
    path = patch_file(run, instant)
    P = read_csv(path)
    if P is None:
        return None
    t0 = time.time()
    prm = read_parameters(run)
    from . import profile_compare, profile_reference
    if profile_reference.is_profile_run(prm):
        return profile_compare.as_comparison(run, instant, grid)
    law, f_s, law_text = law_of(prm)
    V = float(prm["Wheelset/Rolling speed"])
    t, xc = patch_header(path)
    Fn, Fx, slip_fe = patch_totals(P)
    names, stats = read_statistics(run)
    creep_fe = float("nan")
    if stats is not None and column(names, stats, "creepage") is not None and math.isfinite(t):
        creep_fe = float(np.interp(t, column(names, stats, "time"), column(names, stats, "creepage")))

    g, p, _, hertz, X, Y, _ = normal_case(prm, Fn, grid)
    fx, note = Fx, None
    if abs(Fx) >= CAP * f_s * Fn:
        fx = math.copysign(CAP * f_s * Fn, Fx)
        note = ("the patch's F_x / F_N = %.4f is at or beyond the Coulomb limit f_S = %g: "
                "half-space at F_x = %.3f f_S F_N" % (Fx / Fn, f_s, CAP))
    try:
        sol = hs.rolling(g, p, law, V, fx=fx)
    except hs.InputError:
        # the exponential law's F_x(xi) has a maximum below f_S F_N
        if not math.isfinite(creep_fe):
            raise
        sol = hs.rolling(g, p, law, V, creep=creep_fe)
        fx = sol["q"][0].sum() * g.dA
        note = ("the patch's F_x / F_N = %.4f is beyond the largest the %s law reaches in steady "
                "rolling: half-space at the run's creepage %.4g instead (F_x / F_N %.4f)"
                % (Fx / Fn, prm["Contact/Friction law"], creep_fe, fx / Fn))
    fl = hs.fields(g, p, sol, V)
    contact = sol["contact"]
    slip_hs = contact & ~sol["stick"]
    if prm["Contact/Friction law"] == "constant" or not slip_hs.any():
        f_ref = f_s
    else:
        f_ref = float(np.sum(sol["f"][slip_hs] * p[slip_hs]) / np.sum(p[slip_hs]))
    mid = g.shape[1] // 2
    axis = dict(x=X[:, mid], p=fl["p"][:, mid], q_x=fl["q_x"][:, mid], s=fl["s"][:, mid],
                contact=contact[:, mid])

    rows = axis_rows(P)
    x_fe = P["x"][rows] - xc
    p_hs = np.interp(x_fe, axis["x"], axis["p"], left=0., right=0.)
    q_hs = np.interp(x_fe, axis["x"], axis["q_x"], left=0., right=0.)
    compared = (P["in_contact"][rows] > 0) | (p_hs > 0)
    p0_hs = p.max()
    rms_p = np.sqrt(np.mean((P["pressure"][rows][compared] - p_hs[compared]) ** 2)) / p0_hs
    rms_q = np.sqrt(np.mean((P["shear_x"][rows][compared] - q_hs[compared]) ** 2)) / (f_ref * p0_hs)
    return dict(Fn=Fn, Fx=Fx, fx_hs=fx, xc=xc, t=t, creep_fe=creep_fe, creep_hs=sol["xi"],
                slip_fe=slip_fe, slip_hs=slip_hs.sum() / contact.sum(), p0_hs=p0_hs, f_ref=f_ref,
                rms_p=rms_p, rms_q=rms_q, axis=axis, hertz=hertz, sol=sol, grid=g, note=note,
                fe=dict(x=x_fe, p=P["pressure"][rows], q_x=P["shear_x"][rows]),
                seconds=time.time() - t0, law=law_text, instant=instant)


def halves(x):
    """Masks of the leading (x above the middle of the extent of @p x) and
    trailing nodes. A node within 1e-3 of the extent of the middle belongs
    to neither: on a symmetric row its side would be decided by round-off."""
    mid, tol = 0.5 * (x.max() + x.min()), 1e-3 * (x.max() - x.min())
    return x > mid + tol, x < mid - tol


def slip_halves(run, r=None, instant="t"):
    """The slip state of the leading and trailing halves (in x, about the
    middle of the contact's extent) of the patch of RUN at @p instant: dict
    with the eq. 6 slip share of the nodes in contact in each half (lead_eq6,
    trail_eq6), the eq. 5 slip share of all of them (eq5), the mean s_n of
    the nodes in contact along y = 0 in each half (lead_s, trail_s) and,
    given the compare_patch() result @p r, the half-space's mean slip
    velocity of each half along y = 0 (hs_lead_s, hs_trail_s)."""
    P = read_patch(run, instant)
    c = P["in_contact"] > 0
    x, share = P["x"][c], P["slip_share"][c]
    lead, trail = halves(x)
    rows = axis_rows(P)
    rows = rows[c[rows]]
    xr, sr = P["x"][rows], P["slip_velocity"][rows]
    lr, tr = halves(xr)
    out = dict(lead_eq6=share[lead].mean(), trail_eq6=share[trail].mean(),
               lead_s=sr[lr].mean(), trail_s=sr[tr].mean(), eq5=1. - P["adhesion_share"][c].mean())
    if r is not None:
        a = r["axis"]
        ca = a["contact"] > 0
        xa, sa = a["x"][ca], a["s"][ca]
        la, ta = halves(xa)
        out.update(hs_lead_s=sa[la].mean(), hs_trail_s=sa[ta].mean())
    return out


def summary_lines(r):
    """The comparison as text lines (printed by plot.py, listed in report.html);
    a profile run's: profile_compare.summary_lines."""
    if "profile" in r:
        from . import profile_compare
        return profile_compare.summary_lines(r["profile"])
    g = r["grid"].shape
    lines = ["half-space comparison at instant %s (%s; grid %d x %d, %.1f s): F_N %.2f kN, "
             "F_x / F_N %.4f, creepage FE %.4g / half-space %.4g"
             % (r["instant"], r["law"], g[0], g[1], r["seconds"], r["Fn"] * 1e-3, r["Fx"] / r["Fn"],
                r["creep_fe"], r["creep_hs"])]
    if r["note"]:
        lines.append("note: " + r["note"])
    lines.append("RMS difference along y = 0: pressure / p0 %.4f, shear_x / (f p0) %.4f "
                 "(p0 %.0f MPa, f %.4g)" % (r["rms_p"], r["rms_q"], r["p0_hs"] * 1e-6, r["f_ref"]))
    lines.append("slip-area fraction: FE %.3f, half-space %.3f" % (r["slip_fe"], r["slip_hs"]))
    return lines


def creep_curve(prm, Fn, creepages, grid=DEFAULT_GRID):
    """Half-space F_x / F_N and slip-area fraction at each creepage (rows
    (xi, F_x / F_N, slip fraction), by xi). Each solution starts from the
    previous one at the next smaller |xi| (the branch followed from xi = 0);
    F_x(-xi) = -F_x(xi) (eta = 0, a symmetric patch), so one sign is solved."""
    law, _, _ = law_of(prm)
    V = float(prm["Wheelset/Rolling speed"])
    g, p, *_ = normal_case(prm, Fn, grid)
    load = p.sum() * g.dA
    solved, start = {}, None
    for m in sorted(set(abs(float(x)) for x in creepages)):
        if m == 0:
            solved[m] = (0.0, 0.0)
            continue
        sol = hs.bem.solve_rolling(g, p, [-m, 0.0], law, V, start=start)
        start = (sol["q"], sol["stick"], sol["f"])
        c = sol["contact"]
        solved[m] = (sol["q"][0].sum() * g.dA / load, (c & ~sol["stick"]).sum() / c.sum())
    rows = []
    for x in sorted(set(float(x) for x in creepages)):
        ratio, slip = solved[abs(x)]
        rows.append((x, -ratio if x > 0 else ratio, slip))
    return rows
