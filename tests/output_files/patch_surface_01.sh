#!/usr/bin/env bash
# The contact patch as a surface mesh (patch_NAME.vtu, issue 27): a short
# rolling run on a coarse mesh (the plot test's case), then each of the three
# patch files read back by VTK's own XML reader (Debian's python3-vtk9, what
# ParaView uses): quadrilateral cells whose vertices are exactly the rail-top
# nodes of patch_NAME.csv, and the point data equal to the CSV columns
# (pressure, shear_x, |shear|, micro-slip, COF, the state from the flags) to
# single precision, the vectors with three components; the cells tile the
# zone's rail top (their area against the nodes' extent). The tread side,
# patch_tread_NAME.vtu (the wheel's candidate faces over the zone at their
# current positions): quadrilaterals with the same fields, whose integrals of
# pressure and shear_x (VTK's vtkIntegrateAttributes) carry the rail top's
# within 3 % and 5 % (the two bodies' faces differ) and the normal force of
# the statistics within 3 %.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
bash "$(dirname "$0")/rolling_case.sh" "$src" surface_run > surface.prm
rm -rf surface_run
"$exe" surface.prm > wheelrail.log
/usr/bin/python3 - <<'PY'
import csv
import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

for name in ("t-5.7us", "t", "t+5.7us"):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName("surface_run/patch_%s.vtu" % name)
    reader.Update()
    grid = reader.GetOutput()
    cells, points = grid.GetNumberOfCells(), grid.GetNumberOfPoints()
    assert cells > 0 and all(grid.GetCellType(i) == vtk.VTK_QUAD for i in range(cells)), "not quadrilaterals"
    data = grid.GetPointData()
    field = lambda n: vtk_to_numpy(data.GetArray(n)).astype(float)
    assert data.GetArray("shear_Pa").GetNumberOfComponents() == 3
    assert data.GetArray("slip_rate_m_s").GetNumberOfComponents() == 3
    X = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    rows = list(csv.reader(l for l in open("surface_run/patch_%s.csv" % name) if not l.startswith("#")))
    head, table = rows[0], np.array(rows[1:], float)
    col = lambda n: table[:, head.index(n)]
    key = lambda x, y: (int(round(x * 1e6)), int(round(y * 1e6)))  # um
    row_of = {key(x, y): i for i, (x, y) in enumerate(zip(col("x"), col("y")))}
    idx = np.array([row_of[key(x, y)] for x, y, _ in X])
    assert set(idx) == set(range(len(table))), "the vertices are not the CSV's nodes"
    state = col("in_contact") * (1 + (1 - col("adhesion_eq5")))
    shear = field("shear_Pa")
    worst = 0.
    for vtu, ref in ((field("pressure_Pa"), col("pressure")), (shear[:, 0], col("shear_x")),
                     (np.linalg.norm(shear, axis=1), col("shear")),
                     (field("slip_velocity_m_s"), col("slip_velocity")), (field("cof"), col("cof")),
                     (field("state_0free_1adhesion_2slip"), state)):
        scale = max(np.abs(ref).max(), 1e-30)
        worst = max(worst, np.abs(vtu - ref[idx]).max() / scale)
    print("patch_%s.vtu: %d quadrilaterals, %d vertices on %d nodes (all of the CSV), %d in contact; "
          "largest difference from the CSV %.1e of each field's largest value (limit 1e-6)"
          % (name, cells, points, len(table), int(col("in_contact").sum()), worst))
    assert worst < 1e-6 and col("in_contact").sum() > 0
    # the quadrilaterals tile the zone's rail top (a vertex order that twists
    # a cell would change its area): their area against the nodes' extent
    sizes = vtk.vtkCellSizeFilter()
    sizes.SetInputData(grid)
    sizes.Update()
    area = vtk_to_numpy(sizes.GetOutput().GetCellData().GetArray("Area")).sum()
    extent = np.ptp(X[:, 0]) * np.ptp(X[:, 1])
    print("  surface area %.2f mm^2, extent of the nodes %.2f mm^2 (ratio %.4f, limit 1 +- 0.01)"
          % (area * 1e6, extent * 1e6, area / extent))
    assert abs(area / extent - 1) < 0.01

# the tread side against the rail top and the statistics' F_N at each instant
stats = np.loadtxt("surface_run/statistics")
heads = [l.split(":", 1)[1].strip() for l in open("surface_run/statistics") if l[:2] == "# " and l[2:3].isdigit()]
FN = stats[:, heads.index("F_N [N]")]

def integrals(grid):
    f = vtk.vtkIntegrateAttributes()
    f.SetInputData(grid)
    f.Update()
    pd = f.GetOutput().GetPointData()
    return pd.GetArray("pressure_Pa").GetValue(0), pd.GetArray("shear_Pa").GetTuple3(0)[0]

for name in ("t-5.7us", "t", "t+5.7us"):
    grids = []
    for prefix in ("patch_", "patch_tread_"):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName("surface_run/%s%s.vtu" % (prefix, name))
        reader.Update()
        grids.append(reader.GetOutput())
    rail, tread = grids
    cells = tread.GetNumberOfCells()
    assert cells > 0 and all(tread.GetCellType(i) == vtk.VTK_QUAD for i in range(cells)), "not quadrilaterals"
    assert tread.GetPointData().GetArray("shear_Pa").GetNumberOfComponents() == 3
    p_tread = vtk_to_numpy(tread.GetPointData().GetArray("pressure_Pa"))
    P_r, Q_r = integrals(rail)
    P_t, Q_t = integrals(tread)
    t = tread.GetFieldData().GetArray("TIME").GetValue(0)
    F_N = FN[np.argmin(np.abs(stats[:, 1] - t))]
    print("patch_tread_%s.vtu: %d quadrilaterals, %d vertices in contact; integral of p %.2f kN "
          "(rail top %.2f kN, F_N of the statistics %.2f kN), of shear_x %.4f kN (rail top %.4f kN)"
          % (name, cells, int((p_tread > 0).sum()), P_t / 1e3, P_r / 1e3, F_N / 1e3, Q_t / 1e3, Q_r / 1e3))
    assert (p_tread > 0).sum() > 0
    assert abs(P_t / P_r - 1) < 0.03 and abs(P_t / F_N - 1) < 0.03 and abs(Q_t / Q_r - 1) < 0.05
PY
