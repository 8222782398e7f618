"""Velocity-dependent friction: convergence and comparison with exact theory.

Issue 25, items 3 and 4. Runs (or reads) wheelrail results of one rolling
case with the exponential law (eq. 1) at several h, dt and friction options
and reports for each run:

  F_N, mu_a      F_N and F_x / F_N of the patch at instant t; mu_a's spread
                 (max - min) / mean over the statistics rows of the in-zone
                 stretch: the wheel positions up to O at which the whole patch
                 (its half-length at t) lies in the rail's solution zone (the
                 last 20 mm before O where the mesh has no zone); the rigid
                 creepage (mean over those rows, and its change over them: a
                 run-away slip shows there). A patch that crosses into the
                 zone passes a change of mesh size, whose transient (the
                 trailing s_n dips by up to half for a few mm) grows with the
                 zone's refinement and is not part of the solution's h-dependence
  slip area      area fractions of the rail nodes in contact flagged slipping
                 by eq. 5 (force criterion) and eq. 6 (s_n > 0.05 m/s) at t
                 (decided on the slave nodes), the eq. 6 share of the leading
                 half, and the time means over the patch window (patch_t_mean.csv)
  series         eq. 5 and eq. 6 slip-area fractions of the rail top, means over
                 the frames of patch_series.h5 in the in-zone stretch
  s_n trailing   mean micro-slip of the trailing half of the contact along
                 y = 0 at t
  half-space     Kalker's steady rolling solution with the same law (its
                 friction state included) at the patch's own F_N and F_x
                 (scripts/wheelrail_post/compare.py): its slip-area fraction and mean
                 trailing slip velocity along y = 0, and the RMS difference of
                 the shear along y = 0 over f_S p0, at t and of the window means
  spectra        RMS velocity of the wheel node that passes O (wheel_probe.csv)
                 in the paper's 30-60 kHz band, in 0.5-2 MHz and 2-20 MHz, over the
                 last LENGTH of rolling before the run's end; the strongest
                 frequency above 100 kHz; and the strongest frequency of the
                 same history sampled at the paper's 175 kHz and its RMS in
                 30-60 kHz (what a 175 kHz output shows: the fast motion
                 folded into the band)

Usage:
  friction_study.py --run --base CASE.prm --work DIR --variants LABEL:h:dt[:xi_0[:SET...]] ...
        runs the variants that are missing (as scripts/convergence_study.py)
  friction_study.py --work DIR --variants ... [--markdown FILE] [--figure PNG]
                    [--spectra PNG] [--check NAME=LIMIT ...]
        compares the runs found there; --check limits (exit status 1 if one is
        exceeded): lead_eq6 (eq. 6 slip share of the leading half), eq5_eq6
        (|eq. 5 - eq. 6 slip share|), slip (|eq. 5 slip area - half-space|),
        trail_s (|trailing s_n / half-space - 1|, at t), rms_q (shear RMS
        difference)
"""
import argparse
import os

import numpy as np

from . import convergence_study as cs  # variants: parsing and running
from . import compare as hc  # the run's files and the half-space comparison

PAPER_SAMPLING = 175e3  # Hz, the paper's output rate
EQ6_THRESHOLD = 0.05  # m/s, eq. 6's slip: s_n above it (NodalContact::slip_velocity_threshold)
BANDS = {"30-60 kHz": (30e3, 60e3), "0.5-2 MHz": (0.5e6, 2e6), "2-20 MHz": (2e6, 20e6)}


def detrended(t, v):
    """v less its straight-line fit in t."""
    return v - np.polyval(np.polyfit(t - t[0], v, 1), t - t[0])


def band_rms(t, v, bands):
    """RMS of v (1D) in each frequency band (lo, hi) [Hz] of its detrended
    history, from one FFT (rectangular window: Parseval over the band's bins)."""
    v0 = detrended(t, v)
    power = np.abs(np.fft.rfft(v0)) ** 2
    f = np.fft.rfftfreq(len(v0), np.median(np.diff(t)))
    return [np.sqrt(2 * np.sum(power[(f >= lo) & (f < hi)])) / len(v0) for lo, hi in bands]


