/**
 * @file element_kernel.h
 * The one-point hexahedron of SPEC 2 on batches of W cells: the vectorised
 * force kernel (total-Lagrangian St. Venant-Kirchhoff stress, element
 * stiffness damping, stiffness hourglass control) on the element data of
 * element_data.h. The gather and scatter of families are in family_batch.h.
 *
 * Included only by the solver's translation units compiled with -O3 (see
 * CMakeLists.txt); the functions are forced inline so that the kernel is
 * compiled into the element loop and its results stay the same bit for bit.
 */
#ifndef wheelrail_solver_element_kernel_h
#define wheelrail_solver_element_kernel_h

#include <wheelrail/solver/element_data.h>

namespace WheelRail
{
  namespace ElementKernel
  {
    /**
     * A nodal field of a batch stored as [vertex][component][lane] (W lanes
     * per vector, from the first lane the kernel works on): the kernel
     * reads vertex @p a's component @p i of its lanes as one vector. The
     * families' grid values are read by FamilyGridField (family_batch.h).
     */
    template <typename V>
    struct BatchField
    {
      const double *__restrict w;
      WHEELRAIL_ALWAYS_INLINE V
      operator()(const unsigned int a, const unsigned int i) const
      {
        return load<V>(w + (a * 3 + i) * W);
      }
    };

    /** Gradient sum_a w_a (x) b_a of the nodal field @p w of a batch: H
     *  from the displacements, L from the velocities. */
    template <typename Data, typename Nodal, typename V = typename Data::vector>
    WHEELRAIL_ALWAYS_INLINE void
    batch_gradient(const Data &data, const Nodal &w, V (&G)[3][3])
    {
#pragma GCC unroll 3
      for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
        for (unsigned int j = 0; j < 3; ++j)
          G[i][j] = V{};
#pragma GCC unroll 8
      for (unsigned int a = Data::translation_free ? 1 : 0; a < 8; ++a)
        {
          V b[3];
#pragma GCC unroll 3
          for (unsigned int j = 0; j < 3; ++j)
            b[j] = data.b(a, j);
#pragma GCC unroll 3
          for (unsigned int i = 0; i < 3; ++i)
            {
              const V wa = Data::translation_free ? w(a, i) - w(0, i) : w(a, i);
#pragma GCC unroll 3
              for (unsigned int j = 0; j < 3; ++j)
                G[i][j] += wa * b[j];
            }
        }
    }



    /** The four hourglass sums sum_a hg[alpha][a] w_a of the nodal field @p
     *  w of a batch, component @p i, by a partial
     *  Walsh-Hadamard transform over the vertex bits (x, y, z): 18 additions
     *  instead of 28. */
    template <typename V, typename Nodal>
    WHEELRAIL_ALWAYS_INLINE void
    hourglass_sums(const Nodal &w, const unsigned int i, V (&s)[4])
    {
      V p[4], m[4];
#pragma GCC unroll 4
      for (unsigned int k = 0; k < 4; ++k)
        {
          const V w0 = w(2 * k, i);
          const V w1 = w(2 * k + 1, i);
          p[k]       = w0 + w1;
          m[k]       = w0 - w1;
        }
      const V mm0 = m[0] - m[1], mm1 = m[2] - m[3];
      s[0] = (p[0] - p[1]) - (p[2] - p[3]); // (-1)^(y+z)
      s[1] = (m[0] + m[1]) - (m[2] + m[3]); // (-1)^(x+z)
      s[2] = mm0 + mm1;                     // (-1)^(x+y)
      s[3] = mm1 - mm0;                     // -(-1)^(x+y+z)
    }

