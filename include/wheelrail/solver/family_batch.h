/**
 * @file family_batch.h
 * Families: batches that hold the 8 children of one parent, whose 64
 * (vertex, lane) pairs are the 27 nodes of the parent's 3x3x3 grid. Their
 * nodal values are gathered once per grid node and expanded to the kernel's
 * [vertex][component][lane] layout by permutations; their forces are summed
 * per grid node in vector registers and added once per node.
 *
 * Included only by the solver's translation units compiled with -O3, like
 * element_kernel.h, whose vector types it uses.
 *
 * The permutations act on whole 8-lane vectors where the target has 8-lane
 * registers (AVX-512). Elsewhere (AVX2, SSE2) the compiler would take such
 * a permutation apart value by value through the stack, so the kernel reads
 * the grid values in place (FamilyGridField), and the same values are
 * gathered by scalar copies and the grid sums added by scalar additions in
 * the same order: the same bits either way.
 */
#ifndef wheelrail_solver_family_batch_h
#define wheelrail_solver_family_batch_h

#include <wheelrail/solver/element_kernel.h>

#include <algorithm>
#include <utility>

namespace WheelRail
{
  namespace ElementKernel
  {
    /**
     * Families: when a batch holds the 8 children of one parent in child
     * order, vertex a of lane (child) l is node family_offset[a] +
     * family_offset[l] of the parent's 3x3x3 grid (lexicographic vertex and
     * child numbering of deal.II), 27 distinct nodes instead of 64.
     */
    constexpr unsigned int family_offset[8] = {0, 1, 3, 4, 9, 10, 12, 13};
    typedef long long      v8i __attribute__((vector_size(64)));

    /** W lane indices as the index vector of a permutation. */
    constexpr v8i
    lane_vector(const long long (&l)[W])
    {
      return v8i{l[0], l[1], l[2], l[3], l[4], l[5], l[6], l[7]};
    }

    /** The permutations that expand_family() applies: vertex a's vector
     *  takes lane l from grid value family_offset[a] + family_offset[l];
     *  first from the two grid vectors from `first` on (lanes below 16),
     *  then, where `second`, the lanes beyond them from the vector after. */
    struct FamilyExpansion
    {
      unsigned int first[8];
      long long    lane[8][W];
      bool         second[8];
      long long    lane2[8][W];
      constexpr FamilyExpansion()
        : first{}
        , lane{}
        , second{}
        , lane2{}
      {
        for (unsigned int a = 0; a < 8; ++a)
          {
            first[a] = family_offset[a] / W;
            for (unsigned int l = 0; l < W; ++l)
              {
                const unsigned int i = family_offset[a] + family_offset[l] - W * first[a];
                lane[a][l]           = i < 2 * W ? i : 0;
                lane2[a][l]          = i < 2 * W ? l : W + i - 2 * W;
                if (i >= 2 * W)
                  second[a] = true;
              }
          }
      }
    };
    inline constexpr FamilyExpansion family_expansion{};

    /** Vertex @p a's vector over the children of the grid component @p g
     *  (32 values, 4 aligned vectors): one or two permutations of aligned
     *  grid vectors, the values moved, not combined. */
    template <unsigned int a>
    WHEELRAIL_ALWAYS_INLINE v8d
    expand_vertex(const double *g)
    {
      constexpr FamilyExpansion e     = family_expansion;
      constexpr unsigned int    q     = e.first[a];
      constexpr v8i             lanes = lane_vector(e.lane[a]);
      const v8d r = __builtin_shuffle(load(g + q * W), load(g + (q + 1) * W), lanes);
      if constexpr (e.second[a])
        {
          constexpr v8i lanes2 = lane_vector(e.lane2[a]);
          return __builtin_shuffle(r, load(g + (q + 2) * W), lanes2);
        }
      else
        return r;
    }

    /** A family's vertex vectors @p wb ([vertex][component][lane]) from its
     *  grid values @p g ([component][32], aligned), for 8-lane registers;
     *  narrower vectors read the grid values in place (FamilyGridField). */
    template <unsigned int... a>
    WHEELRAIL_ALWAYS_INLINE void
    expand_family(const double (&g)[3][32], double *wb, std::integer_sequence<unsigned int, a...>)
    {
#pragma GCC unroll 3
      for (unsigned int d = 0; d < 3; ++d)
        (store(wb + (a * 3 + d) * W, expand_vertex<a>(g[d])), ...);
    }

