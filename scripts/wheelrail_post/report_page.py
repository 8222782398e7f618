"""The report page of a wheelrail run (plots/report.html) and its HTML frame.

page()        a self-contained HTML page: a style sheet, the sections given and
              the figures embedded as PNG data (no files beside it needed);
              a script marks <body data-figures="LOADED/TOTAL"> once the
              page has loaded, which the headless-browser test reads
run_report()  the run's page: what was run; its key figures against Hertz and
              the half-space solution with a verdict per line against the
              limits of doc/notes/convergence.md; the notes on what to trust that
              apply to its settings; the figures with captions

Used by scripts/plot.py (run reports) and scripts/sweep.py (sweep reports).
"""
import base64
import html
import os
import time

import numpy as np

from . import compare as hc  # the ellipse fit
from . import atomic_file

STYLE = """
body { font-family: sans-serif; max-width: 1100px; margin: 1.5em auto; color: #222; line-height: 1.4; }
h1 { font-size: 1.5em; border-bottom: 2px solid #444; }
h2 { font-size: 1.15em; margin-top: 1.6em; }
table { border-collapse: collapse; margin: 0.6em 0; }
td, th { border: 1px solid #bbb; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #eee; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
.meets { color: #176317; font-weight: bold; }
.outside { color: #a31515; font-weight: bold; }
.info { color: #555; }
figure { margin: 1.2em 0; }
figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.92em; color: #444; }
ul.notes li { margin-bottom: 0.4em; }
"""
SCRIPT = """
window.addEventListener('load', function () {
  var imgs = document.querySelectorAll('figure img'), ok = 0;
  imgs.forEach(function (i) { if (i.complete && i.naturalWidth > 0) ok++; });
  document.body.setAttribute('data-figures', ok + '/' + imgs.length);
});
"""
# the limits of the verdicts where the run states no expectation of its own
# (issue 24's targets, met on the paper mesh; doc/notes/convergence.md)
LIMITS = dict(p0=0.02, a=0.02, b=0.02, rms_q=0.05, slip=0.03, creep=0.05, spread=0.01)


def expected_errors(run):
    """The limits of the patch at t for the run's mesh size: expected_errors.csv,
    written by wheelrail beside patch_t.csv from the convergence study's
    errors at h 1.32, 0.66, 0.33 mm (source/verification/expected_errors.cc).
    {key: {h_m, expected, limit, in_study, paper_mesh, target}}; {} if absent."""
    name = os.path.join(run, "expected_errors.csv")
    if not os.path.exists(name):
        return {}
    with open(name) as f:
        lines = [l.rstrip("\n") for l in f if l.strip() and not l.startswith("#")]
    head = lines[0].split(",")
    out = {}
    for line in lines[1:]:
        cells = line.split(",", len(head) - 1)
        row = dict(zip(head, cells))
        out[row["key"]] = {k: (int(row[k]) if k == "in_study" else float(row[k]))
                           for k in ("h_m", "expected", "limit", "in_study", "paper_mesh", "target")}
    return out


def figure_html(path, caption):
    with open(path, "rb") as f:
        data = base64.b64encode(f.read()).decode("ascii")
    return ("<figure><img alt='%s' src='data:image/png;base64,%s'><figcaption>%s (<code>%s</code>)"
            "</figcaption></figure>" % (html.escape(caption, quote=True), data, html.escape(caption),
                                        html.escape(os.path.basename(path))))


def page(title, body, figures):
    """The page: @p body (HTML lines), then @p figures [(path, caption)]."""
    parts = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
             "<title>%s</title><style>%s</style></head><body>" % (html.escape(title), STYLE)]
    parts += list(body)
    if figures:
        parts.append("<h2>Figures</h2>")
        parts += [figure_html(p, c) for p, c in figures]
    parts.append("<p class='info'>written by wheelrail's scripts/plot.py, %s</p>"
                 % time.strftime("%Y-%m-%d %H:%M %Z"))
    parts.append("<script>%s</script></body></html>" % SCRIPT)
    return "\n".join(parts) + "\n"


def table(rows, head=None):
    out = ["<table>"]
    if head:
        out.append("<tr>%s</tr>" % "".join("<th>%s</th>" % html.escape(h) for h in head))
    for r in rows:
        out.append("<tr>%s</tr>" % "".join(
            c if c.startswith("<td") else "<td>%s</td>" % html.escape(c) for c in r))
    out.append("</table>")
    return out


