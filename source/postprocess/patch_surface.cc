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



  namespace
  {
    /** A face's quadrilateral (DataOutBase::Patch<2, 3>, the vertices in the
     *  faces' lexicographic order, which is deal.II's) with the values of
     *  patch_field_values() at its vertices. */
    DataOutBase::Patch<2, dim>
    face_patch(const std::array<unsigned int, 4> &face,
               const std::vector<NodalContact>   &nodes,
               const bool                         current_position,
               const unsigned int                 index)
    {
      DataOutBase::Patch<2, dim> patch;
      patch.patch_index    = index;
      patch.reference_cell = ReferenceCells::Quadrilateral;
      patch.data.reinit(n_patch_values, 4);
      for (unsigned int v = 0; v < 4; ++v)
        {
          const NodalContact &m = nodes[face[v]];
          patch.vertices[v]     = current_position ? m.x : m.X;
          const auto row        = patch_field_values(m);
          for (unsigned int k = 0; k < n_patch_values; ++k)
            patch.data(k, v) = row[k];
        }
      return patch;
    }

    /** The quadrilaterals with the fields of patch_fields() as point data:
     *  binary, zlib-compressed VTU by DataOutBase (Output/VTU compression). */
    void
    write_quads(const SimulatorAccess                         &access,
                const std::vector<DataOutBase::Patch<2, dim>> &patches,
                const std::string                             &file_name)
    {
      std::vector<std::string> names;
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
      DataOutBase::VtkFlags flags;
      flags.time              = access.solver.time();
      flags.compression_level = vtu_compression_level(access.parameters.output.vtu_compression);
      std::ostringstream out;
      DataOutBase::write_vtu(patches, names, vectors, flags, out);
      access.write_file(file_name, out.str());
    }
  } // namespace



  // The contact fields on the rail-top surface of the solution zone: every
  // master face of the first pass whose four nodes lie in the zone, at the
  // nodes' reference positions, with the nodal values of
  // master_node_results(). ParaView then interpolates, contours and clips
  // the fields on the surface.
  void
  write_patch_surface(const SimulatorAccess           &access,
                      const std::vector<NodalContact> &nodes,
                      const std::string               &file_name)
  {
    const GeometryParameters               &g = access.parameters.geometry;
    std::vector<DataOutBase::Patch<2, dim>> patches;
    for (const auto &face : access.contact->master_face_nodes())
      {
        bool inside = true;
        for (const unsigned int n : face)
          inside = inside && in_solution_zone(g, nodes[n]);
        if (inside)
          patches.push_back(face_patch(face, nodes, false, patches.size()));
      }
    write_quads(access, patches, file_name);
  }



  // The same fields on the wheel tread: every slave face of the first pass
  // whose four nodes are contact candidates (their current positions are
  // kept) and lie, at those positions, over the solution zone, drawn at the
  // current positions, so that it lies on the rail top's surface where the
  // two touch.
  std::vector<std::array<unsigned int, 4>>
  tread_faces_over_zone(const SimulatorAccess &access, const std::vector<NodalContact> &nodes)
  {
    const GeometryParameters                &g = access.parameters.geometry;
    std::vector<std::array<unsigned int, 4>> faces;
    for (const auto &face : access.contact->candidate_slave_faces())
      {
        bool inside = true;
        for (const unsigned int n : face)
          inside = inside && over_solution_zone(g, nodes[n].x);
        if (inside)
          faces.push_back(face);
      }
    return faces;
  }



  void
  write_tread_surface(const SimulatorAccess           &access,
                      const std::vector<NodalContact> &nodes,
                      const std::string               &file_name)
  {
    std::vector<DataOutBase::Patch<2, dim>> patches;
    for (const auto &face : tread_faces_over_zone(access, nodes))
      patches.push_back(face_patch(face, nodes, true, patches.size()));
    write_quads(access, patches, file_name);
  }
} // namespace WheelRail
