"""A profile run's FE contact patch against its half-space reference
(profile_reference.py), and the command line scripts/profile_reference.py.

The FE patch (patch_<instant>.csv: the rail-top nodes of the solution zone,
x along the track, y lateral from O, the main rigid contact point, in the
horizontal plane) is taken into each reference patch's tangent plane:
s = (y - y_P) / cos(delta_P), y_P the patch's point from O, delta_P its
contact angle (at 1:40, cos delta = 0.9997; the rail top's curvature across
the patch is neglected). With several reference patches each FE node in
contact goes to the patch whose point is nearest in s.

Compared per patch: area, length (x extent), width (s extent), p_max,
F_N, F_x / F_N and the slip-area fraction (FE: eq. 5 on the slave nodes,
as compare.patch_totals; reference: the elements in slip). Area and extents
count the nodes / elements with p >= P_SHARE p_max (5 %: the penalty
contact gives nodes beyond the patch's edge, touching master faces, a few
per cent of p_max), one node spacing / element added to the extents (each
node and element stands for a cell of that size), so both are quantised:
the FE's to its node spacing h, the reference's to its element.
An FE patch whose contact reaches the outermost rows of the patch file was
clipped by the solution zone (Geometry/Mesh/Solution zone half width): its
width, area and load are then lower bounds, flagged 'clipped'.
"""
import math
import os
import sys
import time

import numpy as np

from . import atomic_file
from . import compare as hc
from . import profile_reference as pr

MM = 1e-3
QUANTITIES = ("area", "length", "width", "p_max", "F_N", "fx_fn", "slip")


def spacing(values):
    """The median spacing of the distinct values (a node spacing)."""
    u = np.unique(np.round(values, 9))
    return float(np.median(np.diff(u))) if u.size > 1 else float("nan")


def fe_patches(P, ref):
    """The FE patch split and measured in the reference patches' frames: a
    list (one per reference patch) of dicts with the module's QUANTITIES
    and clipped."""
    inc = P["in_contact"] > 0
    y0 = ref["points"][0]["y"]
    pts = [p["point"] for p in ref["patches"]]
    s = [(P["y"] - (c["y"] - y0)) / math.cos(c["delta"]) for c in pts]
    owner = np.argmin(np.abs(np.array(s)), axis=0)
    hx, hy = spacing(P["x"]), spacing(P["y"])
    y_edge = (np.isclose(P["y"], P["y"].min()) | np.isclose(P["y"], P["y"].max()))
    out = []
    for k, c in enumerate(pts):
        m = inc & (owner == k)
        if not m.any():
            out.append(dict(dict.fromkeys(QUANTITIES, float("nan")), clipped=False, nodes=0))
            continue
        fn = float(P["F_n"][m].sum())
        fx = float((P["shear_x"][m] * P["area"][m]).sum())
        slip = m & (P["adhesion_eq5"] == 0)
        pm = float(P["pressure"][m].max())
        e = m & (P["pressure"] >= pr.P_SHARE * pm)
        out.append(dict(area=float(P["area"][e].sum()), length=np.ptp(P["x"][e]) + hx,
                        width=(np.ptp(P["y"][e]) + hy) / math.cos(c["delta"]),
                        p_max=pm, F_N=fn, fx_fn=fx / fn,
                        slip=float(P["area"][slip].sum() / P["area"][m].sum()),
                        clipped=bool((m & y_edge).any()), nodes=int(m.sum()), h=(hx, hy)))
    return out


def expectation(q, fe):
    """What to expect of quantity q of the FE patch FE (a fe_patches entry) on
    its mesh (doc/manual/halfspace.md, Profile runs), as text."""
    if fe.get("clipped") and q in ("area", "width", "F_N"):
        return "FE patch clipped by the solution zone: a lower bound"
    h = max(fe.get("h", (float("nan"),) * 2))
    return {"length": "extents: FE quantised to its node spacing (%.2f mm), penalty contact adds up to"
                      " a node at each edge" % (h / MM),
            "width": "extents: FE quantised to its node spacing (%.2f mm), penalty contact adds up to a"
                     " node at each edge" % (h / MM),
            "area": "nodal areas of the nodes in contact: edge nodes add up to h/2 around the perimeter",
            "p_max": "coarse meshes flatten peaks (Hertz: -3.6 %% at h 1.32 mm); h here %.2f mm" % (h / MM),
            }.get(q, "")