    /**
     * A family's nodal field read by the kernel straight from its grid
     * values @p g ([component][32]) where its vector is narrower than W:
     * lanes l .. l + 3 of vertex a are the grid values o + {0, 1, 3, 4}
     * with o = family_offset[a] + family_offset[l] (l = 0, 4), two pairs of
     * neighbours (one pair for 2 lanes). Two 2-lane loads and one insert
     * per vector, and no vertex vectors stored: the values are moved, not
     * combined, as by expand_family().
     */
    template <typename V>
    struct FamilyGridField
    {
      const double (*g)[32];
      unsigned int lane;
      WHEELRAIL_ALWAYS_INLINE V
      operator()(const unsigned int a, const unsigned int i) const
      {
        static_assert(lanes_of<V> == 2 || lanes_of<V> == 4, "pairs of neighbours");
        const double *p = g[i] + family_offset[a] + family_offset[lane];
        if constexpr (lanes_of<V> == 2)
          return load<v2d>(p);
        else
          return __builtin_shufflevector(load<v2d>(p), load<v2d>(p + 3), 0, 1, 2, 3);
      }
    };

    /** The nodal values of a family's 27 grid nodes @p grid (x-DoF
     *  indices into @p X, node-blocked) per component, @p g[d][n], by
     *  scalar copies (any node index; lanes 27-31 left as they are). */
    WHEELRAIL_ALWAYS_INLINE void
    gather_family_grid_by_node(const double *X, const unsigned int *grid, double (&g)[3][32])
    {
#pragma GCC unroll 27
      for (unsigned int n = 0; n < 27; ++n)
        for (unsigned int d = 0; d < 3; ++d)
          g[d][n] = X[grid[n] + d];
    }

    /** The nodal values of a family's 27 grid nodes @p grid (x-DoF
     *  indices into @p X, node-blocked) per component, @p g[d][n]: each
     *  node's x, y, z (and one value beyond, unused) by one 4-wide load,
     *  eight nodes transposed by permutations (lanes 27-31 repeat node 26).
     *  The values are moved, not combined: the same bits as scalar copies.
     *  Every node needs idx + 4 <= the vector's size. For 8-lane registers
     *  (gather_family_grid()); compiled everywhere, so that
     *  tests/family_batch_01 compares it with the scalar copies on any host. */
    WHEELRAIL_ALWAYS_INLINE void
    gather_family_grid_vector(const double *X, const unsigned int *grid, double (&g)[3][32])
    {
#pragma GCC unroll 4
      for (unsigned int q = 0; q < 4; ++q)
        {
          v4d node[8];
#pragma GCC unroll 8
          for (unsigned int k = 0; k < 8; ++k)
            __builtin_memcpy(&node[k], X + grid[std::min(8 * q + k, 26u)], sizeof(v4d));
          // pairs of nodes, then x and y of four nodes, z of four nodes
          const v8d n01 = __builtin_shufflevector(node[0], node[1], 0, 1, 2, 3, 4, 5, 6, 7);
          const v8d n23 = __builtin_shufflevector(node[2], node[3], 0, 1, 2, 3, 4, 5, 6, 7);
          const v8d n45 = __builtin_shufflevector(node[4], node[5], 0, 1, 2, 3, 4, 5, 6, 7);
          const v8d n67 = __builtin_shufflevector(node[6], node[7], 0, 1, 2, 3, 4, 5, 6, 7);
          const v8d xy0 = __builtin_shufflevector(n01, n23, 0, 4, 8, 12, 1, 5, 9, 13);
          const v8d xy1 = __builtin_shufflevector(n45, n67, 0, 4, 8, 12, 1, 5, 9, 13);
          const v8d z0  = __builtin_shufflevector(n01, n23, 2, 6, 10, 14, 2, 6, 10, 14);
          const v8d z1  = __builtin_shufflevector(n45, n67, 2, 6, 10, 14, 2, 6, 10, 14);
          store(&g[0][8 * q], __builtin_shufflevector(xy0, xy1, 0, 1, 2, 3, 8, 9, 10, 11));
          store(&g[1][8 * q], __builtin_shufflevector(xy0, xy1, 4, 5, 6, 7, 12, 13, 14, 15));
          store(&g[2][8 * q], __builtin_shufflevector(z0, z1, 0, 1, 2, 3, 8, 9, 10, 11));
        }
    }

    /** The family gather of the target: gather_family_grid_vector() with
     *  8-lane registers, else gather_family_grid_by_node() (a permutation
     *  of 8-lane vectors would be taken apart through the stack). */
    WHEELRAIL_ALWAYS_INLINE void
    gather_family_grid(const double *X, const unsigned int *grid, double (&g)[3][32])
    {
#if WHEELRAIL_EIGHT_LANE_REGISTERS
      gather_family_grid_vector(X, grid, g);
#else
      gather_family_grid_by_node(X, grid, g);
#endif
    }

