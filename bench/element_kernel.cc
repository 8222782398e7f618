// The element loop's cost where memory plays no part: the family path of the
// explicit force loop (source/solver/element_forces.cc) run, phase by phase,
// over a row of family batches whose nodal values and element data stay in
// the caches (about 330 kB for 64 families). It uses the loop's own header
// functions and compiler flags, so that its figures bound the loop's from
// below on this host: the paper case's element loop takes 1.5-1.8 times the
// whole family batch here (the rest is waiting for memory), the undamped
// block benchmark about as long as its phases here.
//
// Phases, each the best of 7 repetitions, in ns per cell (8 cells per
// batch): the gathers of u and v of a family's 27 grid nodes, their
// expansion to the kernel's vertex vectors, the force kernel (damped and
// undamped, double and single-precision geometry), the scatter of the
// forces, and the whole family batch as the paper case runs it (damped,
// single geometry). No deal.II, so that it builds in seconds.
//
// usage: element_kernel [families] [repetitions]   (default 64, 4000)

#include <wheelrail/solver/family_batch.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <type_traits>
#include <vector>

using namespace WheelRail::ElementKernel;

namespace
{
  typedef kernel_vector Vec;

  // a row of families along x, neighbours sharing their faces' 9 nodes;
  // node-blocked x, y, z as in the solver's vectors
  struct Row
  {
    unsigned int              n_families;
    std::vector<unsigned int> grid;
    std::vector<double>       U, V, F;
    std::vector<double>       double_data, single_data;

    explicit Row(const unsigned int n)
      : n_families(n)
      , grid(27 * n)
    {
      const unsigned int n_nodes = (2 * n + 1) * 9;
      // 4 values beyond the last node: the 4-wide loads of the gather
      U.resize(3 * n_nodes + 4);
      V.resize(U.size());
      F.resize(U.size());
      for (unsigned int f = 0; f < n; ++f)
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int j = 0; j < 3; ++j)
            for (unsigned int i = 0; i < 3; ++i)
              grid[27 * f + 9 * k + 3 * j + i] = 3 * ((2 * f + i) * 9 + 3 * k + j);
      // the scales of a 1 mm steel cell: u ~ 1 um, v ~ 1 cm/s, b ~ 1/h
      // (summing to zero over the vertices), c ~ h/10, V0 = h^3
      std::mt19937                           random(1);
      std::uniform_real_distribution<double> unit(-1., 1.);
      for (std::size_t i = 0; i < U.size(); ++i)
        {
          U[i] = 1e-6 * unit(random);
          V[i] = 1e-2 * unit(random);
        }
      double_data.assign(std::size_t(n) * Field::n_fields * W, 0.);
      single_data.assign(std::size_t(n) * SingleField::n_double, 0.);
      for (unsigned int f = 0; f < n; ++f)
        {
          double *d = &double_data[std::size_t(f) * Field::n_fields * W];
          float  *s =
            reinterpret_cast<float *>(&single_data[std::size_t(f) * SingleField::n_double]);
          for (unsigned int l = 0; l < W; ++l)
            {
              for (unsigned int j = 0; j < 3; ++j)
                {
                  double sum = 0;
                  for (unsigned int a = 0; a < 8; ++a)
                    {
                      const double b = a < 7 ? 250. * unit(random) : -sum;
                      sum += b;
                      d[(Field::b + a * 3 + j) * W + l] = b;
                    }
                }
              for (unsigned int k = 0; k < 12; ++k)
                d[(Field::c + k) * W + l] = 1e-4 * unit(random);
              d[Field::volume * W + l] = 1e-9;
              d[Field::kappa * W + l]  = 1e6;
              d[Field::beta * W + l]   = 1e-8;
              for (unsigned int k = 0; k < SingleField::n_geometry; ++k)
                s[k * W + l] = static_cast<float>(d[k * W + l]);
            }
          double *sd = &single_data[std::size_t(f) * SingleField::n_double];
          for (unsigned int l = 0; l < W; ++l)
            {
              sd[SingleField::volume + l] = d[Field::volume * W + l];
              sd[SingleField::kappa + l]  = d[Field::kappa * W + l];
              sd[SingleField::beta + l]   = d[Field::beta * W + l];
            }
        }
    }
  };

  // the kernel on a family's grid values as the force loop runs it: on the
  // expanded vertex vectors with 8-lane registers, else part by part on
  // the grid values in place
  template <typename Data, bool damping>
  double
  kernel(const double *data,
         const double (&ug)[3][32],
         const double (&vg)[3][32],
         const double *ub,
         const double *vb,
         double       *fb)
  {
    double power = 0;
    if constexpr (lanes_of<Vec> == W)
      power = batch_forces<damping>(
        Data{data}, 1.2e11, 8e10, BatchField<Vec>{ub}, BatchField<Vec>{vb}, fb);
    else
      for (unsigned int lane = 0; lane < W; lane += lanes_of<Vec>)
        power = batch_forces<damping>(Data{data, lane},
                                      1.2e11,
                                      8e10,
                                      FamilyGridField<Vec>{ug, lane},
                                      FamilyGridField<Vec>{vg, lane},
                                      fb + lane,
                                      power);
    return power;
  }

  // The kernel's floating-point operations per cell, counted: the kernel
  // run on one lane of a number type that counts its +, -, * and / (an FMA
  // is two, as in the host's FMA peak). The kernel is straight-line code,
  // so the count is that of every call.
  unsigned long flop_count = 0;
  struct Counted
  {
    double x;
    double &
    operator[](unsigned int)
    {
      return x;
    }
  };
