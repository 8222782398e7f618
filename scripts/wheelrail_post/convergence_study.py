"""Mesh and time-step convergence of a rolling case against exact theory.

Runs (or reads) wheelrail results of one rolling case at several minimum cell
sizes h and time steps, and compares each run's contact patch at instant t
(patch_t.csv) with Hertz and with the half-space solution of the same normal
and longitudinal force (Kalker's exact theory of steady rolling, by
scripts/wheelrail_post/compare.py, which plot.py uses too):

  p0, a, b     Hertzian ellipse p^2 = p0^2 (1 - x^2/a^2 - y^2/b^2) fitted to the
               rail-node pressures above 25 % of the largest (as the program's
               own fit), against Hertz at the patch's normal force
  L(y=0)       length of the row of rail nodes in contact nearest y = 0
  mu_a         F_x / F_N of the patch at t; its spread (max - min) / mean over
               the statistics rows of the last 20 mm before O
  creepage     rigid creepage (v_x - omega r_eff) / v_x: mean over the last
               20 mm before O, against the half-space creepage at the same F_x
  slip area    area fraction of the rail nodes in contact that slip (eq. 5 as
               decided on the slave nodes), against the half-space fraction
  RMS p, q_x   RMS differences along y = 0 of the pressure (over p0) and the
               longitudinal shear (over f p0) from the half-space solution

Usage:
  convergence_study.py --run --base CASE.prm --work DIR [--np 2]
        runs CASE.prm at the variants of --variants (LABEL:h:dt[:xi_0[:SET...]],
        default the h 1.32 / 0.66 / 0.33 mm at dt = 2.6e-8 s and h 0.66 mm at
        dt / 2; xi_0, if given and not empty, replaces the case's
        Wheelset/Initial creepage; each SET, Subsection/Entry=value, sets one
        more parameter) into DIR/LABEL (an existing DIR/LABEL/patch_t.csv is
        reused)
  convergence_study.py --work DIR [--variants ...] [--markdown FILE] [--figure PNG]
        compares the runs found there
  convergence_study.py --work DIR --variants ... --creep-figure PNG
        also plots the runs' mean mu_a over the last 20 mm against their
        creepage on the half-space creep curve and prints the differences
        (driving runs, xi < 0, as the comparison cases)
  convergence_study.py --work DIR --variants ... --check p0=0.05 rms_q=0.1 ...
        also checks each run against limits and exits with status 1 if one is
        exceeded: p0, a, b (relative error from Hertz), L (relative error of
        the length on y = 0 from 2a), creep (relative error of the creepage from
        the half-space one), slip (absolute difference of the slip-area
        fractions), rms_p, rms_q (the RMS differences), spread (mu_a spread),
        stick (the mean adhesion share of the slip zone's nodes over the
        window of patch_t_mean.csv: the steps in which they stick)

Coulomb friction only (constant f, read from each run's parameters.prm).
"""
import argparse
import os
import subprocess

import numpy as np

from . import SCRIPTS_DIR
# compare: the run's files and the half-space comparison of its patch
from . import compare as hc

DEFAULT_VARIANTS = ["h1.32:0.00132:2.6e-8", "h0.66:0.00066:2.6e-8",
                    "h0.66-dt/2:0.00066:1.3e-8", "h0.33:0.00033:2.6e-8"]