def ref_values(patch):
    """The reference patch's QUANTITIES (F_x / F_N and slip NaN without friction)."""
    m = patch["measures"]
    roll = patch.get("rolling")
    return dict(area=m["area"], length=m["length"], width=m["width"], p_max=m["p_max"],
                F_N=m["load"], fx_fn=roll["F_x"] / roll["F_N"] if roll else float("nan"),
                slip=roll["slip_fraction"] if roll else float("nan"))


# the creep forces and the spin moment per program patch (statistics)
PART_QUANTITIES = ("part_fx_fn", "part_fs_fn", "part_mn")


PART_FORCES = ("F_n", "F_x", "F_s", "M_n")


def turned(fs, fn, d):
    """(F_s, F_n) of a force given as (fs, fn) in the frame of contact angle
    delta, in the frame of contact angle delta - d (turned about x by d)."""
    return fs * math.cos(d) + fn * math.sin(d), -fs * math.sin(d) + fn * math.cos(d)


def reference_parts(ref):
    """The reference's forces split as the program splits its patches: each
    element of a solved group goes to the group's rigid point nearest in
    track y (the program's patch_of on y), and each part's forces are turned
    into that point's frame (its contact angle delta_k): a list, per rigid
    point, of dicts F_n, F_x, F_s [N] and M_n [N m] (the moment about the
    normal through the part's centre of pressure), or None where no group
    solved the point's tangential problem."""
    parts = [None] * len(ref["points"])
    for patch in ref["patches"]:
        roll = patch.get("rolling")
        if patch["grid"] is None or roll is None:
            continue
        g, p, q, c = patch["grid"], patch["p"], roll["q"], patch["point"]
        X, S = np.meshgrid(g.x, g.y, indexing="ij")
        y = c["y"] + S * math.cos(c["delta"])
        members = list(patch["group"])
        near = np.argmin([np.abs(y - ref["points"][i]["y"]) for i in members], axis=0)
        for j, i in enumerate(members):
            m = near == j
            fn = float(p[m].sum() * g.dA)
            if fn <= 0:
                continue
            fx, fs = (float(q[d][m].sum() * g.dA) for d in (0, 1))
            xc, sc = float((p * X)[m].sum() * g.dA / fn), float((p * S)[m].sum() * g.dA / fn)
            mn = float((((X - xc) * q[1] - (S - sc) * q[0])[m]).sum() * g.dA)
            F_s, F_n = turned(fs, fn, c["delta"] - ref["points"][i]["delta"])
            parts[i] = dict(F_n=F_n, F_x=fx, F_s=F_s, M_n=mn)
    return parts


def fe_parts(run, t, n, window=0.0):
    """The program's patch forces (statistics 'patch k F_n', F_x, F_s, M_n):
    the row nearest time t, or with window > 0 [m] their means over the last
    window of rolling before that row; a list of n dicts (None for a patch
    without columns), or None without them (a run that reports no patches)."""
    names, stats = hc.read_statistics(run)
    if stats is None or hc.column(names, stats, "patch 1 F_n") is None or not math.isfinite(t):
        return None
    row = int(np.argmin(np.abs(hc.column(names, stats, "time") - t)))
    if window > 0:
        x = hc.column(names, stats, "wheel x")
        sel = (x >= x[row] - window) & (x <= x[row])
        if sel.sum() < 4:
            raise ValueError("%s: fewer than 4 statistics rows in the last %g mm before t"
                             % (run, window * 1e3))
    out = []
    for k in range(n):
        cols = [hc.column(names, stats, "patch %d %s " % (k + 1, q)) for q in PART_FORCES]
        out.append(None if cols[0] is None else
                   dict(zip(PART_FORCES, (float(c[sel].mean() if window > 0 else c[row])
                                          for c in cols))))
    return out


def part_rows(run, t, ref):
    """Rows (k, quantity, FE, reference, difference) of F_x / F_n, F_s / F_n
    (differences) and M_n (ratio - 1) per program patch k."""
    rp = reference_parts(ref)
    fp = fe_parts(run, t, len(rp))
    rows = []
    if fp is None:
        return rows
    for k, (f, r) in enumerate(zip(fp, rp)):
        if f is None or r is None or f["F_n"] <= 0:
            continue
        for q, a, b in (("part_fx_fn", f["F_x"] / f["F_n"], r["F_x"] / r["F_n"]),
                        ("part_fs_fn", f["F_s"] / f["F_n"], r["F_s"] / r["F_n"]),
                        ("part_mn", f["M_n"], r["M_n"])):
            rows.append((k, q, a, b, a / b - 1 if q == "part_mn" else a - b))
    return rows


