#!/usr/bin/env bash
# The contact patch as a time series (patch_series.h5 + patch_series.xdmf,
# issue 27): the plot test's short rolling case on 2 ranks with a frame
# every 20 steps, once uninterrupted and once stopped after step 310 (a
# checkpoint) and resumed. Checked with h5py and the XML parser:
# - the frames: one per 20 steps (30), their times those of the steps;
# - each frame's pressure integrated over the nodes' areas against the
#   statistics' F_N at the same time: the nodal forces are magnitudes along
#   the surface normals, F_N the vertical component of the total, so the
#   integral is somewhat larger (1.9e-4 measured, of which the rail
#   profile's slope, the pressure-weighted mean of 1 - cos(y / 0.3 m),
#   accounts for 0.9e-4); limit 1e-3;
# - the XDMF lists every frame with its time, and every HDF5 reference in it
#   names a dataset of the file with the dimensions it states;
# - the wheel tread's frames (/tread/K, patch_series_tread.xdmf): quads on
#   the frame's own nodes, the tread nodes' normal forces (p A) against the
#   statistics' F_N as for the rail top (limit 1e-3), the same references
#   check;
# - the resumed run's file and XDMF hold exactly the uninterrupted run's
#   frames.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
bash "$(dirname "$0")/rolling_case.sh" "$src" whole > whole.prm
printf 'subsection Output\n  set Patch series interval = 20\nend\n' >> whole.prm
{ echo 'include whole.prm'; printf 'subsection Problem\n  set Output directory = split\nend\nsubsection Output\n  set Stop after step = 310\nend\n'; } > split.prm
rm -rf whole split
mpirun -np 2 "$exe" whole.prm > whole.log
mpirun -np 2 "$exe" split.prm > split.log
mpirun -np 2 "$exe" split.prm --resume > resume.log
grep "^Resumed from" resume.log
/usr/bin/python3 - <<'PY'
import re
import xml.etree.ElementTree as ET
import h5py
import numpy as np

with h5py.File("whole/patch_series.h5", "r") as f, h5py.File("split/patch_series.h5", "r") as g:
    t, area = f["time"][()], f["mesh/area"][()]
    p = f["fields/pressure_Pa"][()]
    assert len(t) == 30, "expected 30 frames, got %d" % len(t)
    names = [l.split(":", 1)[1].strip() for l in open("whole/statistics") if re.match(r"# \d+:", l)]
    S = np.loadtxt("whole/statistics", comments="#", ndmin=2)
    time, fn = S[:, names.index("time [s]")], S[:, [i for i, n in enumerate(names) if n.startswith("F_N")][0]]
    errors = []
    for k in range(len(t)):
        j = np.argmin(np.abs(time - t[k]))
        if abs(time[j] - t[k]) < 1e-12:
            errors.append(abs((p[k] * area).sum() / fn[j] - 1))
    print("%d frames, %d nodes, %d quadrilaterals; sum of p A against F_N at %d frames: largest "
          "difference %.1e (limit 1e-3)" % (len(t), len(area), f["mesh/quads"].shape[0], len(errors),
                                            max(errors)))
    assert len(errors) == len(t) and max(errors) < 1e-3
    for name in ["time", "mesh/points", "mesh/quads", "mesh/area"] + ["fields/" + n for n in f["fields"]]:
        assert np.array_equal(f[name][()], g[name][()]), "resumed run differs in " + name
    print("resumed run: the same %d frames, every dataset equal" % len(g["time"]))

    root = ET.parse("whole/patch_series.xdmf").getroot()
    grids = root.findall("./Domain/Grid/Grid")
    times = [float(gr.find("Time").get("Value")) for gr in grids]
    assert len(grids) == len(t) and np.allclose(times, t, rtol=1e-9, atol=0), "XDMF frames or times differ"
    checked = 0
    for item in root.iter("DataItem"):
        if item.get("Format") != "HDF":
            continue
        name = item.text.strip().split(":", 1)[1]
        dims = tuple(int(v) for v in item.get("Dimensions").split())
        assert name in f and f[name].shape == dims, "XDMF reference %s %s: file has %s" % (
            name, dims, f[name].shape if name in f else "nothing")
        checked += 1
    print("patch_series.xdmf: %d frames, %d HDF5 references, each a dataset of the stated dimensions"
          % (len(grids), checked))
    # the tread frames
    tread = f["tread"]
    assert sorted(tread, key=int) == sorted(g["tread"], key=int), "resumed run's tread frames differ"
    errors, sizes = [], []
    for key in tread:
        k, fr = int(key), tread[key]
        n, quads = fr["points"].shape[0], fr["quads"][()]
        assert quads.min() >= 0 and quads.max() < n and len(np.unique(quads)) == n, "tread quads"
        j = np.argmin(np.abs(time - t[k]))
        errors.append(abs((fr["pressure_Pa"][()] * fr["area"][()]).sum() / fn[j] - 1))
        sizes.append(n)
        for name in fr:
            assert np.array_equal(fr[name][()], g["tread"][key][name][()]), "resumed tread differs"
    print("tread: %d frames of %d-%d nodes; sum of p A against F_N: largest difference %.1e (limit 1e-3)"
          % (len(errors), min(sizes), max(sizes), max(errors)))
    assert len(errors) == len(t) and max(errors) < 1e-3
    root = ET.parse("whole/patch_series_tread.xdmf").getroot()
    grids = root.findall("./Domain/Grid/Grid")
    assert len(grids) == len(tread)
    checked = 0
    for item in root.iter("DataItem"):
        name = item.text.strip().split(":", 1)[1]
        dims = tuple(int(v) for v in item.get("Dimensions").split())
        assert name in f and f[name].shape == dims, "tread XDMF reference %s %s" % (name, dims)
        checked += 1
    print("patch_series_tread.xdmf: %d frames, %d HDF5 references, each a dataset of the stated "
          "dimensions" % (len(grids), checked))
for name in ("patch_series.xdmf", "patch_series_tread.xdmf"):
    assert open("whole/" + name).read() == open("split/" + name).read(), name
PY
