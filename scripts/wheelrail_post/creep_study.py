"""Lateral creep force and spin moment of profile cases against the half-space reference.

Usage:
    scripts/creep_study.py CASE.prm [CASE.prm ...] [--etas LIST] [--set ENTRY=VALUE ...]
                           [--rolling MM] [--np N] [--out DIR] [--grid NXxNY]
                           [--window MM] [--wheelrail PATH] [--plot-only]

Each CASE (a rolling case with profile files, so that the statistics carry
the patch columns) is run once per lateral creepage eta of --etas (default:
the case's own), with the longitudinal creepage held at 0 at O
(Wheelset/Initial creepage = 0, Creepage control time = 1 s, no driving
torque) and the wheel's rigid motion on its web damped at 8000 1/s (Run-up
damping, as scripts/creep_curve.py); --set changes any further entry of
every run (e.g. --set "Geometry/Mesh/Minimum cell size=0.00132" --set "Time
integration/Time step=1.04e-7" for a coarser study). The spin comes from the
profiles (a coned tread, the contact angle of S1002 on 60E1): its study is a
list of cases.

The lateral force relaxes through the wheel's lateral deflection (a time
constant of about 3 ms at 140 km/h): it is steady only after some 350 mm of
rolling. --rolling MM starts the wheel MM before O (the rail 100 mm further
back) and ends the run 1.5 mm past O; the shipped profile cases roll 450 mm
(prm/lateral_run_in.prm).

Every run is compared with the half-space solution of the same gap, load and
creepages at instant t (scripts/profile_reference.py: the run's xi, eta and
the profiles' phi), split at the program's patch boundaries
(profile_compare.reference_parts): per patch k, F_s / F_n and F_x / F_n
(differences) and the spin moment M_n about the patch's centre of pressure
(ratio), the FE's as means over the last --window mm (default 20) before t.
The lateral force of the whole contact, F_s / F_n of all patches in the
main patch's frame, is compared too; the drift (the main patch's F_s / F_n
over the window's second half minus its first half) says whether the run
was steady. DIR (default results/creep_study) then holds:

  creep_study.csv   one row per run and patch: case, eta, phi, xi, patch, F_n,
                    F_s/F_n, F_x/F_n, M_n (FE and reference), F_s/F_n of the
                    contact (FE, reference), drift
  creep_study.png   F_s / F_n against eta and M_n against phi, FE beside the
                    reference
  CASE_eta_K.prm, CASE_eta_K/  the runs

--plot-only re-reads existing runs.
"""
import argparse
import math
import os
import sys
import time

import numpy as np

from . import SCRIPTS_DIR
from . import atomic_file
from . import compare as hc
from . import profile_compare as pc
from . import profile_reference as pr
from . import sweep

COLUMNS = ("case", "eta", "phi", "xi", "patch", "F_n_N", "fe_Fs_over_Fn", "ref_Fs_over_Fn",
           "fe_Fx_over_Fn", "ref_Fx_over_Fn", "fe_Mn_Nm", "ref_Mn_Nm", "fe_contact_Fs_over_Fn",
           "ref_contact_Fs_over_Fn", "fe_Fs_over_Fn_drift")


WHO = "scripts/creep_study.py"


def fail(message):
    sys.exit("creep_study.py: " + message)


def in_frame(parts, points, k0=0):
    """F_s / F_n of all PARTS (each in its point's frame) in point k0's frame."""
    fs = fn = 0.0
    for part, c in zip(parts, points):
        if part is not None:
            s, n = pc.turned(part["F_s"], part["F_n"], c["delta"] - points[k0]["delta"])
            fs, fn = fs + s, fn + n
    return fs / fn if fn > 0 else float("nan")


def drift(run, t, window):
    """The main patch's F_s / F_n over the last WINDOW [m] of rolling before
    the statistics row nearest t: its mean over the window's second half
    minus that over its first half."""
    names, stats = hc.read_statistics(run)
    x, time_ = hc.column(names, stats, "wheel x"), hc.column(names, stats, "time")
    end = x[int(np.argmin(np.abs(time_ - t)))]
    sel = (x >= end - window) & (x <= end)
    r = (hc.column(names, stats, "patch 1 F_s ") / hc.column(names, stats, "patch 1 F_n "))[sel]
    half = r.size // 2
    return float(r[half:].mean() - r[:half].mean())


