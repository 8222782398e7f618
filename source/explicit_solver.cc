#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <wheelrail/explicit_solver.h>
#include <wheelrail/geometry.h>
#include <wheelrail/stopwatch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace WheelRail
{
  namespace
  {
    constexpr unsigned int W = ExplicitSolver::n_lanes;

    /** Fields of the per-cell element data, each stored for W lanes. */
    namespace Field
    {
      constexpr unsigned int b        = 0;  ///< 24: B_a / V0, [a*3+j]
      constexpr unsigned int c        = 24; ///< 12: h_alpha . X_j, [alpha*3+j]
      constexpr unsigned int volume   = 36; ///< V0
      constexpr unsigned int kappa    = 37; ///< hourglass stiffness
      constexpr unsigned int beta     = 38; ///< damping time constant [s]
      constexpr unsigned int n_fields = 39;
      // Only what the kernel reads streams through it every step: the
      // Lame constants are the same for all cells (one material), the
      // hourglass stiffness with the reference QM lives in its own array
      // (energies only).
    } // namespace Field

    /** Reference hourglass coefficient of the hourglass-mode indicator. */
    constexpr double reference_hourglass_coefficient = 0.1;

    /**
     * Flanagan-Belytschko hourglass base vectors for the lexicographic
     * vertex numbering of deal.II: eta zeta, xi zeta, xi eta, xi eta zeta.
     */
    constexpr double hg[4][8] = {{1, 1, -1, -1, -1, -1, 1, 1},
                                 {1, -1, 1, -1, -1, 1, -1, 1},
                                 {1, -1, -1, 1, 1, -1, -1, 1},
                                 {-1, 1, 1, -1, 1, -1, -1, 1}};

    /**
     * W lanes of doubles as one value: GCC/Clang vector extension. With
     * -march=native on an AVX-512 machine one batch is one zmm register,
     * with AVX2 two ymm registers. Debian's deal.II has no SIMD
     * (VectorizedArray<double> has one lane), so the kernel does its own.
     */
    typedef double v8d __attribute__((vector_size(64)));
    static_assert(W == 8, "the vector kernel is written for 8 lanes");

    inline v8d
    load(const double *p)
    {
      v8d x;
      __builtin_memcpy(&x, p, sizeof(x));
      return x;
    }
    inline void
    store(double *p, const v8d &x)
    {
      __builtin_memcpy(p, &x, sizeof(x));
    }

    /**
     * Families: when a batch holds the 8 children of one parent in child
     * order, vertex a of lane (child) l is node family_offset[a] +
     * family_offset[l] of the parent's 3x3x3 grid (lexicographic vertex and
     * child numbering of deal.II), 27 distinct nodes instead of 64.
     */
    constexpr unsigned int family_offset[8] = {0, 1, 3, 4, 9, 10, 12, 13};
    typedef long long      v8i __attribute__((vector_size(64)));
    /** Lane l of the vector of vertex a over the children: grid node
     *  family_offset[a] + family_offset[l], i.e. element family_offset[l] of
     *  the 16 grid values from family_offset[a] on. */
    constexpr v8i family_lanes = {family_offset[0],
                                  family_offset[1],
                                  family_offset[2],
                                  family_offset[3],
                                  family_offset[4],
                                  family_offset[5],
                                  family_offset[6],
                                  family_offset[7]};

    /** Per grid node, the (vertex, lane) pairs that reach it as offsets
     *  a * 3 W + l into a [vertex][component][lane] array, by ascending a:
     *  the order in which the general scatter adds them. */
    struct FamilyScatter
    {
      unsigned char start[28];
      unsigned char entry[64];
      FamilyScatter()
        : start{}
        , entry{}
      {
        unsigned int count[27] = {};
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int l = 0; l < W; ++l)
            ++count[family_offset[a] + family_offset[l]];
        start[0] = 0;
        for (unsigned int n = 0; n < 27; ++n)
          start[n + 1] = start[n] + count[n];
        unsigned int next[27];
        for (unsigned int n = 0; n < 27; ++n)
          next[n] = start[n];
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int l = 0; l < W; ++l)
            entry[next[family_offset[a] + family_offset[l]]++] = a * 3 * W + l;
      }
    };
    const FamilyScatter family_scatter;

    /** Gradient sum_a w_a (x) b_a of the nodal field @p wb ([vertex][component][lane])
     *  of a batch: H from the displacements, L from the velocities. */
    inline void
    batch_gradient(const double *__restrict data, const double *__restrict wb, v8d (&G)[3][3])
    {
#pragma GCC unroll 3
      for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
        for (unsigned int j = 0; j < 3; ++j)
          G[i][j] = v8d{};
#pragma GCC unroll 8
      for (unsigned int a = 0; a < 8; ++a)
        {
          v8d b[3];
#pragma GCC unroll 3
          for (unsigned int j = 0; j < 3; ++j)
            b[j] = load(data + (Field::b + a * 3 + j) * W);
#pragma GCC unroll 3
          for (unsigned int i = 0; i < 3; ++i)
            {
              const v8d wa = load(wb + (a * 3 + i) * W);
#pragma GCC unroll 3
              for (unsigned int j = 0; j < 3; ++j)
                G[i][j] += wa * b[j];
            }
        }
    }



    /**
     * Element forces of one batch of W cells: one-point total-Lagrangian
     * St. Venant-Kirchhoff stress, element stiffness damping and FB
     * stiffness hourglass forces. u, v, f are [vertex][component][lane];
     * every operation acts on all W lanes at once, and all loops are
     * unrolled so that the 3x3 tensors stay in registers. Returns the
     * damping power.
     */
    template <bool with_damping>
    double
    batch_forces(const double *__restrict data,
                 const double lambda,
                 const double mu_,
                 const double *__restrict ub,
                 const double *__restrict vb,
                 double *__restrict fb)
    {
      const v8d V0 = load(data + Field::volume * W);
      const v8d la = v8d{} + lambda;
      const v8d mu = v8d{} + mu_;
      const v8d ka = load(data + Field::kappa * W);

      v8d H[3][3];
      batch_gradient(data, ub, H);

      v8d E[3][3];
#pragma GCC unroll 3
      for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
        for (unsigned int j = 0; j < 3; ++j)
          {
            v8d hth = H[0][i] * H[0][j] + H[1][i] * H[1][j] + H[2][i] * H[2][j];
            E[i][j] = 0.5 * (H[i][j] + H[j][i] + hth);
          }
      const v8d trE = E[0][0] + E[1][1] + E[2][2];
      v8d       S[3][3];
#pragma GCC unroll 3
      for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
        for (unsigned int j = 0; j < 3; ++j)
          S[i][j] = 2. * mu * E[i][j];
      S[0][0] += la * trE;
      S[1][1] += la * trE;
      S[2][2] += la * trE;

      v8d power = {};
      if constexpr (with_damping)
        {
          const v8d beta = load(data + Field::beta * W);
          v8d       L[3][3];
          batch_gradient(data, vb, L);
          // F = I + H
          v8d Fd[3][3];
#pragma GCC unroll 3
          for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
            for (unsigned int j = 0; j < 3; ++j)
              Fd[i][j] = H[i][j] + (i == j ? 1. : 0.);
          v8d Ed[3][3];
#pragma GCC unroll 3
          for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
            for (unsigned int j = 0; j < 3; ++j)
              {
                v8d ftl = {};
#pragma GCC unroll 3
                for (unsigned int k = 0; k < 3; ++k)
                  ftl += Fd[k][i] * L[k][j] + L[k][i] * Fd[k][j];
                Ed[i][j] = 0.5 * ftl;
              }
          const v8d trEd = Ed[0][0] + Ed[1][1] + Ed[2][2];
          v8d       p    = la * trEd * trEd;
#pragma GCC unroll 3
          for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
            for (unsigned int j = 0; j < 3; ++j)
              {
                S[i][j] += beta * (2. * mu * Ed[i][j] + (i == j ? la * trEd : v8d{}));
                p += 2. * mu * Ed[i][j] * Ed[i][j];
              }
          power = beta * V0 * p;
        }

      v8d g[4][3];
#pragma GCC unroll 4
      for (unsigned int al = 0; al < 4; ++al)
        {
          v8d c[3];
#pragma GCC unroll 3
          for (unsigned int j = 0; j < 3; ++j)
            c[j] = load(data + (Field::c + al * 3 + j) * W);
#pragma GCC unroll 3
          for (unsigned int i = 0; i < 3; ++i)
            {
              v8d s = {};
#pragma GCC unroll 8
              for (unsigned int a = 0; a < 8; ++a)
                s = hg[al][a] > 0 ? s + load(ub + (a * 3 + i) * W) : s - load(ub + (a * 3 + i) * W);
              s -= c[0] * H[i][0] + c[1] * H[i][1] + c[2] * H[i][2];
              g[al][i] = ka * s;
            }
        }

      v8d T[3][3];
#pragma GCC unroll 3
      for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
        for (unsigned int j = 0; j < 3; ++j)
          {
            v8d fs  = S[i][j] + H[i][0] * S[0][j] + H[i][1] * S[1][j] + H[i][2] * S[2][j];
            T[i][j] = V0 * fs;
          }
#pragma GCC unroll 4
      for (unsigned int al = 0; al < 4; ++al)
        {
          v8d c[3];
#pragma GCC unroll 3
          for (unsigned int j = 0; j < 3; ++j)
            c[j] = load(data + (Field::c + al * 3 + j) * W);
#pragma GCC unroll 3
          for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
            for (unsigned int j = 0; j < 3; ++j)
              T[i][j] -= g[al][i] * c[j];
        }

#pragma GCC unroll 8
      for (unsigned int a = 0; a < 8; ++a)
        {
          v8d b[3];
#pragma GCC unroll 3
          for (unsigned int j = 0; j < 3; ++j)
            b[j] = load(data + (Field::b + a * 3 + j) * W);
#pragma GCC unroll 3
          for (unsigned int i = 0; i < 3; ++i)
            {
              v8d s = T[i][0] * b[0] + T[i][1] * b[1] + T[i][2] * b[2];
#pragma GCC unroll 4
              for (unsigned int al = 0; al < 4; ++al)
                s = hg[al][a] > 0 ? s + g[al][i] : s - g[al][i];
              store(fb + (a * 3 + i) * W, s);
            }
        }
      double sum = 0;
      for (unsigned int l = 0; l < W; ++l)
        sum += power[l];
      return sum;
    }



    /** Displacement gradient H = sum_a u_a (x) b_a of lane l of a batch. */
    inline void
    displacement_gradient(const double       *U,
                          const unsigned int *nodes,
                          const double       *data,
                          const unsigned int  l,
                          double (&H)[3][3])
    {
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          H[i][j] = 0;
      for (unsigned int a = 0; a < 8; ++a)
        for (unsigned int i = 0; i < 3; ++i)
          for (unsigned int j = 0; j < 3; ++j)
            H[i][j] += U[nodes[a * W + l] + i] * data[(Field::b + a * 3 + j) * W + l];
    }



    /** Rotation about +y by angle @p theta applied to @p r. */
    Tensor<1, dim>
    rotate_about_y(const Tensor<1, dim> &r, const double theta)
    {
      const double c = std::cos(theta), s = std::sin(theta);
      return Tensor<1, dim>({c * r[0] + s * r[2], r[1], -s * r[0] + c * r[2]});
    }



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

  } // namespace



  ExplicitSolver::ExplicitSolver(const Parameters                          &parameters,
                                 parallel::distributed::Triangulation<dim> &tria)
    : prm(parameters)
    , triangulation(tria)
    , mpi_communicator(tria.get_communicator())
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(tria)
  {}



  void
  ExplicitSolver::setup()
  {
    check_boundary_ids(prm, triangulation);
    dof_handler.distribute_dofs(fe);

    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    hanging_constraints.clear();
    hanging_constraints.reinit(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, hanging_constraints);
    hanging_constraints.close();
    make_hanging_vertices_conforming();

    // ghost set: locally relevant DoFs and every master of a constraint
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

    constrained_dofs.clear();
    constraint_offsets.assign(1, 0);
    constraint_masters.clear();
    constraint_weights.clear();
    for (const auto &line : hanging_constraints.get_lines())
      {
        for (const auto &entry : line.entries)
          {
            constraint_masters.push_back(vector_partitioner->global_to_local(entry.first));
            constraint_weights.push_back(entry.second);
          }
        constrained_dofs.push_back(vector_partitioner->global_to_local(line.index));
        constraint_offsets.push_back(constraint_masters.size());
      }

    for (VectorType *vec : {&u, &v, &f, &v_old, &mass, &inv_mass, &f_ext, &u0})
      vec->reinit(vector_partitioner);
    f_cleared = false;

    setup_cell_data();
    setup_mass_and_loads();
    setup_prescribed_dofs();
    setup_applied_forces();
    t                   = 0;
    n_steps             = 0;
    damping_dissipation = 0;
    boundary_work       = 0;
  }



  void
  ExplicitSolver::make_hanging_vertices_conforming()
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



  void
  ExplicitSolver::setup_cell_data()
  {
    const MaterialParameters &mat    = prm.material;
    const double              lambda = mat.lambda(), mu = mat.mu();
    const double              c_wave = mat.wave_speed();
    const double              qm     = prm.solver.hourglass_coefficient;

    // which DoF of the FESystem is component c of vertex a
    unsigned int dof_of[dim][8];
    for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
      {
        const auto ci               = fe.system_to_component_index(i);
        dof_of[ci.first][ci.second] = i;
      }

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

    double min_edge = std::numeric_limits<double>::max(), min_size = min_edge, min_le = min_edge,
           min_jac = min_edge, max_aspect = 0, min_dt = min_edge;

    // Cell order: first the families, the 8 children of a parent that are
    // all active and locally owned, in child order and in the order of
    // their first child, so that each fills one batch (see family_offset:
    // 27 nodes to gather and scatter instead of 64); then the other cells
    // in the triangulation's order.
    std::vector<DoFHandler<dim>::active_cell_iterator> cells;
    cells.reserve(n_cells);
    {
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
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && !taken[cell->active_cell_index()])
          cells.push_back(cell);
      AssertThrow(cells.size() == n_cells, ExcInternalError());
    }

    for (unsigned int c = 0; c < n_cells; ++c)
      {
        const auto        &cell  = cells[c];
        const unsigned int batch = c / W, lane = c % W;
        double            *data = &batch_data[std::size_t(batch) * Field::n_fields * W];
        fe_values.reinit(typename Triangulation<dim>::active_cell_iterator(cell));
        cell->get_dof_indices(dofs);

        double B[8][3] = {}, V0 = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            V0 += fe_values.JxW(q);
            for (unsigned int a = 0; a < 8; ++a)
              for (unsigned int j = 0; j < 3; ++j)
                B[a][j] += fe_values.shape_grad(a, q)[j] * fe_values.JxW(q);
          }
        double BB = 0;
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

        // sizes, L_e = V / A_max, quality
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
            min_jac          = std::min(min_jac, det / (e[0].norm() * e[1].norm() * e[2].norm()));
          }
        min_edge   = std::min(min_edge, emin);
        min_size   = std::min(min_size, emax);
        min_le     = std::min(min_le, Le);
        max_aspect = std::max(max_aspect, emax / emin);

        // damping: beta_e = 2 COEF / omega_e (omega_e = 2c/L_e) or Rayleigh
        double beta = 0;
        if (prm.solver.damping_model == "stiffness")
          beta = prm.solver.stiffness_damping_coefficient * Le / c_wave;
        else if (prm.solver.damping_model == "Rayleigh")
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
        std::fill(std::begin(grid), std::end(grid), numbers::invalid_unsigned_int);
        bool family = true;
        for (unsigned int a = 0; a < 8 && family; ++a)
          for (unsigned int l = 0; l < W && family; ++l)
            {
              const unsigned int idx = batch_nodes[(std::size_t(b) * 8 + a) * W + l];
              unsigned int      &g   = grid[family_offset[a] + family_offset[l]];
              if (g == numbers::invalid_unsigned_int)
                g = idx;
              else
                family = (g == idx);
            }
        if (family)
          {
            batch_family[b] = family_nodes.size() / 27;
            family_nodes.insert(family_nodes.end(), std::begin(grid), std::end(grid));
          }
      }
    family_nodes.shrink_to_fit();
    // padding lanes point at node 0 with zero volume: they produce zero force
    // and are never scattered

    quality.min_edge            = Utilities::MPI::min(min_edge, mpi_communicator);
    quality.min_longest_edge    = Utilities::MPI::min(min_size, mpi_communicator);
    quality.min_length          = Utilities::MPI::min(min_le, mpi_communicator);
    quality.min_scaled_jacobian = Utilities::MPI::min(min_jac, mpi_communicator);
    quality.max_aspect_ratio    = Utilities::MPI::max(max_aspect, mpi_communicator);
    AssertThrow(quality.min_scaled_jacobian > 0,
                ExcMessage("The mesh has an inverted or degenerate cell (smallest "
                           "scaled Jacobian <= 0): check Geometry/Bar/Distortion "
                           "and the Geometry parameters."));
    stable_dt = prm.solver.courant_factor * Utilities::MPI::min(min_dt, mpi_communicator);
  }



  void
  ExplicitSolver::setup_mass_and_loads()
  {
    const double  rho = prm.material.density;
    FE_Q<dim>     fe_scalar(1);
    QGauss<dim>   quadrature(2);
    FEValues<dim> fe_values(fe_scalar, quadrature, update_values | update_JxW_values);

    mass = 0;
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

    // gravity load: g times the condensed row-sum mass (= condensed rho g N)
    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      {
        f_ext.local_element(i)    = mass.local_element(i) * prm.solver.gravity[node_component[i]];
        inv_mass.local_element(i) = mass.local_element(i) > 0 ? 1. / mass.local_element(i) : 0.;
      }
    // hanging DoFs carry neither mass nor load: they follow their masters
    for (const unsigned int i : constrained_dofs)
      if (i < inv_mass.locally_owned_size())
        {
          inv_mass.local_element(i) = 0;
          f_ext.local_element(i)    = 0;
        }
  }



  void
  ExplicitSolver::setup_prescribed_dofs()
  {
    std::map<unsigned int, PrescribedDof> dofs;
    const auto add = [&](const unsigned int i, const unsigned int d, const unsigned int kind) {
      if (i + d >= vector_partitioner->locally_owned_size() ||
          hanging_constraints.is_constrained(vector_partitioner->local_to_global(i + d)))
        return;
      auto it = dofs.find(i + d);
      if (it == dofs.end() || kind < it->second.kind) // fixed wins
        dofs[i + d] = PrescribedDof{i + d, d, kind};
    };

    const std::string bore = prm.boundary.wheel_bore;
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
                        add(i, d, 0);
                  if (std::find(prm.boundary.prescribed_velocity_ids.begin(),
                                prm.boundary.prescribed_velocity_ids.end(),
                                id) != prm.boundary.prescribed_velocity_ids.end())
                    for (unsigned int d = 0; d < dim; ++d)
                      add(i, d, 1);
                  if (id == Geometry::BoundaryIds::wheel_bore)
                    {
                      for (unsigned int d = 0; d < dim; ++d)
                        {
                          if (bore == "fixed")
                            add(i, d, 0);
                          else if (bore == "spinning axle")
                            add(i, d, 2);
                          else if (bore == "rigid axle")
                            add(i, d, 3);
                          if (i + d < vector_partitioner->locally_owned_size())
                            bore_dofs.push_back(i + d);
                        }
                    }
                }
            }
    std::sort(bore_dofs.begin(), bore_dofs.end());
    bore_dofs.erase(std::unique(bore_dofs.begin(), bore_dofs.end()), bore_dofs.end());

    prescribed.clear();
    for (const auto &entry : dofs)
      {
        prescribed.push_back(entry.second);
        inv_mass.local_element(entry.first) = 0;
      }

    prescribed_velocity.reset();
    if (!prm.boundary.prescribed_velocity_ids.empty())
      {
        prescribed_velocity = make_vector_function(prm.boundary.prescribed_velocity_expression,
                                                   prm.boundary.prescribed_velocity_constants,
                                                   "x,y,z,t",
                                                   "Boundary conditions/Prescribed velocity");
      }
  }



  void
  ExplicitSolver::attach_wheelset(Wheelset *ws)
  {
    wheelset = ws;
    if (wheelset == nullptr)
      return;
    const Point<dim> centre   = Geometry::wheel_centre(prm.geometry);
    double           local[2] = {0, 0};
    for (const auto &p : prescribed)
      if (p.kind == 3 && p.component == 0)
        {
          const Tensor<1, dim> r = node_points[p.index] - centre;
          local[0] += mass.local_element(p.index);
          local[1] += mass.local_element(p.index) * (r[0] * r[0] + r[2] * r[2]);
        }
    // polar inertia of the whole FE wheel about the axle
    double wheel_inertia = 0;
    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      if (node_material[i] == Geometry::MaterialIds::wheel && node_component[i] == 0)
        {
          const Tensor<1, dim> r = node_points[i] - centre;
          wheel_inertia += mass.local_element(i) * (r[0] * r[0] + r[2] * r[2]);
        }
    double global[2];
    Utilities::MPI::sum(ArrayView<const double>(local, 2),
                        mpi_communicator,
                        ArrayView<double>(global, 2));
    wheelset->set_bore_inertia(global[0],
                               global[1],
                               total_mass(Geometry::MaterialIds::wheel),
                               Utilities::MPI::sum(wheel_inertia, mpi_communicator));
  }



  void
  ExplicitSolver::setup_applied_forces()
  {
    applied.clear();
    applied_force.reset();
    if (prm.boundary.applied_force_ids.empty())
      return;
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
    condense(area);
    area.compress(VectorOperation::add);
    double total = 0;
    for (unsigned int i = 0; i < area.locally_owned_size(); ++i)
      total += area.local_element(i);
    total = Utilities::MPI::sum(total, mpi_communicator);
    AssertThrow(total > 0,
                ExcMessage("Boundary conditions/Applied force boundaries: no such boundary in "
                           "this geometry."));
    for (unsigned int i = 0; i < area.locally_owned_size(); ++i)
      if (area.local_element(i) > 0)
        for (unsigned int d = 0; d < dim; ++d)
          applied.emplace_back(i + d, d, area.local_element(i) / total);
    applied_force = make_vector_function(prm.boundary.applied_force_expression,
                                         prm.boundary.applied_force_constants,
                                         "x,y,z,t",
                                         "Boundary conditions/Applied force");
  }



  void
  ExplicitSolver::set_time_step(const double time_step)
  {
    AssertThrow(time_step > 0, ExcMessage("Internal error: time step <= 0."));
    dt = time_step;
  }



  void
  ExplicitSolver::condense(VectorType &x) const
  {
    // flat arrays: the lines stream, only the masters are gathered
    double *X = x.begin();
    for (unsigned int k = 0; k < constrained_dofs.size(); ++k)
      {
        const double value = X[constrained_dofs[k]];
        for (unsigned int j = constraint_offsets[k]; j < constraint_offsets[k + 1]; ++j)
          X[constraint_masters[j]] += constraint_weights[j] * value;
        X[constrained_dofs[k]] = 0;
      }
  }



  void
  ExplicitSolver::distribute(VectorType &x, VectorType *y) const
  {
    // both vectors in one pass over the lines (u and v every step)
    double *X = x.begin();
    double *Y = y ? y->begin() : nullptr;
    for (unsigned int k = 0; k < constrained_dofs.size(); ++k)
      {
        double value = 0, value_y = 0;
        for (unsigned int j = constraint_offsets[k]; j < constraint_offsets[k + 1]; ++j)
          {
            value += constraint_weights[j] * X[constraint_masters[j]];
            if (Y)
              value_y += constraint_weights[j] * Y[constraint_masters[j]];
          }
        X[constrained_dofs[k]] = value;
        if (Y)
          Y[constrained_dofs[k]] = value_y;
      }
  }



  void
  ExplicitSolver::set_displacement(const std::function<Tensor<1, dim>(const Point<dim> &)> &u_of_X,
                                   const types::material_id material)
  {
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      for (unsigned int lane = 0; lane < W; ++lane)
        if (batch_cell_index[std::size_t(batch) * W + lane] != numbers::invalid_unsigned_int &&
            (material == numbers::invalid_material_id ||
             batch_material[std::size_t(batch) * W + lane] == material))
          for (unsigned int a = 0; a < 8; ++a)
            {
              const unsigned int   idx   = batch_nodes[(std::size_t(batch) * 8 + a) * W + lane];
              const Tensor<1, dim> value = u_of_X(node_points[idx]);
              for (unsigned int d = 0; d < dim; ++d)
                u.local_element(idx + d) = value[d];
            }
    u.update_ghost_values();
    distribute(u);
    u0 = u;
    for (auto &p : prescribed)
      p.u_prev = u.local_element(p.index);
  }



  void
  ExplicitSolver::set_velocity(
    const std::function<Tensor<1, dim>(const Point<dim> &, const types::material_id)> &v_of_X)
  {
    for (unsigned int i = 0; i < node_points.size(); ++i)
      if (node_material[i] != numbers::invalid_material_id)
        v.local_element(i) = v_of_X(node_points[i], node_material[i])[node_component[i]];
    v.update_ghost_values();
    distribute(v);
    for (auto &p : prescribed)
      p.v_prev = v.local_element(p.index);
  }



  void
  ExplicitSolver::add_centrifugal_load(const Point<dim> &centre,
                                       const double      omega,
                                       const double      factor)
  {
    for (unsigned int k = 0; k < f_ext.locally_owned_size(); ++k)
      if (node_material[k] == Geometry::MaterialIds::wheel && node_component[k] != 1)
        f_ext.local_element(k) += factor * mass.local_element(k) * omega * omega *
                                  (node_points[k] - centre)[node_component[k]];
  }



  void
  ExplicitSolver::set_rolling_velocity(const Tensor<1, dim> &V,
                                       const Point<dim>     &centre,
                                       const double          omega)
  {
    // volume-weighted nodal average of H = grad u: gradient[j] holds H_ij at
    // DoF (node, i)
    std::array<VectorType, dim> gradient;
    VectorType                  weight(vector_partitioner);
    for (auto &g : gradient)
      g.reinit(vector_partitioner);
    const double *U = u.begin();
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      {
        const unsigned int *nodes   = &batch_nodes[std::size_t(batch) * 8 * W];
        const double       *data    = &batch_data[std::size_t(batch) * Field::n_fields * W];
        const unsigned int  n_valid = std::min(W, n_cells - batch * W);
        for (unsigned int l = 0; l < n_valid; ++l)
          {
            double H[3][3];
            displacement_gradient(U, nodes, data, l, H);
            const double V0 = data[Field::volume * W + l];
            for (unsigned int a = 0; a < 8; ++a)
              for (unsigned int i = 0; i < 3; ++i)
                {
                  const unsigned int k = nodes[a * W + l] + i;
                  weight.local_element(k) += V0;
                  for (unsigned int j = 0; j < 3; ++j)
                    gradient[j].local_element(k) += V0 * H[i][j];
                }
          }
      }
    weight.compress(VectorOperation::add);
    for (auto &g : gradient)
      g.compress(VectorOperation::add);

    for (unsigned int k = 0; k < v.locally_owned_size(); ++k)
      {
        const unsigned int i = node_component[k];
        double             H[3];
        for (unsigned int j = 0; j < 3; ++j)
          H[j] = weight.local_element(k) > 0 ?
                   gradient[j].local_element(k) / weight.local_element(k) :
                   0.;
        if (node_material[k] == Geometry::MaterialIds::wheel)
          {
            const Tensor<1, dim> r    = node_points[k] - centre;
            const double         w[3] = {omega * r[2], 0., -omega * r[0]};
            v.local_element(k)        = V[i] + w[i] + H[0] * w[0] + H[1] * w[1] + H[2] * w[2];
          }
        else
          v.local_element(k) = -V[0] * H[0];
      }
    v.update_ghost_values();
    distribute(v);
    for (auto &p : prescribed)
      p.v_prev = v.local_element(p.index);
  }



  double
  ExplicitSolver::assemble_forces(const VectorType &u_in,
                                  const VectorType *v_in,
                                  VectorType       &f_out,
                                  const bool        with_contact,
                                  const bool        advance,
                                  const bool        f_is_zero)
  {
    Clock::time_point clock = Clock::now();
    if (!f_is_zero)
      f_out = 0.;
    else
      Assert(std::all_of(f_out.begin(),
                         f_out.begin() + f_out.locally_owned_size() +
                           f_out.get_partitioner()->n_ghost_indices(),
                         [](const double x) { return x == 0; }),
             ExcInternalError());
    const double *U       = u_in.begin();
    const double *V       = v_in ? v_in->begin() : nullptr;
    double       *F       = f_out.begin();
    const bool    damping = (v_in != nullptr) && prm.solver.damping_model != "none";

    alignas(64) double ub[8 * 3 * W], vb[8 * 3 * W], fb[8 * 3 * W];
    std::fill(std::begin(vb), std::end(vb), 0.);
    // a family's grid values per component, padded: the permutations read
    // 16 values from any vertex's offset (at most 13 + 15 = 28)
    alignas(64) double ug[3][32] = {}, vg[3][32] = {};
    double             power = 0;
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      {
        const unsigned int *nodes = &batch_nodes[std::size_t(batch) * 8 * W];
        const double       *data  = &batch_data[std::size_t(batch) * Field::n_fields * W];
        if (batch + prefetch_distance < n_batches)
          prefetch_batch(batch + prefetch_distance);
        const unsigned int family = batch_family[batch];
        if (family != numbers::invalid_unsigned_int)
          {
            // the 27 grid nodes once, then each vertex's vector over the
            // children by one two-source permutation of the grid values
            const unsigned int *grid = &family_nodes[std::size_t(family) * 27];
            for (unsigned int n = 0; n < 27; ++n)
              {
                const unsigned int idx = grid[n];
                for (unsigned int d = 0; d < 3; ++d)
                  ug[d][n] = U[idx + d];
                if (damping)
                  for (unsigned int d = 0; d < 3; ++d)
                    vg[d][n] = V[idx + d];
              }
            for (unsigned int a = 0; a < 8; ++a)
              for (unsigned int d = 0; d < 3; ++d)
                {
                  const unsigned int o = family_offset[a];
                  store(&ub[(a * 3 + d) * W],
                        __builtin_shuffle(WheelRail::load(&ug[d][o]),
                                          WheelRail::load(&ug[d][o + W]),
                                          family_lanes));
                  if (damping)
                    store(&vb[(a * 3 + d) * W],
                          __builtin_shuffle(WheelRail::load(&vg[d][o]),
                                            WheelRail::load(&vg[d][o + W]),
                                            family_lanes));
                }
          }
        else
          for (unsigned int a = 0; a < 8; ++a)
            for (unsigned int l = 0; l < W; ++l)
              {
                const unsigned int idx = nodes[a * W + l];
                for (unsigned int d = 0; d < 3; ++d)
                  ub[(a * 3 + d) * W + l] = U[idx + d];
                if (damping)
                  for (unsigned int d = 0; d < 3; ++d)
                    vb[(a * 3 + d) * W + l] = V[idx + d];
              }
        power += damping ? batch_forces<true>(data, lame_lambda, lame_mu, ub, vb, fb) :
                           batch_forces<false>(data, lame_lambda, lame_mu, ub, vb, fb);
        if (family != numbers::invalid_unsigned_int)
          {
            // each grid node's sum in a register, its terms in the order
            // of the general scatter below (ascending vertex): the same bits
            const unsigned int *grid = &family_nodes[std::size_t(family) * 27];
            for (unsigned int n = 0; n < 27; ++n)
              {
                const unsigned int idx = grid[n];
                double             f0 = F[idx], f1 = F[idx + 1], f2 = F[idx + 2];
                for (unsigned int e = family_scatter.start[n]; e < family_scatter.start[n + 1]; ++e)
                  {
                    const double *fe = &fb[family_scatter.entry[e]];
                    f0 += fe[0];
                    f1 += fe[W];
                    f2 += fe[2 * W];
                  }
                F[idx]     = f0;
                F[idx + 1] = f1;
                F[idx + 2] = f2;
              }
            continue;
          }
        const unsigned int n_valid = std::min(W, n_cells - batch * W);
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int l = 0; l < n_valid; ++l)
            {
              const unsigned int idx = nodes[a * W + l];
              for (unsigned int d = 0; d < 3; ++d)
                F[idx + d] += fb[(a * 3 + d) * W + l];
            }
      }
    times.elements += lap(clock);
    if (with_contact && contact != nullptr)
      {
        contact->add_forces(u_in, dt, advance, f_out);
        times.contact += lap(clock);
      }
    condense(f_out);
    times.update += lap(clock);
    f_out.compress(VectorOperation::add);
    times.communication += lap(clock);
    return power;
  }



  void
  ExplicitSolver::prefetch_batch(const unsigned int batch) const
  {
    // The kernel reads a batch's 39 fields (2.5 kB) in its own order, not as
    // one stream, and the hardware prefetcher does not follow: these loads
    // were the hottest instructions of the element loop (perf annotate of
    // the paper run). Requested a few batches ahead they arrive while the
    // current batch computes; the arithmetic is untouched, so are the
    // results. Measured (./run.sh bench, 2 ranks, 1000 steps): elements
    // 17.7 -> 14.7-15.6 s. Prefetching the gathered nodal values as well
    // was slower (17.9 s): those mostly hit the cache already.
    const char *data =
      reinterpret_cast<const char *>(&batch_data[std::size_t(batch) * Field::n_fields * W]);
    for (unsigned int offset = 0; offset < Field::n_fields * W * sizeof(double); offset += 64)
      __builtin_prefetch(data + offset, 0, 0);
  }



  void
  ExplicitSolver::compute_internal_force(VectorType &force)
  {
    force.reinit(vector_partitioner);
    assemble_forces(u, nullptr, force, false, false);
  }



  void
  ExplicitSolver::compute_residual(VectorType &residual)
  {
    residual.reinit(vector_partitioner);
    assemble_forces(u, nullptr, residual, true, false);
    for (unsigned int i = 0; i < residual.locally_owned_size(); ++i)
      residual.local_element(i) -= f_ext.local_element(i);
  }



  void
  ExplicitSolver::set_displacement(const VectorType &displacement)
  {
    for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
      u.local_element(i) = displacement.local_element(i);
    u.update_ghost_values();
    distribute(u);
    u0 = u;
    for (auto &p : prescribed)
      p.u_prev = u.local_element(p.index);
  }



  Tensor<1, dim>
  ExplicitSolver::momentum(const types::material_id material) const
  {
    double local[3] = {0, 0, 0};
    for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
      if (node_material[i] == material)
        local[node_component[i]] += mass.local_element(i) * v.local_element(i);
    double global[3];
    Utilities::MPI::sum(ArrayView<const double>(local, 3),
                        mpi_communicator,
                        ArrayView<double>(global, 3));
    return Tensor<1, dim>({global[0], global[1], global[2]});
  }



  Tensor<1, dim>
  ExplicitSolver::mean_displacement(const types::material_id material) const
  {
    double local[4] = {0, 0, 0, 0};
    for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
      if (node_material[i] == material)
        {
          local[node_component[i]] += u.local_element(i);
          if (node_component[i] == 0)
            local[3] += 1;
        }
    double global[4];
    Utilities::MPI::sum(ArrayView<const double>(local, 4),
                        mpi_communicator,
                        ArrayView<double>(global, 4));
    Tensor<1, dim> mean;
    for (unsigned int d = 0; d < dim; ++d)
      mean[d] = global[3] > 0 ? global[d] / global[3] : 0.;
    return mean;
  }



  void
  ExplicitSolver::assemble_stiffness(TrilinosWrappers::SparseMatrix  &matrix,
                                     const AffineConstraints<double> &constraints) const
  {
    FullMatrix<double>                   K(24, 24);
    std::vector<types::global_dof_index> dofs(24);
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      for (unsigned int l = 0; l < std::min(W, n_cells - batch * W); ++l)
        {
          const double *data = &batch_data[std::size_t(batch) * Field::n_fields * W];
          const auto    D    = [&](const unsigned int field) { return data[field * W + l]; };
          const double  V0 = D(Field::volume), la = lame_lambda, mu = lame_mu, ka = D(Field::kappa);
          // gamma_alpha,a = h_alpha,a - c_alpha . b_a
          double gamma[4][8];
          for (unsigned int al = 0; al < 4; ++al)
            for (unsigned int a = 0; a < 8; ++a)
              {
                gamma[al][a] = hg[al][a];
                for (unsigned int j = 0; j < 3; ++j)
                  gamma[al][a] -= D(Field::c + al * 3 + j) * D(Field::b + a * 3 + j);
              }
          for (unsigned int a = 0; a < 8; ++a)
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int bn = 0; bn < 8; ++bn)
                for (unsigned int k = 0; k < 3; ++k)
                  {
                    // V0 (lambda b_ai b_bk + mu (b_ak b_bi + delta_ik b_a.b_b))
                    double bb = 0;
                    for (unsigned int j = 0; j < 3; ++j)
                      bb += D(Field::b + a * 3 + j) * D(Field::b + bn * 3 + j);
                    double value = V0 * (la * D(Field::b + a * 3 + i) * D(Field::b + bn * 3 + k) +
                                         mu * D(Field::b + a * 3 + k) * D(Field::b + bn * 3 + i) +
                                         (i == k ? mu * bb : 0.));
                    if (i == k)
                      for (unsigned int al = 0; al < 4; ++al)
                        value += ka * gamma[al][a] * gamma[al][bn];
                    K(3 * a + i, 3 * bn + k) = value;
                  }
          const unsigned int *nodes = &batch_nodes[std::size_t(batch) * 8 * W];
          for (unsigned int a = 0; a < 8; ++a)
            for (unsigned int d = 0; d < 3; ++d)
              dofs[3 * a + d] = vector_partitioner->local_to_global(nodes[a * W + l] + d);
          constraints.distribute_local_to_global(K, dofs, matrix);
        }
  }



  void
  ExplicitSolver::strain_energies(Energies &e) const
  {
    const double *U  = u.begin();
    double        ie = 0, hge = 0, hge_ref = 0;
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      {
        const unsigned int *nodes   = &batch_nodes[std::size_t(batch) * 8 * W];
        const double       *data    = &batch_data[std::size_t(batch) * Field::n_fields * W];
        const unsigned int  n_valid = std::min(W, n_cells - batch * W);
        for (unsigned int l = 0; l < n_valid; ++l)
          {
            double H[3][3];
            displacement_gradient(U, nodes, data, l, H);
            double E[3][3], EE = 0;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                {
                  double hth = 0;
                  for (unsigned int k = 0; k < 3; ++k)
                    hth += H[k][i] * H[k][j];
                  E[i][j] = 0.5 * (H[i][j] + H[j][i] + hth);
                  EE += E[i][j] * E[i][j];
                }
            const double trE = E[0][0] + E[1][1] + E[2][2];
            ie += data[Field::volume * W + l] * (0.5 * lame_lambda * trE * trE + lame_mu * EE);
            double gg = 0;
            for (unsigned int al = 0; al < 4; ++al)
              for (unsigned int i = 0; i < 3; ++i)
                {
                  double s = 0;
                  for (unsigned int a = 0; a < 8; ++a)
                    s += hg[al][a] * U[nodes[a * W + l] + i];
                  for (unsigned int j = 0; j < 3; ++j)
                    s -= data[(Field::c + al * 3 + j) * W + l] * H[i][j];
                  gg += s * s;
                }
            hge += 0.5 * data[Field::kappa * W + l] * gg;
            hge_ref += 0.5 * batch_kappa_ref[std::size_t(batch) * W + l] * gg;
          }
      }
    e.internal            = ie;
    e.hourglass           = hge;
    e.hourglass_reference = hge_ref;
  }



  void
  ExplicitSolver::step(Energies *energies)
  {
    Assert(dt > 0, ExcInternalError());
    const bool   first = (n_steps == 0);
    const double h     = first ? 0.5 * dt : dt; // v_{1/2} = v_0 + dt/2 a_0

    Clock::time_point clock        = Clock::now();
    double            gravity_work = 0;
    if (energies)
      {
        energies->time = t;
        energies->step = n_steps;
        strain_energies(*energies);
        for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
          gravity_work += f_ext.local_element(i) * (u.local_element(i) - u0.local_element(i));
        times.energies += lap(clock);
      }

    const bool   damping = prm.solver.damping_model != "none";
    const double power   = assemble_forces(u, damping ? &v : nullptr, f, true, true, f_cleared);
    clock                = Clock::now();

    // applied forces at t_n (enter f with the sign of internal forces)
    double         work_step = 0;
    Tensor<1, dim> applied_total;
    if (applied_force)
      {
        applied_force->set_time(t);
        for (unsigned int d = 0; d < dim; ++d)
          applied_total[d] = applied_force->value(Point<dim>(), d);
        for (const auto &[i, d, w] : applied)
          f.local_element(i) -= w * applied_total[d];
      }

    double *U = u.begin();
    double *V = v.begin();
    // applied-force work over the step, with the old velocity (the new one
    // is added below)
    for (const auto &[i, d, w] : applied)
      work_step += 0.5 * h * w * applied_total[d] * V[i];
    double       *F = f.begin();
    const double *G = f_ext.begin();
    // the net forces that the prescribed DoFs and the axle need after the
    // update, which clears f behind itself (f = 0 for the next step's
    // assembly without a pass of its own over the vector)
    for (auto &p : prescribed)
      {
        const unsigned int n_components = (p.kind == 3 && p.component == 0) ? 3 : 1;
        for (unsigned int c = 0; c < n_components; ++c)
          p.net_force[c] = G[p.index + c] - F[p.index + c];
      }
    const double      *IM = inv_mass.begin();
    const double      *M  = mass.begin();
    const unsigned int n  = u.locally_owned_size();
    double             ke = 0;
    if (energies == nullptr)
      {
#pragma omp simd
        for (unsigned int i = 0; i < n; ++i)
          {
            V[i] += h * IM[i] * (G[i] - F[i]);
            U[i] += dt * V[i];
            F[i] = 0;
          }
      }
    else
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            const double vo = V[i];
            V[i] += h * IM[i] * (G[i] - F[i]);
            U[i] += dt * V[i];
            F[i]            = 0;
            const double va = first ? vo : 0.5 * (vo + V[i]);
            if (IM[i] > 0)
              ke += 0.5 * M[i] * va * va;
          }
      }

    f_cleared = true;
    for (const auto &[i, d, w] : applied)
      work_step += 0.5 * h * w * applied_total[d] * V[i];

    // the rigid axle: the FE forces on the bore nodes and their moment
    if (wheelset)
      {
        const Point<dim> axle     = wheelset->axle_position();
        double           local[4] = {0, 0, 0, 0};
        // per bore vertex (its x-DoF; y and z follow contiguously)
        for (const auto &p : prescribed)
          if (p.kind == 3 && p.component == 0)
            {
              const unsigned int i  = p.index;
              const double       fx = p.net_force[0], fy = p.net_force[1], fz = p.net_force[2];
              const double       rx = node_points[i][0] + U[i] - axle[0];
              const double       rz = node_points[i][2] + U[i + 2] - axle[2];
              local[0] += fx;
              local[1] += fy;
              local[2] += fz;
              local[3] += rz * fx - rx * fz;
            }
        double global[4];
        Utilities::MPI::sum(ArrayView<const double>(local, 4),
                            mpi_communicator,
                            ArrayView<double>(global, 4));
        wheelset->advance(Tensor<1, dim>({global[0], global[1], global[2]}), global[3], h, dt, t);
      }

    // prescribed DoFs: fixed, velocity function (at the middle of the
    // step), spinning axle, rigid axle
    if (prescribed_velocity)
      prescribed_velocity->set_time(t + 0.5 * dt);
    const double     t_new  = t + dt;
    const Point<dim> centre = Geometry::wheel_centre(prm.geometry);
    const double     omega  = prm.initial.wheel_angular_velocity;
    for (auto &p : prescribed)
      {
        double u_new = p.u_prev;
        if (p.kind == 1)
          u_new = p.u_prev + dt * prescribed_velocity->value(node_points[p.index], p.component);
        else if (p.kind == 2)
          {
            const Tensor<1, dim> r = node_points[p.index] - centre;
            u_new                  = (rotate_about_y(r, omega * t_new) - r)[p.component];
          }
        else if (p.kind == 3)
          u_new = wheelset->bore_displacement(node_points[p.index])[p.component];
        const double v_new = (u_new - p.u_prev) / dt;
        // reaction that enforces the motion, and its work over the step
        // over [t_{n-1/2}, t_{n+1/2}] (the first step: [0, dt/2])
        // (the rigid axle's bore nodes are part of the wheelset's balance)
        if (p.kind != 3)
          {
            const double r = M[p.index] * (v_new - p.v_prev) / h - p.net_force[0];
            work_step += r * h * 0.5 * (p.v_prev + v_new);
          }
        const double va = first ? p.v_prev : 0.5 * (p.v_prev + v_new);
        if (energies)
          ke += 0.5 * M[p.index] * va * va;
        U[p.index] = u_new;
        V[p.index] = v_new;
        p.u_prev   = u_new;
        p.v_prev   = v_new;
      }
    if (energies)
      {
        // dissipation and boundary work up to t_n: all earlier steps plus
        // half of the current one (none at t_0)
        const double half     = first ? 0. : 0.5;
        const double local[7] = {ke,
                                 gravity_work,
                                 damping_dissipation + half * h * power,
                                 boundary_work + half * work_step,
                                 energies->internal,
                                 energies->hourglass,
                                 energies->hourglass_reference};
        double       global[7];
        Utilities::MPI::sum(ArrayView<const double>(local, 7),
                            mpi_communicator,
                            ArrayView<double>(global, 7));
        energies->kinetic             = global[0];
        energies->damping             = global[2];
        energies->external_work       = global[1] + global[3];
        energies->internal            = global[4];
        energies->hourglass           = global[5];
        energies->hourglass_reference = global[6];
        if (contact)
          {
            // replicated on every rank: no sum
            energies->contact  = contact->summary().elastic_energy;
            energies->friction = contact->friction_dissipation();
            energies->damping += contact->damping_dissipation();
          }
        if (wheelset)
          {
            // replicated: axle, sprung mass, suspension, torque
            energies->kinetic += wheelset->kinetic();
            energies->internal += wheelset->spring_energy();
            energies->damping += wheelset->damper_dissipation();
            energies->external_work += wheelset->external_work();
          }
      }
    damping_dissipation += h * power;
    boundary_work += work_step;
    times.update += lap(clock);

    u.update_ghost_values();
    v.update_ghost_values();
    times.communication += lap(clock);
    distribute(u, &v);
    times.update += lap(clock);
    t = t_new;
    ++n_steps;
    ++times.steps;
  }



  void
  ExplicitSolver::save(Checkpoint::Writer &out) const
  {
    for (const VectorType *x : {&u, &v, &f_ext, &u0})
      out.array(x->begin(), x->locally_owned_size());
    out.pod(t);
    out.pod(dt);
    out.pod(n_steps);
    out.pod(damping_dissipation);
    out.pod(boundary_work);
    std::vector<double> states;
    for (const auto &p : prescribed)
      {
        states.push_back(p.u_prev);
        states.push_back(p.v_prev);
      }
    out.vector(states);
  }



  void
  ExplicitSolver::load(Checkpoint::Reader &in)
  {
    for (VectorType *x : {&u, &v, &f_ext, &u0})
      {
        in.array(x->begin(), x->locally_owned_size());
        x->update_ghost_values();
      }
    in.pod(t);
    in.pod(dt);
    in.pod(n_steps);
    in.pod(damping_dissipation);
    in.pod(boundary_work);
    std::vector<double> states;
    in.vector(states);
    AssertThrow(states.size() == 2 * prescribed.size(),
                ExcMessage("The checkpoint does not fit this run (prescribed DoFs differ)."));
    for (unsigned int i = 0; i < prescribed.size(); ++i)
      {
        prescribed[i].u_prev = states[2 * i];
        prescribed[i].v_prev = states[2 * i + 1];
      }
    distribute(u);
    distribute(v);
  }



  std::vector<CellStress>
  ExplicitSolver::cell_stresses() const
  {
    std::vector<CellStress> result(triangulation.n_active_cells());
    const double           *U = u.begin();
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      {
        const unsigned int *nodes   = &batch_nodes[std::size_t(batch) * 8 * W];
        const double       *data    = &batch_data[std::size_t(batch) * Field::n_fields * W];
        const unsigned int  n_valid = std::min(W, n_cells - batch * W);
        for (unsigned int l = 0; l < n_valid; ++l)
          {
            double h[3][3];
            displacement_gradient(U, nodes, data, l, h);
            Tensor<2, dim> H;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                H[i][j] = h[i][j];
            const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + H;
            const Tensor<2, dim> E = 0.5 * (transpose(F) * F - unit_symmetric_tensor<dim>());
            const Tensor<2, dim> S =
              lame_lambda * trace(E) * Tensor<2, dim>(unit_symmetric_tensor<dim>()) +
              2. * lame_mu * E;
            const Tensor<2, dim> sigma = F * S * transpose(F) / determinant(F);
            const Tensor<2, dim> dev =
              sigma - trace(sigma) / 3. * Tensor<2, dim>(unit_symmetric_tensor<dim>());
            CellStress &cs            = result[batch_cell_index[std::size_t(batch) * W + l]];
            cs.second_piola_kirchhoff = S;
            cs.von_mises              = std::sqrt(1.5 * scalar_product(dev, dev));
          }
      }
    return result;
  }



  double
  ExplicitSolver::total_mass(const types::material_id material) const
  {
    double m = 0;
    for (unsigned int i = 0; i < mass.locally_owned_size(); i += 1)
      if (material == numbers::invalid_material_id || node_material[i] == material)
        m += mass.local_element(i);
    return Utilities::MPI::sum(m, mpi_communicator) / dim;
  }



  double
  ExplicitSolver::mesh_volume(const types::material_id material) const
  {
    double vol = 0;
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      for (unsigned int l = 0; l < std::min(W, n_cells - batch * W); ++l)
        if (material == numbers::invalid_material_id ||
            batch_material[std::size_t(batch) * W + l] == material)
          vol += batch_data[(std::size_t(batch) * Field::n_fields + Field::volume) * W + l];
    return Utilities::MPI::sum(vol, mpi_communicator);
  }



  Tensor<1, dim>
  ExplicitSolver::bore_displacement() const
  {
    double local[4] = {0, 0, 0, 0};
    for (const unsigned int i : bore_dofs)
      {
        const unsigned int d = node_component[i];
        local[d] += u.local_element(i);
        if (d == 0)
          local[3] += 1;
      }
    double global[4];
    Utilities::MPI::sum(ArrayView<const double>(local, 4),
                        mpi_communicator,
                        ArrayView<double>(global, 4));
    Tensor<1, dim> mean;
    if (global[3] > 0)
      for (unsigned int d = 0; d < dim; ++d)
        mean[d] = global[d] / global[3];
    return mean;
  }
} // namespace WheelRail
