#!/usr/bin/env bash
# ctest driver of one verification of scripts/halfspace.py (the half-space
# reference of the contact patch): runs --check NAME, which prints the
# figures and exits non-zero beyond its tolerances.
# Arguments: the source directory, the check name.
set -euo pipefail
src=$1 name=$2
/usr/bin/python3 "$src/scripts/halfspace.py" --check "$name"
