/**
 * @file boundary_conditions.cc
 * The DoFs of the boundary conditions (SPEC 3): prescribed (fixed,
 * prescribed velocity, wheel bore) and loaded (applied force), found on the
 * boundary faces of the elastic operator's mesh.
 */
#include <deal.II/base/mpi.h>

#include <wheelrail/mesh/geometry.h>
#include <wheelrail/solver/boundary_conditions.h>

#include <algorithm>
#include <map>
#include <string>

namespace WheelRail
{
  /**
   * Throw if an entry of Boundary conditions names a boundary id that the
   * mesh does not have: such an entry would silently hold or load nothing.
   * Fixed boundaries at its default (the rail's ids) is left to geometries
   * without a rail to ignore. Collective: the ids of the whole mesh are gathered from all ranks.
   */
  void
  check_boundary_ids(const Parameters &prm, const Triangulation<dim> &triangulation)
  {
    const std::vector<types::boundary_id> mesh_ids = triangulation.get_boundary_ids();
    std::string                           listed;
    for (const types::boundary_id id : mesh_ids)
      listed += (listed.empty() ? "" : ", ") + std::to_string(id);
    const auto check = [&](const std::string &entry, const types::boundary_id id) {
      AssertThrow(std::find(mesh_ids.begin(), mesh_ids.end(), id) != mesh_ids.end(),
                  ExcMessage("Boundary conditions/" + entry + " names boundary id " +
                             std::to_string(id) + ", which the '" + prm.problem.geometry +
                             "' mesh does not have (its boundary ids: " + listed + ")."));
    };
    if (!prm.boundary.fixed_is_default)
      for (const auto &entry : prm.boundary.fixed)
        check("Fixed boundaries", entry.first);
    for (const types::boundary_id id : prm.boundary.prescribed_velocity_ids)
      check("Prescribed velocity boundaries", id);
    for (const types::boundary_id id : prm.boundary.applied_force_ids)
      check("Applied force boundaries", id);
  }



  std::vector<PrescribedDof>
  prescribed_dofs(const Parameters          &prm,
                  const ElasticOperator     &op,
                  std::vector<unsigned int> &bore_dofs)
  {
    const DoFHandler<dim>           &dof_handler         = op.get_dof_handler();
    const FiniteElement<dim>        &fe                  = dof_handler.get_fe();
    const AffineConstraints<double> &hanging_constraints = op.get_hanging_constraints();
    const auto                      &vector_partitioner  = op.partitioner();

    std::map<unsigned int, PrescribedDof> dofs;
    const auto add = [&](const unsigned int i, const unsigned int d, const BoundaryKind kind) {
      if (i + d >= vector_partitioner->locally_owned_size() ||
          hanging_constraints.is_constrained(vector_partitioner->local_to_global(i + d)))
        return;
      auto it = dofs.find(i + d);
      if (it == dofs.end() || kind < it->second.kind) // fixed wins
        dofs[i + d] = PrescribedDof{i + d, d, kind};
    };

    const WheelBore bore = prm.boundary.wheel_bore;
    bore_dofs.clear();
    std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int face : cell->face_indices())
          if (cell->face(face)->at_boundary())
            {
              const types::boundary_id id = cell->face(face)->boundary_id();
              cell->face(face)->get_dof_indices(face_dofs);
              for (unsigned int k = 0; k < face_dofs.size(); ++k)
                {
                  if (fe.face_system_to_component_index(k).first != 0)
                    continue;
                  const unsigned int i     = vector_partitioner->global_to_local(face_dofs[k]);
                  const auto         fixed = prm.boundary.fixed.find(id);
                  if (fixed != prm.boundary.fixed.end())
                    for (unsigned int d = 0; d < dim; ++d)
                      if (fixed->second.find("xyz"[d]) != std::string::npos)
                        add(i, d, BoundaryKind::fixed);
                  if (std::find(prm.boundary.prescribed_velocity_ids.begin(),
                                prm.boundary.prescribed_velocity_ids.end(),
                                id) != prm.boundary.prescribed_velocity_ids.end())
                    for (unsigned int d = 0; d < dim; ++d)
                      add(i, d, BoundaryKind::prescribed_velocity);
                  if (id == Geometry::BoundaryIds::wheel_bore)
                    {
                      for (unsigned int d = 0; d < dim; ++d)
                        {
                          if (bore == WheelBore::fixed)
                            add(i, d, BoundaryKind::fixed);
                          else if (bore == WheelBore::spinning_axle)
                            add(i, d, BoundaryKind::spinning_axle);
                          else if (bore == WheelBore::rigid_axle)
                            add(i, d, BoundaryKind::rigid_axle);
                          if (i + d < vector_partitioner->locally_owned_size())
                            bore_dofs.push_back(i + d);
                        }
                    }
                }
            }
    std::sort(bore_dofs.begin(), bore_dofs.end());
    bore_dofs.erase(std::unique(bore_dofs.begin(), bore_dofs.end()), bore_dofs.end());

    std::vector<PrescribedDof> prescribed;
    for (const auto &entry : dofs)
      prescribed.push_back(entry.second);
    return prescribed;
  }



  std::vector<AppliedForceDof>
  applied_force_dofs(const Parameters &prm, const ElasticOperator &op)
  {
    std::vector<AppliedForceDof> applied;
    if (prm.boundary.applied_force_ids.empty())
      return applied;
    const DoFHandler<dim>                                    &dof_handler = op.get_dof_handler();
    const std::shared_ptr<const Utilities::MPI::Partitioner> &vector_partitioner = op.partitioner();
    // nodal areas of the loaded boundaries, assembled like a force
    VectorType area(vector_partitioner);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int face : cell->face_indices())
          if (cell->face(face)->at_boundary() &&
              std::find(prm.boundary.applied_force_ids.begin(),
                        prm.boundary.applied_force_ids.end(),
                        cell->face(face)->boundary_id()) != prm.boundary.applied_force_ids.end())
            {
              const auto   fc = cell->face(face);
              const double a =
                0.5 * cross_product_3d(fc->vertex(3) - fc->vertex(0), fc->vertex(2) - fc->vertex(1))
                        .norm();
              for (unsigned int v = 0; v < 4; ++v)
                area.local_element(
                  vector_partitioner->global_to_local(fc->vertex_dof_index(v, 0))) += 0.25 * a;
            }
    op.condense(area);
    area.compress(VectorOperation::add);
    double total = 0;
    for (unsigned int i = 0; i < area.locally_owned_size(); ++i)
      total += area.local_element(i);
    total = Utilities::MPI::sum(total, vector_partitioner->get_mpi_communicator());
    AssertThrow(total > 0,
                ExcMessage("Boundary conditions/Applied force boundaries: no such boundary in "
                           "this geometry."));
    for (unsigned int i = 0; i < area.locally_owned_size(); ++i)
      if (area.local_element(i) > 0)
        for (unsigned int d = 0; d < dim; ++d)
          applied.emplace_back(i + d, d, area.local_element(i) / total);
    return applied;
  }
} // namespace WheelRail
