#!/usr/bin/env bash
# The default case as a newcomer runs it (prm/default.prm as shipped, 2
# ranks, only the output directory changed), then its report page
# (scripts/plot.py, as ./run.sh does). Checked:
# - the report's verdicts: none 'outside', the patch at t judged against
#   what the convergence study measured at h 1.32 mm (expected_errors.csv,
#   written by the run beside patch_t.csv), mu_a steady over the last 20 mm,
#   the energy balance; the verdict rows are printed;
# - the program's own Hertz check of the patch at t (as expected for h);
# - the patch series: patch_series.xdmf lists frames, and every HDF5
#   reference in it (and in patch_series_tread.xdmf) names a dataset of
#   patch_series.h5 with the dimensions it states.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
rm -rf out
sed 's#^\( *set Output directory *=\).*#\1 out#' "$src/prm/default.prm" > default.prm
grep -q "set Output directory = out" default.prm
mpirun -np 2 "$exe" default.prm > wheelrail.log
grep -A4 "^Contact patch at t against Hertz" wheelrail.log
grep -q "within what the convergence study expects at h = 1.32 mm (doc/convergence.md): yes" wheelrail.log
grep "^Summary at t" wheelrail.log
/usr/bin/python3 "$src/scripts/plot.py" out --hs-grid 48x33 > plot.log
/usr/bin/python3 - <<'PY'
import html
import re
import xml.etree.ElementTree as ET

import h5py

page = open("out/plots/report.html").read()
rows = re.findall(r"<tr>(.*?)</tr>", page, re.S)
verdicts, outside = 0, []
for r in rows:
    cells = re.findall(r"<td[^>]*>(.*?)</td>", r, re.S)
    classes = re.findall(r"<td class='(meets|outside)'", r)
    if classes:
        verdicts += 1
        plain = [html.unescape(re.sub("<[^>]+>", "", c)).strip() for c in cells]
        text = "%-58s FE %-14s ref %-6s diff %-8s %s" % (plain[0][:58], plain[1], plain[2], plain[3],
                                                         plain[-1])
        print(text)
        if "outside" in classes:
            outside.append(text)
assert verdicts >= 9, "the report has %d verdicts, expected at least 9" % verdicts
assert page.count("as expected for h = 1.32 mm") >= 7, "not judged by the expectation at h 1.32 mm"
assert not outside, "outside: %s" % outside
print("report: %d verdicts, none outside" % verdicts)

with h5py.File("out/patch_series.h5", "r") as f:
    for name in ("patch_series.xdmf", "patch_series_tread.xdmf"):
        root = ET.parse("out/" + name).getroot()
        grids = root.findall("./Domain/Grid/Grid")
        checked = 0
        for item in root.iter("DataItem"):
            if item.get("Format") != "HDF":
                continue
            ref = item.text.strip().split(":", 1)[1]
            dims = tuple(int(v) for v in item.get("Dimensions").split())
            assert ref in f and f[ref].shape == dims, "%s: reference %s %s, the file has %s" % (
                name, ref, dims, f[ref].shape if ref in f else "nothing")
            checked += 1
        assert len(grids) > 100 and checked >= len(grids), "%s: %d frames" % (name, len(grids))
        print("%s: %d frames, %d HDF5 references, each a dataset of the stated dimensions"
              % (name, len(grids), checked))
PY
