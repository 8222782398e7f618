#!/usr/bin/python3
"""Two runs of one case side by side: the measures of SPEC's paper case and
their differences, against the h 0.66 -> 0.33 mm differences of the
convergence study (doc/notes/convergence.md, shipped settings, F_x / F_N 0.3),
the bound within which a change of the numerics (a damping form, a longer
step) is to keep the paper case's results.

Per run: F_N and mu_a of the statistics row nearest the patch's time t; the
patch at t (patch_t.csv): its F_N, peak pressure, the fitted Hertzian p0, a,
b, the contact and slip areas; the largest energy balance error and the
damping dissipation at the end. Then the node by node RMS differences of the
two patches' pressure and shear_x over the larger peak (the runs share the
mesh).

usage: compare_runs.py RUN_A RUN_B [--labels A B]
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from wheelrail_post import compare as cmp  # noqa: E402

# h 0.66 -> 0.33 mm (doc/notes/convergence.md, 'Convergence at F_x / F_N = 0.3',
# shipped settings): |difference| of F_N [kN], mu_a, p0 [MPa], a, b [mm], slip area
H_DIFFERENCE = {"F_N [kN]": 0.23, "mu_a": 0.0005, "p0 [MPa]": 12, "a [mm]": 0.010,
                "b [mm]": 0.005, "slip fraction": 0.001}


def measures(run):
    names, data = cmp.read_statistics(run)
    P = cmp.read_patch(run, "t")
    if names is None or P is None:
        sys.exit("compare_runs.py: %s has no statistics or patch_t.csv" % run)
    t, _ = cmp.patch_header(cmp.patch_file(run, "t"))
    time = cmp.column(names, data, "time")
    row = int(np.argmin(np.abs(time - t)))
    Fn_patch, Fx_patch, slip = cmp.patch_totals(P)
    inc = P["in_contact"] > 0
    p0, a, b = cmp.fit_ellipse(P["x"][inc], P["y"][inc], P["pressure"][inc], P["F_n"][inc])
    return {
        "t [ms]": 1e3 * t,
        "statistics row t [ms]": 1e3 * time[row],
        "F_N [kN]": 1e-3 * cmp.column(names, data, "F_N")[row],
        "mu_a": cmp.column(names, data, "mu_a")[row],
        "patch F_N [kN]": 1e-3 * Fn_patch,
        "patch F_x / F_N": Fx_patch / Fn_patch,
        "p_max [MPa]": 1e-6 * P["pressure"].max(),
        "p0 [MPa]": 1e-6 * p0,
        "a [mm]": 1e3 * a,
        "b [mm]": 1e3 * b,
        "contact area [mm^2]": 1e6 * np.sum(P["area"][inc]),
        "slip fraction": slip,
        "largest balance error": np.max(np.abs(cmp.column(names, data, "balance error"))),
        "damping dissipation [J]": cmp.column(names, data, "damping dissipation")[-1],
    }, P


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs=2)
    parser.add_argument("--labels", nargs=2, default=["A", "B"])
    args = parser.parse_args()
    (ma, Pa), (mb, Pb) = (measures(r) for r in args.runs)
    print("%-26s %14s %14s %12s %12s" % ("", args.labels[0], args.labels[1], "B - A",
                                         "h-difference"))
    for k in ma:
        bound = H_DIFFERENCE.get(k)
        print("%-26s %14.6g %14.6g %12.3g %12s" % (k, ma[k], mb[k], mb[k] - ma[k],
                                                   "" if bound is None else "%g" % bound))
    same = (len(Pa["x"]) == len(Pb["x"]) and np.allclose(Pa["x"], Pb["x"]) and
            np.allclose(Pa["y"], Pb["y"]))
    if same:
        peak = max(Pa["pressure"].max(), Pb["pressure"].max())
        for k in ("pressure", "shear_x"):
            rms = np.sqrt(np.mean((Pa[k] - Pb[k]) ** 2)) / peak
            inc = (Pa["in_contact"] > 0) | (Pb["in_contact"] > 0)
            rms_in = np.sqrt(np.mean((Pa[k][inc] - Pb[k][inc]) ** 2)) / peak
            print("patch %-20s RMS difference over the peak pressure: %.2e "
                  "(over the %d nodes in contact in either: %.2e)" % (k, rms, inc.sum(), rms_in))
        print("nodes in contact: %d / %d, in both: %d" % (
            (Pa["in_contact"] > 0).sum(), (Pb["in_contact"] > 0).sum(),
            ((Pa["in_contact"] > 0) & (Pb["in_contact"] > 0)).sum()))
    else:
        print("the patches' nodes differ: no node by node comparison")


if __name__ == "__main__":
    main()