    /** Per vertex a, q_a = sum_alpha hg[alpha][a] g_alpha (the inverse of
     *  hourglass_sums(): 12 additions instead of 24) from the four sums
     *  and differences of the g_alpha formed once. */
    template <typename V>
    struct HourglassSpread
    {
      V A, B, P, M;
      WHEELRAIL_ALWAYS_INLINE
      HourglassSpread(const V &g0, const V &g1, const V &g2, const V &g3)
        : A(g0 - g3)
        , B(g0 + g3)
        , P(g1 + g2)
        , M(g1 - g2)
      {}
      /** s + q_a for vertex a = x + 2y + 4z. */
      WHEELRAIL_ALWAYS_INLINE V
      add_to(const unsigned int a, const V &s) const
      {
        switch (a)
          {
            case 0:
              return s + (A + P);
            case 1:
              return s + (B - P);
            case 2:
              return s + (M - A);
            case 3:
              return s - (B + M);
            case 4:
              return s - (A + M);
            case 5:
              return s + (M - B);
            case 6:
              return s + (A - P);
            default:
              return s + (B + P);
          }
      }
    };



    /** The symmetric tensors of the kernel by their components 00 11 22
     *  01 02 12. */
    constexpr unsigned int sym_i[6] = {0, 1, 2, 0, 0, 1}, sym_j[6] = {0, 1, 2, 1, 2, 2};

    /** Green-Lagrange strain E = (H + H^T + H^T H) / 2 of the displacement
     *  gradient @p H, by its six components. */
    template <typename V>
    WHEELRAIL_ALWAYS_INLINE void
    green_lagrange(const V (&H)[3][3], V (&E)[6])
    {
#pragma GCC unroll 6
      for (unsigned int q = 0; q < 6; ++q)
        {
          const unsigned int i = sym_i[q], j = sym_j[q];
          const V            hth = H[0][i] * H[0][j] + H[1][i] * H[1][j] + H[2][i] * H[2][j];
          E[q]                   = 0.5 * (H[i][j] + H[j][i] + hth);
        }
    }

    /** A : A of a symmetric tensor given by its six components. */
    template <typename V>
    WHEELRAIL_ALWAYS_INLINE V
    symmetric_square(const V (&A)[6])
    {
      V       d = A[0] * A[0] + A[1] * A[1] + A[2] * A[2];
      const V o = A[3] * A[3] + A[4] * A[4] + A[5] * A[5];
      d += o + o;
      return d;
    }

    /** Strain energies of the batches a force loop has passed, per lane
     *  (zero on padding lanes, which have zero volume and stiffness). */
    struct BatchEnergies
    {
      alignas(64) double internal[W]            = {}; ///< V0 (lambda/2 tr(E)^2 + mu E:E)
      alignas(64) double hourglass[W]           = {}; ///< kappa/2 |hourglass modes|^2
      alignas(64) double hourglass_reference[W] = {}; ///< the same with the reference QM
    };

    /** @p x added to the lanes of @p sum that it stands for. */
    template <typename V>
    WHEELRAIL_ALWAYS_INLINE void
    add_lanes(double *sum, const V &x)
    {
      store(sum, load<V>(sum) + x);
    }

    /**
     * The strain energy V0 (lambda/2 tr(E)^2 + mu E:E) of the lanes at the
     * gradient @p H, added to @p energies (batch_forces()). E is formed once
     * more, from a copy of H that the compiler cannot see through: further
     * uses of the forces' E would change how it is contracted into FMAs, and
     * with it the forces' last bits.
     */
    template <typename Data, typename V>
    WHEELRAIL_ALWAYS_INLINE void
    add_strain_energy(const Data    &data,
                      const V        V0,
                      const V        la,
                      const V        mu,
                      const V (&H)[3][3],
                      BatchEnergies *energies)
    {
      V h[3][3];
#pragma GCC unroll 3
      for (unsigned int i = 0; i < 3; ++i)
#pragma GCC unroll 3
        for (unsigned int j = 0; j < 3; ++j)
          h[i][j] = H[i][j];
      asm("" : "+m"(h));
      V e[6];
      green_lagrange(h, e);
      const V tr = e[0] + e[1] + e[2];
      add_lanes(energies->internal + data.lane,
                V0 * (0.5 * la * tr * tr + mu * symmetric_square(e)));
    }

