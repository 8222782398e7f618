// Unit test of the element kernel's batches on every host, for each vector
// width the kernel is built with somewhere (2 lanes: SSE2, 4: AVX2, 8:
// AVX-512), whatever this host's widest is:
//  - the family data movement (family_batch.h): the 8-lane gather of a
//    family's 27 grid nodes, the 8-lane expansion to vertex vectors, the
//    in-place reads of 2 and 4 lanes (FamilyGridField) and the 8-lane
//    scatter give the same bits as the scalar gathers and sums that the
//    other builds use, and as the batch's own per-vertex gather;
//  - batch_forces() on a batch of random element data (double and single
//    precision geometry, with and without damping, with energies) against a
//    plain scalar evaluation of the same one-point St. Venant-Kirchhoff
//    stress (the law of st_venant_kirchhoff.h on deal.II tensors),
//    stiffness damping and hourglass forces, cell by cell: forces,
//    damping power and strain energies within 1e-12 of their scale (the
//    vector widths contract products into FMAs differently); the same
//    with the family's values read through expand_family() or
//    FamilyGridField.
// Host-independent output: counts of differing values and verdicts.
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <wheelrail/solver/family_batch.h>
#include <wheelrail/solver/st_venant_kirchhoff.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

using namespace WheelRail;
using namespace WheelRail::ElementKernel;

namespace
{
  constexpr double lambda = 1.15e11, mu = 7.9e10;

  /** One cell's element data and nodal values, and what the kernel must
   *  give for them. */
  struct Cell
  {
    double b[8][3], c[4][3], volume, kappa, beta, kappa_ref;
    double u[8][3], v[8][3];
    double f[8][3] = {}, power = 0, internal = 0, hourglass = 0, hourglass_reference = 0;
  };

