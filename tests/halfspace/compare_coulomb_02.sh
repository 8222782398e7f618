#!/usr/bin/env bash
# ctest driver of the steady comparison case (issue 24, item 5):
# prm/compare_coulomb_steady.prm (prm/compare_coulomb.prm with the wheel
# starting at x = -125 mm and an 80 mm solution zone) on 1.32 mm cells with
# four times the paper's step, then scripts/convergence_study.py --check on
# its patch at t. The point of this case is spread: mu_a's (max - min) / mean
# over the last 20 mm before O, measured 0.008 (the shortened case of
# compare_coulomb_01 0.014: the patch enters the fine cells inside its window
# and the twist is still settling); limit 0.012. The other limits are those of
# compare_coulomb_01 where its measured values fit them (p0 0.036, a 0.002,
# b 0.001, creep 0.014, rms_p 0.030, rms_q 0.037); slip (0.050) and stick
# (0.023) are larger here at this h than in the shortened case (0.039,
# 0.000), not explained (doc/convergence.md), with the same margin of a third.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exec bash "$(dirname "$0")/coulomb_check.sh" "$1" "$2" prm/compare_coulomb_steady.prm \
  p0=0.06 a=0.02 b=0.02 creep=0.03 slip=0.07 rms_p=0.04 rms_q=0.05 spread=0.012 stick=0.035