def compare_run(run, instant="t", case_dir=None, grid=pr.DEFAULT_GRID, log=None, load=None):
    """The FE patch of RUN at INSTANT against the reference at its time:
    dict ref (profile_reference.reference), fe (fe_patches), rows
    [(patch, quantity, FE, reference, FE / reference - 1)], t, xc, seconds;
    None without the patch file."""
    path = hc.patch_file(run, instant)
    P = hc.read_csv(path)
    if P is None:
        return None
    t0 = time.time()
    t, xc = hc.patch_header(path)
    ref = pr.reference(run, t, case_dir, grid, log, load)
    fe = fe_patches(P, ref)
    rows = []
    for k, (patch, f) in enumerate(zip(ref["patches"], fe)):
        if patch["grid"] is None:
            continue
        r = ref_values(patch)
        for q in QUANTITIES:
            diff = f[q] - r[q] if q in ("fx_fn", "slip") else f[q] / r[q] - 1
            rows.append((k, q, f[q], r[q], diff))
    rows += part_rows(run, t, ref)
    return dict(ref=ref, fe=fe, rows=rows, t=t, xc=xc, instant=instant, P=P,
                seconds=time.time() - t0)


def find_log(run):
    """The run's printed output if it lies where the tests and ./run.sh put it:
    RUN/wheelrail.log, RUN.log, or wheelrail.log beside RUN; else None."""
    run = os.path.normpath(run)
    for cand in (os.path.join(run, "wheelrail.log"), run + ".log",
                 os.path.join(os.path.dirname(run), "wheelrail.log")):
        if os.path.exists(cand):
            return cand
    return None


def as_comparison(run, instant="t", grid=pr.DEFAULT_GRID):
    """compare_run's result in the shape of compare.compare_patch's (what
    plot.py and the report page read): the main patch's solution along its
    row nearest s = 0 as 'axis', the FE's axis rows as 'fe', the RMS
    differences along them, 'hertz' the reference's semi-extents and p_max;
    'profile' the full result. Needs a run with friction (compare.law_of)."""
    prm = hc.read_parameters(run)
    hc.law_of(prm)  # a frictionless run: ValueError, as for the Hertzian case
    r = compare_run(run, instant, None, grid, find_log(run))
    if r is None:
        return None
    P, patch = r["P"], r["ref"]["patches"][0]
    g, p, sol = patch["grid"], patch["p"], patch["rolling"]
    speed = float(prm["Wheelset/Rolling speed"])
    j = int(np.argmin(np.abs(g.y)))
    axis = dict(x=g.x, p=p[:, j], q_x=sol["q"][0][:, j],
                s=speed * np.linalg.norm(sol["W"], axis=0)[:, j], contact=sol["contact"][:, j])
    rows = hc.axis_rows(P)
    x_fe = P["x"][rows] - r["xc"]
    p_hs = np.interp(x_fe, axis["x"], axis["p"], left=0., right=0.)
    q_hs = np.interp(x_fe, axis["x"], axis["q_x"], left=0., right=0.)
    used = (P["in_contact"][rows] > 0) | (p_hs > 0)
    fn, fx, slip_fe = hc.patch_totals(P)
    f_s = float(prm["Contact/Static friction coefficient"])
    m, p0 = patch["measures"], float(p.max())
    rms = lambda a, b: float(np.sqrt(np.mean((a[used] - b[used]) ** 2)))
    return dict(Fn=fn, Fx=fx, fx_hs=sol["F_x"] / sol["F_N"] * fn, xc=r["xc"], t=r["t"],
                creep_fe=r["ref"]["xi"], creep_hs=r["ref"]["xi"], slip_fe=slip_fe,
                slip_hs=sol["slip_fraction"], p0_hs=p0, f_ref=f_s,
                rms_p=rms(P["pressure"][rows], p_hs) / p0,
                rms_q=rms(P["shear_x"][rows], q_hs) / (f_s * p0), axis=axis,
                hertz=dict(a=0.5 * m["length"], b=0.5 * m["width"], p0=p0, area=m["area"],
                           approach=patch["info"]["approach"]),
                sol=sol, grid=g, note="profile run: the reference is the half-space solution on the"
                " profiles' gap at the run's creepages (not at the patch's F_x)",
                fe=dict(x=x_fe, p=P["pressure"][rows], q_x=P["shear_x"][rows]),
                seconds=r["seconds"], law=r["ref"]["law"], instant=instant, profile=r)


