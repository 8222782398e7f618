#include <deal.II/base/mpi.h>

#include <wheelrail/postprocess/output_files.h>
#include <wheelrail/postprocess/series_hdf5.h>

#include <hdf5.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace WheelRail
{
  namespace
  {
    void
    check(const long status, const std::string &what, const std::string &file)
    {
      AssertThrow(status >= 0,
                  ExcMessage("HDF5 could not " + what + " in " + file +
                             " (disk full or not writable?)."));
    }

    /** A string-array attribute @p name on @p object. */
    void
    write_names(const hid_t                     object,
                const char                     *name,
                const std::vector<std::string> &names,
                const std::string              &file)
    {
      std::vector<const char *> c;
      for (const std::string &n : names)
        c.push_back(n.c_str());
      const hsize_t n_names = c.size();
      const hid_t   type    = H5Tcopy(H5T_C_S1);
      check(H5Tset_size(type, H5T_VARIABLE), "make a string type", file);
      const hid_t space     = H5Screate_simple(1, &n_names, nullptr);
      const hid_t attribute = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
      check(attribute, std::string("create the attribute ") + name, file);
      check(H5Awrite(attribute, type, c.data()), std::string("write ") + name, file);
      H5Aclose(attribute);
      H5Sclose(space);
      H5Tclose(type);
    }

    /** A rows x columns dataset @p name of doubles (row-major @p data),
     *  chunked, shuffled, deflated, extendable in rows. */
    hid_t
    write_matrix(const hid_t                parent,
                 const std::string         &name,
                 const std::vector<double> &data,
                 const hsize_t              n_columns,
                 const std::string         &file)
    {
      const hsize_t dims[2]    = {data.size() / n_columns, n_columns};
      const hsize_t maxdims[2] = {H5S_UNLIMITED, n_columns};
      const hsize_t chunk[2] = {std::min<hsize_t>(std::max<hsize_t>(dims[0], 1), 4096), n_columns};
      const hid_t   space    = H5Screate_simple(2, dims, maxdims);
      const hid_t   properties = H5Pcreate(H5P_DATASET_CREATE);
      check(H5Pset_chunk(properties, 2, chunk), "set the chunks of " + name, file);
      check(H5Pset_shuffle(properties), "set the shuffle filter of " + name, file);
      check(H5Pset_deflate(properties, 4), "set the compression of " + name, file);
      check(H5Pset_obj_track_times(properties, false), "switch off time stamps", file);
      const hid_t set = H5Dcreate2(
        parent, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, properties, H5P_DEFAULT);
      check(set, "create the dataset " + name, file);
      if (!data.empty())
        check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()),
              "write " + name,
              file);
      H5Pclose(properties);
      H5Sclose(space);
      return set;
    }

    /** Each probe's history at rank 0 (empty elsewhere, but for the
     *  probes a rank owns): the owners other than rank 0 send theirs, the
     *  length first, in the order of the probes (collective). */
    std::vector<std::vector<double>>
    gather_histories(const MPI_Comm comm, const unsigned int rank, const Probes &probes)
    {
      std::vector<std::vector<double>> histories;
      for (const Probe &probe : probes.nodes())
        {
          std::vector<double> h = probe.owner == rank ? probe.history : std::vector<double>();
          if (probe.owner != 0)
            {
              if (rank == probe.owner)
                {
                  const unsigned long n = h.size();
                  MPI_Send(&n, 1, MPI_UNSIGNED_LONG, 0, 0, comm);
                  MPI_Send(h.data(), n, MPI_DOUBLE, 0, 1, comm);
                }
              else if (rank == 0)
                {
                  unsigned long n = 0;
                  MPI_Recv(&n, 1, MPI_UNSIGNED_LONG, probe.owner, 0, comm, MPI_STATUS_IGNORE);
                  h.resize(n);
                  MPI_Recv(h.data(), n, MPI_DOUBLE, probe.owner, 1, comm, MPI_STATUS_IGNORE);
                }
            }
          histories.push_back(std::move(h));
        }
      return histories;
    }

    /** The dataset /statistics of @p file (named @p temp in messages): the
     *  statistics table row-major, a column shorter than the first padded
     *  with NaN, and the attribute 'columns'; none without columns. */
    void
    write_statistics(const hid_t file, const Statistics &statistics, const std::string &temp)
    {
      const StatisticsTable           &table = statistics.rows();
      const std::vector<std::string>  &keys  = table.keys();
      std::vector<std::vector<double>> columns;
      for (const std::string &key : keys)
        columns.push_back(table.values(key));
      const std::size_t   n_rows = columns.empty() ? 0 : columns.front().size();
      std::vector<double> rows;
      rows.reserve(n_rows * keys.size());
      for (std::size_t r = 0; r < n_rows; ++r)
        for (const auto &column : columns)
          rows.push_back(r < column.size() ? column[r] : std::numeric_limits<double>::quiet_NaN());
      if (!keys.empty())
        {
          const hid_t set = write_matrix(file, "statistics", rows, keys.size(), temp);
          write_names(set, "columns", keys, temp);
          H5Dclose(set);
        }
    }

    /** The group /probes of @p file (named @p temp in messages): per probe
     *  the dataset NAME (its CSV name without '.csv') of @p histories'
     *  entry, with the attributes 'columns' and 'location'. */
    void
    write_probes(const hid_t                             file,
                 const Probes                           &probes,
                 const std::vector<std::vector<double>> &histories,
                 const std::string                      &temp)
    {
      const hid_t group = H5Gcreate2(file, "probes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      check(group, "create the group probes", temp);
      const std::vector<std::string> probe_columns = {
        "t [s]", "u_x [m]", "u_y [m]", "u_z [m]", "v_x [m/s]", "v_y [m/s]", "v_z [m/s]"};
      for (unsigned int i = 0; i < probes.nodes().size(); ++i)
        {
          const Probe &probe = probes.nodes()[i];
          std::string  name  = probe.file;
          if (name.size() > 4 && name.compare(name.size() - 4, 4, ".csv") == 0)
            name.resize(name.size() - 4);
          const hid_t set = write_matrix(group, name, histories[i], 7, temp);
          write_names(set, "columns", probe_columns, temp);
          const hsize_t three = dim;
          const hid_t   space = H5Screate_simple(1, &three, nullptr);
          const hid_t   location =
            H5Acreate2(set, "location", H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT);
          check(location, "create the attribute location", temp);
          double X[dim];
          for (unsigned int d = 0; d < dim; ++d)
            X[d] = probe.location[d];
          check(H5Awrite(location, H5T_NATIVE_DOUBLE, X), "write location", temp);
          H5Aclose(location);
          H5Sclose(space);
          H5Dclose(set);
        }
      H5Gclose(group);
    }
  } // namespace



  void
  write_series_hdf5(const SimulatorAccess &access,
                    const Statistics      &statistics,
                    const Probes          &probes)
  {
    const MPI_Comm                         comm      = access.mpi_communicator;
    const unsigned int                     rank      = Utilities::MPI::this_mpi_process(comm);
    const std::vector<std::vector<double>> histories = gather_histories(comm, rank, probes);
    if (rank != 0)
      return;

    const std::string path = access.output_directory + "/series.h5";
    TemporaryPath     guard(path + ".tmp");
    const std::string temp = guard.name();
    const hid_t       file = H5Fcreate(temp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    check(file, "create the file", temp);
    write_statistics(file, statistics, temp);
    write_probes(file, probes, histories, temp);
    check(H5Fclose(file), "close the file", temp);
    AssertThrow(std::rename(temp.c_str(), path.c_str()) == 0,
                ExcMessage("Could not rename " + temp + " to " + path + "."));
    guard.commit();
  }
} // namespace WheelRail
