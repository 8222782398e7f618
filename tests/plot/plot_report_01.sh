#!/usr/bin/env bash
# ctest driver of the plot test: run wheelrail on plot_report_01.prm, then
# scripts/plot.py --check on its output, once alone and once against itself.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
sed "s#@SOURCE_DIR@#$src/tests/plot#" "$src/tests/plot/plot_report_01.prm.in" > plot_report_01.prm
rm -rf plot_run plots plots2
"$exe" plot_report_01.prm > wheelrail.log
/usr/bin/python3 "$src/scripts/plot.py" plot_run --out plots --check
/usr/bin/python3 "$src/scripts/plot.py" plot_run plot_run --out plots2 --check
