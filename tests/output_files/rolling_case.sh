#!/usr/bin/env bash
# Prints the plot test's short rolling case (tests/plot/plot_report_01.prm.in:
# 3 mm cells, 0.2 ms of rolling over O) with output directory DIR, for the
# output-file tests. Arguments: the source directory, DIR.
set -euo pipefail
sed -e "s#@SOURCE_DIR@#$1/tests/plot#" -e "s#= plot_run#= $2#" "$1/tests/plot/plot_report_01.prm.in"
