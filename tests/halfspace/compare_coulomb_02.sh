#!/usr/bin/env bash
# ctest driver of the steady comparison case (issue 24, item 5):
# prm/compare_coulomb_steady.prm (prm/compare_coulomb.prm with the wheel
# starting at x = -125 mm and an 80 mm solution zone) on 1.32 mm cells with
# four times the paper's step, then scripts/convergence_study.py --check on
# its patch at t. The point of this case is spread: mu_a's (max - min) / mean
# over the last 20 mm before O, measured 0.008 (the shortened case of
# compare_coulomb_01 0.017: the patch enters the fine cells inside its window
# and the twist is still settling); limit 0.012. The other limits are those of
# compare_coulomb_01 where its measured values fit them; slip and stick have
# their own, set with a margin of a third when this case's were larger than
# the shortened case's (at 525d133: slip 0.050 against 0.039, stick 0.023
# against 0.000; not explained, doc/notes/convergence.md). Measured at ee8f93a
# (2026-11-27): p0 0.037, a 0.002, b 0.000, creep 0.016, slip 0.042, rms_p
# 0.030, rms_q 0.037, spread 0.008, stick 0.020 (the shortened case: slip
# 0.048, stick 0.000).
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exec bash "$(dirname "$0")/coulomb_check.sh" "$1" "$2" prm/compare_coulomb_steady.prm \
  p0=0.06 a=0.02 b=0.02 creep=0.03 slip=0.07 rms_p=0.04 rms_q=0.05 spread=0.012 stick=0.035
