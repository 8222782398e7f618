"""Run a traction sweep of wheelrail cases and plot it (paper Figs. 14, 15).

Usage:
    scripts/sweep.py BASE.prm [--mu 0.1,0.2,0.3,0.4,0.5] [--laws constant,exponential]
                     [--np N] [--out DIR] [--wheelrail PATH] [--hs-grid 32x17]
                     [--solve-each-static-start] [--plot-only] [--check]

For every friction law and nominal traction coefficient mu_n, a case file
DIR/LAW_muNN.prm is written (it includes BASE.prm and sets the law, the
coefficients of SPEC 4 - constant: f = 0.5; exponential: f_S = 0.5,
f_D = 0.32, k = 6 s/m - mu_n and its output directory) and run, one after
another, on N MPI ranks. The runs share one static start (the first solves
it, the others read it: Wheelset/Static start state = DIR/static_start,
removed after the runs) unless --solve-each-static-start. Then DIR holds:

  sweep.csv                 law, mu_n, mean mu_a and F_N over the second half
                            of each run, mu_a at the end
  fig14_traction.png        achieved mu_a against mu_n for both laws, with the
                            saturation curve (mu_a = mu_n up to f, f for
                            Coulomb; f_D for the exponential law)
  fig15_shear_axis.png      surface shear stress along y = 0 at instant t for
                            all runs, and the pressure
  creep_curve.png           creep curve: F_x / F_N against the rigid creepage
                            xi, each run's mean mu_a against its mean
                            creepage (statistics, second half) beside the
                            half-space curve of each law (Kalker's exact
                            steady rolling theory, scripts/wheelrail_post/compare.py, at
                            the runs' mean F_N, on --hs-grid elements)
  creep_curve.csv           its data: source (FE or half-space), law, mu_n,
                            creepage, Fx_over_Fn, and the half-space
                            halfspace_Fx_over_Fn and
                            halfspace_slip_area_fraction at that creepage
  report.html               the figures and the tables

--plot-only skips the runs (re-plots existing output); --check verifies that
the figures show finite data and the creep curve the half-space curve (exit
status 1 if not).
"""
import argparse
import html
import os
import shutil
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import SCRIPTS_DIR  # noqa: E402
from . import atomic_file  # noqa: E402
from . import compare as hc  # noqa: E402  (readers, the half-space)
from . import plots as plot  # noqa: E402  (the figure check)

LAWS = {
    "constant": {"Friction law": "constant", "Static friction coefficient": "0.5"},
    "exponential": {"Friction law": "exponential", "Static friction coefficient": "0.5",
                    "Dynamic friction coefficient": "0.32", "Decay coefficient": "6"},
}


def case_name(law, mu):
    return "%s_mu%02d" % (law, round(mu * 100))


def write_variant(case, path, outdir, entries, who):
    """PATH: a parameter file that includes CASE, writes into OUTDIR and sets
    @p entries ({"Section/Subsection/Entry": value}, in order); @p who
    names the writing script in its first line."""
    lines = ["# written by %s" % who, "include %s" % os.path.abspath(case),
             "subsection Problem", "  set Output directory = %s" % os.path.abspath(outdir), "end"]
    for entry, value in entries.items():
        parts = entry.split("/")
        lines += ["subsection %s" % p for p in parts[:-1]]
        lines.append("  set %s = %s" % (parts[-1], value))
        lines += ["end"] * (len(parts) - 1)
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_case(base, out, law, mu, state=None):
    """The case file of one run; with @p state the runs share one static
    start there (Wheelset/Static start state: the first run solves and
    writes it, the others read it)."""
    name = case_name(law, mu)
    lines = ["# wheelrail sweep case: %s law, mu_n = %g (written by scripts/sweep.py)" % (law, mu),
             "include %s" % os.path.abspath(base),
             "subsection Problem",
             "  set Output directory = %s" % os.path.abspath(os.path.join(out, name)),
             "end",
             "subsection Contact"]
    lines += ["  set %s = %s" % kv for kv in LAWS[law].items()]
    # the traction comes from the torque of mu_n (the paper's start), also on
    # a base case that holds the creepage instead (prm/default.prm)
    lines += ["end", "subsection Wheelset", "  set Nominal traction coefficient = %g" % mu,
              "  set Initial creepage = 0", "  set Creepage control time = 0"]
    if state:
        lines.append("  set Static start state = %s" % os.path.abspath(state))
    lines += ["end", ""]
    path = os.path.join(out, name + ".prm")
    with open(path, "w") as f:
        f.write("\n".join(lines))
    return path, os.path.join(out, name)


