// Unit test of NodalUpdate, the central-difference update from per-node
// mass data (v += h w (m gravity - f), u += dt v, f = 0):
//  - on 8 k + 5 nodes (the vector path and the remainder) with random u, v,
//    f and masses, hanging nodes (mass and inverse mass 0) and prescribed
//    DoFs (inverse mass 0 per DoF, "overwritten"), the per-node update gives
//    every DoF that is not overwritten the same bits as the per-DoF update
//    with the stored load m gravity, and clears f everywhere;
//  - prepare() declines where the per-node form would change the results:
//    components of one node with different masses, a load other than mass
//    times gravity, different inverse masses on a node's free DoFs, DoFs
//    not in node order, a DoF count that is not a multiple of three.
#include <deal.II/base/tensor.h>

#include <wheelrail/solver/nodal_update.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

using namespace WheelRail;

int
main()
{
  const unsigned int                     n_nodes = 8 * 37 + 5, n = 3 * n_nodes;
  const Tensor<1, 3>                     gravity({0.3, -1.7, -9.81});
  std::mt19937                           random(42);
  std::uniform_real_distribution<double> value(-1., 1.), positive(0.5, 2.);

  std::vector<double>        mass(n), inverse_mass(n), load(n), u(n), v(n), f(n);
  std::vector<unsigned char> component(n);
  std::vector<bool>          overwritten(n, false);
  unsigned int               n_hanging = 0, n_prescribed = 0;
  for (unsigned int k = 0; k < n_nodes; ++k)
    {
      const bool   hanging = k % 11 == 3;
      const double m       = hanging ? 0. : 1e-3 * positive(random);
      n_hanging += hanging;
      for (unsigned int c = 0; c < 3; ++c)
        {
          const unsigned int i = 3 * k + c;
          component[i]         = c;
          mass[i]              = m;
          inverse_mass[i]      = m > 0 ? 1. / m : 0.;
          load[i]              = mass[i] * gravity[c];
          u[i]                 = 1e-5 * value(random);
          v[i]                 = value(random);
          f[i]                 = 1e2 * value(random);
          // some nodes prescribed in one component, some in all three
          if ((k % 7 == 2 && c == 1) || k % 13 == 5)
            {
              overwritten[i]  = true;
              inverse_mass[i] = 0;
              ++n_prescribed;
            }
        }
    }

  NodalUpdate nodal;
  const bool  taken = nodal.prepare(
    mass.data(), inverse_mass.data(), load.data(), component.data(), overwritten, n, gravity);
  std::printf("%u nodes (%u hanging), %u prescribed DoFs: per-node form taken: %s\n",
              n_nodes,
              n_hanging,
              n_prescribed,
              taken ? "yes" : "no");

  const double        h = 2.6e-8, dt = 2.6e-8;
  std::vector<double> u_dof = u, v_dof = v, f_dof = f;
  NodalUpdate::apply_per_dof(
    h, dt, inverse_mass.data(), load.data(), n, u_dof.data(), v_dof.data(), f_dof.data());
  if (taken)
    nodal.apply(h, dt, u.data(), v.data(), f.data());
  unsigned int n_different = 0, n_f = 0;
  for (unsigned int i = 0; i < n; ++i)
    {
      if (!overwritten[i] && (u[i] != u_dof[i] || v[i] != v_dof[i]))
        ++n_different;
      if (f[i] != 0 || f_dof[i] != 0)
        ++n_f;
    }
  std::printf("DoFs not overwritten whose u or v differ from the per-DoF update in any bit: %u\n",
              n_different);
  std::printf("DoFs with f not cleared: %u\n", n_f);

  // what prepare() must decline
  const auto declines = [&](const char *what, auto change) {
    std::vector<double>        m = mass, w = inverse_mass, g = load;
    std::vector<unsigned char> comp   = component;
    unsigned int               n_dofs = n;
    change(m, w, g, comp, n_dofs);
    NodalUpdate other;
    const bool  ok =
      other.prepare(m.data(), w.data(), g.data(), comp.data(), overwritten, n_dofs, gravity);
    std::printf("declines %s: %s\n", what, ok ? "no" : "yes");
  };
  declines("a component with another mass",
           [](auto &m, auto &, auto &, auto &, auto &) { m[3 * 20 + 2] *= 1.5; });
  declines("a load other than mass times gravity", [](auto &, auto &, auto &g, auto &, auto &) {
    g[3 * 20 + 2] = std::nextafter(g[3 * 20 + 2], 0.);
  });
  declines("another inverse mass on a free DoF",
           [](auto &, auto &w, auto &, auto &, auto &) { w[3 * 20 + 1] *= 0.5; });
  declines("DoFs not in node order", [](auto &, auto &, auto &, auto &comp, auto &) {
    std::swap(comp[3 * 20], comp[3 * 20 + 1]);
  });
  declines("a DoF count not a multiple of 3",
           [](auto &, auto &, auto &, auto &, auto &n_dofs) { n_dofs -= 1; });
  return 0;
}
