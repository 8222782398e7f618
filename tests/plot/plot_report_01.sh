#!/usr/bin/env bash
# ctest driver of the plot test: run wheelrail on plot_report_01.prm, then
# scripts/plot.py --check on its output, once alone and once against itself;
# the half-space overlay (halfspace_axis.csv, the printed RMS and slip-area
# lines, report.html) is checked on the first, and --check is shown to fail
# when the half-space comparison cannot be made.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
sed "s#@SOURCE_DIR@#$src/tests/plot#" "$src/tests/plot/plot_report_01.prm.in" > plot_report_01.prm
rm -rf plot_run plots plots2 plot_bad plots_bad
"$exe" plot_report_01.prm > wheelrail.log
/usr/bin/python3 "$src/scripts/plot.py" plot_run --out plots --check | tee plot.log
/usr/bin/python3 "$src/scripts/plot.py" plot_run plot_run --out plots2 --check

# the half-space comparison: the RMS and slip-area lines with finite values in
# range, the same lines in report.html, and the solution along y = 0 written.
# This coarse, short run (3 mm cells, F_x / F_N about -4e-4) gives
# RMS p / p0 0.27 (its pressure peak is 0.61 of p0 on 3 mm cells) and
# RMS q_x / (f p0) 0.001; the limits are 1.5 and 1.8 times those.
/usr/bin/python3 - <<'PY'
import csv, math, re
log = open("plot.log").read()
m = re.search(r"^RMS difference along y = 0: pressure / p0 (\S+), shear_x / \(f p0\) (\S+) ", log, re.M)
assert m, "no RMS line in the output of plot.py"
rms_p, rms_q = float(m.group(1)), float(m.group(2))
s = re.search(r"^slip-area fraction: FE (\S+), half-space (\S+)$", log, re.M)
assert s, "no slip-area line in the output of plot.py"
slip_fe, slip_hs = float(s.group(1)), float(s.group(2))
print("RMS p / p0 %.4f (limit 0.4), RMS q_x / (f p0) %.4f (limit 0.002); slip-area fractions "
      "FE %.3f, half-space %.3f" % (rms_p, rms_q, slip_fe, slip_hs))
assert 0 < rms_p < 0.4 and 0 < rms_q < 0.002, "RMS differences out of range"
assert 0 <= slip_fe <= 1 and 0 <= slip_hs <= 1, "slip-area fractions outside [0, 1]"
page = open("plots/report.html").read()
assert m.group(0).strip() in page and s.group(0) in page, "report.html lacks the comparison lines"
rows = list(csv.DictReader(open("plots/halfspace_axis.csv")))
inside = [r for r in rows if float(r["in_contact"]) > 0]
assert len(rows) == 32 and inside, "halfspace_axis.csv: expected 32 rows, some in contact"
p0 = max(float(r["p [Pa]"]) for r in rows)
print("halfspace_axis.csv: %d rows, %d in contact, p0 %.0f MPa" % (len(rows), len(inside), p0 * 1e-6))
assert abs(p0 / 1.385e9 - 1) < 0.02, "half-space p0 is not Hertz's"
PY

# --check fails when the comparison cannot be made (no friction law in parameters.prm)
mkdir plot_bad
cp plot_run/statistics plot_run/patch_t*.csv plot_run/*probe.csv plot_bad/
grep -v "Friction law" plot_run/parameters.prm > plot_bad/parameters.prm
if /usr/bin/python3 "$src/scripts/plot.py" plot_bad --out plots_bad --check > bad.log; then
  echo "plot.py --check passed without the half-space comparison"; exit 1
fi
grep -q "check failed: half-space comparison not made" bad.log
grep "check failed" bad.log

# The report page as a user sees it: rendered in headless Chromium (Debian's
# chromium, installed by ./run.sh test), every embedded figure decoded (the
# page's script counts them into <body data-figures="LOADED/TOTAL">), the
# sections present, and the end values' labels carrying the units their
# values are in (F_N in kN, as the statistics' N / 1000).
command -v chromium > /dev/null || { echo "chromium is not installed (./run.sh test installs it)"; exit 1; }
for page in plots plots2; do
  chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=10000 \
    --dump-dom "file://$PWD/$page/report.html" > $page.dom.html 2> $page.chromium.log
done
/usr/bin/python3 - <<'PY'
import re
for page, figures in (("plots", 8), ("plots2", 9)):
    dom = open(page + ".dom.html").read()
    m = re.search(r'data-figures="(\d+)/(\d+)"', dom)
    assert m, "%s: the page's script did not run in Chromium" % page
    print("%s/report.html in Chromium: %s of %s figures decoded (expected %d)" % (page, m.group(1), m.group(2), figures))
    assert m.group(1) == m.group(2) == str(figures), "figures missing or not decoded"
    for section in ("What was run", "Key figures at t against exact theory", "What to trust in this run",
                    "At the end of the run", "Figures"):
        assert "<h2>%s</h2>" % section in dom, "%s: section '%s' missing" % (page, section)
stats = [l.split() for l in open("plot_run/statistics") if not l.startswith("#")]
names = [l.split(":", 1)[1].strip() for l in open("plot_run/statistics") if re.match(r"# \d+:", l)]
fn = float(stats[-1][[i for i, n in enumerate(names) if n.startswith("F_N")][0]])
m = re.search(r"<td>F_N \[kN\]</td><td class=\"num\">([^<]+)</td>", open("plots.dom.html").read())
assert m, "no F_N [kN] row at the end"
print("end F_N: page %s kN, statistics %.6g N" % (m.group(1), fn))
assert abs(float(m.group(1)) - fn * 1e-3) <= 1e-5 * abs(fn * 1e-3), "F_N [kN] row does not show kN"
PY