def spectrum(t, v):
    """Frequencies [Hz] and Hann-windowed amplitude of the detrended v."""
    v0 = detrended(t, v)
    return (np.fft.rfftfreq(len(v0), np.median(np.diff(t))),
            np.abs(np.fft.rfft(v0 * np.hanning(len(v0)))) * 2 / len(v0))


def strongest(f, amplitude, above):
    use = f > above
    return f[use][np.argmax(amplitude[use])] if use.any() else float("nan")


def probe_analysis(run, names, stats, length):
    """The wheel probe's tangential velocities over the last @p length of rolling."""
    pr = hc.read_probe(run, "wheel_probe")
    if pr is None:
        return None
    t = pr["t [s]"]
    x_w = np.interp(t, hc.column(names, stats, "time"), hc.column(names, stats, "wheel x"))
    use = x_w >= x_w[-1] - length
    t = t[use]
    out = {}
    for comp in "xy":
        v = pr["v_%s [m/s]" % comp][use]
        for name, rms in zip(BANDS, band_rms(t, v, BANDS.values())):
            out[(comp, name)] = rms
        f, a = spectrum(t, v)
        out[(comp, "peak")] = strongest(f, a, 100e3)
        # the same history as an output at 175 kHz would hold it
        stride = max(1, int(round(1 / (PAPER_SAMPLING * np.median(np.diff(t))))))
        fs, as_ = spectrum(t[::stride], v[::stride])
        out[(comp, "alias")] = strongest(fs, as_, 10e3)
        out[(comp, "band at 175 kHz")] = band_rms(t[::stride], v[::stride], [BANDS["30-60 kHz"]])[0]
        out[(comp, "spectra")] = (f, a, fs, as_)
    return out


def in_zone_start(parameters, x_contact):
    """The first wheel position of the in-zone stretch: the patch's trailing edge
    (half its node extent at t behind the wheel) at the solution zone's start
    (the zone is centred at O); -20 mm where the mesh has no zone. @p parameters:
    the run's hc.read_parameters()."""
    zone = float(parameters.get("Geometry/Mesh/Solution zone length", 0) or 0)
    if zone <= 0 or x_contact.size == 0:
        return -0.020
    return -0.5 * zone + 0.5 * (x_contact.max() - x_contact.min())


def series_slip(run, names, S, start):
    """Slip-area fractions of the rail top by eq. 5 (the series' state field: the
    force criterion) and eq. 6 (the node's s_n, the mean of its slave states, over
    0.05 m/s), area-weighted over the nodes with pressure, means over the frames
    of patch_series.h5 whose wheel position lies in the in-zone stretch
    [start, 0]: the stretch's time means that one instant or one window at t
    cannot give. None without the file or without frames in the stretch."""
    path = os.path.join(run, "patch_series.h5")
    if not os.path.exists(path):
        return None
    import h5py
    with h5py.File(path, "r") as f:
        x_w = np.interp(f["time"][:], hc.column(names, S, "time"), hc.column(names, S, "wheel x"))
        frames = np.flatnonzero((x_w >= start) & (x_w <= 0.))
        if frames.size == 0:
            return None
        area = f["mesh/area"][:]
        contact = f["fields/pressure_Pa"][frames] > 0
        slipping = f["fields/state_0free_1adhesion_2slip"][frames] == 2
        fast = f["fields/slip_velocity_m_s"][frames] > EQ6_THRESHOLD
    a = np.maximum((contact * area).sum(axis=1), 1e-300)
    return dict(eq5=np.mean((slipping * contact * area).sum(axis=1) / a),
                eq6=np.mean((fast * contact * area).sum(axis=1) / a))