# ----------------------------------------------------------------------------
# Text, CSV, figure

_LABEL = dict(area=("area", "mm^2", 1e6), length=("length along x", "mm", 1e3),
              width=("width along s", "mm", 1e3), p_max=("p_max", "MPa", 1e-6),
              F_N=("F_N", "kN", 1e-3), fx_fn=("F_x / F_N", "-", 1.0),
              slip=("slip-area fraction", "-", 1.0), part_fx_fn=("patch F_x / F_n", "-", 1.0),
              part_fs_fn=("patch F_s / F_n", "-", 1.0), part_mn=("patch M_n", "N m", 1.0))


def point_lines(ref):
    """The rigid contact points and their check against the program's print."""
    lines = []
    for k, c in enumerate(ref["points"]):
        lines.append("point %d: y %.3f mm (track frame; %.3f from O), separation %.4f mm, delta %+.3f"
                     " deg, r %.3f mm" % (k, c["y"] / MM, (c["y"] - ref["points"][0]["y"]) / MM,
                                          c["gap"] / MM, math.degrees(c["delta"]), c["r"] / MM))
    if ref["check"] is None:
        lines.append("no log of the run given: the points are not checked against the program's")
    for c in ref["check"] or []:
        lines.append("point %d, profiles.py - program: y %+.4f mm, separation %+.5f mm, angle "
                     "%+.4f deg (the program's sign: %s), rolling radius %+.4f mm; radius across"
                     " %.1f mm (fit over +-2 mm) vs %.1f mm (program, local)"
                     % (c["k"], c["dy"] / MM, c["dsep"] / MM, math.degrees(c["dangle"]),
                        "delta" if c["sign"] > 0 else "-delta", c["dr"] / MM,
                        c["across"] / MM, c["across_printed"] / MM))
    if ref["printed"] is not None and len(ref["printed"]) != len(ref["points"]):
        lines.append("the program printed %d points, profiles.py finds %d"
                     % (len(ref["printed"]), len(ref["points"])))
    return lines


def summary_lines(r):
    """The comparison as text lines."""
    ref = r["ref"]
    lines = ["profile reference at instant %s (t = %.6g s): vertical load %.2f kN (%s), %s, "
             "the run's creepage (statistics) %.4g" % (r["instant"], r["t"], ref["load"] / 1e3,
                                              ref["load_source"], ref["law"], ref["xi"])]
    lines.append("wheel angular velocity at t %.6g rad/s: the run's r_eff %.4f mm; with the undeformed"
                 " rolling radius at O, %.4f mm, xi would be %.4g (not used)" % (ref["omega"], ref["r_eff"] / MM,
                 ref["points"][0]["r"] / MM, ref["xi_undeformed"]))
    lines += point_lines(ref)
    for k, (patch, f) in enumerate(zip(ref["patches"], r["fe"])):
        if patch["grid"] is None:
            lines.append("patch %d: no contact at the common approach" % k)
            continue
        roll = patch.get("rolling")
        lines.append("patch %d (points %s, grid %d x %d): approach %.2f um%s%s" % (
            k, ",".join(str(i) for i in patch["group"]), patch["grid"].shape[0],
            patch["grid"].shape[1], patch["info"]["approach"] * 1e6,
            "; phi %.4g 1/m, xi %.4g" % (roll["phi"], roll["xi"]) if roll else "",
            "; FE patch CLIPPED by the solution zone (width, area, F_N lower bounds)"
            if f["clipped"] else ""))
    lines.append("%-5s %-20s %6s %12s %12s %10s" % ("patch", "quantity", "unit", "FE", "reference",
                                                   "FE/ref-1"))
    for k, q, fe, rv, d in r["rows"]:
        label, unit, scale = _LABEL[q]
        lines.append("%-5d %-20s %6s %12.5g %12.5g %+10.4f%s" % (
            k, label, unit, fe * scale, rv * scale, d, "  (difference)" if q in ("fx_fn", "slip", "part_fx_fn", "part_fs_fn") else ""))
    return lines


def write_csv(path, r):
    """The comparison rows as CSV (SI units)."""
    with atomic_file.replacing(path) as tmp, open(tmp, "w") as f:
        f.write("patch,quantity,fe,reference,difference,clipped\n")
        for k, q, fe, rv, d in r["rows"]:
            clipped = q in QUANTITIES and r["fe"][k]["clipped"]
            f.write("%d,%s,%.9g,%.9g,%.9g,%d\n" % (k, q, fe, rv, d, clipped))