def verdict(error, limit):
    if not np.isfinite(error):
        return "<td class='info'>not measured</td>"
    ok = abs(error) <= limit
    return "<td class='%s'>%s (limit %g)</td>" % ("meets" if ok else "outside",
                                                 "within" if ok else "outside", limit)


def expected_verdict(error, key, expected):
    """The verdict on @p error of quantity @p key: against what the convergence
    study measured at the run's h where the run states it (@p expected, from
    expected_errors()), else against LIMITS."""
    e = expected.get(key)
    if e is None:
        return verdict(error, LIMITS[key])
    if not np.isfinite(error):
        return "<td class='info'>not measured</td>"
    ok = abs(error) <= e["limit"]
    h = "h = %.3g mm" % (e["h_m"] * 1e3)
    if not e["in_study"]:
        text = "%s the target %g (%s is coarser than the convergence study's meshes)" % (
            "within" if ok else "outside", e["limit"], h)
    else:
        text = "%s for %s (limit %.3f; paper mesh: %.3f)" % (
            "as expected" if ok else "outside the expectation", h, e["limit"], e["paper_mesh"])
    return "<td class='%s'>%s</td>" % ("meets" if ok else "outside", text)


def key_figures(prm, names, stats, patch, comparison, column, expected=None):
    """Rows (quantity, FE, reference, difference, verdict) of the run at t; @p expected
    as from expected_errors()."""
    expected = expected or {}
    rows = []
    num = lambda v: "<td class='num'>%s</td>" % v
    if comparison is not None and "profile" in comparison:
        rows += profile_rows(comparison["profile"])
    elif comparison is not None:
        c, h = comparison, comparison["hertz"]
        p0, a, b = hc.fit_ellipse(patch["x"], patch["y"], patch["pressure"], patch["F_n"])
        rows.append(["normal force F_N at t [kN]", num("%.2f" % (c["Fn"] * 1e-3)), num(""), num(""),
                     "<td class='info'>the load it carries</td>"])
        for label, fe, ref, key in (("peak pressure p0 [MPa] (fitted ellipse; Hertz)", p0 * 1e-6,
                                     h["p0"] * 1e-6, "p0"),
                                    ("semi-axis a, rolling direction [mm] (Hertz)", a * 1e3, h["a"] * 1e3, "a"),
                                    ("semi-axis b, lateral [mm] (Hertz)", b * 1e3, h["b"] * 1e3, "b")):
            rows.append([label, num("%.4g" % fe), num("%.4g" % ref), num("%+.1f %%" % (100 * (fe / ref - 1))),
                         expected_verdict(fe / ref - 1, key, expected)])
        rows.append(["F_x / F_N at t", num("%.4f" % (c["Fx"] / c["Fn"])), num("%.4f" % (c["fx_hs"] / c["Fn"])),
                     num(""), "<td class='info'>the half-space solution is solved at this force</td>"])
        creep_err = c["creep_fe"] / c["creep_hs"] - 1 if c["creep_hs"] != 0 else float("nan")
        rows.append(["rigid creepage at t [1e-3] (half-space at the same F_x)", num("%.4g" % (c["creep_fe"] * 1e3)),
                     num("%.4g" % (c["creep_hs"] * 1e3)), num("%+.1f %%" % (100 * creep_err)),
                     expected_verdict(creep_err, "creep", expected)])
        rows.append(["slip-area fraction (eq. 5; half-space on %d x %d)" % c["grid"].shape, num("%.3f" % c["slip_fe"]), num("%.3f" % c["slip_hs"]),
                     num("%+.3f" % (c["slip_fe"] - c["slip_hs"])), expected_verdict(c["slip_fe"] - c["slip_hs"], "slip", expected)])
        rows.append(["RMS difference of the pressure along y = 0 [of p0]", num("%.1f %%" % (100 * c["rms_p"])),
                     num("0"), num(""),
                     expected_verdict(c["rms_p"], "rms_p", expected) if "rms_p" in expected else
                     "<td class='info'>1.1-1.3 % with the shipped settings at h 0.33</td>"])
        rows.append(["RMS difference of the shear q_x along y = 0 [of f p0]", num("%.1f %%" % (100 * c["rms_q"])),
                     num("0"), num(""), expected_verdict(c["rms_q"], "rms_q", expected)])
    if stats is not None and len(stats) and comparison is not None and np.isfinite(comparison["xc"]):
        x, mu = column(names, stats, "wheel x"), column(names, stats, "mu_a")
        xt = np.interp(comparison["t"], column(names, stats, "time"), x)
        sel = (x >= xt - 0.02) & (x <= xt)
        if sel.sum() >= 3:
            spread = (mu[sel].max() - mu[sel].min()) / abs(mu[sel].mean())
            rows.append(["mu_a over the last 20 mm before t: mean, (max - min) / mean",
                         num("%.4f, %.1f %%" % (mu[sel].mean(), 100 * spread)), num(""), num(""),
                         verdict(spread, LIMITS["spread"]).replace("within", "steady")
                         .replace("outside", "not steady")])
    if stats is not None and len(stats):
        err = column(names, stats, "balance error")
        if err is not None:
            worst = np.nanmax(np.abs(err))
            rows.append(["energy balance error, largest over the run", num("%.2g" % worst), num(""), num(""),
                         verdict(worst, 1e-3)])
    return rows