def analyse(run, grid, length):
    r = hc.compare_patch(run, "t", grid)
    if r["note"]:
        print(f"{run}: {r['note']}")
    s = hc.slip_halves(run, r)
    parameters = hc.read_parameters(run)
    _, f_s, _ = hc.law_of(parameters)
    P = hc.read_patch(run, "t")
    inc = P["in_contact"] > 0
    eq6 = np.sum(P["area"][inc & (P["slip_eq6"] > 0)]) / np.sum(P["area"][inc])
    names, S = hc.read_statistics(run)
    wheel_x = hc.column(names, S, "wheel x")
    start = in_zone_start(parameters, P["x"][inc])
    last = (wheel_x >= start) & (wheel_x <= 0.)
    mu = hc.column(names, S, "mu_a")[last]
    creep_hist = hc.column(names, S, "creepage")[last]
    t_hist = hc.column(names, S, "time")[last]
    trail_hist = hc.column(names, S, "trailing micro-slip")[last]
    slip_hist = hc.column(names, S, "slip nodes")[last] / hc.column(names, S, "contact nodes")[last]
    out = dict(start=start, Fn=r["Fn"], mu=r["Fx"] / r["Fn"], spread=(mu.max() - mu.min()) / abs(mu.mean()),
               creep=creep_hist.mean(), creep_drift=creep_hist[-1] - creep_hist[0],
               creep_hs=r["creep_hs"],
               eq5=r["slip_fe"], eq6=eq6, lead_eq6=s["lead_eq6"],
               trail_s=s["trail_s"], slip_hs=r["slip_hs"], hs_trail_s=s["hs_trail_s"],
               rms_q=r["rms_q"] * r["f_ref"] / f_s, axis=r["axis"], fe=r["fe"],
               trail_hist=trail_hist.mean(), slip_hist=slip_hist.mean(),
               trail_band=band_rms(t_hist, trail_hist, [BANDS["30-60 kHz"]])[0],
               slip_band=band_rms(t_hist, slip_hist, [BANDS["30-60 kHz"]])[0])
    series = series_slip(run, names, S, start)
    if series is not None:
        out["series_eq5"], out["series_eq6"] = series["eq5"], series["eq6"]
    M = hc.read_patch(run, "t_mean")
    if M is not None:
        w = M["contact"] * M["area"]
        out["eq5_mean"] = np.sum((M["contact"] - M["adhesion"]) * M["area"]) / w.sum()
        out["eq6_mean"] = np.sum(M["slip_eq6"] * M["area"]) / w.sum()
        # the window's mean shear along y = 0 against the same half-space solution
        rows = hc.axis_rows(M)
        x = M["x"][rows] - r["xc"]
        # mean s_n of the trailing half of the contact along y = 0 (a node's mean over
        # the steps it is in contact)
        c = M["contact"][rows] > 0.5
        xc = x[c]
        trail = hc.halves(xc)[1]
        out["trail_s_mean"] = np.mean(M["slip_velocity"][rows][c][trail] / M["contact"][rows][c][trail])
        a = r["axis"]
        q_hs = np.interp(x, a["x"], a["q_x"], left=0., right=0.)
        compared = (M["contact"][rows] > 0) | (q_hs != 0)
        out["rms_q_mean"] = (np.sqrt(np.mean((M["shear_x"][rows][compared] - q_hs[compared]) ** 2))
                             / (f_s * r["p0_hs"]))
    out["probe"] = probe_analysis(run, names, S, length)
    return out


CHECKS = {
    "lead_eq6": lambda r: r["lead_eq6"],
    "eq5_eq6": lambda r: abs(r["eq5"] - r["eq6"]),
    "slip": lambda r: abs(r["eq5"] - r["slip_hs"]),
    "trail_s": lambda r: abs(r["trail_s"] / r["hs_trail_s"] - 1),
    "rms_q": lambda r: r["rms_q"],
}


