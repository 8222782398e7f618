"""Creep-force table of a wheelrail case: F_x / F_N against the longitudinal creepage.

Usage:
    scripts/creep_curve.py CASE.prm [--creepages LIST | --levels LIST] [--np N]
                           [--out DIR] [--window MM] [--runup-damping ALPHA]
                           [--hs-grid NXxNY] [--wheelrail PATH] [--solve-each-static-start]
                           [--plot-only] [--check]

CASE.prm is any rolling case (the paper cases, prm/default.prm, ...). For each
creepage xi the case is run with the creepage held for the whole run
(Wheelset/Initial creepage = xi, Creepage control time = 1 s, Nominal traction
coefficient = 0; the wheel's angular velocity is held at V (1 - xi) / r) and,
unless --runup-damping 0, with the wheel's rigid motion on its web damped at
ALPHA [1/s] (Run-up damping shape = wheel rigid motion, default 8000 1/s,
about critical for the wheel's 680 Hz torsional mode; doc/notes/convergence.md):
that is what makes the traction steady within a few tens of mm of rolling. A
torque-driven case needs the wheelset's spin-up (a lag of about 1 ms) and its
torsional vibration to die out first, which takes longer than the runs last.
The runs share one static start (the first solves it, the others read it:
Wheelset/Static start state = DIR/static_start, removed after the runs) unless
--solve-each-static-start.

--creepages gives xi directly (driving: xi < 0); --levels gives F_x / F_N
targets instead, and xi is taken from the half-space creep curve of the case's
law at its static wheel load (the FE's own curve lies within a few percent at
the paper's interface settings; at a soft interface its creepage is larger).
Default: --levels 0.1,0.2,0.3,0.4.

Each row is measured over the last --window mm (default 20) of rolling before
the patch's instant t (the wheel centre at x = 0, point O), or before the end
of the run if it ends earlier; the slip-area fraction and the largest
micro-slip come from the patch at t. DIR (default results/creep_curve/CASE)
then holds:

  creep_table.csv   '#' lines with the case's metadata, then one row per run:
                    creepage, Fx_over_Fn, Fy_over_Fn, F_N_N, mu_a_spread,
                    slip_area_fraction, max_micro_slip_m_s,
                    trailing_micro_slip_m_s, halfspace_Fx_over_Fn,
                    halfspace_slip_area_fraction (the half-space solution of
                    the same law at the row's creepage and the runs' mean F_N)
  creep_table.h5    the same: /creep_table (one dataset per column, 'unit'
                    attributes), /halfspace (the half-space curve: creepage,
                    Fx_over_Fn, slip_area_fraction) and the metadata as
                    attributes of the root (load, radii, material, friction
                    law and coefficients, speed, mesh, step, window)
  creep_table.png   F_x / F_N and the slip-area fraction against xi, FE rows
                    beside the half-space curve
  xi_K.prm, xi_K/   the runs (K = 1, 2, ...)

For a multibody code: read creep_table.h5 (or the CSV) and interpolate
Fx_over_Fn in creepage; it holds for the metadata's load, radii, material,
speed and friction law.

--plot-only re-reads existing runs; --check verifies that the CSV and the HDF5
file hold the same finite rows and that the figure shows the half-space curve
(exit status 1 if not).
"""
import argparse
import os
import shutil
import sys
import time

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import SCRIPTS_DIR  # noqa: E402
from . import atomic_file  # noqa: E402
from . import compare as hc  # noqa: E402  (readers, the half-space)
from . import plots as plot  # noqa: E402  (Report, the figure check)
from . import sweep  # noqa: E402  (running a case)