def rows_of(case, run, grid, window, case_dir):
    """The table rows of one run (one per program patch); relative profile
    file names are read from case_dir (the case file's directory)."""
    path = hc.patch_file(run, "t")
    if not os.path.exists(path):
        fail("%s: no patch at t (the run must pass O)" % run)
    t, _ = hc.patch_header(path)
    ref = pr.reference(run, t, case_dir, grid, pc.find_log(run))
    rp = pc.reference_parts(ref)
    try:
        fp = pc.fe_parts(run, t, len(rp), window)
    except ValueError as e:
        fail(str(e))
    if fp is None:
        fail("%s: the statistics have no patch columns" % run)
    moved = drift(run, t, window)
    contact = (in_frame(fp, ref["points"]), in_frame(rp, ref["points"]))
    rows = []
    for k, (f, r) in enumerate(zip(fp, rp)):
        if f is None or r is None or f["F_n"] <= 0:
            continue
        phi = math.sin(ref["points"][k]["delta"]) / ref["points"][k]["r"]
        rows.append(dict(case=case, eta=ref["eta"], phi=phi, xi=ref["xi"], patch=k + 1,
                         F_n_N=f["F_n"], fe_Fs_over_Fn=f["F_s"] / f["F_n"],
                         ref_Fs_over_Fn=r["F_s"] / r["F_n"], fe_Fx_over_Fn=f["F_x"] / f["F_n"],
                         ref_Fx_over_Fn=r["F_x"] / r["F_n"], fe_Mn_Nm=f["M_n"], ref_Mn_Nm=r["M_n"],
                         fe_contact_Fs_over_Fn=contact[0], ref_contact_Fs_over_Fn=contact[1],
                         fe_Fs_over_Fn_drift=moved))
    return rows


def write_csv(path, rows, meta):
    lines = ["# wheelrail lateral creep force and spin moment against the half-space reference "
             "(scripts/creep_study.py)"] + ["# %s = %s" % kv for kv in meta.items()]
    lines.append(",".join(COLUMNS))
    for r in rows:
        lines.append(",".join(r[c] if c == "case" else ("%d" % r[c] if c == "patch" else "%.6g" % r[c])
                              for c in COLUMNS))
    with atomic_file.replacing(path) as tmp, open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")