def tables(results):
    head = ("| run | F_N [kN] | mu_a at t | in-zone stretch [mm]: from, spread | creepage [1e-3]: mean, change over the "
            "stretch (HS at F_x) | "
            "slip area eq. 5 / eq. 6 / half-space | window mean eq. 5 / eq. 6 | eq. 6 slip, leading half | "
            "s_n trailing FE at t, window mean / HS [m/s] | RMS q_x / (f_S p0) at t, window mean | "
            "stretch means: slip nodes / contact nodes, trailing s_n [m/s] | "
            "stretch means of the patch series: slip area eq. 5 / eq. 6 |")
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for label, r in results:
        def opt(key, fmt, scale=1.0):
            return fmt % (scale * r[key]) if key in r else "-"
        lines.append(
            f"| {label} | {r['Fn'] / 1e3:.2f} | {r['mu']:.4f} | {r['start'] * 1e3:.1f}, {100 * r['spread']:.1f} % | "
            f"{r['creep'] * 1e3:.3f}, {r['creep_drift'] * 1e3:+.3f} ({r['creep_hs'] * 1e3:.3f}) | {r['eq5']:.3f} / {r['eq6']:.3f} / "
            f"{r['slip_hs']:.3f} | {opt('eq5_mean', '%.3f')} / {opt('eq6_mean', '%.3f')} | "
            f"{r['lead_eq6']:.2f} | {r['trail_s']:.3f}, {opt('trail_s_mean', '%.3f')} / "
            f"{r['hs_trail_s']:.3f} | {100 * r['rms_q']:.1f} %, {opt('rms_q_mean', '%.1f %%', 100)} | "
            f"{r['slip_hist']:.3f}, {r['trail_hist']:.3f} | "
            f"{opt('series_eq5', '%.3f')} / {opt('series_eq6', '%.3f')} |")
    head = ("| run | " + " | ".join(f"v_{c} {n}" + (" [m/s]" if c == "x" and n == "30-60 kHz" else "")
                                   for c in "xy" for n in BANDS) + " | "
            "strongest above 100 kHz, x / y [kHz] | at 175 kHz sampling: v_x 30-60 kHz [m/s], "
            "strongest x / y [kHz] | 30-60 kHz RMS over the in-zone stretch: slip-node fraction, "
            "trailing s_n [m/s] |")
    spectra = [head, "|" + "---|" * (head.count("|") - 1)]
    for label, r in results:
        p = r["probe"]
        if p is None:
            continue
        b = [f"{p[(c, n)]:.4f}" for c in "xy" for n in BANDS]
        spectra.append(f"| {label} | " + " | ".join(b) + f" | {p[('x', 'peak')] * 1e-3:.0f} / "
                       f"{p[('y', 'peak')] * 1e-3:.0f} | {p[('x', 'band at 175 kHz')]:.4f}, "
                       f"{p[('x', 'alias')] * 1e-3:.1f} / "
                       f"{p[('y', 'alias')] * 1e-3:.1f} | {r['slip_band']:.4f}, {r['trail_band']:.4f} |")
    return "\n".join(lines), "\n".join(spectra)


def finish(fig, axes, png, xlabel, ylabels=None):
    """Labels, grid and legend on each axis; the figure written to png."""
    for k, ax in enumerate(axes):
        ax.set_xlabel(xlabel)
        if ylabels:
            ax.set_ylabel(ylabels[k])
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"wrote {png}")


def history_figure(runs, png):
    """mu_a and the rigid creepage against the wheel position, one line per run."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(12, 4))
    for label, d in runs:
        names, S = hc.read_statistics(d)
        x = hc.column(names, S, "wheel x") * 1e3
        axes[0].plot(x, hc.column(names, S, "mu_a"), lw=0.8, label=label)
        axes[1].plot(x, hc.column(names, S, "creepage") * 1e3, lw=0.8, label=label)
    finish(fig, axes, png, "wheel position x_w [mm] (O at 0)",
           ["mu_a = F_x / F_N", "rigid creepage (v_x - omega r) / v_x [1e-3]"])


def history_table(runs, window=0.002, at=(-0.06, 0.0, 0.01)):
    """The run-away of slip under a torque above the creep curve's peak: mu_a's
    peak and where, mu_a and the creepage at the wheel positions AT (means over
    WINDOW of rolling), and the creepage's growth between the first two."""
    where = ", ".join(f"{x * 1e3:g}" for x in at)
    head = (f"| run | mu_a peak at x_w [mm] | mu_a at x_w = {where} mm | creepage [1e-3] at the same | "
            f"creepage growth from {at[0] * 1e3:g} to {at[1] * 1e3:g} mm [1e-3 per 100 mm] |")
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for label, d in runs:
        names, S = hc.read_statistics(d)
        x = hc.column(names, S, "wheel x")
        mu = hc.column(names, S, "mu_a")
        xi = hc.column(names, S, "creepage")

        def mean_at(v, c):
            near = np.abs(x - c) <= 0.5 * window
            return v[near].mean() if near.any() else np.nan

        centres = np.arange(x[0] + 0.5 * window, x[-1] - 0.5 * window, 0.25 * window)
        smooth = np.array([mean_at(mu, c) for c in centres])
        k = int(np.nanargmax(smooth))
        span = (x >= at[0]) & (x <= at[1])
        growth = np.polyfit(x[span], xi[span], 1)[0] * 0.1 if span.sum() > 2 else np.nan
        lines.append(f"| {label} | {smooth[k]:.4f} at {centres[k] * 1e3:.0f} | "
                     + ", ".join(f"{mean_at(mu, c):.4f}" for c in at) + " | "
                     + ", ".join(f"{mean_at(xi, c) * 1e3:.2f}" for c in at)
                     + f" | {growth * 1e3:.2f} |")
    return "\n".join(lines)