  /** The kernel's quantities for one cell in plain scalar arithmetic, the
   *  law by the project's St. Venant-Kirchhoff on deal.II tensors (E from
   *  F^T F, rounded unlike the kernel's (H + H^T + H^T H) / 2); with
   *  @p translation_free the gradients sum u_a - u_0 (single precision
   *  geometry, whose b_a need not sum to zero). */
  void
  reference(Cell &cell, const bool damping, const bool translation_free)
  {
    Tensor<2, dim> H, L;
    for (unsigned int a = 0; a < 8; ++a)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          {
            const double du = cell.u[a][i] - (translation_free ? cell.u[0][i] : 0.);
            const double dv = cell.v[a][i] - (translation_free ? cell.v[0][i] : 0.);
            H[i][j] += du * cell.b[a][j];
            L[i][j] += dv * cell.b[a][j];
          }
    const auto stress = [](const Tensor<2, dim> &A) {
      return StVenantKirchhoff::second_piola_kirchhoff_stress(A, lambda, mu);
    };
    const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + H;
    const Tensor<2, dim> E = StVenantKirchhoff::green_lagrange_strain(F);
    // the rate of E, dE/dt = sym(F^T L), and the first Piola-Kirchhoff
    // stress of the elastic and the damping stress together
    const Tensor<2, dim> Ed =
      damping ? 0.5 * (transpose(F) * L + transpose(L) * F) : Tensor<2, dim>();
    const Tensor<2, dim> P     = F * stress(E + cell.beta * Ed);
    double               modes = 0;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int al = 0; al < 4; ++al)
        {
          double mode = 0;
          for (unsigned int a = 0; a < 8; ++a)
            mode += hg[al][a] * cell.u[a][i];
          for (unsigned int j = 0; j < 3; ++j)
            mode -= cell.c[al][j] * H[i][j];
          modes += mode * mode;
          for (unsigned int a = 0; a < 8; ++a)
            {
              double shape = hg[al][a];
              for (unsigned int j = 0; j < 3; ++j)
                shape -= cell.c[al][j] * cell.b[a][j];
              cell.f[a][i] += cell.kappa * mode * shape;
            }
        }
    for (unsigned int a = 0; a < 8; ++a)
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          cell.f[a][i] += cell.volume * P[i][j] * cell.b[a][j];
    cell.power               = cell.beta * cell.volume * scalar_product(Ed, stress(Ed));
    cell.internal            = 0.5 * cell.volume * scalar_product(E, stress(E));
    cell.hourglass           = 0.5 * cell.kappa * modes;
    cell.hourglass_reference = 0.5 * cell.kappa_ref * modes;
  }

  /** The batch's element data of @p cells in the layout of @p Data. */
  template <typename Data>
  std::vector<double>
  element_block(const Cell (&cells)[W])
  {
    constexpr bool      single = Data::translation_free;
    std::vector<double> block(single ? SingleField::n_double : Field::n_fields * W);
    float              *geometry = reinterpret_cast<float *>(block.data());
    for (unsigned int l = 0; l < W; ++l)
      {
        // b (24 fields), then c (12)
        for (unsigned int k = 0; k < 36; ++k)
          {
            const double x = k < 24 ? cells[l].b[k / 3][k % 3] : cells[l].c[(k - 24) / 3][k % 3];
            if (single)
              geometry[(Field::b + k) * W + l] = x;
            else
              block[(Field::b + k) * W + l] = x;
          }
        block[(single ? SingleField::volume : Field::volume * W) + l] = cells[l].volume;
        block[(single ? SingleField::kappa : Field::kappa * W) + l]   = cells[l].kappa;
        block[(single ? SingleField::beta : Field::beta * W) + l]     = cells[l].beta;
      }
    return block;
  }

  /** The largest difference of the kernel's results from the reference,
   *  each relative to the largest magnitude of its quantity. */
  struct Deviation
  {
    double force = 0, power = 0, energy = 0;
    bool
    within(const double tolerance) const
    {
      return force <= tolerance && power <= tolerance && energy <= tolerance;
    }
  };

  /** batch_forces() on @p cells with the nodal fields given by
   *  @p field_of(field, lane), against reference(). */
  template <typename Data, bool damping, typename FieldOf>
  Deviation
  run_kernel(Cell (&cells)[W], const FieldOf &field_of)
  {
    typedef typename Data::vector V;
    const bool                    single = Data::translation_free;
    for (Cell &cell : cells)
      {
        // the kernel computes with the geometry as stored
        if (single)
          {
            for (auto &b : cell.b)
              for (double &x : b)
                x = static_cast<float>(x);
            for (auto &c : cell.c)
              for (double &x : c)
                x = static_cast<float>(x);
          }
        std::fill(&cell.f[0][0], &cell.f[0][0] + 24, 0.);
        reference(cell, damping, single);
      }
    const std::vector<double> block = element_block<Data>(cells);
    alignas(64) double        fb[8 * 3 * W], kappa_ref[W];
    for (unsigned int l = 0; l < W; ++l)
      kappa_ref[l] = cells[l].kappa_ref;
    BatchEnergies energies;
    double        power = 0;
    for (unsigned int lane = 0; lane < W; lane += lanes_of<V>)
      power = batch_forces<damping, true>(Data{block.data(), lane},
                                          lambda,
                                          mu,
                                          field_of(0, lane),
                                          field_of(1, lane),
                                          fb + lane,
                                          power,
                                          &energies,
                                          kappa_ref + lane);

    Deviation d;
    double    f_scale = 0, p_ref = 0, e_scale = 0;
    for (const Cell &cell : cells)
      {
        for (unsigned int k = 0; k < 24; ++k)
          f_scale = std::max(f_scale, std::abs(cell.f[k / 3][k % 3]));
        p_ref += cell.power;
        e_scale = std::max({e_scale, cell.internal, cell.hourglass, cell.hourglass_reference});
      }
    for (unsigned int l = 0; l < W; ++l)
      {
        const Cell &cell = cells[l];
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int i = 0; i < 3; ++i)
            d.force = std::max(d.force, std::abs(fb[(a * 3 + i) * W + l] - cell.f[a][i]) / f_scale);
        d.energy = std::max(
          {d.energy,
           std::abs(energies.internal[l] - cell.internal) / e_scale,
           std::abs(energies.hourglass[l] - cell.hourglass) / e_scale,
           std::abs(energies.hourglass_reference[l] - cell.hourglass_reference) / e_scale});
      }
    d.power = damping ? std::abs(power - p_ref) / std::abs(p_ref) : std::abs(power);
    return d;
  }
} // namespace

