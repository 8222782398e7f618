#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <wheelrail/solver/elastic_operator.h>
#include <wheelrail/solver/element_kernel.h>

#include <algorithm>
#include <map>

namespace WheelRail
{
  using namespace ElementKernel;

  static_assert(ElasticOperator::n_lanes == W, "the batches are the kernel's");



  ElasticOperator::ElasticOperator(const Parameters                          &parameters,
                                   parallel::distributed::Triangulation<dim> &tria)
    : prm(parameters)
    , triangulation(tria)
    , mpi_communicator(tria.get_communicator())
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(tria)
  {}



  void
  ElasticOperator::setup()
  {
    dof_handler.distribute_dofs(fe);

    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    hanging_constraints.clear();
    hanging_constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    hanging_constraints.close();
    make_hanging_vertices_conforming();
    setup_partitioner();

    damping = prm.solver.damping_model;
    setup_node_data();
    setup_cell_data();
    find_families();
    setup_lumped_mass();
  }



  void
  ElasticOperator::setup_partitioner()
  {
    // ghost set: locally relevant DoFs and every master of a constraint
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    IndexSet                             ghosts = relevant;
    std::vector<types::global_dof_index> masters;
    for (const auto &line : hanging_constraints.get_lines())
      for (const auto &entry : line.entries)
        masters.push_back(entry.first);
    std::sort(masters.begin(), masters.end());
    masters.erase(std::unique(masters.begin(), masters.end()), masters.end());
    ghosts.add_indices(masters.begin(), masters.end());
    ghosts.compress();
    vector_partitioner =
      std::make_shared<Utilities::MPI::Partitioner>(dof_handler.locally_owned_dofs(),
                                                    ghosts,
                                                    mpi_communicator);

    // group the lines by node where the dim lines of a node have the same
    // masters (shifted by the component) and the same weights; the groups
    // keep the lines' order, so every entry receives its additions in the
    // same order as line by line
    const auto &lines     = hanging_constraints.get_lines();
    const auto  groupable = [&](const unsigned int k) {
      if (k + dim > lines.size())
        return false;
      const auto first = vector_partitioner->global_to_local(lines[k].index);
      for (unsigned int d = 1; d < dim; ++d)
        {
          const auto &line = lines[k + d];
          if (vector_partitioner->global_to_local(line.index) != first + d ||
              line.entries.size() != lines[k].entries.size())
            return false;
          for (unsigned int j = 0; j < line.entries.size(); ++j)
            if (vector_partitioner->global_to_local(line.entries[j].first) !=
                  vector_partitioner->global_to_local(lines[k].entries[j].first) + d ||
                line.entries[j].second != lines[k].entries[j].second)
              return false;
        }
      return true;
    };
    constraint_width = dim;
    for (unsigned int k = 0; k < lines.size() && constraint_width == dim; k += dim)
      if (!groupable(k))
        constraint_width = 1;

    constrained_dofs.clear();
    constraint_offsets.assign(1, 0);
    constraint_masters.clear();
    constraint_weights.clear();
    for (unsigned int k = 0; k < lines.size(); k += constraint_width)
      {
        for (const auto &entry : lines[k].entries)
          {
            constraint_masters.push_back(vector_partitioner->global_to_local(entry.first));
            constraint_weights.push_back(entry.second);
          }
        constrained_dofs.push_back(vector_partitioner->global_to_local(lines[k].index));
        constraint_offsets.push_back(constraint_masters.size());
      }
  }



