#include <deal.II/base/mpi.h>

#include <wheelrail/contact/penalty_contact.h>
#include <wheelrail/postprocess/contact_patch.h>
#include <wheelrail/postprocess/output_files.h>
#include <wheelrail/postprocess/patch_series.h>

#include <hdf5.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace WheelRail
{
  namespace
  {
    const std::string file_name = "patch_series.h5";

    void
    check(const long status, const std::string &what)
    {
      AssertThrow(status >= 0,
                  ExcMessage("HDF5 could not " + what + " in " + file_name +
                             " (disk full, not writable, or on a resume a file that is not "
                             "this run's?)."));
    }

    /** The fields of the series: those of the surface files without the
     *  adhesion and slip shares. */
    const unsigned int n_series_fields = 6;

    /** A dataset of @p dims (rank 1-3) of @p type, the first dimension
     *  unlimited if @p extendable, chunked by one frame, shuffled and gzip. */
    hid_t
    create(const hid_t                 parent,
           const std::string          &name,
           const std::vector<hsize_t> &dims,
           const hid_t                 type,
           const bool                  extendable)
    {
      std::vector<hsize_t> maxdims = dims, chunk = dims;
      if (extendable)
        {
          maxdims[0] = H5S_UNLIMITED;
          chunk[0]   = 1;
        }
      for (hsize_t &c : chunk)
        c = std::max<hsize_t>(c, 1);
      const hid_t space      = H5Screate_simple(dims.size(), dims.data(), maxdims.data());
      const hid_t properties = H5Pcreate(H5P_DATASET_CREATE);
      check(H5Pset_chunk(properties, chunk.size(), chunk.data()), "chunk " + name);
      check(H5Pset_shuffle(properties), "shuffle " + name);
      check(H5Pset_deflate(properties, 4), "compress " + name);
      check(H5Pset_obj_track_times(properties, false), "switch off time stamps");
      const hid_t set =
        H5Dcreate2(parent, name.c_str(), type, space, H5P_DEFAULT, properties, H5P_DEFAULT);
      check(set, "create " + name);
      H5Pclose(properties);
      H5Sclose(space);
      return set;
    }

    /** A fixed dataset @p name of @p dims (none zero) in @p parent from @p data. */
    void
    write_dataset(const hid_t                 parent,
                  const std::string          &name,
                  const std::vector<hsize_t> &dims,
                  const hid_t                 file_type,
                  const hid_t                 memory_type,
                  const void                 *data)
    {
      const hid_t set = create(parent, name, dims, file_type, false);
      check(H5Dwrite(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write " + name);
      H5Dclose(set);
    }

    /** The values of @p field at each node, components interleaved. */
    std::vector<float>
    field_column(const std::vector<std::array<float, n_patch_values>> &values,
                 const PatchField                                     &field)
    {
      std::vector<float> data;
      for (const auto &v : values)
        data.insert(data.end(), &v[field.first], &v[field.first] + field.components);
      return data;
    }

    /** The name of tread frame @p k's group. */
    std::string
    tread_group(const unsigned long k)
    {
      return "tread/" + std::to_string(k);
    }

    /** Append row @p k (dims[1:] from @p data) to the extendable dataset @p name. */
    void
    append(const hid_t        file,
           const std::string &name,
           const hid_t        type,
           const void        *data,
           const hsize_t      k)
    {
      const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
      check(set, "open " + name);
      hid_t     space = H5Dget_space(set);
      hsize_t   dims[3];
      const int rank = H5Sget_simple_extent_ndims(space);
      H5Sget_simple_extent_dims(space, dims, nullptr);
      H5Sclose(space);
      dims[0] = k + 1;
      check(H5Dset_extent(set, dims), "extend " + name);
      space            = H5Dget_space(set);
      hsize_t start[3] = {k, 0, 0}, count[3] = {1, dims[1], rank > 2 ? dims[2] : 1};
      check(H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr),
            "select a frame of " + name);
      const hid_t memory = H5Screate_simple(rank, count, nullptr);
      check(H5Dwrite(set, type, memory, space, H5P_DEFAULT, data), "write " + name);
      H5Sclose(memory);
      H5Sclose(space);
      H5Dclose(set);
    }
  } // namespace



  PatchSeries::PatchSeries(const SimulatorAccess &access)
    : access(access)
  {}



  PatchSeries::~PatchSeries()
  {
    if (file >= 0)
      H5Fclose(file);
  }



  void
  PatchSeries::open(const unsigned long frames)
  {
    const auto             nodes = access.contact->master_node_results();
    const auto             faces = access.contact->master_face_nodes();
    const std::vector<int> quads = select_zone(nodes, faces);
    const std::string      path  = access.output_directory + "/" + file_name;
    if (frames == 0)
      create_file(path, nodes, quads);
    else
      {
        reopen_file(path, frames);
        cut_tread_frames(frames);
      }
  }



  std::vector<int>
  PatchSeries::select_zone(const std::vector<NodalContact>                &nodes,
                           const std::vector<std::array<unsigned int, 4>> &faces)
  {
    const GeometryParameters &g = access.parameters.geometry;
    std::vector<int>          index(nodes.size(), -1);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      if (in_solution_zone(g, nodes[i]))
        {
          index[i] = zone_nodes.size();
          zone_nodes.push_back(i);
        }
    std::vector<int> quads;
    for (const auto &face : faces)
      {
        bool inside = true;
        for (const unsigned int n : face)
          inside = inside && index[n] >= 0;
        if (inside)
          {
            // VTK / XDMF quadrilaterals go round the cell; the faces are lexicographic
            for (const unsigned int v : {0u, 1u, 3u, 2u})
              quads.push_back(index[face[v]]);
          }
      }
    n_quads = quads.size() / 4;
    return quads;
  }



  void
  PatchSeries::create_file(const std::string               &path,
                           const std::vector<NodalContact> &nodes,
                           const std::vector<int>          &quads)
  {
    const hsize_t n = zone_nodes.size();
    file            = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    check(file, "create the file");
    const hid_t         mesh = H5Gcreate2(file, "mesh", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<double> points, area;
    for (const unsigned int i : zone_nodes)
      {
        for (unsigned int d = 0; d < dim; ++d)
          points.push_back(nodes[i].X[d]);
        area.push_back(nodes[i].area);
      }
    hid_t set = create(mesh, "points", {n, 3}, H5T_IEEE_F64LE, false);
    check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, points.data()),
          "write the points");
    H5Dclose(set);
    set = create(mesh, "quads", {hsize_t(n_quads), 4}, H5T_STD_I32LE, false);
    if (n_quads > 0)
      check(H5Dwrite(set, H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, quads.data()),
            "write the quadrilaterals");
    H5Dclose(set);
    set = create(mesh, "area", {n}, H5T_IEEE_F64LE, false);
    check(H5Dwrite(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, area.data()),
          "write the areas");
    H5Dclose(set);
    H5Gclose(mesh);
    H5Dclose(create(file, "time", {0}, H5T_IEEE_F64LE, true));
    const hid_t group = H5Gcreate2(file, "fields", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    for (unsigned int f = 0; f < n_series_fields; ++f)
      {
        const PatchField &field = patch_fields()[f];
        H5Dclose(create(group,
                        field.name,
                        field.components == 1 ? std::vector<hsize_t>{0, n} :
                                                std::vector<hsize_t>{0, n, field.components},
                        H5T_IEEE_F32LE,
                        true));
      }
    H5Gclose(group);
    H5Gclose(H5Gcreate2(file, "tread", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  }



  void
  PatchSeries::reopen_file(const std::string &path, const unsigned long frames)
  {
    const hsize_t n = zone_nodes.size();
    file            = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    AssertThrow(file >= 0,
                ExcMessage("Output/Patch series interval: the resumed run's " + path +
                           " is missing or not readable; it holds the frames before "
                           "the checkpoint."));
    const hid_t time = H5Dopen2(file, "time", H5P_DEFAULT);
    check(time, "open time");
    hid_t   space = H5Dget_space(time);
    hsize_t have  = 0;
    H5Sget_simple_extent_dims(space, &have, nullptr);
    H5Sclose(space);
    AssertThrow(have >= frames,
                ExcMessage(path + " holds " + std::to_string(have) + " frames, the checkpoint " +
                           std::to_string(frames) + "."));
    times.resize(frames);
    if (frames > 0)
      {
        space                  = H5Dget_space(time);
        const hsize_t start[1] = {0}, count[1] = {frames};
        H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
        const hid_t memory = H5Screate_simple(1, count, nullptr);
        check(H5Dread(time, H5T_NATIVE_DOUBLE, memory, space, H5P_DEFAULT, times.data()),
              "read the times");
        H5Sclose(memory);
        H5Sclose(space);
      }
    const hsize_t cut[1] = {frames};
    check(H5Dset_extent(time, cut), "cut time");
    H5Dclose(time);
    for (unsigned int f = 0; f < n_series_fields; ++f)
      {
        const PatchField &field   = patch_fields()[f];
        const hid_t       set     = H5Dopen2(file, ("fields/" + field.name).c_str(), H5P_DEFAULT);
        const hsize_t     dims[3] = {frames, n, field.components};
        check(set, "open " + field.name);
        check(H5Dset_extent(set, dims), "cut " + field.name);
        H5Dclose(set);
      }
  }



  void
  PatchSeries::cut_tread_frames(const unsigned long frames)
  {
    tread_sizes.assign(frames, {{0, 0}});
    for (unsigned long k = 0; k < frames; ++k)
      if (H5Lexists(file, tread_group(k).c_str(), H5P_DEFAULT) > 0)
        for (unsigned int which = 0; which < 2; ++which)
          {
            const std::string name = tread_group(k) + (which == 0 ? "/points" : "/quads");
            const hid_t       set  = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
            check(set, "open " + name);
            const hid_t space = H5Dget_space(set);
            hsize_t     dims[2];
            H5Sget_simple_extent_dims(space, dims, nullptr);
            H5Sclose(space);
            H5Dclose(set);
            tread_sizes[k][which] = dims[0];
          }
    const hid_t tread = H5Gopen2(file, "tread", H5P_DEFAULT);
    check(tread, "open tread");
    H5G_info_t info;
    check(H5Gget_info(tread, &info), "read tread");
    std::vector<std::string> later;
    for (hsize_t i = 0; i < info.nlinks; ++i)
      {
        char name[32] = {};
        H5Lget_name_by_idx(
          tread, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof(name), H5P_DEFAULT);
        if (std::stoul(name) >= frames)
          later.emplace_back(name);
      }
    for (const std::string &name : later)
      check(H5Ldelete(tread, name.c_str(), H5P_DEFAULT), "cut the tread frames");
    H5Gclose(tread);
  }



  void
  PatchSeries::execute(const StepInfo &step)
  {
    const unsigned int every = access.parameters.output.patch_series_interval;
    if (every == 0 || !access.wheelset || !access.contact || (step.step + 1) % every != 0)
      return;
    if (Utilities::MPI::this_mpi_process(access.mpi_communicator) != 0)
      return;
    const unsigned long frame = (step.step + 1) / every - 1;
    if (file < 0)
      open(frame);
    const auto                                     nodes = access.contact->master_node_results();
    std::vector<std::array<float, n_patch_values>> values;
    for (const unsigned int i : zone_nodes)
      values.push_back(patch_field_values(nodes[i]));
    for (unsigned int f = 0; f < n_series_fields; ++f)
      {
        const PatchField &field = patch_fields()[f];
        append(file,
               "fields/" + field.name,
               H5T_NATIVE_FLOAT,
               field_column(values, field).data(),
               frame);
      }
    write_tread_frame(frame);
    const double t = access.solver.time();
    append(file, "time", H5T_NATIVE_DOUBLE, &t, frame);
    check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush");
    times.resize(frame);
    times.push_back(t);
    // The lists grow with the frames (2.5 MB for the paper run's 994):
    // rewritten at every frame they cost O(frames^2), seconds of rank 0's
    // time that the other ranks wait for. At a report step and at the run's
    // last frame they list every frame written and flushed so far.
    xdmf_pending = true;
    if (step.report_step || step.step + every >= step.n_steps)
      write_xdmf();
  }



  void
  PatchSeries::write_tread_frame(const unsigned long frame)
  {
    tread_sizes.resize(frame);
    if (!access.parameters.output.patch_series_tread)
      {
        tread_sizes.push_back({{0, 0}});
        return;
      }
    const auto nodes = access.contact->slave_node_results();
    const auto faces = tread_faces_over_zone(access, nodes);
    // the frame's own nodes, numbered as the faces reach them; VTK / XDMF
    // quadrilaterals go round the cell, the faces are lexicographic
    std::vector<int>          index(nodes.size(), -1);
    std::vector<unsigned int> used;
    std::vector<int>          quads;
    for (const auto &face : faces)
      for (const unsigned int v : {0u, 1u, 3u, 2u})
        {
          const unsigned int n = face[v];
          if (index[n] < 0)
            {
              index[n] = used.size();
              used.push_back(n);
            }
          quads.push_back(index[n]);
        }
    tread_sizes.push_back({{used.size(), faces.size()}});
    if (faces.empty())
      return;
    const hid_t group =
      H5Gcreate2(file, tread_group(frame).c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    check(group, "create " + tread_group(frame));
    const hsize_t                                  n = used.size();
    std::vector<float>                             points, area;
    std::vector<std::array<float, n_patch_values>> values;
    for (const unsigned int i : used)
      {
        for (unsigned int d = 0; d < dim; ++d)
          points.push_back(nodes[i].x[d]);
        area.push_back(nodes[i].area);
        values.push_back(patch_field_values(nodes[i]));
      }
    write_dataset(group, "points", {n, 3}, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, points.data());
    write_dataset(
      group, "quads", {hsize_t(faces.size()), 4}, H5T_STD_I32LE, H5T_NATIVE_INT, quads.data());
    write_dataset(group, "area", {n}, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, area.data());
    for (unsigned int f = 0; f < n_series_fields; ++f)
      {
        const PatchField &field = patch_fields()[f];
        write_dataset(group,
                      field.name,
                      field.components == 1 ? std::vector<hsize_t>{n} :
                                              std::vector<hsize_t>{n, field.components},
                      H5T_IEEE_F32LE,
                      H5T_NATIVE_FLOAT,
                      field_column(values, field).data());
      }
    H5Gclose(group);
  }



  void
  PatchSeries::write_files() const
  {
    if (xdmf_pending)
      write_xdmf();
  }



  void
  PatchSeries::write_xdmf() const
  {
    xdmf_pending                 = false;
    const unsigned long n        = zone_nodes.size();
    const unsigned long n_frames = times.size();
    std::ostringstream  x;
    x << std::setprecision(10) << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n<Domain>\n"
      << "<Grid Name=\"contact patch\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (unsigned long k = 0; k < n_frames; ++k)
      {
        x << "<Grid Name=\"frame " << k << "\" GridType=\"Uniform\">\n<Time Value=\"" << times[k]
          << "\"/>\n<Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" << n_quads
          << "\">\n<DataItem Dimensions=\"" << n_quads << " 4\" NumberType=\"Int\" Format=\"HDF\">"
          << file_name << ":/mesh/quads</DataItem>\n</Topology>\n"
          << "<Geometry GeometryType=\"XYZ\">\n<DataItem Dimensions=\"" << n
          << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << file_name
          << ":/mesh/points</DataItem>\n</Geometry>\n";
        for (unsigned int f = 0; f < n_series_fields; ++f)
          {
            const std::string &name       = patch_fields()[f].name;
            const unsigned int components = patch_fields()[f].components;
            const std::string  c          = components == 1 ? "" : " 3";
            x << "<Attribute Name=\"" << name << "\" AttributeType=\""
              << (components == 1 ? "Scalar" : "Vector") << "\" Center=\"Node\">\n"
              << "<DataItem ItemType=\"HyperSlab\" Dimensions=\"" << n << c << "\">\n"
              << "<DataItem Dimensions=\"3 " << (components == 1 ? 2 : 3) << "\" Format=\"XML\">"
              << k << " 0" << (components == 1 ? "" : " 0") << " 1 1"
              << (components == 1 ? "" : " 1") << " 1 " << n << c << "</DataItem>\n"
              << "<DataItem Dimensions=\"" << n_frames << " " << n << c
              << "\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">" << file_name
              << ":/fields/" << name << "</DataItem>\n</DataItem>\n</Attribute>\n";
          }
        x << "</Grid>\n";
      }
    x << "</Grid>\n</Domain>\n</Xdmf>\n";
    write_file_atomically(access.output_directory + "/patch_series.xdmf", x.str());

    if (!access.parameters.output.patch_series_tread)
      return;
    // the tread: each frame its own mesh (the faces over the zone change as
    // the wheel rolls), at the nodes' current positions
    std::ostringstream w;
    w << std::setprecision(10) << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n<Domain>\n"
      << "<Grid Name=\"contact patch, wheel tread\" GridType=\"Collection\" "
         "CollectionType=\"Temporal\">\n";
    for (unsigned long k = 0; k < n_frames && k < tread_sizes.size(); ++k)
      {
        const unsigned long nodes = tread_sizes[k][0], quads = tread_sizes[k][1];
        if (quads == 0)
          continue;
        const std::string h5 = file_name + ":/" + tread_group(k) + "/";
        w << "<Grid Name=\"frame " << k << "\" GridType=\"Uniform\">\n<Time Value=\"" << times[k]
          << "\"/>\n<Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" << quads
          << "\">\n<DataItem Dimensions=\"" << quads << " 4\" NumberType=\"Int\" Format=\"HDF\">"
          << h5 << "quads</DataItem>\n</Topology>\n"
          << "<Geometry GeometryType=\"XYZ\">\n<DataItem Dimensions=\"" << nodes
          << " 3\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">" << h5
          << "points</DataItem>\n</Geometry>\n";
        for (unsigned int f = 0; f < n_series_fields; ++f)
          {
            const std::string &name       = patch_fields()[f].name;
            const unsigned int components = patch_fields()[f].components;
            w << "<Attribute Name=\"" << name << "\" AttributeType=\""
              << (components == 1 ? "Scalar" : "Vector") << "\" Center=\"Node\">\n"
              << "<DataItem Dimensions=\"" << nodes << (components == 1 ? "" : " 3")
              << "\" NumberType=\"Float\" Precision=\"4\" Format=\"HDF\">" << h5 << name
              << "</DataItem>\n</Attribute>\n";
          }
        w << "</Grid>\n";
      }
    w << "</Grid>\n</Domain>\n</Xdmf>\n";
    write_file_atomically(access.output_directory + "/patch_series_tread.xdmf", w.str());
  }
} // namespace WheelRail