def analyse(directory, nx, ny):
    prm = hc.read_parameters(directory)
    law = prm["Contact/Friction law"]
    if law != "constant":
        raise SystemExit(f"{directory}: friction law '{law}': this study compares Coulomb runs")
    # the half-space solution of the same case at the patch's F_N and F_x
    r = hc.compare_patch(directory, "t", (nx, ny))
    if r["note"]:
        print(f"{directory}: {r['note']}")
    P = hc.read_patch(directory, "t")
    p0, a, b = hc.fit_ellipse(P["x"], P["y"], P["pressure"], P["F_n"])
    rows = hc.axis_rows(P)
    xs = P["x"][rows][P["in_contact"][rows] > 0]
    length = xs.max() - xs.min() if xs.size else 0.

    # the slip state's steadiness: over the window of patch_t_mean.csv, the
    # mean adhesion share (eq. 5) of the nodes in contact at every step that
    # adhere in less than half of the steps (the slip zone); in steady
    # rolling they slip at every step
    M = hc.read_patch(directory, "t_mean")
    stick = float("nan")
    if M is not None:
        zone = (M["contact"] > 0.999) & (M["adhesion"] < 0.5)
        stick = M["adhesion"][zone].mean() if zone.any() else 0.

    names, S = hc.read_statistics(directory)
    wheel_x = hc.column(names, S, "wheel x")
    last = (wheel_x >= -0.020) & (wheel_x <= 0.)
    mu = hc.column(names, S, "mu_a")[last]
    creep = hc.column(names, S, "creepage")[last]
    axis = r["axis"]
    return dict(Fn=r["Fn"], Fx=r["Fx"], mu=r["Fx"] / r["Fn"], p0=p0, a=a, b=b, hertz=r["hertz"],
                length=length,
                mu_spread=(mu.max() - mu.min()) / abs(mu.mean()) if mu.size else float("nan"),
                mu_window=(mu.mean(), mu.min(), mu.max()) if mu.size else (float("nan"),) * 3,
                prm=prm,
                creep=creep.mean() if creep.size else float("nan"),
                creep_hs=r["creep_hs"], slip=r["slip_fe"], slip_hs=r["slip_hs"],
                rms_p=r["rms_p"], rms_q=r["rms_q"], stick=stick, f=r["f_ref"], row_x=r["fe"]["x"],
                row_p=r["fe"]["p"], row_q=r["fe"]["q_x"],
                ref=dict(x=axis["x"], p=axis["p"], q_x=axis["q_x"]))


# The errors --check can limit, each as a function of analyse()'s result.
CHECKS = {
    "p0": lambda r: abs(r["p0"] / r["hertz"]["p0"] - 1),
    "a": lambda r: abs(r["a"] / r["hertz"]["a"] - 1),
    "b": lambda r: abs(r["b"] / r["hertz"]["b"] - 1),
    "L": lambda r: abs(r["length"] / (2 * r["hertz"]["a"]) - 1),
    "creep": lambda r: abs(r["creep"] / r["creep_hs"] - 1),
    "slip": lambda r: abs(r["slip"] - r["slip_hs"]),
    "rms_p": lambda r: r["rms_p"],
    "rms_q": lambda r: r["rms_q"],
    "spread": lambda r: r["mu_spread"],
    "stick": lambda r: r["stick"],
}


def check(results, limits):
    """Prints each limited error of each run; True if all are within."""
    passed = True
    for label, r in results:
        for name, limit in limits.items():
            error = CHECKS[name](r)
            ok = bool(error <= limit)
            passed &= ok
            print(f"{label}: {name:6s} error {error:.3f}  limit {limit:.3f}  {'ok' if ok else 'FAILED'}")
    return passed


def parse_variants(texts):
    """(label, h, dt, xi_0 or None, [(path, value), ...]) of each
    LABEL:h:dt[:xi_0[:Subsection/Entry=value...]]; ValueError if malformed."""
    variants = []
    for v in texts:
        fields = v.split(":")
        if len(fields) < 3 or not all(fields[:3]):
            raise ValueError(f"variant '{v}': expected LABEL:h:dt[:xi_0[:Subsection/Entry=value...]]")
        sets = []
        for item in fields[4:]:
            path, eq, value = item.partition("=")
            if not eq or "/" not in path or not value.strip():
                raise ValueError(f"variant '{v}': '{item}' is not Subsection/Entry=value")
            sets.append((path.strip(), value.strip()))
        xi0 = fields[3] if len(fields) > 3 and fields[3] else None
        variants.append((fields[0], fields[1], fields[2], xi0, sets))
    return variants


def prm_entry(path, value):
    """The parameter-file lines setting Subsection/.../Entry to value."""
    *sections, entry = path.split("/")
    lines = [" " * (2 * i) + f"subsection {s}" for i, s in enumerate(sections)]
    lines.append(" " * (2 * len(sections)) + f"set {entry} = {value}")
    lines += [" " * (2 * i) + "end" for i in reversed(range(len(sections)))]
    return "\n".join(lines) + "\n"


