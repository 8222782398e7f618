#!/usr/bin/env bash
# The run's histories in HDF5 (series.h5, issue 27): a short rolling run (the
# plot test's case) on 2 ranks, then series.h5 read back with h5py against the
# text files of the same run: /statistics column by column against
# 'statistics' (written with 9 significant digits: limit 1e-7 relative),
# /probes/probe and /probes/wheel_probe against probe.csv and
# wheel_probe.csv (10 digits: 1e-8 of the largest value), their 'location'
# against the CSV headers, the column names, and the datasets chunked and
# gzip-compressed. The probe point is the top of the wheel, whose node rank 1
# owns on 2 ranks: its history reaches the file through rank 0.
# Arguments: the wheelrail executable, the source directory.
set -euo pipefail
exe=$1 src=$2
# Open MPI as root (CI, containers) and more ranks than cores
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
bash "$(dirname "$0")/rolling_case.sh" "$src" series_run > series.prm
# the probe at the top of the wheel: a node that rank 1 owns on 2 ranks
printf 'subsection Output\n  set Probe point = -0.003, 0, 0.92\nend\n' >> series.prm
rm -rf series_run
mpirun -np 2 "$exe" series.prm > wheelrail.log
/usr/bin/python3 - <<'PY'
import re
import h5py
import numpy as np

with h5py.File("series_run/series.h5", "r") as f:
    s = f["statistics"]
    names = [c.decode() if isinstance(c, bytes) else c for c in s.attrs["columns"]]
    text_names = [l.split(":", 1)[1].strip() for l in open("series_run/statistics") if re.match(r"# \d+:", l)]
    assert names == text_names, "column names differ: %s / %s" % (names, text_names)
    table = np.loadtxt("series_run/statistics", comments="#", ndmin=2)
    assert s.shape == table.shape, "statistics: %s rows x columns, the text file %s" % (s.shape, table.shape)
    assert s.compression == "gzip" and s.chunks is not None
    scale = np.maximum(np.abs(table), np.abs(table).max(axis=0) * 1e-12 + 1e-300)
    err = np.max(np.abs(s[()] - table) / scale)
    print("statistics: %d rows x %d columns, largest relative difference from the text file %.1e "
          "(limit 1e-7)" % (s.shape + (err,)))
    assert err < 1e-7
    for name in ("probe", "wheel_probe"):
        p = f["probes/" + name]
        csv = np.loadtxt("series_run/%s.csv" % name, delimiter=",", skiprows=2, ndmin=2)
        head = open("series_run/%s.csv" % name).readline()
        location = np.array([float(v) for v in re.search(r"node at \(([^)]*)\)", head).group(1).split()])
        err = np.max(np.abs(p[()] - csv)) / np.max(np.abs(csv))
        print("%s: %d steps, location %s m, largest difference from the CSV %.1e of its largest value "
              "(limit 1e-8)" % (name, p.shape[0], p.attrs["location"], err))
        assert p.shape == csv.shape and p.compression == "gzip" and err < 1e-8
        assert np.allclose(p.attrs["location"], location, rtol=1e-5, atol=1e-10)
PY