#define WHEELRAIL_COUNTED_OP(op)                                \
  inline Counted operator op(const Counted a, const Counted b)  \
  {                                                             \
    ++flop_count;                                               \
    return {a.x op b.x};                                        \
  }                                                             \
  inline Counted operator op(const double a, const Counted b)   \
  {                                                             \
    ++flop_count;                                               \
    return {a op b.x};                                          \
  }                                                             \
  inline Counted operator op(const Counted a, const double b)   \
  {                                                             \
    ++flop_count;                                               \
    return {a.x op b};                                          \
  }                                                             \
  inline Counted &operator op##=(Counted &a, const Counted b)   \
  {                                                             \
    ++flop_count;                                               \
    a.x op## = b.x;                                             \
    return a;                                                   \
  }
  WHEELRAIL_COUNTED_OP(+)
  WHEELRAIL_COUNTED_OP(-)
  WHEELRAIL_COUNTED_OP(*)
  WHEELRAIL_COUNTED_OP(/)
#undef WHEELRAIL_COUNTED_OP
  inline Counted
  operator-(const Counted a)
  {
    return {-a.x};
  }
} // namespace

namespace WheelRail::ElementKernel
{
  template <>
  Counted
  load_widened<Counted>(const float *p)
  {
    return {double(*p)};
  }
} // namespace WheelRail::ElementKernel

namespace
{
  template <template <typename> class Data, bool damping>
  unsigned long
  kernel_flops(const Row &row)
  {
    alignas(64) double ub[8 * 3 * W] = {}, vb[8 * 3 * W] = {}, fb[8 * 3 * W] = {};
    const double      *data = std::is_same_v<Data<Counted>, DoubleData<Counted>> ?
                                row.double_data.data() :
                                row.single_data.data();
    flop_count              = 0;
    batch_forces<damping>(Data<Counted>{data},
                          1.2e11,
                          8e10,
                          BatchField<Counted>{ub},
                          BatchField<Counted>{vb},
                          fb);
    return flop_count;
  }

  template <typename Phase>
  double
  best_ns_per_cell(const Row &row, const unsigned int repetitions, const Phase &phase)
  {
    double best = 1e300;
    for (unsigned int k = 0; k < 7; ++k)
      {
        const auto start = std::chrono::steady_clock::now();
        for (unsigned int r = 0; r < repetitions; ++r)
          for (unsigned int f = 0; f < row.n_families; ++f)
            phase(f);
        const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = std::min(best, s / (double(repetitions) * row.n_families * W) * 1e9);
      }
    return best;
  }
} // namespace