    /**
     * The strain that the stress is formed from, E + beta dE/dt, from the
     * displacement gradient @p H and the velocity field @p vb, with the
     * damping power beta V0 (lambda tr(dE/dt)^2 + 2 mu dE/dt : dE/dt)
     * (batch_forces() with damping). The rate of strain before the strain:
     * H and L live together only while dE/dt is formed (the fewer tensors
     * live at once, the fewer of them the compiler keeps on the stack with
     * 16 vector registers).
     */
    template <typename Data, typename VField, typename V>
    WHEELRAIL_ALWAYS_INLINE V
    damped_strain(const Data   &data,
                  const VField &vb,
                  const V       V0,
                  const V       la,
                  const V       mu,
                  const V (&H)[3][3],
                  V (&E)[6])
    {
      constexpr const unsigned int(&si)[6] = sym_i, (&sj)[6] = sym_j;
      const V beta = data.beta();
      V       L[3][3];
      batch_gradient(data, vb, L);
      reload_barrier<Data>();
      // dE/dt = sym(F^T L), F = I + H
      V Ed[6];
#pragma GCC unroll 6
      for (unsigned int q = 0; q < 6; ++q)
        {
          const unsigned int i = si[q], j = sj[q];
          V                  ftl = L[i][j] + L[j][i];
#pragma GCC unroll 3
          for (unsigned int k = 0; k < 3; ++k)
            ftl += H[k][i] * L[k][j] + L[k][i] * H[k][j];
          Ed[q] = 0.5 * ftl;
        }
      const V trEd  = Ed[0] + Ed[1] + Ed[2];
      const V power = beta * V0 * (la * trEd * trEd + 2. * mu * symmetric_square(Ed));
      green_lagrange(H, E);
#pragma GCC unroll 6
      for (unsigned int q = 0; q < 6; ++q)
        E[q] += beta * Ed[q];
      return power;
    }

    /** The second Piola-Kirchhoff stress S = lambda tr(E) I + 2 mu E of
     *  the strain @p E (six components), as a full tensor. */
    template <typename V>
    WHEELRAIL_ALWAYS_INLINE void
    svk_stress(const V (&E)[6], const V la, const V mu, V (&S)[3][3])
    {
      constexpr const unsigned int(&si)[6] = sym_i, (&sj)[6] = sym_j;
      const V trE = E[0] + E[1] + E[2];
#pragma GCC unroll 6
      for (unsigned int q = 0; q < 6; ++q)
        {
          const V sq      = q < 3 ? 2. * mu * E[q] + la * trE : 2. * mu * E[q];
          S[si[q]][sj[q]] = sq;
          S[sj[q]][si[q]] = sq;
        }
    }