  void
  ElasticOperator::make_hanging_vertices_conforming()
  {
    // Refinement on a curved manifold puts a hanging vertex on the curve,
    // while the trilinear coarse neighbour's face and the FE_Q(1) constraint
    // put it at the mean of its masters. Moving the vertex there makes the
    // geometry agree with the displacement space, so that linear fields
    // (rigid rotations among them) are represented exactly.
    std::vector<types::global_dof_index>          dofs(fe.n_dofs_per_cell());
    std::map<types::global_dof_index, Point<dim>> position;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int a = 0; a < 8; ++a)
            position[dofs[fe.component_to_system_index(0, a)]] = cell->vertex(a);
        }
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int a = 0; a < 8; ++a)
            {
              const auto *entries = hanging_constraints.get_constraint_entries(
                dofs[fe.component_to_system_index(0, a)]);
              if (entries == nullptr)
                continue;
              Point<dim> x;
              for (const auto &entry : *entries)
                {
                  const auto it = position.find(entry.first);
                  AssertThrow(it != position.end(),
                              ExcMessage(
                                "Internal error: master vertex of a hanging node not found."));
                  x += entry.second * it->second;
                }
              cell->vertex(a) = x;
            }
        }
  }


  std::vector<unsigned int>
  ElasticOperator::constrained_local_dofs() const
  {
    std::vector<unsigned int> dofs;
    dofs.reserve(constrained_dofs.size() * constraint_width);
    for (const unsigned int k : constrained_dofs)
      for (unsigned int d = 0; d < constraint_width; ++d)
        dofs.push_back(k + d);
    return dofs;
  }



  VectorType
  ElasticOperator::point_mass() const
  {
    VectorType m = mass;
    m.update_ghost_values();
    for (unsigned int c = 0; c < constrained_dofs.size(); ++c)
      for (unsigned int d = 0; d < constraint_width; ++d)
        {
          double mobility = 0;
          for (unsigned int k = constraint_offsets[c]; k < constraint_offsets[c + 1]; ++k)
            {
              const double master = m.local_element(constraint_masters[k] + d);
              if (master > 0)
                mobility += constraint_weights[k] * constraint_weights[k] / master;
            }
          m.local_element(constrained_dofs[c] + d) = mobility > 0 ? 1. / mobility : 0.;
        }
    return m;
  }



  void
  ElasticOperator::setup_lumped_mass()
  {
    const double  rho = prm.material.density;
    FE_Q<dim>     fe_scalar(1);
    QGauss<dim>   quadrature(2);
    FEValues<dim> fe_values(fe_scalar, quadrature, update_values | update_JxW_values);

    mass.reinit(vector_partitioner);
    // row-sum lumping rho int N_a dV, cell by cell in the triangulation's
    // order (not the batches'), each cell's nodes from its batch slot
    std::vector<unsigned int> slot(triangulation.n_active_cells(), numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < n_cells; ++c)
      slot[batch_cell_index[c]] = c;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int batch = slot[cell->active_cell_index()] / W,
                             lane  = slot[cell->active_cell_index()] % W;
          fe_values.reinit(cell);
          for (unsigned int a = 0; a < 8; ++a)
            {
              double m = 0;
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                m += rho * fe_values.shape_value(a, q) * fe_values.JxW(q);
              const unsigned int idx = batch_nodes[(std::size_t(batch) * 8 + a) * W + lane];
              for (unsigned int d = 0; d < dim; ++d)
                mass.local_element(idx + d) += m;
            }
        }
    condense(mass);
    mass.compress(VectorOperation::add);
  }


  namespace
  {
    // The loops of condense() and distribute() for constraint groups of
    // `width` DoFs: flat arrays, the groups stream, only the masters are
    // gathered, their lines requested a few groups ahead.
    constexpr unsigned int group_prefetch_distance = 16;

    template <unsigned int width>
    void
    condense_groups(double                          *X,
                    const std::vector<unsigned int> &constrained,
                    const std::vector<unsigned int> &offsets,
                    const std::vector<unsigned int> &masters,
                    const std::vector<double>       &weights)
    {
      const unsigned int n = constrained.size();
      for (unsigned int k = 0; k < n; ++k)
        {
          if (k + group_prefetch_distance < n)
            {
              __builtin_prefetch(X + constrained[k + group_prefetch_distance], 1);
              for (unsigned int j = offsets[k + group_prefetch_distance];
                   j < offsets[k + group_prefetch_distance + 1];
                   ++j)
                __builtin_prefetch(X + masters[j], 1);
            }
          double value[width];
          for (unsigned int d = 0; d < width; ++d)
            value[d] = X[constrained[k] + d];
          for (unsigned int j = offsets[k]; j < offsets[k + 1]; ++j)
            for (unsigned int d = 0; d < width; ++d)
              X[masters[j] + d] += weights[j] * value[d];
          for (unsigned int d = 0; d < width; ++d)
            X[constrained[k] + d] = 0;
        }
    }

    template <unsigned int width>
    void
    distribute_groups(double                          *X,
                      double                          *Y,
                      const double                    *B,
                      double                          *Z,
                      const std::vector<unsigned int> &constrained,
                      const std::vector<unsigned int> &offsets,
                      const std::vector<unsigned int> &masters,
                      const std::vector<double>       &weights)
    {
      const unsigned int n = constrained.size();
      for (unsigned int k = 0; k < n; ++k)
        {
          if (k + group_prefetch_distance < n)
            {
              const unsigned int i = constrained[k + group_prefetch_distance];
              __builtin_prefetch(X + i, 1);
              if (Y)
                __builtin_prefetch(Y + i, 1);
              if (Z)
                {
                  __builtin_prefetch(Z + i, 1);
                  __builtin_prefetch(B + i);
                }
              for (unsigned int j = offsets[k + group_prefetch_distance];
                   j < offsets[k + group_prefetch_distance + 1];
                   ++j)
                {
                  __builtin_prefetch(X + masters[j]);
                  if (Y)
                    __builtin_prefetch(Y + masters[j]);
                }
            }
          double value[width] = {}, value_y[width] = {};
          for (unsigned int j = offsets[k]; j < offsets[k + 1]; ++j)
            for (unsigned int d = 0; d < width; ++d)
              {
                value[d] += weights[j] * X[masters[j] + d];
                if (Y)
                  value_y[d] += weights[j] * Y[masters[j] + d];
              }
          for (unsigned int d = 0; d < width; ++d)
            {
              X[constrained[k] + d] = value[d];
              if (Y)
                Y[constrained[k] + d] = value_y[d];
              if (Z)
                Z[constrained[k] + d] = value[d] + B[constrained[k] + d] * value_y[d];
            }
        }
    }
  } // namespace


  void
  ElasticOperator::condense(VectorType &x) const
  {
    if (constraint_width == dim)
      condense_groups<dim>(
        x.begin(), constrained_dofs, constraint_offsets, constraint_masters, constraint_weights);
    else
      condense_groups<1>(
        x.begin(), constrained_dofs, constraint_offsets, constraint_masters, constraint_weights);
  }


  void
  ElasticOperator::distribute(VectorType       &x,
                              VectorType       *y,
                              const VectorType *beta,
                              VectorType       *z) const
  {
    // both vectors in one pass over the groups (u and v every step), and
    // z = x + beta y on the constrained entries if asked
    Assert(!z || (y && beta), ExcInternalError());
    double       *Y = y ? y->begin() : nullptr;
    double       *Z = z ? z->begin() : nullptr;
    const double *B = beta ? beta->begin() : nullptr;
    if (constraint_width == dim)
      distribute_groups<dim>(x.begin(),
                             Y,
                             B,
                             Z,
                             constrained_dofs,
                             constraint_offsets,
                             constraint_masters,
                             constraint_weights);
    else
      distribute_groups<1>(x.begin(),
                           Y,
                           B,
                           Z,
                           constrained_dofs,
                           constraint_offsets,
                           constraint_masters,
                           constraint_weights);
  }


  void
  ElasticOperator::interpolate(const std::function<Tensor<1, dim>(const Point<dim> &)> &value_of_X,
                               const types::material_id                                 material,
                               VectorType                                              &x) const
  {
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      for (unsigned int lane = 0; lane < W; ++lane)
        if (batch_cell_index[std::size_t(batch) * W + lane] != numbers::invalid_unsigned_int &&
            (material == numbers::invalid_material_id ||
             batch_material[std::size_t(batch) * W + lane] == material))
          for (unsigned int a = 0; a < 8; ++a)
            {
              const unsigned int   idx   = batch_nodes[(std::size_t(batch) * 8 + a) * W + lane];
              const Tensor<1, dim> value = value_of_X(node_points[idx]);
              for (unsigned int d = 0; d < dim; ++d)
                x.local_element(idx + d) = value[d];
            }
  }


  double
  ElasticOperator::total_mass(const types::material_id material) const
  {
    double m = 0;
    for (unsigned int i = 0; i < mass.locally_owned_size(); i += 1)
      if (material == numbers::invalid_material_id || node_material[i] == material)
        m += mass.local_element(i);
    return Utilities::MPI::sum(m, mpi_communicator) / dim;
  }


  double
  ElasticOperator::mesh_volume(const types::material_id material) const
  {
    double vol = 0;
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      for (unsigned int l = 0; l < std::min(W, n_cells - batch * W); ++l)
        if (material == numbers::invalid_material_id ||
            batch_material[std::size_t(batch) * W + l] == material)
          vol += batch_data[(std::size_t(batch) * Field::n_fields + Field::volume) * W + l];
    return Utilities::MPI::sum(vol, mpi_communicator);
  }
} // namespace WheelRail
