#!/usr/bin/env bash
# ctest driver: the paper's settings on the quick mesh (prm/quick_paper_settings.prm: exponential law, mu_n = 0.3, h 1.5 mm)
# with the regularised friction of doc/notes/friction_regularisation.md
# (Slip rate = irreversible, Friction relaxation length = 10 um). Its patch
# at instant t must have what steady rolling theory has and the paper's
# instantaneous law does not (eq. 6 slips 92 % of the leading half there):
# a leading adhesion zone by eq. 6, eq. 5 and eq. 6 agreeing, and slip area
# and trailing slip velocity near the half-space solution of the same law
# (its state relaxing over the same L) at the patch's F_x / F_N. Measured
# at ee8f93a (2026-11-27): leading share 0.001 (0.040 until 731fe79, a
# change of scripts/hs_compare.py only, left the patch's centre node out of
# both halves), eq. 5 - eq. 6 0.012, slip area 0.318 / 0.307, trailing s_n
# 0.42 above the half-space's (0.17 / 0.12 m/s on 2026-11-25). The limits
# leave room for round-off between hosts and for that case's soft
# interface (SF 0.1 one-pass): it needs a creepage of -3.07e-3 for the F_x
# that the half-space transmits at -2.20e-3, and the trailing slip velocity
# is higher by about that ratio.
# compare_exponential_01 checks the same law on the stiff interface.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
rm -rf out
cat > case.prm <<PRM
include $src/prm/quick_paper_settings.prm
subsection Problem
  set Output directory = out
end
subsection Contact
  set Slip rate                  = irreversible
  set Friction relaxation length = 1e-5
end
PRM
"$exe" case.prm > wheelrail.log
PYTHONPATH="$src/scripts" /usr/bin/python3 - <<'PY'
import sys
from wheelrail_post import compare as h
r = h.compare_patch("out", grid=(32, 17))
s = h.slip_halves("out", r)
print("\n".join(h.summary_lines(r)))
checks = [("eq. 6 slip share of the leading half", s["lead_eq6"], 0.15),
          ("eq. 5 slip share - eq. 6 slip share", abs(s["eq5"] - 0.5 * (s["lead_eq6"] + s["trail_eq6"])), 0.06),
          ("slip-area fraction FE - half-space", abs(r["slip_fe"] - r["slip_hs"]), 0.10),
          ("trailing mean s_n on y = 0 FE / HS - 1", abs(s["trail_s"] / s["hs_trail_s"] - 1), 0.6)]
failed = 0
for what, value, limit in checks:
    ok = value <= limit
    failed += not ok
    print("%-42s %.3f (limit %.2f) %s" % (what, value, limit, "OK" if ok else "FAILED"))
sys.exit(1 if failed else 0)
PY