# (column, unit, description) of the table, in order
COLUMNS = [
    ("creepage", "-", "rigid creepage (v_x - omega r) / v_x, mean over the window"),
    ("Fx_over_Fn", "-", "longitudinal force over normal force (mu_a), mean over the window"),
    ("Fy_over_Fn", "-", "lateral force over normal force, mean over the window"),
    ("F_N_N", "N", "normal force, mean over the window"),
    ("mu_a_spread", "-", "(max - min) / mean of mu_a over the window: how steady the row is"),
    ("slip_area_fraction", "-", "area fraction of the patch at t that slips (eq. 5)"),
    ("max_micro_slip_m_s", "m/s", "largest micro-slip s_n of the patch at t (window means if written)"),
    ("trailing_micro_slip_m_s", "m/s", "mean micro-slip of the trailing part, mean over the window"),
    ("halfspace_Fx_over_Fn", "-", "half-space solution of the same law at the row's creepage"),
    ("halfspace_slip_area_fraction", "-", "its slip-area fraction"),
]
# metadata: (attribute, parameter, unit)
METADATA = [
    ("wheel_radius", "Geometry/Wheel/Radius", "m"),
    ("rail_profile_radius", "Geometry/Rail/Profile radius", "m"),
    ("youngs_modulus", "Material/Young's modulus", "Pa"),
    ("poissons_ratio", "Material/Poisson's ratio", "-"),
    ("density", "Material/Density", "kg/m^3"),
    ("rolling_speed", "Wheelset/Rolling speed", "m/s"),
    ("friction_law", "Contact/Friction law", ""),
    ("static_friction_coefficient", "Contact/Static friction coefficient", "-"),
    ("dynamic_friction_coefficient", "Contact/Dynamic friction coefficient", "-"),
    ("decay_coefficient", "Contact/Decay coefficient", "s/m"),
    ("slip_rate", "Contact/Slip rate", ""),
    ("friction_relaxation_length", "Contact/Friction relaxation length", "m"),
    ("penalty_scale_factor", "Contact/Penalty scale factor", "-"),
    ("two_pass", "Contact/Two pass", ""),
    ("contact_damping", "Contact/Contact damping", "-"),
    ("minimum_cell_size", "Geometry/Mesh/Minimum cell size", "m"),
    ("time_step", "Time integration/Time step", "s"),
]
# half-space curve magnitudes beside the runs' own creepages
CURVE = [2.5e-4, 5e-4, 1e-3, 1.5e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3, 8e-3, 1e-2, 1.2e-2]


def fail(message):
    sys.exit("creep_curve.py: " + message)


def write_case(case, path, outdir, sets):
    """PATH including CASE with the entries of @p sets ({subsection: {entry: value}})."""
    sweep.write_variant(case, path, outdir, {"%s/%s" % (section, entry): value
                                             for section, entries in sets.items()
                                             for entry, value in entries.items()},
                        "scripts/creep_curve.py")


def static_load(prm):
    """The static wheel load [N]: (unsprung + sprung mass) g."""
    m = float(prm["Wheelset/Unsprung mass"]) + float(prm["Wheelset/Sprung mass"])
    g = np.linalg.norm([float(v) for v in prm["Time integration/Gravity"].split(",")])
    return m * (g if g > 0 else 9.81)


def creepages_for(prm, levels, grid):
    """xi at which the half-space solution of the case's law reaches each
    F_x / F_N of @p levels (driving), at the static load."""
    xis = sorted(set([-m for m in CURVE] + [-m * 1.5 for m in CURVE[-3:]] + [0.0]))
    curve = hc.creep_curve(prm, static_load(prm), xis, grid)
    xi = np.array([c[0] for c in curve])[::-1]  # 0 down to the most negative
    ratio = np.array([c[1] for c in curve])[::-1]
    top = int(np.argmax(ratio))  # the rising branch only
    out = []
    for level in levels:
        if not 0 < level < ratio[top]:
            fail("--levels %g: the half-space creep curve of this law reaches at most %.4f"
                 % (level, ratio[top]))
        out.append(float(np.interp(level, ratio[:top + 1], xi[:top + 1])))
    return out