    /** The family scatter in vector form: for vertex a, which lanes
     *  (children) of its force vector reach the grid nodes 8 r .. 8 r + 7
     *  (lane index, or W for none: a lane of a zero vector). */
    struct FamilyVectorScatter
    {
      long long lane[8][4][W];
      bool      hit[8][4];
      constexpr FamilyVectorScatter()
        : lane{}
        , hit{}
      {
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int r = 0; r < 4; ++r)
            for (unsigned int i = 0; i < W; ++i)
              {
                lane[a][r][i] = W;
                for (unsigned int l = 0; l < W; ++l)
                  if (family_offset[a] + family_offset[l] == 8 * r + i)
                    {
                      lane[a][r][i] = l;
                      hit[a][r]     = true;
                    }
              }
      }
    };
    inline constexpr FamilyVectorScatter family_vector_scatter{};

    /** Adds vertex @p a's forces @p f (over the children) to the grid sums
     *  @p sums (27 grid nodes in 4 vectors), by one permutation per vector
     *  that it reaches. */
    template <unsigned int a, unsigned int... r>
    WHEELRAIL_ALWAYS_INLINE void
    add_vertex_to_grid(const v8d &f, v8d (&sums)[4], std::integer_sequence<unsigned int, r...>)
    {
      (
        [&] {
          if constexpr (family_vector_scatter.hit[a][r])
            {
              constexpr v8i lanes = lane_vector(family_vector_scatter.lane[a][r]);
              sums[r] += __builtin_shuffle(f, v8d{}, lanes);
            }
        }(),
        ...);
    }

    /** Per grid node of a family, where its terms lie in the batch forces
     *  ([vertex][component][lane], component 0), in ascending vertex order. */
    struct FamilyNodeTerms
    {
      unsigned int count[27];
      unsigned int offset[27][8];
      constexpr FamilyNodeTerms()
        : count{}
        , offset{}
      {
        for (unsigned int a = 0; a < 8; ++a)
          for (unsigned int l = 0; l < W; ++l)
            {
              const unsigned int n  = family_offset[a] + family_offset[l];
              offset[n][count[n]++] = a * 3 * W + l;
            }
      }
    };
    inline constexpr FamilyNodeTerms family_node_terms{};

    /** The family scatter in vector registers: the batch forces @p fb
     *  summed per grid node (terms in ascending vertex order), then each
     *  grid node's three sums added to F. For 8-lane registers
     *  (scatter_family()); compiled everywhere, like
     *  gather_family_grid_vector(). */
    template <unsigned int... a>
    WHEELRAIL_ALWAYS_INLINE void
    scatter_family_vector(double             *F,
                          const unsigned int *grid,
                          const double *__restrict fb,
                          std::integer_sequence<unsigned int, a...>)
    {
      alignas(64) double grid_sums[3][32];
#pragma GCC unroll 3
      for (unsigned int d = 0; d < 3; ++d)
        {
          v8d sums[4] = {};
          (add_vertex_to_grid<a>(load(fb + (a * 3 + d) * W),
                                 sums,
                                 std::make_integer_sequence<unsigned int, 4>{}),
           ...);
#pragma GCC unroll 4
          for (unsigned int r = 0; r < 4; ++r)
            store(&grid_sums[d][8 * r], sums[r]);
        }
#pragma GCC unroll 27
      for (unsigned int n = 0; n < 27; ++n)
        {
          const unsigned int idx = grid[n];
          F[idx] += grid_sums[0][n];
          F[idx + 1] += grid_sums[1][n];
          F[idx + 2] += grid_sums[2][n];
        }
    }

    /** The family scatter by scalar sums: per grid node, its terms in
     *  ascending vertex order from zero, as scatter_family_vector() adds
     *  them (the same bits). */
    WHEELRAIL_ALWAYS_INLINE void
    scatter_family_by_node(double *F, const unsigned int *grid, const double *__restrict fb)
    {
#pragma GCC unroll 27
      for (unsigned int n = 0; n < 27; ++n)
        {
          const unsigned int idx = grid[n];
#pragma GCC unroll 3
          for (unsigned int d = 0; d < 3; ++d)
            {
              double s = 0;
#pragma GCC unroll 8
              for (unsigned int t = 0; t < family_node_terms.count[n]; ++t)
                s += fb[family_node_terms.offset[n][t] + d * W];
              F[idx + d] += s;
            }
        }
    }

    /** The family scatter of the target: in vector registers with 8-lane
     *  registers, else by scalar sums. */
    template <unsigned int... a>
    WHEELRAIL_ALWAYS_INLINE void
    scatter_family(double             *F,
                   const unsigned int *grid,
                   const double *__restrict fb,
                   std::integer_sequence<unsigned int, a...> vertices)
    {
#if WHEELRAIL_EIGHT_LANE_REGISTERS
      scatter_family_vector(F, grid, fb, vertices);
#else
      (void)vertices;
      scatter_family_by_node(F, grid, fb);
#endif
    }
  } // namespace ElementKernel
} // namespace WheelRail

#endif