int
main()
{
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> value(-1., 1.);

  // a family: 27 grid nodes of a nodal vector (node-blocked x, y, z), at
  // random distinct nodes; vertex a of child l is grid node
  // family_offset[a] + family_offset[l]
  const unsigned int        n_nodes = 200;
  std::vector<double>       U(3 * n_nodes + 1), V(3 * n_nodes + 1);
  std::vector<unsigned int> order(n_nodes - 1);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), random);
  unsigned int grid[27];
  for (unsigned int n = 0; n < 27; ++n)
    grid[n] = 3 * order[n];
  for (unsigned int i = 0; i < U.size(); ++i)
    {
      U[i] = 1e-5 * value(random);
      V[i] = 2. * value(random);
    }
  const auto node_of = [&](const unsigned int a, const unsigned int l) {
    return grid[family_offset[a] + family_offset[l]];
  };
  // the batch's own gather, [vertex][component][lane]
  alignas(64) double ub[8 * 3 * W], vb[8 * 3 * W];
  for (unsigned int a = 0; a < 8; ++a)
    for (unsigned int d = 0; d < 3; ++d)
      for (unsigned int l = 0; l < W; ++l)
        {
          ub[(a * 3 + d) * W + l] = U[node_of(a, l) + d];
          vb[(a * 3 + d) * W + l] = V[node_of(a, l) + d];
        }

  // the gathers of the grid: 8-lane permutations, scalar copies
  alignas(64) double ug[3][32] = {}, ug_node[3][32] = {}, vg[3][32] = {};
  gather_family_grid_vector(U.data(), grid, ug);
  gather_family_grid_by_node(U.data(), grid, ug_node);
  gather_family_grid_vector(V.data(), grid, vg);
  unsigned int n_gather = 0;
  for (unsigned int d = 0; d < 3; ++d)
    for (unsigned int n = 0; n < 27; ++n)
      n_gather += ug[d][n] != ug_node[d][n] || ug[d][n] != U[grid[n] + d];
  std::printf("grid values of the 8-lane gather that differ from the scalar copies: %u of 81\n",
              n_gather);

  // the vertex vectors: 8-lane expansion, 4 and 2 lanes read in place
  alignas(64) double ue[8 * 3 * W];
  expand_family(ug, ue, std::make_integer_sequence<unsigned int, 8>{});
  unsigned int n_expand = 0, n_in_place_4 = 0, n_in_place_2 = 0;
  for (unsigned int a = 0; a < 8; ++a)
    for (unsigned int d = 0; d < 3; ++d)
      for (unsigned int l = 0; l < W; ++l)
        {
          const double x = ub[(a * 3 + d) * W + l];
          n_expand += ue[(a * 3 + d) * W + l] != x;
          n_in_place_4 += FamilyGridField<v4d>{ug, l / 4 * 4}(a, d)[l % 4] != x;
          n_in_place_2 += FamilyGridField<v2d>{ug, l / 2 * 2}(a, d)[l % 2] != x;
        }
  std::printf("vertex values that differ from the batch's gather: 8-lane expansion %u, "
              "4 lanes in place %u, 2 lanes in place %u (of 192)\n",
              n_expand,
              n_in_place_4,
              n_in_place_2);

  // the scatter: 8-lane grid sums, scalar grid sums, and the batch's own
  // per-vertex additions (another order: round-off)
  alignas(64) double fb[8 * 3 * W];
  for (double &f : fb)
    f = 1e3 * value(random);
  std::vector<double> F_vector(U.size()), F_node(U.size()), F_batch(U.size());
  for (unsigned int i = 0; i < U.size(); ++i)
    F_vector[i] = F_node[i] = F_batch[i] = value(random);
  scatter_family_vector(F_vector.data(), grid, fb, std::make_integer_sequence<unsigned int, 8>{});
  scatter_family_by_node(F_node.data(), grid, fb);
  for (unsigned int a = 0; a < 8; ++a)
    for (unsigned int d = 0; d < 3; ++d)
      for (unsigned int l = 0; l < W; ++l)
        F_batch[node_of(a, l) + d] += fb[(a * 3 + d) * W + l];
  unsigned int n_scatter         = 0;
  double       scatter_deviation = 0;
  for (unsigned int i = 0; i < U.size(); ++i)
    {
      n_scatter += F_vector[i] != F_node[i];
      scatter_deviation = std::max(scatter_deviation, std::abs(F_vector[i] - F_batch[i]) / 1e3);
    }
  std::printf("nodal forces of the 8-lane scatter that differ from the scalar sums: %u; "
              "within 1e-14 of the per-vertex additions: %s\n",
              n_scatter,
              scatter_deviation <= 1e-14 ? "yes" : "no");

  // the kernel: 8 cells of random element data of the scales of a 1 mm
  // steel cell (b ~ 1/h with sum_a b_a = 0, c ~ h/10, V0 ~ h^3), nodal values
  // of the family above
  Cell cells[W];
  for (unsigned int l = 0; l < W; ++l)
    {
      Cell &cell = cells[l];
      for (unsigned int j = 0; j < 3; ++j)
        {
          double sum = 0;
          for (unsigned int a = 0; a < 7; ++a)
            sum += cell.b[a][j] = 1e3 * value(random);
          cell.b[7][j] = -sum;
        }
      for (auto &c : cell.c)
        for (double &x : c)
          x = 1e-4 * value(random);
      cell.volume    = 1e-9 * (1 + 0.5 * value(random));
      cell.kappa     = 1e8 * (1 + 0.5 * value(random));
      cell.kappa_ref = 1e8 * (1 + 0.5 * value(random));
      cell.beta      = 1e-9 * (1 + 0.5 * value(random));
      for (unsigned int a = 0; a < 8; ++a)
        for (unsigned int d = 0; d < 3; ++d)
          {
            cell.u[a][d] = ub[(a * 3 + d) * W + l];
            cell.v[a][d] = vb[(a * 3 + d) * W + l];
          }
    }
  const auto gathered = [&](auto vector) {
    typedef decltype(vector) Vector;
    return [&](const unsigned int field, const unsigned int lane) {
      return BatchField<Vector>{(field == 0 ? ub : vb) + lane};
    };
  };
  alignas(64) double ve[8 * 3 * W];
  expand_family(vg, ve, std::make_integer_sequence<unsigned int, 8>{});
  const auto expanded = [&](const unsigned int field, const unsigned int lane) {
    return BatchField<v8d>{(field == 0 ? ue : ve) + lane};
  };
  const auto in_place = [&](auto vector) {
    typedef decltype(vector) Vector;
    return [&](const unsigned int field, const unsigned int lane) {
      return FamilyGridField<Vector>{field == 0 ? ug : vg, lane};
    };
  };

  const auto report = [](const char *what, const Deviation &d) {
    std::printf("%-58s within 1e-12: %s\n", what, d.within(1e-12) ? "yes" : "no");
    if (!d.within(1e-12))
      std::printf("  deviations: forces %.1e, power %.1e, energies %.1e\n",
                  d.force,
                  d.power,
                  d.energy);
  };
  report("8 lanes, double geometry, damping, batch's gather",
         run_kernel<DoubleData<v8d>, true>(cells, gathered(v8d{})));
  report("8 lanes, double geometry, damping, family expansion",
         run_kernel<DoubleData<v8d>, true>(cells, expanded));
  report("8 lanes, single geometry, damping, family expansion",
         run_kernel<SingleData<v8d>, true>(cells, expanded));
  report("8 lanes, double geometry, no damping, family expansion",
         run_kernel<DoubleData<v8d>, false>(cells, expanded));
  report("4 lanes, double geometry, damping, batch's gather",
         run_kernel<DoubleData<v4d>, true>(cells, gathered(v4d{})));
  report("4 lanes, double geometry, damping, family in place",
         run_kernel<DoubleData<v4d>, true>(cells, in_place(v4d{})));
  report("4 lanes, single geometry, damping, family in place",
         run_kernel<SingleData<v4d>, true>(cells, in_place(v4d{})));
  report("4 lanes, single geometry, no damping, family in place",
         run_kernel<SingleData<v4d>, false>(cells, in_place(v4d{})));
  report("2 lanes, double geometry, damping, family in place",
         run_kernel<DoubleData<v2d>, true>(cells, in_place(v2d{})));
  report("2 lanes, single geometry, damping, batch's gather",
         run_kernel<SingleData<v2d>, true>(cells, gathered(v2d{})));
  return 0;
}