def profile_rows(r):
    """Rows (quantity, FE, reference, difference, note) of a profile run's patch
    against its half-space reference (profile_compare.compare_run's @p r);
    no verdicts: the convergence study covers the Hertzian case only."""
    from . import profile_compare as pc
    num = lambda v: "<td class='num'>%s</td>" % v
    rows = []
    for k, q, fe, ref, d in r["rows"]:
        label, unit, scale = pc._LABEL[q]
        part = q in pc.PART_QUANTITIES  # k: the program's patch, not the reference's
        note = ("the reference split at the program's patch boundary, in its frame" if part
                else pc.expectation(q, r["fe"][k]))
        rows.append(["patch %d: %s [%s]" % (k, label, unit), num("%.4g" % (fe * scale)),
                     num("%.4g" % (ref * scale)),
                     num("%+.3f" % d if q in ("fx_fn", "slip", "part_fx_fn", "part_fs_fn")
                         else "%+.1f %%" % (100 * d)),
                     "<td class='info'>%s</td>" % html.escape(note)])
    return rows


def trust_notes(prm, comparison, rows_html):
    """What to trust in this run, from its settings (doc/ and README)."""
    notes = []
    sf = float(prm.get("Contact/Penalty scale factor", "nan"))
    two = prm.get("Contact/Two pass", "false") == "true"
    h = float(prm.get("Geometry/Mesh/Minimum cell size", "nan"))
    law = prm.get("Contact/Friction law", "")
    if sf < 1 or not two:
        notes.append("Soft contact layer: one-pass contact or a penalty scale factor below 1 (the paper's "
                     "LS-DYNA interface) puts the peak pressure about 13 % under Hertz on the paper mesh and "
                     "adds compliance to the creepage; the paper cases use two-pass SF 1 (doc/interface.md).")
    if float(prm.get("Contact/Contact damping", "0")) == 0:
        notes.append("No contact damping: the contact nodes ring on their penalty springs and slip-zone "
                     "nodes stick in part of the steps, more so on finer meshes (doc/interface.md).")
    if h > 0.00034:
        notes.append("Mesh coarser than the paper's (h_min %.2f mm): p0 converges from below as h halves "
                     "(-3.6, -2.0, -1.1 %% at 1.32, 0.66, 0.33 mm; doc/convergence.md)." % (h * 1e3))
    if law == "exponential" and prm.get("Contact/Slip rate", "total") == "total" and \
            float(prm.get("Contact/Friction relaxation length", "0")) == 0 and \
            float(prm.get("Contact/Friction relaxation time", "0")) == 0:
        notes.append("The paper's instantaneous velocity-dependent law: each contact node is unstable at "
                     "the scale of the step, so s_n and the eq. 6 slip map show numerical MHz chatter "
                     "(nearly the whole patch 'slips' by eq. 6); trust eq. 5 and means over many steps "
                     "(F_N, mu_a). The regularised law (Slip rate = irreversible, Friction relaxation "
                     "length = 1e-5) converges (doc/friction_regularisation.md).")
    if float(prm.get("Wheelset/Creepage control time", "0")) == 0 and \
            float(prm.get("Wheelset/Nominal traction coefficient", "0")) > 0:
        notes.append("Torque start: the wheelset spins up with a lag of about 1 ms (longer on the flat top "
                     "of the creep curve), so the traction may still be rising at t; the half-space "
                     "comparison assumes steady rolling (see the mu_a line above).")
    if comparison is None:
        notes.append("No half-space comparison was made for this run.")
    if any("outside" in r for r in rows_html):
        notes.append("Lines marked 'outside' exceed what the convergence study (doc/convergence.md) "
                     "measured with the default case's settings at this run's h, with a margin of a third "
                     "(or, without expected_errors.csv in the run, the limits met on the paper mesh); with "
                     "other settings, as listed above, that may be expected.")
    notes.append("Forces and energies are exact to the balance shown; patch values at a single instant "
                 "carry the contact nodes' residual vibration; the patch_*_mean.csv files average it out.")
    return notes