def run_variants(args, variants):
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    binary = os.path.join(SCRIPTS_DIR, "..", "build", "wheelrail")
    for label, h, dt, xi0, sets in variants:
        out = os.path.abspath(os.path.join(args.work, label))
        if os.path.exists(os.path.join(out, "patch_t.csv")):
            print(f"{label}: reusing {out}")
            continue
        # the case file and the screen log lie beside the output directory:
        # the program refuses a directory that holds files no run wrote
        os.makedirs(args.work, exist_ok=True)
        prm = out + ".prm"
        with open(prm, "w") as f:
            f.write(f"include {os.path.abspath(args.base)}\n"
                    f"subsection Problem\n  set Output directory = {out}\nend\n"
                    f"subsection Geometry\n  subsection Mesh\n"
                    f"    set Minimum cell size = {h}\n  end\nend\n"
                    f"subsection Time integration\n  set Time step = {dt}\nend\n")
            if xi0 is not None:
                f.write(f"subsection Wheelset\n  set Initial creepage = {xi0}\nend\n")
            for path, value in sets:
                f.write(prm_entry(path, value))
        print(f"{label}: running h = {h} m, dt = {dt} s"
              + (f", xi_0 = {xi0}" if xi0 is not None else "")
              + "".join(f", {path} = {value}" for path, value in sets), flush=True)
        with open(out + ".log", "w") as log:
            subprocess.run(["mpirun", "-np", str(args.np), binary, prm], stdout=log,
                           stderr=subprocess.STDOUT, env=env, check=True)


def add_variant_arguments(parser, default_variants=None):
    """The options of the runs and of the half-space grid (this script and
    friction_study.py)."""
    parser.add_argument("--work", required=True, help="directory of the runs (one per variant)")
    parser.add_argument("--variants", nargs="+", default=default_variants,
                        required=default_variants is None,
                        help="LABEL:h:dt[:xi_0[:Subsection/Entry=value...]], h and dt in m and s")
    parser.add_argument("--run", action="store_true", help="run the variants that are missing")
    parser.add_argument("--base", help="--run: the case file")
    parser.add_argument("--np", type=int, default=2, help="--run: MPI ranks")
    parser.add_argument("--nx", type=int, default=64, help="half-space elements along x")
    parser.add_argument("--ny", type=int, default=49, help="half-space elements along y (odd)")


def variants_of(args, parser):
    """The parsed --variants; with --run, the missing ones run first."""
    try:
        variants = parse_variants(args.variants)
    except ValueError as e:
        parser.error(str(e))
    if args.run:
        if not args.base:
            parser.error("--run needs --base")
        run_variants(args, variants)
    return variants