def figure(path, r, title=None):
    """make_figure written to PATH."""
    import matplotlib.pyplot as plt
    fig = make_figure(r, title)
    with atomic_file.replacing(path, ".tmp.png") as tmp:
        fig.savefig(tmp, dpi=110)
    plt.close(fig)


def make_figure(r, title=None):
    """FE against reference per patch: area, length, width, p_max (bars), and
    the pressure along x = 0 against s (a matplotlib figure)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    qs = ("area", "length", "width", "p_max")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw=dict(width_ratios=(1, 1.4)))
    ax = axes[0]
    rows = [row for row in r["rows"] if row[1] in qs]
    xs = np.arange(len(rows))
    ax.bar(xs - 0.2, [row[2] / row[3] for row in rows], 0.4, label="FE / reference")
    ax.axhline(1.0, color="k", lw=0.8)
    ax.set_xticks(xs)
    ax.set_xticklabels(["%s\n(patch %d)" % (q.replace("_", " "), k) if len(r["fe"]) > 1 else q
                        .replace("_", " ") for k, q, *_ in rows], fontsize=8)
    ax.set_ylabel("FE / reference")
    for x, row in zip(xs, rows):
        ax.text(x - 0.2, row[2] / row[3], "%.3g\n%.3g" % (row[2] * _LABEL[row[1]][2],
                                                       row[3] * _LABEL[row[1]][2]),
                ha="center", va="bottom", fontsize=7)
    ax.set_ylim(0, 1.35)
    ax.set_title("FE / reference (labels: FE, reference in mm, mm^2, MPa)", fontsize=9)
    _pressure_panel(axes[1], r)
    fig.suptitle(title or "profile run against its half-space reference at instant %s" % r["instant"])
    fig.tight_layout()
    return fig


def _pressure_panel(ax, r):
    """Pressure along the row nearest x = 0: FE nodes and reference elements, against s."""
    P, ref = r["P"], r["ref"]
    y0 = ref["points"][0]["y"]
    row = np.isclose(P["x"] - r["xc"], (P["x"] - r["xc"])[np.argmin(np.abs(P["x"] - r["xc"]))])
    c0 = ref["patches"][0]["point"]
    s_fe = P["y"][row] / math.cos(c0["delta"])
    o = np.argsort(s_fe)
    ax.plot(s_fe[o] / MM, P["pressure"][row][o] * 1e-6, "o-", ms=4, label="FE, nodes near x = 0")
    for k, patch in enumerate(ref["patches"]):
        if patch["grid"] is None:
            continue
        g, c = patch["grid"], patch["point"]
        i = int(np.argmin(np.abs(g.x)))
        shift = (c["y"] - y0) / math.cos(c0["delta"])
        ax.step((g.y + shift) / MM, patch["p"][i] * 1e-6, where="mid",
                label="half-space reference, patch %d (x = %.2f mm)" % (k, g.x[i] / MM))
    for c in ref["points"]:
        ax.axvline((c["y"] - y0) / math.cos(c0["delta"]) / MM, color="0.6", ls=":", lw=0.8)
    ax.axvspan(P["y"].max() / MM, ax.get_xlim()[1], color="0.9", zorder=0)
    ax.axvspan(ax.get_xlim()[0], P["y"].min() / MM, color="0.9", zorder=0,
               label="outside the FE solution zone")
    ax.set_xlabel("s [mm] (from O, tangent plane of the main point; dotted: rigid contact points)")
    ax.set_ylabel("pressure [MPa]")
    ax.legend(fontsize=7, loc="lower center")
    ax.grid(True, lw=0.3)


def main(argv=None):
    import argparse
    ap = argparse.ArgumentParser(
        description="The half-space reference of a profile run (non-Hertzian normal problem on the "
        "profiles' gap, steady rolling at the run's creepages and law) and its FE patch against it "
        "(scripts/wheelrail_post/profile_reference.py, profile_compare.py).")
    ap.add_argument("run", help="the run's output directory (parameters.prm, statistics, patch files)")
    ap.add_argument("--instant", default="t", help="the patch file patch_INSTANT.csv (t)")
    ap.add_argument("--case-dir", default=None,
                    help="the case file's directory, for relative profile file names (default: the"
                    " current directory, then the run directory's parent)")
    ap.add_argument("--log", default=None,
                    help="the run's printed output, to check the contact points against (default: "
                    "RUN/wheelrail.log, RUN.log or wheelrail.log beside RUN, if present)")
    ap.add_argument("--grid", default="%dx%d" % pr.DEFAULT_GRID, help="reference grid NXxNY (32x33)")
    ap.add_argument("--load", type=float, default=None,
                    help="vertical wheel load [N] (default: the statistics' F_N at the instant)")
    ap.add_argument("--csv", default=None, help="write the comparison rows here")
    ap.add_argument("--png", default=None, help="write the figure here")
    ap.add_argument("--xi-for", type=float, default=None, metavar="FX_FN",
                    help="print instead the creepage xi at which the reference gives F_x / F_N = "
                    "FX_FN at the static load (RUN may be a dry run), for a case that holds it")
    a = ap.parse_args(argv)
    grid = hc.parse_grid(a.grid)
    if grid is None:
        print("profile_reference.py: error: --grid: NXxNY, 4 <= NX <= 512, NY odd", file=sys.stderr)
        return 2
    if a.xi_for is not None:
        try:
            xi, achieved = pr.creepage_for(a.run, a.xi_for, a.case_dir, grid, a.load)
        except (pr.ReferenceError, ValueError, KeyError, OSError) as e:
            print("profile_reference.py: error: %s" % e, file=sys.stderr)
            return 2
        print("xi %.4e gives F_x / F_N %.4f (half-space reference, grid %d x %d)" % ((xi, achieved) + grid))
        return 0
    log = a.log if a.log is not None else find_log(a.run)
    try:
        r = compare_run(a.run, a.instant, a.case_dir, grid, log, a.load)
    except (pr.ReferenceError, ValueError, KeyError, OSError) as e:
        print("profile_reference.py: error: %s" % e, file=sys.stderr)
        return 2
    if r is None:
        print("profile_reference.py: error: no %s" % hc.patch_file(a.run, a.instant), file=sys.stderr)
        return 2
    for line in summary_lines(r):
        print(line)
    print("(%.1f s)" % r["seconds"])
    if a.csv:
        write_csv(a.csv, r)
    if a.png:
        figure(a.png, r)
    return 0


def make_profiles_figure(r):
    """The profiles at the run's lateral shift in the track frame (rail top
    and wheel surface lowered onto it), the rigid contact points, and the FE
    patch at the instant across them: the lateral extent of each patch's
    nodes with at least 5 % of p_max, drawn on the rail profile (a matplotlib
    figure)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    pair, points, P = r["ref"]["pair"], r["ref"]["points"], r["P"]
    ys = [pt["y"] for pt in points]
    y = np.linspace(min(ys) - 25 * MM, max(ys) + 25 * MM, 801)
    lo, hi = pair.overlap()
    y = y[(y >= lo) & (y <= hi)]
    fig, ax = plt.subplots(figsize=(9, 4.2))
    ax.plot(y / MM, pair.rail_z(y) / MM, color="0.3", label="rail (inclined)")
    ax.plot(y / MM, (pair.wheel_z(y) - pair.dz) / MM, color="tab:blue", label="wheel (lowered)")
    for k, pt in enumerate(points):
        ax.plot(pt["y"] / MM, pair.rail_z(np.array([pt["y"]]))[0] / MM, "kx", ms=9,
                label="rigid contact points" if k == 0 else None)
    strong = P["pressure"] >= 0.05 * P["pressure"].max()
    patch = P["patch"] if "patch" in P else np.ones_like(P["y"])
    colours = ("tab:red", "tab:orange", "tab:green")
    for k in np.unique(patch[strong]).astype(int):
        yk = P["y"][strong & (patch == k)] + points[0]["y"]
        seg = np.linspace(yk.min(), yk.max(), 50)
        ax.plot(seg / MM, pair.rail_z(seg) / MM, lw=6, alpha=0.6, color=colours[(k - 1) % 3],
                label="FE patch %d: %.1f mm wide (p >= 5 %% p_max)" % (k, np.ptp(yk) / MM))
    ax.set_xlabel("y from the rail's centre line, towards the gauge side [mm]")
    ax.set_ylabel("z [mm]")
    ax.set_aspect("auto")
    ax.legend(fontsize=8, loc="lower left")
    ax.set_title("the patches on the profiles at instant %s" % r["instant"])
    fig.tight_layout()
    return fig