def figure(path, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    cases = sorted(set(r["case"] for r in rows))
    for i, case in enumerate(cases):
        mine = sorted((r for r in rows if r["case"] == case and r["patch"] == 1), key=lambda r: r["eta"])
        colour = "C%d" % i
        eta = [r["eta"] * 1e3 for r in mine]
        axes[0].plot(eta, [r["ref_contact_Fs_over_Fn"] for r in mine], "-", c=colour, alpha=0.6,
                     label="%s: half-space" % case)
        axes[0].plot(eta, [r["fe_contact_Fs_over_Fn"] for r in mine], "o", c=colour, mec="k",
                     label="%s: FE" % case)
    for r in rows:
        colour = "C%d" % cases.index(r["case"])
        axes[1].plot(r["phi"], r["ref_Mn_Nm"], "_", c=colour, ms=14, mew=2)
        axes[1].plot(r["phi"], r["fe_Mn_Nm"], "o", c=colour, mec="k")
    axes[0].set_xlabel("lateral creepage eta at O [1e-3]")
    axes[0].set_ylabel("F_s / F_n of the contact (main patch's frame)")
    axes[0].legend(fontsize=7)
    axes[1].set_xlabel("spin phi of the patch's rigid point [1/m]")
    axes[1].set_ylabel("M_n about the centre of pressure [N m]")
    axes[1].set_title("o FE, - half-space (each run, each patch)", fontsize=9)
    for ax in axes:
        ax.axhline(0, c="k", lw=0.5)
    fig.tight_layout()
    with atomic_file.replacing(path, ".tmp.png") as tmp:
        fig.savefig(tmp, dpi=110)
    plt.close(fig)


def rolling_start(case, args, sets, name):
    """The entries that make a run of CASE roll args.rolling mm before O (the
    rolling speed from a dry run of the case with @p sets)."""
    dry = os.path.join(args.out, name + "_dry")
    if not os.path.exists(os.path.join(dry, "parameters.prm")):
        sweep.write_variant(case, dry + ".prm", dry, dict(sets, **{"Problem/Dry run": "true"}), WHO)
        sweep.run_case(dry + ".prm", 1, args.wheelrail, dry + ".log", "creep_study.py")
    speed = float(hc.read_parameters(dry)["Wheelset/Rolling speed"])
    d = args.rolling * 1e-3
    return {"Geometry/Wheel/Centre x": "%.6g" % -d, "Geometry/Rail/Start x": "%.6g" % -(d + 0.1),
            "Time integration/End time": "%.6g" % ((d + 1.5e-3) / speed)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("cases", nargs="+", help="parameter files of rolling cases")
    parser.add_argument("--etas", help="lateral creepages to run, e.g. -2e-3,-1e-3 [default: the case's]")
    parser.add_argument("--set", action="append", default=[], metavar="ENTRY=VALUE",
                        help="a further entry of every run, e.g. 'Geometry/Mesh/Minimum cell size=0.00066'")
    parser.add_argument("--rolling", type=float,
                        help="rolling distance before O [mm]: the wheel starts there, the rail 100 mm "
                        "further back, the run ends 1.5 mm past O [default: the case's]")
    parser.add_argument("--np", type=int, default=2, help="MPI ranks per run")
    parser.add_argument("--out", default=os.path.join("results", "creep_study"))
    parser.add_argument("--grid", default="%dx%d" % pr.DEFAULT_GRID, help="reference grid NXxNY (NY odd)")
    parser.add_argument("--window", type=float, default=20., help="window of the FE means before t [mm]")
    parser.add_argument("--wheelrail", default=os.path.join(SCRIPTS_DIR, "..", "build", "wheelrail"))
    parser.add_argument("--plot-only", action="store_true")
    args = parser.parse_args()
    grid = hc.parse_grid(args.grid)
    if grid is None:
        parser.error("--grid %s: expected NXxNY, NX 4..512, NY odd 3..511" % args.grid)
    try:
        etas = [float(v) for v in args.etas.split(",") if v.strip()] if args.etas else [None]
    except ValueError as e:
        parser.error("--etas: %s" % e)
    if any(e is not None and abs(e) > 0.05 for e in etas):
        parser.error("--etas: |eta| <= 0.05 (Wheelset/Lateral creepage)")
    sets = {"Wheelset/Initial creepage": "0", "Wheelset/Creepage control time": "1",
            "Wheelset/Nominal traction coefficient": "0", "Wheelset/Run-up damping": "8000",
            "Wheelset/Run-up damping shape": "wheel rigid motion", "Wheelset/Run-up time": "1"}
    for item in args.set:
        if "=" not in item:
            parser.error("--set %r: expected ENTRY=VALUE" % item)
        entry, value = item.split("=", 1)
        sets[entry.strip()] = value.strip()
    if args.rolling is not None and not 10 <= args.rolling <= 5000:
        parser.error("--rolling: 10 to 5000 mm")
    os.makedirs(args.out, exist_ok=True)

    rows, t0 = [], time.time()
    for case in args.cases:
        if not os.path.isfile(case):
            fail("no such parameter file: %s" % case)
        name = os.path.splitext(os.path.basename(case))[0]
        mine = dict(sets)
        if args.rolling is not None:
            mine.update(rolling_start(case, args, sets, name))
        for k, eta in enumerate(etas, 1):
            run = os.path.join(args.out, "%s_eta_%d" % (name, k))
            if not args.plot_only:
                if eta is not None:
                    mine["Wheelset/Lateral creepage"] = "%.6g" % eta
                sweep.write_variant(case, run + ".prm", run, mine, WHO)
                print("creep_study.py: running %s on %d rank(s)" % (run + ".prm", args.np), flush=True)
                start = time.time()
                sweep.run_case(run + ".prm", args.np, args.wheelrail, run + ".log", "creep_study.py")
                print("  %.0f s" % (time.time() - start), flush=True)
            rows += rows_of(name, run, grid, args.window * 1e-3, os.path.dirname(os.path.abspath(case)))
    meta = dict(cases=" ".join(os.path.abspath(c) for c in args.cases), settings="; ".join(
        "%s = %s" % kv for kv in sets.items()), reference_grid="%dx%d" % grid,
        window_m=args.window * 1e-3, written=time.strftime("%Y-%m-%d %H:%M:%S %Z"))
    csv_path, png = os.path.join(args.out, "creep_study.csv"), os.path.join(args.out, "creep_study.png")
    write_csv(csv_path, rows, meta)
    figure(png, rows)
    for r in rows:
        print("%-34s eta %+.3e phi %.4f xi %+.2e patch %d: F_s/F_n FE %+.4f ref %+.4f (%+.4f); "
              "contact %+.4f ref %+.4f (%+.1f %%); F_x/F_n FE %+.4f ref %+.4f; M_n FE %+.2f ref %+.2f "
              "N m (%+.1f %%); drift %+.4f"
              % (r["case"], r["eta"], r["phi"], r["xi"], r["patch"], r["fe_Fs_over_Fn"],
                 r["ref_Fs_over_Fn"], r["fe_Fs_over_Fn"] - r["ref_Fs_over_Fn"],
                 r["fe_contact_Fs_over_Fn"], r["ref_contact_Fs_over_Fn"],
                 100 * (r["fe_contact_Fs_over_Fn"] / r["ref_contact_Fs_over_Fn"] - 1)
                 if r["ref_contact_Fs_over_Fn"] else float("nan"),
                 r["fe_Fx_over_Fn"], r["ref_Fx_over_Fn"], r["fe_Mn_Nm"], r["ref_Mn_Nm"],
                 100 * (r["fe_Mn_Nm"] / r["ref_Mn_Nm"] - 1) if r["ref_Mn_Nm"] else float("nan"),
                 r["fe_Fs_over_Fn_drift"]))
    print("creep study: %s, %s (%.0f s)" % (csv_path, png, time.time() - t0))
