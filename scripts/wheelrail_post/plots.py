"""Plots and a report page from a wheelrail run's output directory.

Usage:
    scripts/plot.py RUN_DIR [OTHER_RUN_DIR] [--out DIR] [--hs-grid 32x17] [--check]

Writes PNG files and report.html into DIR (default RUN_DIR/plots): the
paper's figures made from the run (Zhao & Li 2016, section 3):

  fig03_contact_nodes.png      nodes in contact at instant t (and the
                               difference to OTHER_RUN_DIR when given)
  fig04_pressure_shear.png     pressure and surface shear along y = 0 with
                               p f_S and p f_D (also Figs. 11, 15), and the
                               half-space solution at t
  fig05_07_adhesion_slip.png   adhesion/slip by eq. 5 and by eq. 6 at
                               t - 5.7 us, t, t + 5.7 us
  fig08_09_velocity.png        velocity of the rail-top node at O and of the
                               wheel node passing O against wheel position
  fig08_09_spectrum.png        their spectra (FFT), dominant peaks labelled
  fig10_microslip_axis.png     micro-slip along y = 0 at the three instants,
                               and the half-space slip velocity at t
  fig12_trailing_microslip.png mean trailing micro-slip against wheel
                               position, raw and smoothed
  fig13_force_difference.png   F_L(run) - F_L(other run) against wheel
                               position (only with OTHER_RUN_DIR)
  histories.png                F_N, F_L, mu_a and energies against time
  halfspace_axis.csv           the half-space solution along y = 0 at t: x [m]
                               (run coordinates), x - patch centre [m],
                               p, q_x [Pa], |s| [m/s], in_contact

The half-space solution (Kalker's exact steady rolling theory,
scripts/halfspace.py via scripts/wheelrail_post/compare.py) is solved at the F_N and F_x
of the patch at t on a grid of --hs-grid elements (0x0: none); the RMS
differences along y = 0 (pressure over p0, shear_x over f p0) and the
slip-area fractions of FE and half-space are printed and listed in
report.html.

With --check every figure is verified to exist and to show data (each axes
has at least one artist with finite values), and Figs. 4 and 10 to show the
half-space solution; the exit status is 1 if not.
Needs Debian's python3-numpy and python3-matplotlib (run with /usr/bin/python3).
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

# compare: the run's files by column name, the half-space comparison
from . import compare as hc  # noqa: E402
from . import report_page  # noqa: E402
from .compare import axis_rows, column, read_parameters, read_patch, read_statistics  # noqa: E402
from . import atomic_file  # noqa: E402

INSTANTS = ["t-5.7us", "t", "t+5.7us"]


def wheel_position(stats_names, stats, t):
    """Wheel x [m] at times t from the statistics (time, wheel x)."""
    return np.interp(t, column(stats_names, stats, "time"), column(stats_names, stats, "wheel x"))


def zoom(ax, patch, margin=0.004, equal=True):
    """Limit the axes to the contact area of @p patch plus a margin [m]."""
    c = patch["in_contact"] > 0
    if not c.any():
        return
    x, y = patch["x"][c], patch["y"][c]
    ax.set_xlim((x.min() - margin) * 1e3, (x.max() + margin) * 1e3)
    if equal:
        ax.set_ylim((y.min() - margin) * 1e3, (y.max() + margin) * 1e3)


def smooth(values, n):
    n = max(1, min(n, len(values)))
    kernel = np.ones(n) / n
    return np.convolve(values, kernel, mode="same")


def dominant_peaks(f, amplitude, count=3, min_separation=5):
    """The largest local maxima of the spectrum (not the zero frequency)."""
    order = np.argsort(amplitude[3:])[::-1] + 3
    peaks = []
    for i in order:
        if all(abs(i - j) >= min_separation for j in peaks):
            peaks.append(i)
        if len(peaks) == count:
            break
    return sorted(peaks)


class Report:
    def __init__(self, out):
        self.out = out
        self.figures = []  # (file, caption, figure object)

    def save(self, fig, name, caption):
        fig.tight_layout()
        path = os.path.join(self.out, name)
        with atomic_file.replacing(path, ".tmp.png") as tmp:
            fig.savefig(tmp, dpi=110)
        self.figures.append((name, caption, fig))

    def write_page(self, title, header):
        """report.html: @p header (HTML lines), then every figure, embedded, with its caption."""
        path = os.path.join(self.out, "report.html")
        with atomic_file.replacing(path) as tmp, open(tmp, "w") as f:
            f.write(report_page.page(title, header, self.figure_files()))
        return path

    def figure_files(self):
        return [(os.path.join(self.out, name), caption) for name, caption, _ in self.figures]

    def exit_with_check(self, problems=()):
        """Print the figure check (and @p problems found elsewhere); exit 1 if any."""
        problems = list(problems) + self.check()
        for p in problems:
            print("check failed: " + p)
        print("check: %d figures, %d problems" % (len(self.figures), len(problems)))
        sys.exit(1 if problems else 0)

    def check(self):
        """Every figure exists and every axes shows finite data."""
        problems = []
        for name, _, fig in self.figures:
            if not os.path.exists(os.path.join(self.out, name)):
                problems.append("%s: not written" % name)
                continue
            for k, ax in enumerate(fig.axes):
                if ax.get_label() == "<colorbar>":
                    continue
                finite = 0
                for line in ax.get_lines():
                    x, y = (np.asarray(v, dtype=float) for v in line.get_data())
                    finite += int(np.isfinite(x).all() and np.isfinite(y).all() and len(x) > 0)
                for coll in ax.collections:
                    xy = np.asarray(coll.get_offsets(), dtype=float)
                    finite += int(len(xy) > 0 and np.isfinite(xy).all())
                finite += len(ax.images)
                if finite == 0:
                    problems.append("%s: axes %d ('%s') shows no finite data" % (name, k, ax.get_title()))
        return problems


def half_space(run, grid, out):
    """hc.compare_patch at t and its axis as halfspace_axis.csv in @p out:
    (comparison or None, the reason when there is none)."""
    if not grid[0]:
        return None, "half-space comparison not asked for (--hs-grid 0x0)"
    try:
        r = hc.compare_patch(run, "t", grid)
    except (hc.hs.InputError, hc.hs.bem.ConvergenceError, KeyError, ValueError) as e:
        return None, "half-space comparison not made: %s: %s" % (type(e).__name__, e)
    if r is None:
        return None, "half-space comparison not made: no patch_t.csv"
    a = r["axis"]
    hc.hs.write_csv(os.path.join(out, "halfspace_axis.csv"),
                    ["x [m]", "x - patch centre [m]", "p [Pa]", "q_x [Pa]", "s [m/s]", "in_contact"],
                    zip(a["x"] + r["xc"], a["x"], a["p"], a["q_x"], a["s"], a["contact"].astype(float)))
    return r, None


def plot_run(run, other, out, hs_grid=hc.DEFAULT_GRID):
    """The figures and report.html: (Report, half-space comparison or None,
    the reason when there is none)."""
    prm = read_parameters(run)
    names, stats = read_statistics(run)
    rep = Report(out)
    f_s = float(prm.get("Contact/Static friction coefficient", "nan"))
    f_d = float(prm.get("Contact/Dynamic friction coefficient", "nan"))
    law = prm.get("Contact/Friction law", "?")
    patches = {i: read_patch(run, i) for i in INSTANTS}
    have_patch = all(p is not None for p in patches.values())
    comparison, hs_missing = half_space(run, hs_grid, out) if have_patch else (None, "no patch files")
    if comparison is not None and "profile" in comparison:
        from . import profile_compare
        profile_compare.write_csv(os.path.join(out, "profile_reference.csv"), comparison["profile"])
        rep.save(profile_compare.make_figure(comparison["profile"]), "profile_reference.png",
                 "FE patch at t against the half-space reference on the profiles' gap: area, "
                 "length, width, p_max; pressure across the patch")
        rep.save(profile_compare.make_profiles_figure(comparison["profile"]), "profile_patches.png",
                 "the wheel and rail profiles at the run's lateral shift, the rigid contact "
                 "points and the FE patches across them at t")

    # Fig. 3: nodes in contact at t (and the difference to the other run)
    if have_patch:
        p = patches["t"]
        other_p = read_patch(other, "t") if other else None
        ncols = 2 if other_p is not None else 1
        fig, axes = plt.subplots(1, ncols, figsize=(5.5 * ncols, 4.5), squeeze=False)
        ax = axes[0][0]
        c = p["in_contact"] > 0
        ax.scatter(p["x"][~c] * 1e3, p["y"][~c] * 1e3, s=4, c="0.85", label="not in contact")
        ax.scatter(p["x"][c] * 1e3, p["y"][c] * 1e3, s=10, c="tab:red", label="in contact (eq. 4)")
        ax.set_title("nodes in contact at t: %d" % c.sum())
        zoom(ax, p)
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("y [mm]")
        ax.set_aspect("equal")
        ax.legend(loc="upper right", fontsize=7)
        if other_p is not None:
            ax = axes[0][1]
            # match nodes by position
            key = lambda q: {(round(x * 1e7), round(y * 1e7)): v
                             for x, y, v in zip(q["x"], q["y"], q["in_contact"])}
            a, b = key(p), key(other_p)
            common = sorted(set(a) & set(b))
            xy = np.array(common, dtype=float) * 1e-4 if common else np.zeros((0, 2))
            d = np.array([a[k] - b[k] for k in common])
            for value, colour, label in [(1, "tab:red", "only this run"), (-1, "tab:blue", "only the other run"),
                                         (0, "0.8", "same")]:
                sel = d == value
                ax.scatter(xy[sel, 0], xy[sel, 1], s=8, c=colour, label="%s (%d)" % (label, sel.sum()))
            ax.set_title("difference in contact nodes")
            zoom(ax, p)
            ax.set_xlabel("x [mm]")
            ax.set_aspect("equal")
            ax.legend(loc="upper right", fontsize=7)
        rep.save(fig, "fig03_contact_nodes.png", "Nodes in contact at instant t (paper Fig. 3)")

        # Fig. 4: pressure and shear along y = 0
        fig, ax = plt.subplots(figsize=(7, 4.5))
        rows = axis_rows(p)
        x = p["x"][rows] * 1e3
        pr = p["pressure"][rows] * 1e-6
        ax.plot(x, pr, "k-o", ms=3, label="pressure p")
        ax.plot(x, p["shear_x"][rows] * 1e-6, "-s", ms=3, c="tab:red", label="shear stress (x)")
        ax.plot(x, p["shear"][rows] * 1e-6, "--", c="tab:orange", label="|shear stress|")
        if math.isfinite(f_s):
            ax.plot(x, f_s * pr, ":", c="tab:blue", label="p f_S (f_S = %g)" % f_s)
        if math.isfinite(f_d) and law == "exponential":
            ax.plot(x, f_d * pr, ":", c="tab:green", label="p f_D (f_D = %g)" % f_d)
        title = "along y = %.3g mm at instant t" % (p["y"][rows[0]] * 1e3)
        if comparison is not None:
            a = comparison["axis"]
            xh = (a["x"] + comparison["xc"]) * 1e3
            ax.plot(xh, a["p"] * 1e-6, "-", c="0.45", lw=2.5, alpha=0.55, label="half-space p")
            ax.plot(xh, a["q_x"] * 1e-6, "-", c="tab:purple", lw=2.5, alpha=0.55,
                    label="half-space q_x (F_x / F_N %.3f)" % (comparison["fx_hs"] / comparison["Fn"]))
            title += "\nRMS difference: p %.3f p0, q_x %.3f f p0" % (comparison["rms_p"], comparison["rms_q"])
        ax.set_xlabel("x [mm] (rolling direction ->)")
        ax.set_ylabel("[MPa]")
        ax.set_title(title, fontsize=10)
        zoom(ax, p, 0.006, equal=False)
        ax.legend(fontsize=8)
        rep.save(fig, "fig04_pressure_shear.png",
                 "Pressure and surface shear stress along the longitudinal axis (paper Figs. 4, 11, 15), "
                 "with the half-space solution of the same F_N and F_x")

        # Figs. 5-7: adhesion/slip maps by eq. 5 and eq. 6
        fig, axes = plt.subplots(2, 3, figsize=(13, 8), squeeze=False)
        for j, instant in enumerate(INSTANTS):
            q = patches[instant]
            c = q["in_contact"] > 0
            for i, (col, label) in enumerate([("adhesion_eq5", "eq. 5"), ("slip_eq6", "eq. 6")]):
                ax = axes[i][j]
                if col == "adhesion_eq5":
                    stick = c & (q[col] > 0)
                else:
                    stick = c & (q[col] == 0)
                slip = c & ~stick
                ax.scatter(q["x"][~c] * 1e3, q["y"][~c] * 1e3, s=3, c="0.88")
                ax.scatter(q["x"][stick] * 1e3, q["y"][stick] * 1e3, s=10, c="tab:blue",
                           label="adhesion (%d)" % stick.sum())
                ax.scatter(q["x"][slip] * 1e3, q["y"][slip] * 1e3, s=10, c="tab:red",
                           label="slip (%d)" % slip.sum())
                ax.set_title("%s, by %s" % (instant, label))
                zoom(ax, q)
                ax.set_aspect("equal")
                ax.set_xlabel("x [mm]")
                if j == 0:
                    ax.set_ylabel("y [mm]")
                ax.legend(loc="upper right", fontsize=7)
        rep.save(fig, "fig05_07_adhesion_slip.png",
                 "Adhesion and slip areas by eq. 5 (forces) and eq. 6 (micro-slip > 0.05 m/s) at t - 5.7 us, "
                 "t and t + 5.7 us (paper Figs. 5-7)")

        # Fig. 10: micro-slip along the axis
        fig, ax = plt.subplots(figsize=(7, 4.5))
        for instant, style in zip(INSTANTS, ["--", "-", ":"]):
            q = patches[instant]
            rows = axis_rows(q)
            c = q["in_contact"][rows] > 0
            ax.plot(q["x"][rows][c] * 1e3, q["slip_velocity"][rows][c], style, marker="o", ms=3, label=instant)
        if comparison is not None:
            a = comparison["axis"]
            c = a["contact"]
            ax.plot((a["x"][c] + comparison["xc"]) * 1e3, a["s"][c], "-", c="k", lw=2.5, alpha=0.45,
                    label="half-space |s| at t")
        ax.axhline(0.05, c="0.6", lw=0.8, label="eq. 6 threshold 0.05 m/s")
        ax.set_xlabel("x [mm]")
        ax.set_ylabel("micro-slip s_n [m/s]")
        ax.set_title("micro-slip of the contact nodes along y = 0")
        ax.legend(fontsize=8)
        rep.save(fig, "fig10_microslip_axis.png",
                 "Micro-slip along the longitudinal axis (paper Fig. 10), with the half-space slip velocity")

    # Figs. 8, 9: velocity histories and their spectra
    probes = [(hc.read_probe(run, n), label) for n, label in (("probe", "rail-top node at O"),
                                                               ("wheel_probe", "wheel node passing O"))]
    probes = [(pr, label) for pr, label in probes if pr is not None]
    if probes and stats is not None:
        fig, axes = plt.subplots(len(probes), 1, figsize=(8, 3.2 * len(probes)), squeeze=False)
        sfig, saxes = plt.subplots(len(probes), 1, figsize=(8, 3.2 * len(probes)), squeeze=False)
        for k, (pr, label) in enumerate(probes):
            t = pr["t [s]"]
            xw = wheel_position(names, stats, t) * 1e3
            ax, sax = axes[k][0], saxes[k][0]
            for comp, colour in zip("xyz", ["tab:red", "tab:green", "tab:blue"]):
                v = pr["v_%s [m/s]" % comp]
                ax.plot(xw, v, lw=0.7, c=colour, label="v_%s" % comp)
                if len(t) > 16:
                    dt = np.median(np.diff(t))
                    # remove the trend (rolling in, load build-up) before the FFT
                    v0 = v - np.polyval(np.polyfit(t - t[0], v, 1), t - t[0])
                    amp = np.abs(np.fft.rfft(v0 * np.hanning(len(v0)))) * 2 / len(v0)
                    f = np.fft.rfftfreq(len(v0), dt) * 1e-3
                    sax.semilogy(f, amp + 1e-30, lw=0.7, c=colour, label="v_%s" % comp)
                    for i in dominant_peaks(f, amp, 2):
                        sax.annotate("%.0f kHz" % f[i], (f[i], amp[i]), fontsize=7, color=colour,
                                     xytext=(3, 3), textcoords="offset points")
            ax.set_title("velocity of the %s" % label)
            ax.set_xlabel("wheel position x_w [mm]")
            ax.set_ylabel("[m/s]")
            ax.legend(fontsize=7)
            sax.set_title("spectrum of the velocity of the %s" % label)
            sax.set_xlabel("frequency [kHz]")
            sax.set_ylabel("amplitude [m/s]")
            sax.legend(fontsize=7)
        rep.save(fig, "fig08_09_velocity.png",
                 "Velocity histories of the rail-top node at O and of the wheel node that passes O "
                 "against wheel position (paper Figs. 8, 9)")
        rep.save(sfig, "fig08_09_spectrum.png",
                 "Spectra of those velocities (Hann window), dominant frequencies labelled")

    if stats is not None:
        t = column(names, stats, "time")
        xw = column(names, stats, "wheel x") * 1e3
        # Fig. 12: trailing micro-slip
        ts = column(names, stats, "trailing micro-slip")
        if ts is not None:
            fig, ax = plt.subplots(figsize=(7, 4.2))
            ax.plot(xw, ts, lw=0.6, c="0.6", label="s_n = |de|/dt, raw")
            n = max(3, len(ts) // 25)
            ax.plot(xw, smooth(ts, n), c="tab:red", label="s_n, moving mean over %d rows" % n)
            # the signed mean relative velocity (creep): oscillations cancel
            sx = column(names, stats, "trailing slip rate x")
            if sx is not None:
                ax.plot(xw, smooth(sx, n), c="tab:blue",
                        label="x component of the mean de/dt (creep), moving mean")
                ax.axhline(0, c="k", lw=0.5)
            ax.set_xlabel("wheel position x_w [mm]")
            ax.set_ylabel("trailing part: mean micro-slip [m/s]")
            ax.legend(fontsize=8)
            rep.save(fig, "fig12_trailing_microslip.png",
                     "Mean micro-slip of the trailing part of the patch against wheel position (paper Fig. 12)")

        # Fig. 13: longitudinal force difference between two runs
        if other:
            on, os_ = read_statistics(other)
            if os_ is not None:
                fig, ax = plt.subplots(figsize=(7, 4.2))
                x2 = column(on, os_, "wheel x") * 1e3
                fl2 = np.interp(xw, x2, column(on, os_, "F_L"))
                ok = (xw >= x2.min()) & (xw <= x2.max())
                ax.plot(xw[ok], (column(names, stats, "F_L")[ok] - fl2[ok]) * 1e-3, c="tab:purple")
                ax.set_xlabel("wheel position x_w [mm]")
                ax.set_ylabel("F_L(this run) - F_L(other run) [kN]")
                ax.set_title("%s minus %s" % (os.path.basename(os.path.normpath(run)),
                                              os.path.basename(os.path.normpath(other))))
                rep.save(fig, "fig13_force_difference.png",
                         "Longitudinal force difference between the two runs (paper Fig. 13)")

        # histories
        fig, axes = plt.subplots(2, 2, figsize=(11, 7))
        tm = t * 1e3
        fn = column(names, stats, "F_N")
        if fn is not None:
            axes[0][0].plot(tm, fn * 1e-3, label="F_N")
            axes[0][0].plot(tm, column(names, stats, "F_L") * 1e-3, label="F_L")
            axes[0][0].plot(tm, column(names, stats, "F_lateral") * 1e-3, label="F_lateral")
            axes[0][0].set_ylabel("[kN]")
            axes[0][0].legend(fontsize=8)
            axes[0][0].set_title("contact forces")
            axes[0][1].plot(tm, column(names, stats, "mu_a"), c="tab:red")
            axes[0][1].set_title("achieved traction coefficient mu_a = F_L / F_N")
            nc = column(names, stats, "contact nodes")
            axes[1][1].plot(tm, nc, label="contact nodes")
            axes[1][1].plot(tm, column(names, stats, "slip nodes"), label="slip nodes")
            axes[1][1].legend(fontsize=8)
            axes[1][1].set_title("nodes in contact and in slip")
        for label in ["kinetic", "internal", "hourglass", "damping", "contact energy", "friction",
                      "external work"]:
            v = column(names, stats, label)
            if v is not None:
                axes[1][0].plot(tm, v - v[0], label=label + " - initial")
        axes[1][0].set_title("energies (change since the start)")
        axes[1][0].set_ylabel("[J]")
        axes[1][0].legend(fontsize=7)
        for row in axes:
            for ax in row:
                ax.set_xlabel("time [ms]")
        rep.save(fig, "histories.png", "Time histories: forces, mu_a, energies, node counts")

    write_html(rep, run, other, prm, names, stats, comparison,
               hc.summary_lines(comparison) if comparison is not None else [hs_missing])
    return rep, comparison, hs_missing


def write_html(rep, run, other, prm, names, stats, comparison, hs_lines):
    patch = read_patch(run, "t") if comparison is not None else None
    report_page.run_report(os.path.join(rep.out, "report.html"), run, other, prm, names, stats, patch,
                           comparison, hs_lines, rep.figure_files(), column)


def shows_half_space(rep, name):
    """Whether figure @p name has a line labelled 'half-space ...' with finite data."""
    for n, _, fig in rep.figures:
        if n == name:
            return any(line.get_label().startswith("half-space") and len(line.get_xdata()) > 0
                       and np.isfinite(np.asarray(line.get_ydata(), dtype=float)).all()
                       for ax in fig.axes for line in ax.get_lines())
    return False


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run", help="output directory of a wheelrail run")
    parser.add_argument("other", nargs="?", help="a second run to compare with (Figs. 3, 13)")
    parser.add_argument("--out", help="where the PNG files and report.html go (default RUN/plots)")
    parser.add_argument("--hs-grid", default="%dx%d" % hc.DEFAULT_GRID,
                        help="half-space elements NXxNY (NY odd; 0x0: no half-space comparison)")
    parser.add_argument("--check", action="store_true",
                        help="verify that every figure is written and shows finite data")
    args = parser.parse_args()
    hs_grid = hc.parse_grid(args.hs_grid, none_allowed=True)
    if hs_grid is None:
        parser.error("--hs-grid %s: expected NXxNY, NX 4..512, NY odd 3..511, or 0x0" % args.hs_grid)
    for d in [args.run] + ([args.other] if args.other else []):
        if not os.path.isfile(os.path.join(d, "statistics")):
            sys.exit("plot.py: %s is not a wheelrail output directory (no statistics file)" % d)
    out = args.out or os.path.join(args.run, "plots")
    os.makedirs(out, exist_ok=True)
    rep, comparison, hs_missing = plot_run(args.run, args.other, out, hs_grid)
    for name, caption, _ in rep.figures:
        print("%-30s %s" % (name, caption))
    for line in hc.summary_lines(comparison) if comparison is not None else [hs_missing]:
        print(line)
    print("report: %s" % os.path.join(out, "report.html"))
    if args.check:
        expected = ["fig03_contact_nodes.png", "fig04_pressure_shear.png", "fig05_07_adhesion_slip.png",
                    "fig08_09_velocity.png", "fig08_09_spectrum.png", "fig10_microslip_axis.png",
                    "fig12_trailing_microslip.png", "histories.png"]
        if args.other:
            expected.append("fig13_force_difference.png")
        made = [n for n, _, _ in rep.figures]
        problems = ["%s: not made (input missing?)" % n for n in expected if n not in made]
        if hs_grid[0]:
            if comparison is None:
                problems.append(hs_missing)
            problems += ["%s: no half-space line" % n for n in ["fig04_pressure_shear.png",
                                                                "fig10_microslip_axis.png"]
                         if n in made and not shows_half_space(rep, n)]
        rep.exit_with_check(problems)