def measure(run_dir, window):
    """One table row (without the half-space columns) from RUN_DIR."""
    names, stats = hc.read_statistics(run_dir)
    if stats is None:
        fail("%s: no statistics" % run_dir)
    x = hc.column(names, stats, "wheel x")
    end = min(0.0, x.max())
    sel = (x >= end - window) & (x <= end)
    if sel.sum() < 3:
        fail("%s: fewer than 3 statistics rows in the last %g mm before x = %g mm"
             % (run_dir, window * 1e3, end * 1e3))
    col = lambda prefix: hc.column(names, stats, prefix)[sel]
    mu, fn = col("mu_a"), col("F_N")
    row = dict(creepage=col("creepage").mean(), Fx_over_Fn=mu.mean(),
               Fy_over_Fn=(col("F_lateral") / fn).mean(), F_N_N=fn.mean(),
               mu_a_spread=(mu.max() - mu.min()) / abs(mu.mean()),
               trailing_micro_slip_m_s=col("trailing micro-slip").mean(),
               slip_area_fraction=float("nan"), max_micro_slip_m_s=float("nan"))
    P = hc.read_patch(run_dir, "t")
    if P is not None:
        row["slip_area_fraction"] = hc.patch_totals(P)[2]
        M = hc.read_patch(run_dir, "t_mean")
        if M is not None:
            row["max_micro_slip_m_s"] = M["slip_velocity"][M["contact"] > 0.5].max()
        else:
            row["max_micro_slip_m_s"] = P["slip_velocity"][P["in_contact"] > 0].max()
    return row


def step_used(run_dir):
    """The time step the run took [s] (Time step = 0 asks for the stable one)."""
    names, stats = hc.read_statistics(run_dir)
    step, t = hc.column(names, stats, "step"), hc.column(names, stats, "time")
    return float((t[-1] - t[0]) / (step[-1] - step[0])) if len(t) > 1 else float("nan")


def metadata(case, prm, rows, window, run_dir):
    meta = {"case": os.path.abspath(case), "static_wheel_load_N": static_load(prm),
            "time_step_used_s": step_used(run_dir),
            "mean_normal_force_N": float(np.mean([r["F_N_N"] for r in rows])),
            "window_m": window, "written": time.strftime("%Y-%m-%d %H:%M:%S %Z"),
            "columns": "; ".join("%s [%s]: %s" % c for c in COLUMNS)}
    for name, entry, unit in METADATA:
        value = prm.get(entry, "")
        try:
            value = float(value)
        except ValueError:
            pass
        meta[name] = value
        if unit:
            meta[name + "_unit"] = unit
    return meta


def write_csv(path, meta, rows):
    lines = ["# wheelrail creep-force table (scripts/creep_curve.py)"]
    lines += ["# %s = %s" % kv for kv in meta.items()]
    lines.append(",".join(c[0] for c in COLUMNS))
    lines += [",".join("%.6g" % r[c[0]] for c in COLUMNS) for r in rows]
    with atomic_file.replacing(path) as tmp, open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_h5(path, meta, rows, curve):
    with atomic_file.replacing(path) as tmp, h5py.File(tmp, "w") as f:
        for k, v in meta.items():
            f.attrs[k] = v
        g = f.create_group("creep_table")
        for name, unit, text in COLUMNS:
            d = g.create_dataset(name, data=np.array([r[name] for r in rows]))
            d.attrs["unit"], d.attrs["description"] = unit, text
        h = f.create_group("halfspace")
        h.attrs["description"] = ("Kalker's exact steady rolling (scripts/halfspace.py) of the same "
                                  "law at the mean normal force")
        for k, name in enumerate(("creepage", "Fx_over_Fn", "slip_area_fraction")):
            h.create_dataset(name, data=np.array([c[k] for c in curve]))


def plot_table(rep, rows, curve, grid, title):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    xi = np.array([c[0] for c in curve]) * 1e3
    for ax, k, fe, label in ((axes[0], 1, "Fx_over_Fn", "F_x / F_N"),
                             (axes[1], 2, "slip_area_fraction", "slip-area fraction")):
        ax.plot(xi, [c[k] for c in curve], "-", c="tab:blue", lw=2, alpha=0.6,
                label="half-space, same law (%d x %d)" % grid)
        ax.plot([r["creepage"] * 1e3 for r in rows], [r[fe] for r in rows], "o", c="tab:red",
                mec="k", label="FE, held creepage (window means)" if k == 1 else "FE, patch at t")
        ax.axhline(0, c="k", lw=0.5)
        ax.set_xlabel("rigid creepage xi [1e-3] (driving: xi < 0)")
        ax.set_ylabel(label)
        ax.legend(fontsize=8)
    axes[0].set_title(title, fontsize=9)
    rep.save(fig, "creep_table.png", "Creep-force table: F_x / F_N and the slip-area fraction against "
             "the creepage, FE runs with the creepage held, beside the half-space solution")


