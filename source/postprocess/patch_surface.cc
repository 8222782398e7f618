#include <deal.II/base/data_out_base.h>

#include <wheelrail/postprocess/contact_patch.h>

#include <cmath>
#include <sstream>

namespace WheelRail
{
  // The contact fields on the rail-top surface of the solution zone: every
  // master face of the first pass whose four nodes lie in the zone becomes
  // a quadrilateral patch (DataOutBase::Patch<2, 3>, the vertices in the
  // faces' lexicographic order, which is deal.II's), with the nodal values
  // of master_node_results() at its vertices, written by DataOutBase as
  // binary, zlib-compressed VTU (Output/VTU compression). ParaView then
  // interpolates, contours and clips the fields on the surface.
  void
  write_patch_surface(const SimulatorAccess           &access,
                      const std::vector<NodalContact> &nodes,
                      const std::string               &file_name)
  {
    const GeometryParameters &g = access.parameters.geometry;
    // pressure, shear (3), s_n, de/dt (3), cof, state, adhesion share, slip share
    const std::vector<std::string> names  = {"pressure_Pa",
                                             "shear_Pa",
                                             "shear_Pa",
                                             "shear_Pa",
                                             "slip_velocity_m_s",
                                             "slip_rate_m_s",
                                             "slip_rate_m_s",
                                             "slip_rate_m_s",
                                             "cof",
                                             "state_0free_1adhesion_2slip",
                                             "adhesion_share",
                                             "slip_share"};
    const auto                     values = [](const NodalContact &m, float *v) {
      const bool in = m.in_contact();
      v[0]          = m.pressure();
      for (unsigned int d = 0; d < dim; ++d)
        {
          v[1 + d] = m.tangential_force[d] / m.area;
          v[5 + d] = m.slip_rate[d];
        }
      v[4]  = m.slip_velocity;
      v[8]  = m.cof;
      v[9]  = double(in) + double(in && !m.adhesion());
      v[10] = m.adhesion_share;
      v[11] = m.slip_share;
    };

    std::vector<DataOutBase::Patch<2, dim>> patches;
    for (const auto &face : access.contact->master_face_nodes())
      {
        bool inside = true;
        for (const unsigned int n : face)
          inside = inside && in_solution_zone(g, nodes[n]);
        if (!inside)
          continue;
        DataOutBase::Patch<2, dim> patch;
        patch.patch_index    = patches.size();
        patch.reference_cell = ReferenceCells::Quadrilateral;
        patch.data.reinit(names.size(), 4);
        for (unsigned int v = 0; v < 4; ++v)
          {
            const NodalContact &m = nodes[face[v]];
            patch.vertices[v]     = m.X;
            float row[12];
            values(m, row);
            for (unsigned int k = 0; k < names.size(); ++k)
              patch.data(k, v) = row[k];
          }
        patches.push_back(std::move(patch));
      }

    const std::vector<std::tuple<unsigned int,
                                 unsigned int,
                                 std::string,
                                 DataComponentInterpretation::DataComponentInterpretation>>
      vectors = {{1, 3, "shear_Pa", DataComponentInterpretation::component_is_part_of_vector},
                 {5, 7, "slip_rate_m_s", DataComponentInterpretation::component_is_part_of_vector}};
    DataOutBase::VtkFlags flags;
    flags.time               = access.solver.time();
    const std::string &level = access.parameters.output.vtu_compression;
    flags.compression_level  = level == "best" ? DataOutBase::VtkFlags::best_compression :
                               level == "none" ? DataOutBase::VtkFlags::no_compression :
                                                 DataOutBase::VtkFlags::best_speed;
    std::ostringstream out;
    DataOutBase::write_vtu(patches, names, vectors, flags, out);
    access.write_file(file_name, out.str());
  }
} // namespace WheelRail