def runs_found(args, variants):
    """(label, directory) of the variants whose run wrote patch_t.csv."""
    found = []
    for label, *_ in variants:
        d = os.path.join(args.work, label)
        if os.path.exists(os.path.join(d, "patch_t.csv")):
            found.append((label, d))
        else:
            print(f"{label}: no {d}/patch_t.csv, left out")
    if not found:
        raise SystemExit("no runs to compare")
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    add_variant_arguments(parser, DEFAULT_VARIANTS)
    parser.add_argument("--markdown", help="write the table to this file")
    parser.add_argument("--figure", help="write the shear and pressure along y = 0 to this PNG")
    parser.add_argument("--creep-figure", metavar="PNG",
                        help="write the runs' mean mu_a against their creepage (last 20 mm) "
                             "beside the half-space creep curve to this PNG")
    parser.add_argument("--check", nargs="+", metavar="NAME=LIMIT",
                        help="limits of the errors (names: " + ", ".join(CHECKS) + ")")
    args = parser.parse_args()
    variants = variants_of(args, parser)

    results = [(label, analyse(d, args.nx, args.ny)) for label, d in runs_found(args, variants)]

    head = ("| run | F_N [kN] | mu_a at t | mu_a spread, last 20 mm | p0 [MPa] (Hertz) | a [mm] | "
            "b [mm] | L on y=0 [mm] | creepage FE / half-space [1e-3] | slip area FE / HS | "
            "RMS p / p0 | RMS q_x / (f p0) |")
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for label, r in results:
        h = r["hertz"]
        lines.append(
            f"| {label} | {r['Fn'] / 1e3:.2f} | {r['mu']:.3f} | {100 * r['mu_spread']:.1f} % | "
            f"{r['p0'] / 1e6:.0f} ({h['p0'] / 1e6:.0f}) | {r['a'] * 1e3:.3f} ({h['a'] * 1e3:.3f}) | "
            f"{r['b'] * 1e3:.3f} ({h['b'] * 1e3:.3f}) | {r['length'] * 1e3:.2f} | "
            f"{r['creep'] * 1e3:.3f} / {r['creep_hs'] * 1e3:.3f} | {r['slip']:.3f} / "
            f"{r['slip_hs']:.3f} | {100 * r['rms_p']:.1f} % | {100 * r['rms_q']:.1f} % |")
    table = "\n".join(lines)
    print(table)
    print(f"(half-space grid {args.nx} x {args.ny} elements over 1.1 x the Hertz semi-axes)")
    if args.check:
        limits = {}
        for item in args.check:
            name, _, value = item.partition("=")
            if name not in CHECKS or not value:
                parser.error(f"--check {item}: expected NAME=LIMIT with NAME one of "
                             + ", ".join(CHECKS))
            limits[name] = float(value)
        if not check(results, limits):
            raise SystemExit("convergence_study.py: a limit is exceeded")
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(table + "\n")
    if args.figure:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 2, figsize=(11, 4))
        ref = results[-1][1]["ref"]
        axes[0].plot(ref["x"] * 1e3, ref["p"] / 1e6, "k-", lw=2, label="half-space")
        axes[1].plot(ref["x"] * 1e3, ref["q_x"] / 1e6, "k-", lw=2, label="half-space")
        for label, r in results:
            axes[0].plot(r["row_x"] * 1e3, r["row_p"] / 1e6, ".-", ms=3, label=label)
            axes[1].plot(r["row_x"] * 1e3, r["row_q"] / 1e6, ".-", ms=3, label=label)
        axes[0].set_ylabel("pressure [MPa]")
        axes[1].set_ylabel("shear x [MPa]")
        for ax in axes:
            ax.set_xlabel("x - patch centre [mm] (rolling towards +x)")
            ax.grid(alpha=0.3)
            ax.legend(fontsize=8)
        fig.suptitle(f"Along y = 0 at instant t; half-space at the last run's F_N, F_x "
                     f"({args.nx} x {args.ny} elements)")
        fig.tight_layout()
        fig.savefig(args.figure, dpi=120)
        print(f"wrote {args.figure}")
    if args.creep_figure:
        creep_figure(results, args.creep_figure, (args.nx, args.ny))


def creep_figure(results, path, grid):
    """The runs' creep points (mean creepage and mean mu_a over the last 20 mm
    before O, the bar mu_a's range there) on the half-space creep curve of
    the first run's case at the runs' mean F_N; prints the differences."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fn = np.mean([r["Fn"] for _, r in results])
    xis = [r["creep"] for _, r in results]
    top = 1.25 * max(abs(x) for x in xis)
    curve = hc.creep_curve(results[0][1]["prm"], fn, sorted(set(
        [-top * k / 12 for k in range(13)] + xis)), grid)
    at = {xi: ratio for xi, ratio, _ in curve}
    print(f"creep curve (half-space at F_N {fn / 1e3:.2f} kN, {grid[0]} x {grid[1]} elements):")
    print("| run | creepage [1e-3] | mu_a mean, last 20 mm (min, max) | half-space F_x / F_N | difference |")
    print("|---|---|---|---|---|")
    for label, r in results:
        m, lo, hi = r["mu_window"]
        ref = abs(at[r["creep"]])
        print(f"| {label} | {r['creep'] * 1e3:.3f} | {m:.4f} ({lo:.4f}, {hi:.4f}) | {ref:.4f} | "
              f"{100 * (m / ref - 1):+.1f} % |")
    fig, ax = plt.subplots(figsize=(7, 4.8))
    ax.plot([-c[0] * 1e3 for c in curve], [abs(c[1]) for c in curve], "k-", lw=2, alpha=0.6,
            label=f"half-space, Coulomb f {results[0][1]['f']:g} ({grid[0]} x {grid[1]})")
    for label, r in results:
        m, lo, hi = r["mu_window"]
        ax.errorbar([-r["creep"] * 1e3], [m], yerr=[[m - lo], [hi - m]], fmt="o", ms=5, capsize=3,
                    label=f"{label}: mean over the last 20 mm (bar: range)")
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    ax.set_xlabel("-xi, rigid creepage [1e-3] (driving)")
    ax.set_ylabel("F_x / F_N (FE: mu_a)")
    ax.set_title(f"creep curve at F_N {fn / 1e3:.1f} kN: FE runs and exact steady rolling")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")

