#!/usr/bin/env bash
# ctest driver of the creep-force table (scripts/creep_curve.py): the
# Coulomb comparison case (prm/compare_coulomb.prm, f = 0.5) on 1.32 mm cells
# with four times the paper's step, at the creepages where the half-space
# solution gives F_x / F_N = 0.2 and 0.4 (--levels), then --check (the CSV and
# the HDF5 file hold the same finite rows, the figure the half-space curve)
# and the table's content read back from the HDF5 file:
# - the creepages found: the half-space curve at them gives the levels;
# - each FE row against the half-space solution at its own creepage: this
#   mesh transmits about 2 % less F_x than the half-space at a held creepage
#   (compare_coulomb_01; doc/notes/convergence.md), limit 3 %; slip-area fraction
#   within 0.05;
# - the metadata: the static wheel load (14,300 kg x 9.81 m/s^2), the radii,
#   the law.
# Measured at ee8f93a (2026-11-27): F_x / F_N -1.5 % and -0.8 % from the
# half-space, slip area 0.287 / 0.254 and 0.605 / 0.594 (0.598 / 0.594 on
# 2026-11-25).
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
cat > case.prm <<PRM
include $src/prm/compare_coulomb.prm
subsection Geometry
  subsection Mesh
    set Minimum cell size = 0.00132
  end
end
subsection Time integration
  set Time step = 1.04e-7
end
PRM
rm -rf table
/usr/bin/python3 "$src/scripts/creep_curve.py" case.prm --levels 0.2,0.4 --out table \
  --hs-grid 32x17 --wheelrail "$exe" --check | tee creep_curve.log
/usr/bin/python3 - <<'PY'
import h5py, numpy as np
with h5py.File("table/creep_table.h5", "r") as f:
    a = f.attrs
    t = {k: f["creep_table"][k][()] for k in f["creep_table"]}
    hs = {k: f["halfspace"][k][()] for k in f["halfspace"]}
    load, radius, profile, law, f_s = (a["static_wheel_load_N"], a["wheel_radius"],
                                       a["rail_profile_radius"], a["friction_law"],
                                       a["static_friction_coefficient"])
print("metadata: load %.1f N, R_w %g m, R_rail %g m, law %s, f %g" % (load, radius, profile, law, f_s))
assert abs(load - 14300 * 9.81) < 1 and radius == 0.46 and profile == 0.3
assert law == "constant" and f_s == 0.5
order = np.argsort(hs["creepage"])
xi_levels = np.interp([-0.2, -0.4], -hs["Fx_over_Fn"][order][::-1], hs["creepage"][order][::-1])
assert len(t["creepage"]) == 2, "expected 2 rows"
for k in range(2):
    xi, fx, fx_hs = t["creepage"][k], t["Fx_over_Fn"][k], t["halfspace_Fx_over_Fn"][k]
    s, s_hs = t["slip_area_fraction"][k], t["halfspace_slip_area_fraction"][k]
    rel = fx / fx_hs - 1
    print("row %d: xi %.4g, F_x/F_N FE %.4f, half-space %.4f (%+.3f, limit 0.03); slip area %.3f / %.3f "
          "(%.3f, limit 0.05); spread %.3f" % (k + 1, xi, fx, fx_hs, rel, s, s_hs, abs(s - s_hs), t["mu_a_spread"][k]))
    assert abs(rel) < 0.03 and abs(s - s_hs) < 0.05
    assert abs(fx_hs - (0.2, 0.4)[k]) < 0.01, "the creepage does not give the level on the half-space curve"
PY