def check(rep, csv_path, h5_path, rows):
    problems = []
    with h5py.File(h5_path, "r") as f:
        for name, _, _ in COLUMNS:
            a = f["creep_table"][name][()]
            b = np.array([r[name] for r in rows])
            if a.shape != b.shape or not np.allclose(a, b, rtol=1e-5, equal_nan=True):
                problems.append("%s: %s differs from the rows" % (h5_path, name))
    table = hc.read_csv(csv_path)
    for name, _, _ in COLUMNS:
        if table is None or not np.allclose(table[name], [r[name] for r in rows], rtol=1e-5):
            problems.append("%s: %s differs from the rows or is not finite" % (csv_path, name))
    if not plot.shows_half_space(rep, "creep_table.png"):
        problems.append("creep_table.png: no half-space curve")
    rep.exit_with_check(problems)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("case", help="parameter file of a rolling case")
    which = parser.add_mutually_exclusive_group()
    which.add_argument("--creepages", help="creepages xi to run, e.g. -1e-3,-3e-3 (driving < 0)")
    which.add_argument("--levels", help="F_x / F_N targets; xi from the half-space creep curve "
                       "[default 0.1,0.2,0.3,0.4]")
    parser.add_argument("--np", type=int, default=1, help="MPI ranks per run")
    parser.add_argument("--out", help="output directory [default results/creep_curve/CASE]")
    parser.add_argument("--window", type=float, default=20., help="window of the means [mm], > 0")
    parser.add_argument("--runup-damping", type=float, default=8000.,
                        help="damping of the wheel's rigid motion [1/s]; 0 keeps the case's")
    parser.add_argument("--hs-grid", default="48x33", help="half-space elements NXxNY (NY odd)")
    parser.add_argument("--wheelrail", default=os.path.join(SCRIPTS_DIR,
                                                            "..", "build", "wheelrail"))
    parser.add_argument("--solve-each-static-start", action="store_true",
                        help="every run solves its static start (default: the first run solves it, "
                             "the others read it, Wheelset/Static start state)")
    parser.add_argument("--plot-only", action="store_true")
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()

    grid = hc.parse_grid(args.hs_grid)
    if grid is None:
        parser.error("--hs-grid %s: expected NXxNY, NX 4..512, NY odd 3..511" % args.hs_grid)
    if not os.path.isfile(args.case):
        fail("no such parameter file: %s" % args.case)
    if not args.window > 0 or args.runup_damping < 0 or args.np < 1:
        parser.error("--window > 0, --runup-damping >= 0 and --np >= 1 are required")
    name = os.path.splitext(os.path.basename(args.case))[0]
    out = args.out or os.path.join("results", "creep_curve", name)
    os.makedirs(out, exist_ok=True)
    window = args.window * 1e-3

    # the case's parameters as the program reads them (a dry run)
    dry = os.path.join(out, "dry")
    if not args.plot_only or not os.path.exists(os.path.join(dry, "parameters.prm")):
        write_case(args.case, dry + ".prm", dry, {"Problem": {"Dry run": "true"}})
        sweep.run_case(dry + ".prm", 1, args.wheelrail, dry + ".log", "creep_curve.py")
    prm = hc.read_parameters(dry)
    try:
        if args.creepages:
            xis = [float(v) for v in args.creepages.split(",") if v.strip()]
        else:
            levels = [float(v) for v in (args.levels or "0.1,0.2,0.3,0.4").split(",") if v.strip()]
            xis = None if args.plot_only else creepages_for(prm, levels, grid)
    except ValueError as e:
        parser.error(str(e))
    if xis is not None and (not xis or any(abs(x) > 0.1 for x in xis)):
        fail("creepages must be in [-0.1, 0.1] (Wheelset/Initial creepage)")

    runs = []
    if args.plot_only:
        k = 1
        while os.path.exists(os.path.join(out, "xi_%d" % k, "statistics")):
            runs.append(os.path.join(out, "xi_%d" % k))
            k += 1
    else:
        sets = {"Wheelset": {"Nominal traction coefficient": "0", "Creepage control time": "1"}}
        if args.runup_damping > 0:
            sets["Wheelset"].update({"Run-up damping": "%g" % args.runup_damping,
                                     "Run-up damping shape": "wheel rigid motion",
                                     "Run-up time": "1"})
        # the runs differ in creepage only: one static start
        state = None if args.solve_each_static_start else os.path.join(out, "static_start")
        if state:
            shutil.rmtree(state, ignore_errors=True)
            sets["Wheelset"]["Static start state"] = os.path.abspath(state)
        for k, xi in enumerate(xis, 1):
            path = os.path.join(out, "xi_%d" % k)
            sets["Wheelset"]["Initial creepage"] = "%.6g" % xi
            write_case(args.case, path + ".prm", path, sets)
            print("creep_curve.py: running %s (xi = %.4g) on %d rank(s)" % (path + ".prm", xi, args.np),
                  flush=True)
            t0 = time.time()
            sweep.run_case(path + ".prm", args.np, args.wheelrail, path + ".log", "creep_curve.py")
            print("  %.0f s" % (time.time() - t0), flush=True)
            runs.append(path)
        if state:
            shutil.rmtree(state, ignore_errors=True)
    if not runs:
        fail("no runs in %s" % out)

    rows = [measure(r, window) for r in runs]
    fn = float(np.mean([r["F_N_N"] for r in rows]))
    sign = -1 if np.mean([r["creepage"] for r in rows]) <= 0 else 1
    top = max([CURVE[-1]] + [1.2 * abs(r["creepage"]) for r in rows])
    xis_hs = sorted(set([0.0] + [sign * m for m in CURVE + [top]] + [r["creepage"] for r in rows]))
    t0 = time.time()
    curve = hc.creep_curve(prm, fn, xis_hs, grid)
    at = {c[0]: c for c in curve}
    for r in rows:
        r["halfspace_Fx_over_Fn"], r["halfspace_slip_area_fraction"] = at[r["creepage"]][1:]
    hs_seconds = time.time() - t0

    meta = metadata(args.case, prm, rows, window, runs[0])
    csv_path, h5_path = os.path.join(out, "creep_table.csv"), os.path.join(out, "creep_table.h5")
    write_csv(csv_path, meta, rows)
    write_h5(h5_path, meta, rows, curve)
    rep = plot.Report(out)
    plot_table(rep, rows, curve, grid, "%s: %s law, F_N %.1f kN, V %s m/s, h %s m"
               % (name, prm.get("Contact/Friction law", "?"), fn * 1e-3,
                  prm.get("Wheelset/Rolling speed", "?"), prm.get("Geometry/Mesh/Minimum cell size", "?")))
    for r in rows:
        print("creep table: xi %.4g  F_x/F_N %.4f (half-space %.4f, %+.1f %%)  spread %.1f %%  "
              "slip area %.3f (half-space %.3f)  max s_n %.3f m/s"
              % (r["creepage"], r["Fx_over_Fn"], r["halfspace_Fx_over_Fn"],
                 100 * (r["Fx_over_Fn"] / r["halfspace_Fx_over_Fn"] - 1), 100 * r["mu_a_spread"],
                 r["slip_area_fraction"], r["halfspace_slip_area_fraction"], r["max_micro_slip_m_s"]))
    print("half-space curve: %d x %d elements, %d creepages, %.1f s" % (grid + (len(curve), hs_seconds)))
    print("creep table: %s, %s, %s" % (csv_path, h5_path, os.path.join(out, "creep_table.png")))
    if args.check:
        check(rep, csv_path, h5_path, rows)