def run_report(path, run, other, prm, names, stats, patch, comparison, hs_lines, figures, column):
    """Writes the run's report page to @p path."""
    name = os.path.basename(os.path.normpath(run))
    about = [("run directory", run)] + ([("compared with", other)] if other else [])
    for key, label in (("Contact/Friction law", "friction law"),
                       ("Contact/Static friction coefficient", "f (static)"),
                       ("Contact/Dynamic friction coefficient", "f_D"),
                       ("Contact/Slip rate", "slip rate"),
                       ("Contact/Friction relaxation length", "friction relaxation length [m]"),
                       ("Contact/Two pass", "two-pass contact"),
                       ("Contact/Penalty scale factor", "penalty scale factor"),
                       ("Contact/Contact damping", "contact damping [of critical]"),
                       ("Wheelset/Nominal traction coefficient", "nominal traction coefficient mu_n"),
                       ("Wheelset/Initial creepage", "initial creepage"),
                       ("Wheelset/Rolling speed", "rolling speed [m/s]"),
                       ("Geometry/Mesh/Minimum cell size", "smallest cell [m]"),
                       ("Time integration/Time step", "time step [s]"),
                       ("Time integration/End time", "end time [s]")):
        exponential_only = key.split("/")[1] in ("Dynamic friction coefficient", "Slip rate",
                                                 "Friction relaxation length")
        if key in prm and not (exponential_only and prm.get("Contact/Friction law") == "constant"):
            about.append((label, prm[key]))
    timing = _timing(run)
    if timing:
        about += timing
    rows = key_figures(prm, names, stats, patch, comparison, column, expected_errors(run))
    body = ["<h1>wheelrail run report: %s</h1>" % html.escape(name),
            "<p>Transient rolling contact by explicit FE; the contact patch at instant t (patch centre "
            "at O) against Hertz and against Kalker's exact steady rolling solution (half-space, same "
            "law, same F_N and F_x). Units as labelled.</p>",
            "<h2>What was run</h2>"]
    body += table([[k, str(v)] for k, v in about])
    body.append("<h2>Key figures at t against exact theory</h2>")
    if rows:
        body += table(rows, ["quantity", "FE", "reference", "difference", "verdict"])
    body.append("<ul>%s</ul>" % "".join("<li>%s</li>" % html.escape(l) for l in hs_lines))
    body.append("<h2>What to trust in this run</h2><ul class='notes'>")
    body += ["<li>%s</li>" % html.escape(n) for n in trust_notes(prm, comparison, [str(r) for r in rows])]
    body.append("</ul>")
    if stats is not None and len(stats):
        body.append("<h2>At the end of the run</h2>")
        last = stats[-1]
        end = []
        for label, scale, unit in (("time", 1e3, "ms"), ("wheel x", 1e3, "mm"), ("F_N", 1e-3, "kN"),
                                   ("F_L", 1e-3, "kN"), ("mu_a", 1, "-"), ("creepage", 1e3, "1e-3"),
                                   ("contact nodes", 1, "-"), ("slip nodes", 1, "-"),
                                   ("trailing micro-slip", 1, "m/s")):
            for i, n in enumerate(names):
                if n.startswith(label):
                    end.append(["%s [%s]" % (label, unit), "<td class='num'>%.6g</td>" % (last[i] * scale)])
                    break
        body += table(end)
    with atomic_file.replacing(path) as tmp, open(tmp, "w") as f:
        f.write(page("wheelrail report: " + name, body, figures))


def _timing(run):
    name = os.path.join(run, "timing.csv")
    if not os.path.exists(name):
        return []
    with open(name) as f:
        lines = [l.strip() for l in f if l.strip() and not l.startswith("#")]
    if len(lines) < 2:
        return []
    row = dict(zip(lines[0].split(","), lines[-1].split(",")))
    out = []
    for key, label, fmt in (("ranks", "MPI ranks", "%s"), ("cells", "cells", "%s"),
                            ("wall_s", "wall time [s]", "%s"),
                            ("ns_per_element_step", "ns per element-step", "%s"),
                            ("peak_memory_mb", "peak memory per rank [MB]", "%s")):
        if key in row:
            out.append((label, fmt % row[key]))
    return out