def figures(results, patch_png, spectra_png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    if patch_png:
        fig, ax = plt.subplots(1, 1, figsize=(7, 4))
        for k, (label, r) in enumerate(results):
            c = "C%d" % k
            ax.plot(r["axis"]["x"] * 1e3, r["axis"]["q_x"] / 1e6, "-", c=c, lw=1.5,
                    label=f"half-space at {label}'s F_x")
            ax.plot(r["fe"]["x"] * 1e3, r["fe"]["q_x"] / 1e6, ".", c=c, ms=4, label=label)
        finish(fig, [ax], patch_png, "x - patch centre [mm] (rolling towards +x)",
               ["shear x along y = 0 [MPa]"])
    if spectra_png:
        with_probe = [(label, r) for label, r in results if r["probe"] is not None]
        fig, axes = plt.subplots(1, 2, figsize=(12, 4))
        for label, r in with_probe:
            f, a, fs, as_ = r["probe"][("x", "spectra")]
            line, = axes[0].loglog(f[1:] * 1e-3, a[1:] + 1e-12, lw=0.7, label=label)
            axes[1].semilogy(fs[1:] * 1e-3, as_[1:] + 1e-12, lw=0.9, c=line.get_color(), label=label)
        axes[0].axvspan(30, 60, color="0.85", label="paper's 40-50 kHz band")
        axes[1].axvspan(30, 60, color="0.85")
        axes[0].set_title("v_x of the wheel node passing O, every step")
        axes[1].set_title("the same sampled at 175 kHz (the paper's output rate)")
        finish(fig, axes, spectra_png, "frequency [kHz]", ["amplitude [m/s]"] * 2)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    cs.add_variant_arguments(parser)
    parser.add_argument("--length", type=float, default=0.02,
                        help="rolling distance [m] before the run's end analysed for the spectra")
    parser.add_argument("--markdown", help="write the tables to this file")
    parser.add_argument("--figure", help="shear along y = 0 against the half-space (PNG)")
    parser.add_argument("--spectra", help="spectra of the wheel probe (PNG)")
    parser.add_argument("--history", help="mu_a and creepage against the wheel position (PNG)")
    parser.add_argument("--check", nargs="+", metavar="NAME=LIMIT",
                        help="limits (names: " + ", ".join(CHECKS) + ")")
    args = parser.parse_args()
    variants = cs.variants_of(args, parser)

    results = [(label, analyse(d, (args.nx, args.ny), args.length))
               for label, d in cs.runs_found(args, variants)]
    patch, spectra = tables(results)
    print(patch + "\n\n" + spectra)
    print(f"(half-space grid {args.nx} x {args.ny}; spectra over the last {args.length * 1e3:g} mm)")
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write(patch + "\n\n" + spectra + "\n")
    figures(results, args.figure, args.spectra)
    if args.history:
        runs = [(label, os.path.join(args.work, label)) for label, _ in results]
        print("\n" + history_table(runs))
        history_figure(runs, args.history)
    if args.check:
        passed = True
        for item in args.check:
            name, _, value = item.partition("=")
            if name not in CHECKS or not value:
                parser.error(f"--check {item}: expected NAME=LIMIT with NAME one of " + ", ".join(CHECKS))
            for label, r in results:
                error = CHECKS[name](r)
                ok = bool(error <= float(value))
                passed &= ok
                print(f"{label}: {name:8s} {error:.3f}  limit {float(value):.3f}  {'ok' if ok else 'FAILED'}")
        if not passed:
            raise SystemExit("friction_study.py: a limit is exceeded")