    /**
     * Element forces of one batch of W cells: one-point total-Lagrangian
     * St. Venant-Kirchhoff stress, element stiffness damping and FB
     * stiffness hourglass forces. f is [vertex][component][lane];
     * every operation acts on all lanes of the vector at once, and all loops are
     * unrolled; the stress and hourglass forces are formed one force
     * component at a time, so that few tensors are live at once. The
     * symmetric tensors (E, its rate, S) are formed from their six
     * components (svk_stress()), the damping stress with the elastic one as
     * S = C : (E + beta dE/dt) (damped_strain()), and the hourglass sums
     * and their forces by partial Walsh-Hadamard transforms over the vertex
     * bits. Returns the damping power. The parts are force-inlined, and the
     * machine code is the same as with one function body (the loop over the
     * force components stays here: as a function of its own, inlined, it
     * changes the register allocation of the single-precision kernel).
     *
     * With @p with_energies the batch's strain energies at u (from the
     * same gradient and hourglass modes as the forces, i.e. the energy
     * whose derivative the forces are) are added to @p energies, with the
     * reference hourglass stiffness @p kappa_ref (W lanes); the forces
     * are the same bits either way.
     *
     * The kernel works on the lanes data.lane to data.lane +
     * lanes_of<V> - 1 of the batch (all W where V is v8d): the nodal fields
     * @p ub and @p vb (BatchField, FamilyGridField) give those lanes, @p fb
     * and @p kappa_ref start at that lane (the stride between fields stays
     * W). It returns @p power_sum plus the damping power of its
     * lanes, added lane by lane.
     */
    template <bool with_damping,
              bool with_energies = false,
              typename Data,
              typename UField,
              typename VField,
              typename V = typename Data::vector>
    WHEELRAIL_ALWAYS_INLINE double
    batch_forces(const Data   &data,
                 const double  lambda,
                 const double  mu_,
                 const UField &ub,
                 const VField &vb,
                 double *__restrict fb,
                 double         power_sum = 0,
                 BatchEnergies *energies  = nullptr,
                 const double  *kappa_ref = nullptr)
    {
      const V V0 = data.volume();
      const V la = V{} + lambda;
      const V mu = V{} + mu_;
      const V ka = data.kappa();

      V H[3][3];
      batch_gradient(data, ub, H);
      reload_barrier<Data>();
      if constexpr (with_energies)
        add_strain_energy(data, V0, la, mu, H, energies);

      V power = {};
      V E[6];
      if constexpr (with_damping)
        power = damped_strain(data, vb, V0, la, mu, H, E);
      else
        green_lagrange(H, E);
      V S[3][3];
      svk_stress(E, la, mu, S);

      [[maybe_unused]] V modes = {}; // the squared hourglass modes summed (energies)
#pragma GCC unroll 3
      for (unsigned int i = 0; i < 3; ++i)
        {
          reload_barrier<Data>();
          V s[4], g[4];
          hourglass_sums(ub, i, s);
#pragma GCC unroll 4
          for (unsigned int al = 0; al < 4; ++al)
            {
              const V c0 = data.c(al, 0), c1 = data.c(al, 1), c2 = data.c(al, 2);
              const V mode = s[al] - (c0 * H[i][0] + c1 * H[i][1] + c2 * H[i][2]);
              g[al]        = ka * mode;
              if constexpr (with_energies)
                modes += mode * mode;
            }
          V T[3];
#pragma GCC unroll 3
          for (unsigned int j = 0; j < 3; ++j)
            {
              V fs = S[i][j] + H[i][0] * S[0][j] + H[i][1] * S[1][j] + H[i][2] * S[2][j];
              T[j] = V0 * fs;
            }
#pragma GCC unroll 4
          for (unsigned int al = 0; al < 4; ++al)
#pragma GCC unroll 3
            for (unsigned int j = 0; j < 3; ++j)
              T[j] -= g[al] * data.c(al, j);
          const HourglassSpread<V> spread{g[0], g[1], g[2], g[3]};
#pragma GCC unroll 8
          for (unsigned int a = 0; a < 8; ++a)
            store(fb + (a * 3 + i) * W,
                  spread.add_to(a,
                                T[0] * data.b(a, 0) + T[1] * data.b(a, 1) + T[2] * data.b(a, 2)));
        }
      if constexpr (with_energies)
        {
          add_lanes(energies->hourglass + data.lane, 0.5 * ka * modes);
          add_lanes(energies->hourglass_reference + data.lane, 0.5 * load<V>(kappa_ref) * modes);
        }
      for (unsigned int l = 0; l < lanes_of<V>; ++l)
        power_sum += power[l];
      return power_sum;
    }



    /** Displacement gradient H = sum_a u_a (x) b_a of lane l of a batch. */
    WHEELRAIL_ALWAYS_INLINE void
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

  } // namespace ElementKernel
} // namespace WheelRail

#endif