int
main(int argc, char **argv)
{
  const unsigned int n_families  = argc > 1 ? std::atoi(argv[1]) : 64;
  const unsigned int repetitions = argc > 2 ? std::atoi(argv[2]) : 4000;
  if (n_families < 1 || repetitions < 1)
    {
      std::fprintf(stderr, "usage: element_kernel [families >= 1] [repetitions >= 1]\n");
      return 2;
    }
  Row                row(n_families);
  alignas(64) double ug[3][32] = {}, vg[3][32] = {};
  alignas(64) double ub[8 * 3 * W] = {}, vb[8 * 3 * W] = {}, fb[8 * 3 * W] = {};
  double             sink = 0;
  const auto         grid = [&](const unsigned int f) { return &row.grid[27 * f]; };
  const auto         dd   = [&](const unsigned int f) {
    return &row.double_data[std::size_t(f) * Field::n_fields * W];
  };
  const auto sd = [&](const unsigned int f) {
    return &row.single_data[std::size_t(f) * SingleField::n_double];
  };
  // the phases as the force loop runs them, one after the other
  const auto gather = [&](const unsigned int f) {
    gather_family_grid(row.U.data(), grid(f), ug);
    gather_family_grid(row.V.data(), grid(f), vg);
  };
  const auto expand = [&](const unsigned int) {
    if constexpr (lanes_of<Vec> == W)
      {
        expand_family(ug, ub, std::make_integer_sequence<unsigned int, 8>{});
        expand_family(vg, vb, std::make_integer_sequence<unsigned int, 8>{});
      }
  };
  const auto scatter = [&](const unsigned int f) {
    scatter_family(row.F.data(), grid(f), fb, std::make_integer_sequence<unsigned int, 8>{});
  };
  for (unsigned int f = 0; f < n_families; ++f)
    gather(f), expand(f);

  std::printf("The family batch on cached data (%u families, %u lanes per vector), "
              "ns per cell:\n",
              n_families,
              lanes_of<Vec>);
  const auto print = [&](const char *name, const auto &phase) {
    std::printf("  %-44s %6.2f\n", name, best_ns_per_cell(row, repetitions, phase));
  };
  // a phase timed alone reads what the one before wrote; the empty asm
  // after it keeps the compiler from dropping its stores as unused
  const auto print_alone = [&](const char *name, const auto &phase) {
    print(name, [&](const unsigned int f) {
      phase(f);
      asm volatile("" ::: "memory");
    });
  };
  print_alone("gather of u and v (27 grid nodes each)", gather);
  print_alone("expansion to vertex vectors", expand);
  print_alone("kernel, damped, double geometry", [&](const unsigned int f) {
    sink += kernel<DoubleData<>, true>(dd(f), ug, vg, ub, vb, fb);
  });
  print_alone("kernel, damped, single geometry", [&](const unsigned int f) {
    sink += kernel<SingleData<>, true>(sd(f), ug, vg, ub, vb, fb);
  });
  print_alone("kernel, undamped, single geometry", [&](const unsigned int f) {
    sink += kernel<SingleData<>, false>(sd(f), ug, vg, ub, vb, fb);
  });
  print_alone("scatter of the forces", scatter);
  // the whole batch without barriers between its phases, as the loop
  print("whole batch (damped, single geometry)", [&](const unsigned int f) {
    gather(f);
    expand(f);
    sink += kernel<SingleData<>, true>(sd(f), ug, vg, ub, vb, fb);
    scatter(f);
  });
  std::printf("  (checksum %g)\n", sink + row.F[7]);
  // counted on one lane (an FMA as two operations): what the fractions of
  // the host's FMA peak in ./run.sh bench are computed from
  std::printf("Floating-point operations of the kernel per cell (counted): damped %lu and "
              "undamped %lu with double geometry, damped %lu and undamped %lu with single\n",
              kernel_flops<DoubleData, true>(row),
              kernel_flops<DoubleData, false>(row),
              kernel_flops<SingleData, true>(row),
              kernel_flops<SingleData, false>(row));
  return 0;
}
