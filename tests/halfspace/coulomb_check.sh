#!/usr/bin/env bash
# Runs a Coulomb comparison case on 1.32 mm cells with four times the paper's
# step (coarse_run.sh), then scripts/convergence_study.py --check on its patch
# at instant t against Hertz and the half-space solution at the run's own F_N
# and F_x, with the limits given (NAME=LIMIT ...), for compare_coulomb_01/_02.
# Arguments: the wheelrail executable, the source directory, the case file
# relative to it, the limits.
set -euo pipefail
exe=$1 src=$2 case=$3
shift 3
bash "$(dirname "$0")/coarse_run.sh" "$exe" "$src/$case"
/usr/bin/python3 "$src/scripts/convergence_study.py" --work . --variants h1.32:0.00132:1.04e-7 \
  --nx 32 --ny 17 --check "$@"
