#include <deal.II/base/data_out_base.h>

#include <wheelrail/postprocess/contact_patch.h>
#include <wheelrail/postprocess/vtu_output.h>

#include <cmath>
#include <sstream>

namespace WheelRail
{
  const std::vector<PatchField> &
  patch_fields()
  {
    static const std::vector<PatchField> fields = {{"pressure_Pa", 0, 1},
                                                   {"shear_Pa", 1, 3},
                                                   {"slip_velocity_m_s", 4, 1},
                                                   {"slip_rate_m_s", 5, 3},
                                                   {"cof", 8, 1},
                                                   {"state_0free_1adhesion_2slip", 9, 1},
                                                   {"adhesion_share", 10, 1},
                                                   {"slip_share", 11, 1}};
    return fields;
  }



  std::array<float, n_patch_values>
  patch_field_values(const NodalContact &m)
  {
    std::array<float, n_patch_values> v;
    const bool                        in = m.in_contact();
    v[0]                                 = m.pressure();
    for (unsigned int d = 0; d < dim; ++d)
      {
        v[1 + d] = m.area > 0 ? m.tangential_force[d] / m.area : 0.;
        v[5 + d] = m.slip_rate[d];
      }
    v[4]  = m.slip_velocity;
    v[8]  = m.cof;
    v[9]  = double(in) + double(in && !m.adhesion());
    v[10] = m.adhesion_share;
    v[11] = m.slip_share;
    return v;
  }



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
    std::vector<std::string>  names;
    std::vector<std::tuple<unsigned int,
                           unsigned int,
                           std::string,
                           DataComponentInterpretation::DataComponentInterpretation>>
      vectors;
    for (const PatchField &field : patch_fields())
      {
        names.insert(names.end(), field.components, field.name);
        if (field.components > 1)
          vectors.emplace_back(field.first,
                               field.first + field.components - 1,
                               field.name,
                               DataComponentInterpretation::component_is_part_of_vector);
      }

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
            const auto row        = patch_field_values(m);
            for (unsigned int k = 0; k < names.size(); ++k)
              patch.data(k, v) = row[k];
          }
        patches.push_back(std::move(patch));
      }

    DataOutBase::VtkFlags flags;
    flags.time              = access.solver.time();
    flags.compression_level = vtu_compression_level(access.parameters.output.vtu_compression);
    std::ostringstream out;
    DataOutBase::write_vtu(patches, names, vectors, flags, out);
    access.write_file(file_name, out.str());
  }
} // namespace WheelRail