def run_case(prm, ranks, exe, log, who="sweep.py"):
    """Run wheelrail on PRM with RANKS MPI ranks, its output into LOG; exit
    with a message (prefixed by @p who) if it fails."""
    cmd = [exe, prm]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks), "--oversubscribe"] + cmd
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    with open(log, "w") as f:
        result = subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, env=env)
    if result.returncode != 0:
        sys.exit("%s: %s failed (exit status %d), see %s" % (who, prm, result.returncode, log))


def summarise(run):
    names, stats = hc.read_statistics(run)
    half = stats[len(stats) // 2:]
    fn, fl = hc.column(names, half, "F_N"), hc.column(names, half, "F_L")
    mu_end = hc.column(names, stats, "mu_a")[-1]
    return fl.mean() / fn.mean(), fn.mean(), mu_end


def creep_points(run):
    """Mean rigid creepage and mean mu_a over the second half of a run."""
    names, stats = hc.read_statistics(run)
    half = stats[len(stats) // 2:]
    return hc.column(names, half, "creepage").mean(), hc.column(names, half, "mu_a").mean()


# creepage magnitudes of the half-space curves (up to full slip with SPEC 4's
# coefficients: Coulomb f 0.5 saturates near |xi| 0.01), and each run's own
CURVE = [2.5e-4, 5e-4, 1e-3, 2e-3, 3e-3, 4e-3, 5e-3, 6e-3, 8e-3, 1.2e-2, 1.6e-2]


def creep_curves(runs, rows, laws, grid):
    """FE points and half-space curves: ([(law, mu_n, xi, mu_a, hs F_x/F_N,
    hs slip fraction)], {law: [(xi, F_x/F_N, slip fraction)]}, seconds)."""
    t0 = time.time()
    points = [(law, mu) + creep_points(run) for law, mu, run in runs]
    curves, fe = {}, []
    for law in laws:
        sel = [p for p in points if p[0] == law]
        fn = np.mean([r[3] for r in rows if r[0] == law])
        prm = hc.read_parameters([run for l, _, run in runs if l == law][0])
        top = max([CURVE[-1]] + [1.2 * abs(p[2]) for p in sel])
        xis = set([0.0] + [s * m for m in CURVE + [top] for s in (-1, 1)] + [p[2] for p in sel])
        curves[law] = hc.creep_curve(prm, fn, sorted(xis), grid)
        at = {xi: (ratio, slip) for xi, ratio, slip in curves[law]}
        fe += [p + at[p[2]] for p in sel]
    return fe, curves, time.time() - t0


def write_creep_csv(path, fe, curves):
    lines = ["source,law,mu_n,creepage,Fx_over_Fn,halfspace_Fx_over_Fn,halfspace_slip_area_fraction"]
    lines += ["FE,%s,%g,%.6g,%.6g,%.6g,%.6g" % p for p in fe]
    lines += ["half-space,%s,,%.6g,%.6g,%.6g,%.6g" % (law, xi, ratio, ratio, slip)
              for law, curve in curves.items() for xi, ratio, slip in curve]
    with atomic_file.replacing(path) as tmp, open(tmp, "w") as f:
        f.write("\n".join(lines) + "\n")


def plot_creep(rep, fe, curves, grid):
    colours = {"constant": "tab:blue", "exponential": "tab:red"}
    # the curve on the sides of xi = 0 that the runs reach (driving: xi < 0)
    braking, driving = any(p[2] > 0 for p in fe), any(p[2] < 0 for p in fe) or not fe
    fig, ax = plt.subplots(figsize=(7, 4.8))
    for k, (law, curve) in enumerate(curves.items()):
        shown = [c for c in curve if (c[0] <= 0 and driving) or (c[0] >= 0 and braking)]
        ax.plot([c[0] * 1e3 for c in shown], [c[1] for c in shown], "-", c=colours[law], lw=2,
                alpha=0.6, label="half-space, %s law (%d x %d)" % (law, grid[0], grid[1]))
        sel = [p for p in fe if p[0] == law]
        ax.plot([p[2] * 1e3 for p in sel], [p[3] for p in sel], "os"[k % 2], c=colours[law], mec="k",
                label="FE runs, %s law (mean, second half)" % law)
        for p in sel:
            ax.annotate("mu_n %g" % p[1], (p[2] * 1e3, p[3]), fontsize=7, color=colours[law],
                        xytext=(4, (-10, 4)[k % 2]), textcoords="offset points")
    ax.axhline(0, c="k", lw=0.5)
    ax.axvline(0, c="k", lw=0.5)
    ax.set_xlabel("rigid creepage xi [1e-3] (driving: xi < 0)")
    ax.set_ylabel("F_x / F_N (FE: mu_a)")
    ax.set_title("creep curve: FE runs and the half-space solution")
    ax.legend(fontsize=7)
    rep.save(fig, "creep_curve.png", "Creep curve: F_x / F_N against the rigid creepage, FE runs and "
             "the half-space solution (Kalker's exact steady rolling theory)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("base", help="parameter file of the case to sweep (a rolling case)")
    parser.add_argument("--mu", default="0.1,0.2,0.3,0.4,0.5", help="nominal traction coefficients")
    parser.add_argument("--laws", default="constant,exponential", help="friction laws")
    parser.add_argument("--np", type=int, default=1, help="MPI ranks per run")
    parser.add_argument("--out", default="results/sweep", help="sweep directory")
    parser.add_argument("--wheelrail", default=os.path.join(SCRIPTS_DIR,
                                                            "..", "build", "wheelrail"))
    parser.add_argument("--hs-grid", default="%dx%d" % hc.DEFAULT_GRID,
                        help="half-space elements NXxNY of the creep curve (NY odd)")
    parser.add_argument("--solve-each-static-start", action="store_true",
                        help="every run solves its static start (default: the first run solves it, "
                             "the others read it, Wheelset/Static start state)")
    parser.add_argument("--plot-only", action="store_true")
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()

    hs_grid = hc.parse_grid(args.hs_grid)
    if hs_grid is None:
        parser.error("--hs-grid %s: expected NXxNY, NX 4..512, NY odd 3..511" % args.hs_grid)
    mus = [float(m) for m in args.mu.split(",") if m.strip()]
    laws = [l.strip() for l in args.laws.split(",") if l.strip()]
    for law in laws:
        if law not in LAWS:
            sys.exit("sweep.py: unknown law '%s' (constant, exponential)" % law)
    if not os.path.isfile(args.base):
        sys.exit("sweep.py: no such parameter file: %s" % args.base)
    os.makedirs(args.out, exist_ok=True)

    # the runs differ in friction and traction only: one static start
    state = None if args.solve_each_static_start else os.path.join(args.out, "static_start")
    if state and not args.plot_only:
        shutil.rmtree(state, ignore_errors=True)
    runs = []
    for law in laws:
        for mu in mus:
            prm, run = write_case(args.base, args.out, law, mu, state)
            if not args.plot_only:
                print("sweep.py: running %s" % prm, flush=True)
                run_case(prm, args.np, args.wheelrail, run + ".log")
            runs.append((law, mu, run))
    if state:
        shutil.rmtree(state, ignore_errors=True)

    rows = []
    for law, mu, run in runs:
        mu_a, fn, mu_end = summarise(run)
        rows.append((law, mu, mu_a, fn, mu_end))
    csv = os.path.join(args.out, "sweep.csv")
    with atomic_file.replacing(csv) as tmp, open(tmp, "w") as f:
        f.write("law,mu_n,mean_mu_a_second_half,mean_F_N_second_half_N,mu_a_end\n")
        for r in rows:
            f.write("%s,%g,%.6g,%.6g,%.6g\n" % r)

    rep = plot.Report(args.out)
    fig, ax = plt.subplots(figsize=(6.5, 4.8))
    grid = np.linspace(0, max(mus) * 1.05, 100)
    colours = {"constant": "tab:blue", "exponential": "tab:red"}
    for law in laws:
        sel = [r for r in rows if r[0] == law]
        ax.plot([r[1] for r in sel], [r[2] for r in sel], "o-", c=colours[law], label="%s law: mu_a" % law)
        limit = 0.5 if law == "constant" else 0.32
        ax.plot(grid, np.minimum(grid, limit), ":", c=colours[law],
                label="saturation: min(mu_n, %s)" % ("f = 0.5" if law == "constant" else "f_D = 0.32"))
    ax.set_xlabel("nominal traction coefficient mu_n")
    ax.set_ylabel("achieved mu_a = F_L / F_N (mean, second half)")
    ax.set_title("traction against mu_n")
    ax.legend(fontsize=8)
    rep.save(fig, "fig14_traction.png",
             "Achieved traction coefficient against mu_n with the saturation curves (paper Fig. 14)")

    fig, axes = plt.subplots(len(laws), 1, figsize=(7.5, 4 * len(laws)), squeeze=False)
    for k, law in enumerate(laws):
        ax = axes[k][0]
        last = None
        for (l, mu, run) in runs:
            if l != law:
                continue
            p = hc.read_patch(run, "t")
            if p is None:
                continue
            rows_ = hc.axis_rows(p)
            ax.plot(p["x"][rows_] * 1e3, p["shear_x"][rows_] * 1e-6, "-", marker=".", label="mu_n = %g" % mu)
            last = p
        if last is not None:
            rows_ = hc.axis_rows(last)
            ax.plot(last["x"][rows_] * 1e3, last["pressure"][rows_] * 1e-6 * (0.5 if law == "constant" else 0.32),
                    "k:", label="p f (%s)" % ("f = 0.5" if law == "constant" else "f_D"))
            plot.zoom(ax, last, 0.006, equal=False)
        ax.set_title("surface shear stress along y = 0 at instant t, %s law" % law)
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("shear stress (x) [MPa]")
        ax.legend(fontsize=7)
    rep.save(fig, "fig15_shear_axis.png", "Surface shear stress along the axis for all runs (paper Fig. 15)")

    fe, curves, seconds = creep_curves(runs, rows, laws, hs_grid)
    creep_csv = os.path.join(args.out, "creep_curve.csv")
    write_creep_csv(creep_csv, fe, curves)
    plot_creep(rep, fe, curves, hs_grid)
    creep_lines = ["creep curve: %s mu_n %g: creepage %.4g, mu_a FE %.4f, half-space %.4f at that "
                   "creepage (slip-area fraction %.3f)" % p for p in fe]
    creep_lines.append("half-space creep curves: %d x %d elements, %d creepages per law, %.1f s"
                       % (hs_grid[0], hs_grid[1], len(next(iter(curves.values()))), seconds))

    header = ["<h1>wheelrail traction sweep</h1>", "<p>base case: %s</p>" % html.escape(args.base),
              "<table border='1' cellpadding='3'><tr><th>law</th><th>mu_n</th><th>mean mu_a</th>"
              "<th>mean F_N [kN]</th><th>mu_a at the end</th></tr>"]
    header += ["<tr><td>%s</td><td>%g</td><td>%.4f</td><td>%.2f</td><td>%.4f</td></tr>" %
               (r[0], r[1], r[2], r[3] * 1e-3, r[4]) for r in rows]
    header.append("</table>")
    header.append("<h2>Creep curve against the half-space solution</h2><ul>")
    header += ["<li>%s</li>" % html.escape(line) for line in creep_lines]
    header.append("</ul>")
    page = rep.write_page("wheelrail sweep", header)

    for r in rows:
        print("%-12s mu_n %-5g mean mu_a %.4f  mean F_N %.2f kN" % (r[0], r[1], r[2], r[3] * 1e-3))
    for line in creep_lines:
        print(line)
    print("sweep: %s, %s, %s" % (csv, creep_csv, page))
    if args.check:
        rep.exit_with_check([] if plot.shows_half_space(rep, "creep_curve.png")
                            else ["creep_curve.png: no half-space curve"])

