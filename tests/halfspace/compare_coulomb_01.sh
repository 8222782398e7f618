#!/usr/bin/env bash
# ctest driver of the coarse comparison with exact steady rolling theory:
# prm/compare_coulomb.prm (Coulomb f = 0.5, creepage held at the half-space
# creepage of F_x / F_N = 0.3, run-up damping of the wheel's rigid motion for
# the whole run) on 1.32 mm cells (four times the paper's) with four times
# the paper's step, then scripts/convergence_study.py --check on its patch at
# instant t against Hertz and the half-space solution at the run's own F_N
# and F_x. The limits are what this mesh resolves, set with a margin of
# about a third (doc/notes/convergence.md gives the figures at h 1.32, 0.66 and
# 0.33 mm). Measured at ee8f93a (2026-11-27): p0 0.037, a 0.002, b 0.000,
# creep 0.022, slip 0.048, rms_p 0.029, rms_q 0.034, spread 0.017. At
# 525d133 (2026-11-25) slip was 0.039, spread 0.014. The slip error moved
# at 8bdae8b (bisected; the 'area' penalty takes the smaller of the slave's
# and the master face's area, a softer spring where the wheel's and the
# rail's cells differ): 0.417 -> 0.426 against the half-space's 0.378. The
# limit, set before, keeps a margin of only 4 %.
# spread: mu_a's (max - min) / mean over the last 20 mm; 0.040 with the
# run-up damping on every node until 1.3 ms (the wheel's torsional mode,
# released), so the limit of 0.025 fails if the damping of the wheel's rigid
# motion stops acting. With that nodal damping the patch was sampled on the
# upswing of the mode (mu_a 0.301 at t; 0.293 mean over the last 20 mm in the
# same run at the paper's step) and met the half-space creepage within 0.001
# by chance; steady, this mesh transmits 2 % less F_x at the held creepage.
# stick: the slip-zone nodes' mean adhesion share over the 5.7 us window,
# 0.000 with the paper cases' Contact damping 0.2, 0.019 without it (the
# nodes ringing on their penalty springs stick in part of the steps;
# doc/notes/interface.md).
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exec bash "$(dirname "$0")/coulomb_check.sh" "$1" "$2" prm/compare_coulomb.prm \
  p0=0.06 a=0.02 b=0.02 creep=0.03 slip=0.05 rms_p=0.04 rms_q=0.05 spread=0.025 stick=0.005
