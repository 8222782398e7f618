/**
 * @file element_forces.cc
 * The operations of ElasticOperator on the element data: the element force
 * loop (gather, kernel, scatter; strain energies on request), the
 * small-strain stiffness matrix, cell stresses and nodal displacement
 * gradients. Compiled with
 * -O3 (CMakeLists.txt) together with the kernel of element_kernel.h.
 */
#include <deal.II/base/symmetric_tensor.h>

#include <wheelrail/solver/elastic_operator.h>
#include <wheelrail/solver/element_kernel.h>
#include <wheelrail/solver/family_batch.h>
#include <wheelrail/solver/st_venant_kirchhoff.h>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace WheelRail
{
  using namespace ElementKernel;



  double
  ElasticOperator::element_forces(const VectorType &u_in,
                                  const VectorType *v_in,
                                  VectorType       &f_out,
                                  const bool        f_is_zero,
                                  StrainEnergies   *energies) const
  {
    if (!f_is_zero)
      f_out = 0.;
    else
      Assert(std::all_of(f_out.begin(),
                         f_out.begin() + f_out.locally_owned_size() +
                           f_out.get_partitioner()->n_ghost_indices(),
                         [](const double x) { return x == 0; }),
             ExcInternalError());
    const double *U            = u_in.begin();
    const double *V            = v_in ? v_in->begin() : nullptr;
    double       *F            = f_out.begin();
    const bool    with_damping = (v_in != nullptr) && damping != DampingModel::none;
    const auto    loop         = [&](auto with_damping_, auto with_energies) {
      constexpr bool d = decltype(with_damping_)::value, e = decltype(with_energies)::value;
      return prm.solver.single_precision_geometry ?
                          element_loop<SingleData<>, d, e>(batch_single.data(),
                                                batch_single_block.data(),
                                                SingleField::n_double,
                                                U,
                                                V,
                                                F,
                                                energies) :
                          element_loop<DoubleData<>, d, e>(
                 batch_data.data(), nullptr, Field::n_fields * W, U, V, F, energies);
    };
    const auto with_energies = [&](auto with_damping_) {
      return energies != nullptr ? loop(with_damping_, std::true_type()) :
                                   loop(with_damping_, std::false_type());
    };
    return with_damping ? with_energies(std::true_type()) : with_energies(std::false_type());
  }



  /** The nodal values of the batches, gathered one batch ahead of the
   *  kernel (ElasticOperator::element_loop()): two slots, each the batch's
   *  vertex values or, for a family, its grid values per component. */
  struct ElasticOperator::GatherSlots
  {
    // v is gathered, and read, only with damping
    alignas(64) double u_gathered[2][8 * 3 * W], v_gathered[2][8 * 3 * W];
    // a family's grid values per component, padded to 4 aligned vectors
    // (expand_family() reads them whole; the gather repeats node 26)
    alignas(64) double ug[2][3][32] = {}, vg[2][3][32] = {};
  };



  // not inlined: called at two places (the loop's first batch and the one
  // ahead), as the compiler left the lambda it was before
  template <bool with_damping>
  __attribute__((noinline)) void
  ElasticOperator::gather_batch(const unsigned int batch,
                                const unsigned int slot,
                                const double      *U,
                                const double      *V,
                                GatherSlots       &slots) const
  {
    const unsigned int family = batch_family[batch];
    if (family != numbers::invalid_unsigned_int)
      {
        // the 27 grid nodes once
        const unsigned int *grid = &family_nodes[std::size_t(family) * 27];
        if (family_wide_loads[family])
          {
            gather_family_grid(U, grid, slots.ug[slot]);
            if constexpr (with_damping)
              gather_family_grid(V, grid, slots.vg[slot]);
          }
        else
          {
            gather_family_grid_by_node(U, grid, slots.ug[slot]);
            if constexpr (with_damping)
              gather_family_grid_by_node(V, grid, slots.vg[slot]);
          }
      }
    else
      {
        const unsigned int *nodes = &batch_nodes[std::size_t(batch) * 8 * W];
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int l = 0; l < W; ++l)
            {
              const unsigned int idx = nodes[a * W + l];
              for (unsigned int d = 0; d < 3; ++d)
                slots.u_gathered[slot][(a * 3 + d) * W + l] = U[idx + d];
              if constexpr (with_damping)
                for (unsigned int d = 0; d < 3; ++d)
                  slots.v_gathered[slot][(a * 3 + d) * W + l] = V[idx + d];
            }
      }
  }



  template <typename Data, bool with_damping, bool with_energies>
  WHEELRAIL_ALWAYS_INLINE double
  ElasticOperator::batch_kernel(const Data        &data,
                                const bool         in_family,
                                const unsigned int slot,
                                GatherSlots       &slots,
                                double            *fb,
                                BatchEnergies     &batch_energies,
                                const double      *kappa_ref) const
  {
    typedef typename Data::vector V;
    double                        batch_power = 0;
    if constexpr (lanes_of<V> == W)
      {
        // one kernel, inlined here, for both kinds of batch (a kernel
        // called as a function, or inlined at two places, took 8-10 %
        // longer): a family's vertex vectors over the children by
        // permutations of the aligned grid vectors
        alignas(64) double ub[8 * 3 * W], vb[8 * 3 * W];
        const double      *u_batch = slots.u_gathered[slot], *v_batch = slots.v_gathered[slot];
        if (in_family)
          {
            expand_family(slots.ug[slot], ub, std::make_integer_sequence<unsigned int, 8>{});
            if constexpr (with_damping)
              expand_family(slots.vg[slot], vb, std::make_integer_sequence<unsigned int, 8>{});
            u_batch = ub;
            v_batch = vb;
          }
        batch_power = batch_forces<with_damping, with_energies>(data,
                                                                lame_lambda,
                                                                lame_mu,
                                                                BatchField<V>{u_batch},
                                                                BatchField<V>{v_batch},
                                                                fb,
                                                                0.,
                                                                &batch_energies,
                                                                kappa_ref);
      }
    else
      {
        // the kernel once per part of the batch that its vector holds
        const auto run_parts = [&](const auto &field_of) {
#pragma GCC unroll 4
          for (unsigned int lane = 0; lane < W; lane += lanes_of<V>)
            batch_power = batch_forces<with_damping, with_energies>(Data{data.data, lane},
                                                                    lame_lambda,
                                                                    lame_mu,
                                                                    field_of(0, lane),
                                                                    field_of(1, lane),
                                                                    fb + lane,
                                                                    batch_power,
                                                                    &batch_energies,
                                                                    kappa_ref + lane);
        };
        if (!in_family)
          run_parts([&](const unsigned int field, const unsigned int lane) {
            return BatchField<V>{(field == 0 ? slots.u_gathered[slot] : slots.v_gathered[slot]) +
                                 lane};
          });
        else
          // narrower vectors read the grid values in place
          run_parts([&](const unsigned int field, const unsigned int lane) {
            return FamilyGridField<V>{field == 0 ? slots.ug[slot] : slots.vg[slot], lane};
          });
      }
    return batch_power;
  }



  WHEELRAIL_ALWAYS_INLINE void
  ElasticOperator::scatter_batch(const unsigned int batch, const double *fb, double *F) const
  {
    const unsigned int *nodes   = &batch_nodes[std::size_t(batch) * 8 * W];
    const unsigned int  n_valid = std::min(W, n_cells - batch * W);
    for (unsigned int a = 0; a < 8; ++a)
      for (unsigned int l = 0; l < n_valid; ++l)
        {
          const unsigned int idx = nodes[a * W + l];
          for (unsigned int d = 0; d < 3; ++d)
            F[idx + d] += fb[(a * 3 + d) * W + l];
        }
  }



  template <typename Data, bool with_damping, bool with_energies>
  double
  ElasticOperator::element_loop(const double       *batch_blocks,
                                const unsigned int *block_of,
                                const unsigned int  block_size,
                                const double       *U,
                                const double       *V,
                                double             *F,
                                StrainEnergies     *energies) const
  {
    // Software pipelined by one batch: the nodal values of batch + 1 are
    // gathered (scalar stores, or a family's grid vectors) before the
    // kernel of batch runs, so that the vector loads of them (the kernel's,
    // the family permutations' at other offsets) come after the stores
    // have left the store buffer (a load that spans several recent stores
    // cannot be forwarded and waits for them).
    alignas(64) double fb[8 * 3 * W];
    GatherSlots        slots;
    double             power = 0;
    BatchEnergies      batch_energies;
    if (n_batches > 0)
      gather_batch<with_damping>(0, 0, U, V, slots);
    const auto block = [&](const unsigned int batch) {
      return batch_blocks + std::size_t(block_of ? block_of[batch] : batch) * block_size;
    };
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      {
        const Data         data{block(batch)};
        const unsigned int slot = batch & 1;
        // the damping time constants, the block's last W values, only
        // where the kernel damps
        if (batch + prefetch_distance < n_batches)
          prefetch_block(block(batch + prefetch_distance),
                         with_damping ? block_size : block_size - W);
        const unsigned int family = batch_family[batch];
        if (batch + node_prefetch_distance < n_batches)
          prefetch_nodes(batch + node_prefetch_distance, U, V, F, with_damping);
        if (batch + 1 < n_batches)
          gather_batch<with_damping>(batch + 1, slot ^ 1, U, V, slots);
        const bool in_family = family != numbers::invalid_unsigned_int;
        power +=
          batch_kernel<Data, with_damping, with_energies>(data,
                                                          in_family,
                                                          slot,
                                                          slots,
                                                          fb,
                                                          batch_energies,
                                                          &batch_kappa_ref[std::size_t(batch) * W]);
        if (in_family)
          scatter_family(F,
                         &family_nodes[std::size_t(family) * 27],
                         fb,
                         std::make_integer_sequence<unsigned int, 8>{});
        else
          scatter_batch(batch, fb, F);
      }
    if constexpr (with_energies)
      {
        *energies = StrainEnergies();
        for (unsigned int l = 0; l < W; ++l)
          {
            energies->internal += batch_energies.internal[l];
            energies->hourglass += batch_energies.hourglass[l];
            energies->hourglass_reference += batch_energies.hourglass_reference[l];
          }
      }
    return power;
  }


  void
  ElasticOperator::prefetch_block(const double *block, const unsigned int size)
  {
    // The kernel reads a batch's 39 fields (2.5 kB) in its own order, not as
    // one stream, which the hardware prefetcher does not follow. Requested a
    // few batches ahead they arrive while the current batch computes; the
    // arithmetic is untouched, so are the results.
    const char *data = reinterpret_cast<const char *>(block);
    for (unsigned int offset = 0; offset < size * sizeof(double); offset += 64)
      __builtin_prefetch(data + offset, 0, 0);
  }


  void
  ElasticOperator::prefetch_nodes(const unsigned int batch,
                                  const double      *U,
                                  const double      *V,
                                  const double      *F,
                                  const bool         with_damping) const
  {
    // The nodes of a batch lie far apart in the DoF numbering, and their u,
    // v, f come from beyond the L2 cache: the gathers of the loop waited on
    // them (perf). Requested node_prefetch_distance batches ahead (one line
    // per node and vector; f for writing) they are there in time: a
    // family's 27 grid nodes, or the 8 W vertices of a batch of other cells
    // (with shared vertices requested more than once).
    const unsigned int  family = batch_family[batch];
    const bool          grid   = family != numbers::invalid_unsigned_int;
    const unsigned int *nodes =
      grid ? &family_nodes[std::size_t(family) * 27] : &batch_nodes[std::size_t(batch) * 8 * W];
    const unsigned int n_nodes = grid ? 27 : 8 * W;
    for (unsigned int n = 0; n < n_nodes; ++n)
      {
        __builtin_prefetch(U + nodes[n], 0, 3);
        if (with_damping)
          __builtin_prefetch(V + nodes[n], 0, 3);
        __builtin_prefetch(F + nodes[n], 1, 3);
      }
  }


  void
  ElasticOperator::assemble_stiffness(TrilinosWrappers::SparseMatrix  &matrix,
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


  std::vector<CellStress>
  ElasticOperator::stresses(const VectorType &u) const
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
            const Tensor<2, dim> E = StVenantKirchhoff::green_lagrange_strain(F);
            const Tensor<2, dim> S =
              StVenantKirchhoff::second_piola_kirchhoff_stress(E, lame_lambda, lame_mu);
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


  void
  ElasticOperator::nodal_gradient(const VectorType            &u,
                                  std::array<VectorType, dim> &gradient,
                                  VectorType                  &weight) const
  {
    weight.reinit(vector_partitioner);
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
  }
} // namespace WheelRail
