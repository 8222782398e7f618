#include <wheelrail/solver/element_kernel.h>
#include <wheelrail/solver/nodal_update.h>

#include <cstdint>

namespace WheelRail
{
  namespace
  {
    using ElementKernel::load;
    using ElementKernel::store;
    using ElementKernel::v8d;
    typedef long long v8i __attribute__((vector_size(64)));

    // Eight nodes are 24 DoFs, three vectors: lane j of vector p is the DoF
    // 8 p + j, of node (8 p + j) / 3 and component (8 p + j) mod 3.
    constexpr v8i node_of[3] = {{0, 0, 0, 1, 1, 1, 2, 2},
                                {2, 3, 3, 3, 4, 4, 4, 5},
                                {5, 5, 6, 6, 6, 7, 7, 7}};

    // w is only written here, and read in the next element loop: stored
    // past the caches where the line is aligned (no read of its old line)
    inline void
    store_streaming(double *p, const v8d &x)
    {
#ifdef __AVX512F__
      if ((reinterpret_cast<std::uintptr_t>(p) & 63) == 0)
        {
          _mm512_stream_pd(p, reinterpret_cast<__m512d>(x));
          return;
        }
#endif
      store(p, x);
    }

    inline void
    streaming_stores_done()
    {
#ifdef __AVX512F__
      _mm_sfence();
#endif
    }
  } // namespace



  bool
  NodalUpdate::prepare(const double            *mass,
                       const double            *inverse_mass,
                       const double            *load,
                       const unsigned char     *component,
                       const std::vector<bool> &overwritten,
                       const unsigned int       n_dofs,
                       const Tensor<1, 3>      &gravity_vector)
  {
    is_active = false;
    node_mass.clear();
    node_inverse_mass.clear();
    if (n_dofs % 3 != 0)
      return false;
    n_nodes = n_dofs / 3;
    for (unsigned int c = 0; c < 3; ++c)
      gravity[c] = gravity_vector[c];
    node_mass.resize(n_nodes);
    node_inverse_mass.resize(n_nodes, 0.);
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        // the inverse mass of the node's DoFs that are not overwritten
        bool has_free = false;
        for (unsigned int c = 0; c < 3; ++c)
          {
            const unsigned int i = 3 * k + c;
            if (component[i] != c || mass[i] != mass[3 * k])
              return false;
            if (overwritten[i])
              continue;
            // the product as the load was formed: mass times gravity
            const double g = mass[i] * gravity[c];
            if (load[i] != g)
              return false;
            if (has_free && inverse_mass[i] != node_inverse_mass[k])
              return false;
            node_inverse_mass[k] = inverse_mass[i];
            has_free             = true;
          }
        node_mass[k] = mass[3 * k];
      }
    is_active = true;
    return true;
  }



  void
  NodalUpdate::apply_per_dof(const double       h,
                             const double       dt,
                             const double      *W,
                             const double      *G,
                             const unsigned int n_dofs,
                             double            *U,
                             double            *V,
                             double            *F)
  {
#pragma omp simd
    for (unsigned int i = 0; i < n_dofs; ++i)
      {
        V[i] += h * W[i] * (G[i] - F[i]);
        U[i] += dt * V[i];
        F[i] = 0;
      }
  }



  bool
  NodalUpdate::set_damping(const double *beta, const unsigned int n_dofs)
  {
    node_beta.clear();
    if (!is_active || n_dofs != 3 * n_nodes)
      return false;
    std::vector<double> b(n_nodes);
    for (unsigned int k = 0; k < n_nodes; ++k)
      {
        if (beta[3 * k + 1] != beta[3 * k] || beta[3 * k + 2] != beta[3 * k])
          return false;
        b[k] = beta[3 * k];
      }
    node_beta = std::move(b);
    return true;
  }



  void
  NodalUpdate::apply(
    const double h, const double dt, double *U, double *V, double *F, double *W) const
  {
    if (W)
      {
        Assert(forms_damped_field(), ExcInternalError());
        update<true>(h, dt, U, V, F, W);
      }
    else
      update<false>(h, dt, U, V, F, nullptr);
  }



  template <bool damped>
  void
  NodalUpdate::update(const double h,
                      const double dt,
                      double      *U,
                      double      *V,
                      double      *F,
                      [[maybe_unused]] double *W) const
  {
    v8d g_lanes[3];
    for (unsigned int p = 0; p < 3; ++p)
      for (unsigned int j = 0; j < 8; ++j)
        g_lanes[p][j] = gravity[(8 * p + j) % 3];

    unsigned int k = 0;
    for (; k + 8 <= n_nodes; k += 8)
      {
        const v8d m = load(&node_mass[k]), w = load(&node_inverse_mass[k]);
        [[maybe_unused]] v8d b{};
        if constexpr (damped)
          b = load(&node_beta[k]);
#pragma GCC unroll 3
        for (unsigned int p = 0; p < 3; ++p)
          {
            const std::size_t i = 3 * std::size_t(k) + 8 * p;
            // the load rounded to a double before f is subtracted, as the
            // stored one was (no contraction into an FMA)
            v8d g = __builtin_shuffle(m, node_of[p]) * g_lanes[p];
            asm("" : "+m"(g));
            const v8d w_p = __builtin_shuffle(w, node_of[p]);
            v8d       v   = load(V + i);
            v += h * w_p * (g - load(F + i));
            store(V + i, v);
            const v8d u = load(U + i) + dt * v;
            store(U + i, u);
            store(F + i, v8d{});
            if constexpr (damped)
              store_streaming(W + i, u + __builtin_shuffle(b, node_of[p]) * v);
          }
      }
    if constexpr (damped)
      streaming_stores_done();
    for (; k < n_nodes; ++k)
      for (unsigned int c = 0; c < 3; ++c)
        {
          const std::size_t i = 3 * std::size_t(k) + c;
          double            g = node_mass[k] * gravity[c];
          asm("" : "+m"(g));
          V[i] += h * node_inverse_mass[k] * (g - F[i]);
          U[i] += dt * V[i];
          F[i] = 0;
          if constexpr (damped)
            W[i] = U[i] + node_beta[k] * V[i];
        }
  }
} // namespace WheelRail
