/**
 * @file element_kernel.h
 * The one-point hexahedron of SPEC 2 on batches of W cells: the layout of
 * the per-cell element data (Field), the Flanagan-Belytschko hourglass base
 * vectors, the vectorised force kernel (total-Lagrangian St. Venant-Kirchhoff
 * stress, element stiffness damping, stiffness hourglass control) and the
 * gather/scatter of families (the 8 children of one parent in one batch).
 *
 * Included only by the solver's translation units compiled with -O3 (see
 * CMakeLists.txt); the functions are forced inline so that the kernel is
 * compiled into the element loop and its results stay the same bit for bit.
 */
#ifndef wheelrail_solver_element_kernel_h
#define wheelrail_solver_element_kernel_h

#include <cstddef>

#define WHEELRAIL_ALWAYS_INLINE inline __attribute__((always_inline))

namespace WheelRail
{
  namespace ElementKernel
  {
    /** Lanes of a cell batch; the kernel vectorises across them. */
    constexpr unsigned int W = 8;

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

    WHEELRAIL_ALWAYS_INLINE v8d
    load(const double *p)
    {
      v8d x;
      __builtin_memcpy(&x, p, sizeof(x));
      return x;
    }
    WHEELRAIL_ALWAYS_INLINE void
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
    inline const FamilyScatter family_scatter;

    /** Gradient sum_a w_a (x) b_a of the nodal field @p wb ([vertex][component][lane])
     *  of a batch: H from the displacements, L from the velocities. */
    WHEELRAIL_ALWAYS_INLINE void
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
    WHEELRAIL_ALWAYS_INLINE double
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
