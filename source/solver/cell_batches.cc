/**
 * @file cell_batches.cc
 * The element data of ElasticOperator: per-DoF node data, the cells in
 * batches of W (families first), B_a / V0, the hourglass vectors, volume,
 * hourglass stiffness and damping time constant of every cell, the mesh
 * quality and the stable time step.
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <wheelrail/solver/elastic_operator.h>
#include <wheelrail/solver/element_kernel.h>
#include <wheelrail/solver/family_batch.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>

namespace WheelRail
{
  using namespace ElementKernel;

  namespace
  {
    /**
     * Sizes and quality of one cell into @p local (minima and maxima over
     * this rank's cells): edges, L_e = V / A_max (returned), the scaled
     * Jacobian at the corners.
     */
    template <class CellIterator>
    double
    measure_cell(const CellIterator &cell, const double V0, MeshQuality &local)
    {
      double emin = std::numeric_limits<double>::max(), emax = 0;
      for (unsigned int l = 0; l < GeometryInfo<dim>::lines_per_cell; ++l)
        {
          const double e = cell->line(l)->vertex(0).distance(cell->line(l)->vertex(1));
          emin           = std::min(emin, e);
          emax           = std::max(emax, e);
        }
      double amax = 0;
      for (const unsigned int face : cell->face_indices())
        {
          const auto fc = cell->face(face);
          amax          = std::max(amax,
                          0.5 * cross_product_3d(fc->vertex(3) - fc->vertex(0),
                                                 fc->vertex(2) - fc->vertex(1))
                                  .norm());
        }
      const double Le = V0 / amax;
      for (unsigned int a = 0; a < 8; ++a)
        {
          Tensor<1, dim> e[3];
          double         sign = 1;
          for (unsigned int d = 0; d < 3; ++d)
            {
              e[d] = cell->vertex(a ^ (1u << d)) - cell->vertex(a);
              if (a & (1u << d))
                sign = -sign;
            }
          const double det = sign * (e[0] * cross_product_3d(e[1], e[2]));
          local.min_scaled_jacobian =
            std::min(local.min_scaled_jacobian, det / (e[0].norm() * e[1].norm() * e[2].norm()));
        }
      local.min_edge         = std::min(local.min_edge, emin);
      local.min_longest_edge = std::min(local.min_longest_edge, emax);
      local.min_length       = std::min(local.min_length, Le);
      local.max_aspect_ratio = std::max(local.max_aspect_ratio, emax / emin);
      return Le;
    }



    /**
     * Whether the nodes node_of(a, l) of vertex a of cell (lane) l, a and l
     * in 0..7, are those of a family: one 3 x 3 x 3 grid with vertex a of
     * lane l at grid node family_offset[a] + family_offset[l]. The grid
     * into @p grid.
     */
    template <typename NodeOf>
    bool
    is_family(const NodeOf &node_of, unsigned int (&grid)[27])
    {
      std::fill(std::begin(grid), std::end(grid), numbers::invalid_unsigned_int);
      for (unsigned int a = 0; a < 8; ++a)
        for (unsigned int l = 0; l < W; ++l)
          {
            const unsigned int node = node_of(a, l);
            unsigned int      &g    = grid[family_offset[a] + family_offset[l]];
            if (g == numbers::invalid_unsigned_int)
              g = node;
            else if (g != node)
              return false;
          }
      return true;
    }

    /** Which DoF of the FESystem is component c of vertex a: [c][a]. */
    using VertexDofs = std::array<std::array<unsigned int, 8>, dim>;
    VertexDofs
    vertex_dofs(const FiniteElement<dim> &fe)
    {
      VertexDofs dof_of;
      for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
        {
          const auto ci               = fe.system_to_component_index(i);
          dof_of[ci.first][ci.second] = i;
        }
      return dof_of;
    }
  } // namespace



  void
  ElasticOperator::setup_node_data()
  {
    const VertexDofs dof_of = vertex_dofs(fe);

    const unsigned int n_local =
      vector_partitioner->locally_owned_size() + vector_partitioner->n_ghost_indices();
    node_points.assign(n_local, Point<dim>());
    node_material.assign(n_local, numbers::invalid_material_id);
    node_component.assign(n_local, 0);
    on_boundary.assign(n_local, false);

    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int a = 0; a < 8; ++a)
            for (unsigned int d = 0; d < dim; ++d)
              {
                const unsigned int i = vector_partitioner->global_to_local(dofs[dof_of[d][a]]);
                node_points[i]       = cell->vertex(a);
                node_material[i]     = cell->material_id();
                node_component[i]    = d;
              }
          for (const unsigned int face : cell->face_indices())
            if (cell->face(face)->at_boundary())
              for (unsigned int fv = 0; fv < 4; ++fv)
                {
                  const unsigned int a = GeometryInfo<dim>::face_to_cell_vertices(face, fv);
                  for (unsigned int d = 0; d < dim; ++d)
                    on_boundary[vector_partitioner->global_to_local(dofs[dof_of[d][a]])] = true;
                }
        }
  }



  std::vector<DoFHandler<dim>::active_cell_iterator>
  ElasticOperator::cells_in_batch_order() const
  {
    // Cell order: first the families, the 8 children of a parent that are
    // all active and locally owned, in child order and in the order of
    // their first child, so that each fills one batch (see family_offset:
    // 27 nodes to gather and scatter instead of 64); then blocks of other
    // cells arranged the same way; then the remaining cells in the
    // triangulation's order. Mesh::cell_work_parts() weighs the cells for
    // the partition by the same family rule.
    std::vector<DoFHandler<dim>::active_cell_iterator> cells;
    cells.reserve(n_cells);
    std::vector<bool> taken(triangulation.n_active_cells(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->level() > 0)
        {
          const auto parent = cell->parent();
          if (parent->child(0) != cell || parent->n_children() != 8)
            continue;
          bool family = true;
          for (unsigned int i = 0; i < 8 && family; ++i)
            family = parent->child(i)->is_active() && parent->child(i)->is_locally_owned();
          if (family)
            for (unsigned int i = 0; i < 8; ++i)
              {
                cells.emplace_back(parent->child(i));
                taken[parent->child(i)->active_cell_index()] = true;
              }
        }
    std::vector<DoFHandler<dim>::active_cell_iterator> rest;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && !taken[cell->active_cell_index()])
        rest.push_back(cell);

    // Then blocks of 2 x 2 x 2 of the other cells that are arranged as a
    // parent's children (an unrefined structured mesh, the coarse cells of
    // a refined one): cell l of a block has the block's centre as its
    // vertex 7 - l. slot[8 v + k] is the cell of the rest whose vertex k
    // is v (conflict where two are). A block is taken only if its 64
    // (vertex, cell) pairs map onto the 3 x 3 x 3 grid as a family's do, in
    // the order of its first cell; find_families() checks the batches again.
    constexpr unsigned int    none = numbers::invalid_unsigned_int, conflict = none - 1;
    std::vector<unsigned int> slot(std::size_t(triangulation.n_vertices()) * 8, none);
    for (unsigned int i = 0; i < rest.size(); ++i)
      for (unsigned int k = 0; k < 8; ++k)
        {
          unsigned int &s = slot[std::size_t(rest[i]->vertex_index(k)) * 8 + k];
          s               = (s == none) ? i : conflict;
        }
    std::vector<bool> used(rest.size(), false);
    for (unsigned int i = 0; i < rest.size(); ++i)
      {
        if (used[i])
          continue;
        const std::size_t centre = rest[i]->vertex_index(7);
        unsigned int      member[8];
        bool              block = true;
        for (unsigned int l = 0; l < 8 && block; ++l)
          {
            member[l] = slot[centre * 8 + 7 - l];
            block     = member[l] < conflict && !used[member[l]];
          }
        unsigned int grid[27];
        if (block &&
            is_family([&](const unsigned int a,
                          const unsigned int l) { return rest[member[l]]->vertex_index(a); },
                      grid))
          for (unsigned int l = 0; l < 8; ++l)
            {
              cells.push_back(rest[member[l]]);
              used[member[l]] = true;
            }
      }
    for (unsigned int i = 0; i < rest.size(); ++i)
      if (!used[i])
        cells.push_back(rest[i]);
    AssertThrow(cells.size() == n_cells, ExcInternalError());
    return cells;
  }



  void
  ElasticOperator::setup_cell_data()
  {
    const MaterialParameters &mat    = prm.material;
    const double              lambda = mat.lambda(), mu = mat.mu();
    const double              c_wave = mat.wave_speed();
    const double              qm     = prm.solver.hourglass_coefficient;

    const VertexDofs dof_of = vertex_dofs(fe);

    n_cells   = triangulation.n_locally_owned_active_cells();
    n_batches = (n_cells + W - 1) / W;
    batch_data.resize_fast(std::size_t(n_batches) * Field::n_fields * W);
    std::fill(batch_data.begin(), batch_data.end(), 0.);
    batch_nodes.assign(std::size_t(n_batches) * 8 * W, 0);
    batch_cell_index.assign(std::size_t(n_batches) * W, numbers::invalid_unsigned_int);
    batch_material.assign(std::size_t(n_batches) * W, numbers::invalid_material_id);
    batch_kappa_ref.assign(std::size_t(n_batches) * W, 0.);
    lame_lambda = lambda;
    lame_mu     = mu;

    FE_Q<dim>     fe_scalar(1);
    QGauss<dim>   quadrature(2);
    FEValues<dim> fe_values(fe_scalar, quadrature, update_gradients | update_JxW_values);

    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    MeshQuality                          local;
    local.min_edge = local.min_longest_edge = local.min_length = local.min_scaled_jacobian =
      std::numeric_limits<double>::max();
    double min_dt = std::numeric_limits<double>::max();

    const std::vector<DoFHandler<dim>::active_cell_iterator> cells = cells_in_batch_order();
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const auto        &cell  = cells[c];
        const unsigned int batch = c / W, lane = c % W;
        double            *data = &batch_data[std::size_t(batch) * Field::n_fields * W];
        fe_values.reinit(typename Triangulation<dim>::active_cell_iterator(cell));
        cell->get_dof_indices(dofs);

        double V0, BB;
        cell_geometry(fe_values, cell, lane, data, V0, BB);

        const double Le = measure_cell(cell, V0, local);

        // damping: beta_e = 2 COEF / omega_e (omega_e = 2c/L_e) or Rayleigh
        double beta = 0;
        if (damping == DampingModel::stiffness)
          beta = prm.solver.stiffness_damping_coefficient * Le / c_wave;
        else if (damping == DampingModel::rayleigh)
          beta = prm.solver.rayleigh_beta;
        const double omega = 2. * c_wave / Le;
        const double xi    = 0.5 * beta * omega;
        min_dt             = std::min(min_dt, 2. / omega * (std::sqrt(1. + xi * xi) - xi));

        const double k_unit                            = (lambda + 2. * mu) * BB / (8. * V0);
        data[Field::volume * W + lane]                 = V0;
        data[Field::kappa * W + lane]                  = qm * k_unit;
        batch_kappa_ref[std::size_t(batch) * W + lane] = reference_hourglass_coefficient * k_unit;
        data[Field::beta * W + lane]                   = beta;

        for (unsigned int a = 0; a < 8; ++a)
          {
            const auto idx = vector_partitioner->global_to_local(dofs[dof_of[0][a]]);
            for (unsigned int d = 1; d < dim; ++d)
              AssertThrow(vector_partitioner->global_to_local(dofs[dof_of[d][a]]) == idx + d,
                          ExcMessage("Internal error: vertex DoFs not contiguous."));
            batch_nodes[(std::size_t(batch) * 8 + a) * W + lane] = idx;
          }
        batch_cell_index[std::size_t(batch) * W + lane] = cell->active_cell_index();
        batch_material[std::size_t(batch) * W + lane]   = cell->material_id();
      }

    reduce_mesh_quality(local, min_dt);
    copy_single_precision();
  }



  void
  ElasticOperator::cell_geometry(const FEValues<dim>                               &fe_values,
                                 const DoFHandler<dim>::active_cell_iterator       &cell,
                                 const unsigned int                                 lane,
                                 double                                            *data,
                                 double                                            &V0,
                                 double                                            &BB) const
  {
    // the mean shape function gradients b_a = B_a / V0 and the hourglass
    // base vectors c_al of the one-point element, and sum |B_a|^2
    double B[8][3] = {};
    V0             = 0;
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        V0 += fe_values.JxW(q);
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int j = 0; j < 3; ++j)
            B[a][j] += fe_values.shape_grad(a, q)[j] * fe_values.JxW(q);
      }
    BB = 0;
    for (unsigned int a = 0; a < 8; ++a)
      for (unsigned int j = 0; j < 3; ++j)
        {
          data[(Field::b + a * 3 + j) * W + lane] = B[a][j] / V0;
          BB += B[a][j] * B[a][j];
        }
    for (unsigned int al = 0; al < 4; ++al)
      for (unsigned int j = 0; j < 3; ++j)
        {
          double s = 0;
          for (unsigned int a = 0; a < 8; ++a)
            s += hg[al][a] * cell->vertex(a)[j];
          data[(Field::c + al * 3 + j) * W + lane] = s;
        }
  }



  void
  ElasticOperator::reduce_mesh_quality(const MeshQuality &local, const double min_dt)
  {
    quality.min_edge            = Utilities::MPI::min(local.min_edge, mpi_communicator);
    quality.min_longest_edge    = Utilities::MPI::min(local.min_longest_edge, mpi_communicator);
    quality.min_length          = Utilities::MPI::min(local.min_length, mpi_communicator);
    quality.min_scaled_jacobian = Utilities::MPI::min(local.min_scaled_jacobian, mpi_communicator);
    quality.max_aspect_ratio    = Utilities::MPI::max(local.max_aspect_ratio, mpi_communicator);
    AssertThrow(quality.min_scaled_jacobian > 0,
                ExcMessage("The mesh has an inverted or degenerate cell (smallest "
                           "scaled Jacobian <= 0): check Geometry/Bar/Distortion "
                           "and the Geometry parameters."));
    stable_dt = prm.solver.courant_factor * Utilities::MPI::min(min_dt, mpi_communicator);
  }



  void
  ElasticOperator::find_families()
  {
    // Batches that are families (see family_offset): the node map of all
    // 64 (vertex, lane) pairs must be that of the parent's grid. Checked on
    // the node indices alone, so any batch that passes is exact to gather
    // and scatter through the grid.
    batch_family.assign(n_batches, numbers::invalid_unsigned_int);
    family_nodes.clear();
    for (unsigned int b = 0; b < n_batches; ++b)
      {
        if (n_cells - b * W < W)
          continue;
        unsigned int grid[27];
        if (is_family(
              [&](const unsigned int a, const unsigned int l) {
                return batch_nodes[(std::size_t(b) * 8 + a) * W + l];
              },
              grid))
          {
            batch_family[b] = family_nodes.size() / 27;
            family_nodes.insert(family_nodes.end(), std::begin(grid), std::end(grid));
          }
      }
    family_nodes.shrink_to_fit();
    // the 4-wide loads of gather_family_grid() read one value past a
    // node's z: families with the vectors' last node gather by scalars
    const std::size_t n_local =
      vector_partitioner->locally_owned_size() + vector_partitioner->n_ghost_indices();
    family_wide_loads.assign(family_nodes.size() / 27, 1);
    for (std::size_t n = 0; n < family_nodes.size(); ++n)
      if (family_nodes[n] + 4 > n_local)
        family_wide_loads[n / 27] = 0;
    // padding lanes point at node 0 with zero volume: they produce zero force
    // and are never scattered
  }



  void
  ElasticOperator::smallest_cell_beta(VectorType &beta) const
  {
    // +inf where no cell of this rank touches the DoF; the owner takes the
    // smallest of all ranks' values (compress with min), then the ghosts
    beta.reinit(vector_partitioner);
    const std::size_t n_local =
      vector_partitioner->locally_owned_size() + vector_partitioner->n_ghost_indices();
    std::fill(beta.begin(), beta.begin() + n_local, std::numeric_limits<double>::infinity());
    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const unsigned int batch = c / W, lane = c % W;
        const double       beta_e =
          batch_data[(std::size_t(batch) * Field::n_fields + Field::beta) * W + lane];
        for (unsigned int a = 0; a < 8; ++a)
          {
            const unsigned int idx = batch_nodes[(std::size_t(batch) * 8 + a) * W + lane];
            for (unsigned int d = 0; d < dim; ++d)
              beta.local_element(idx + d) = std::min(beta.local_element(idx + d), beta_e);
          }
      }
    beta.compress(VectorOperation::min);
    // an owned DoF of no cell at all (none in a valid mesh) is not damped
    for (unsigned int i = 0; i < beta.locally_owned_size(); ++i)
      if (!std::isfinite(beta.local_element(i)))
        beta.local_element(i) = 0;
    beta.update_ghost_values();
  }
} // namespace WheelRail
