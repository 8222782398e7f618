/**
 * @file postprocess/series_hdf5.h
 * OUTDIR/series.h5: the run's histories in one HDF5 file.
 */
#ifndef wheelrail_postprocess_series_hdf5_h
#define wheelrail_postprocess_series_hdf5_h

#include <wheelrail/postprocess/probes.h>
#include <wheelrail/postprocess/statistics.h>

namespace WheelRail
{
  /**
   * Write OUTDIR/series.h5 (collective; rank 0 writes, the probes' owners
   * send their histories to it):
   *
   * - /statistics: the statistics table, rows x columns (attribute
   *   'columns': the column names with their units, as in the text file);
   * - /probes/NAME (NAME = the probe's CSV name without '.csv'): t, u_x,
   *   u_y, u_z, v_x, v_y, v_z per step (attributes 'columns', 'location':
   *   the node's reference position [m]).
   *
   * Datasets are chunked (up to 4,096 rows), shuffled and deflated, without
   * object time stamps (the same run gives the same file). The file is
   * written under a temporary name and renamed, as every output: it is
   * valid up to the last write (the end of the run and every checkpoint).
   */
  void
  write_series_hdf5(const SimulatorAccess &access,
                    const Statistics      &statistics,
                    const Probes          &probes);
} // namespace WheelRail

#endif
