/**
 * @file element_data.h
 * What the force kernel (element_kernel.h) reads a batch of W cells from:
 * the layout of the per-cell element data (Field, SingleField), the
 * Flanagan-Belytschko hourglass base vectors, the vector types of the
 * target and their loads, and the two views of the element data, in
 * double (DoubleData) and single precision (SingleData).
 */
#ifndef wheelrail_solver_element_data_h
#define wheelrail_solver_element_data_h

#include <algorithm>
#include <cstddef>
#include <utility>

#define WHEELRAIL_ALWAYS_INLINE inline __attribute__((always_inline))

/** Whether the target's vector registers hold 8 doubles (AVX-512). */
#ifdef __AVX512F__
#  define WHEELRAIL_EIGHT_LANE_REGISTERS 1
#else
#  define WHEELRAIL_EIGHT_LANE_REGISTERS 0
#endif
#ifdef __SSE2__
#  include <immintrin.h>
#endif

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
     * W, 4 and 2 lanes of doubles as one value: GCC/Clang vector extension.
     * Debian's deal.II has no SIMD (VectorizedArray<double> has one lane),
     * so the kernel does its own.
     */
    typedef double v8d __attribute__((vector_size(64)));
    typedef double v4d __attribute__((vector_size(32)));
    typedef double v2d __attribute__((vector_size(16)));
    static_assert(W == 8, "the vector kernel is written for 8 lanes");

    /**
     * The vector the force kernel computes with: the widest that the target
     * keeps in registers (one zmm with AVX-512, one ymm with AVX2, one xmm
     * with SSE2). With fewer than W lanes the kernel runs once per part of
     * the batch; every lane's arithmetic is the same, and so are its bits.
     * A wider vector than the registers would be split by the compiler,
     * and the kernel's tensors would no longer fit in them.
     */
#if WHEELRAIL_EIGHT_LANE_REGISTERS
    typedef v8d kernel_vector;
#elif defined(__AVX__)
    typedef v4d kernel_vector;
#else
    typedef v2d kernel_vector;
#endif

    /** Lanes of the vector type @p V. */
    template <typename V>
    constexpr unsigned int lanes_of = sizeof(V) / sizeof(double);

    template <typename V = v8d>
    WHEELRAIL_ALWAYS_INLINE V
    load(const double *p)
    {
      V x;
      __builtin_memcpy(&x, p, sizeof(x));
      return x;
    }
    template <typename V>
    WHEELRAIL_ALWAYS_INLINE void
    store(double *p, const V &x)
    {
      __builtin_memcpy(p, &x, sizeof(x));
    }

    /** The floats of as many lanes as @p V has. */
    template <typename V>
    struct FloatLanes;
    template <>
    struct FloatLanes<v8d>
    {
      typedef float type __attribute__((vector_size(32)));
    };
    template <>
    struct FloatLanes<v4d>
    {
      typedef float type __attribute__((vector_size(16)));
    };
    template <>
    struct FloatLanes<v2d>
    {
      typedef float type __attribute__((vector_size(8)));
    };

    /** Floats widened to doubles, as many as @p V has lanes (exact), by one
     *  conversion from memory on x86-64 (vcvtps2pd of 8, 4 or 2 floats).
     *  GCC 12 lowers __builtin_convertvector of 8 or 4 floats as two
     *  half-width conversions, an extract and an insert (of 2 floats: two
     *  scalar conversions and an unpack); with the split the damped
     *  single-geometry kernel took 12-14 % longer on AVX-512
     *  (doc/notes/performance_kernel.md). The masked form of the 8-lane
     *  intrinsic, all lanes set, is the same instruction; the plain one's
     *  undefined source trips -Wmaybe-uninitialized in GCC 12. */
    template <typename V>
    WHEELRAIL_ALWAYS_INLINE V
    load_widened(const float *p)
    {
#if WHEELRAIL_EIGHT_LANE_REGISTERS
      if constexpr (lanes_of<V> == 8)
        return (V)_mm512_maskz_cvtps_pd(0xFF, _mm256_loadu_ps(p));
#endif
#ifdef __AVX__
      if constexpr (lanes_of<V> == 4)
        return (V)_mm256_cvtps_pd(_mm_loadu_ps(p));
#endif
#ifdef __SSE2__
      if constexpr (lanes_of<V> == 2)
        return (V)_mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64((const __m128i *)p)));
#endif
      typename FloatLanes<V>::type x;
      __builtin_memcpy(&x, p, sizeof(x));
      return __builtin_convertvector(x, V);
    }

    /**
     * Per-batch element data with the geometric factors in single precision
     * (Solver/Element geometry precision = single): b and c as floats
     * ([field][lane], 36 x W), then V0, kappa, beta as doubles: 1,344 bytes
     * per batch instead of 2,496. Arithmetic and accumulation stay double.
     */
    namespace SingleField
    {
      constexpr unsigned int n_geometry = 36; ///< b and c, as in Field
      /** Offsets in doubles from the start of a batch's block. */
      constexpr unsigned int volume   = n_geometry * W / 2;
      constexpr unsigned int kappa    = volume + W;
      constexpr unsigned int beta     = kappa + W;
      constexpr unsigned int n_double = beta + W; ///< block size in doubles
      static_assert(Field::b == 0 && Field::c == 24 && Field::volume == n_geometry,
                    "b and c are the first 36 fields");
      static_assert(Field::beta + 1 == Field::n_fields && beta + W == n_double,
                    "the damping time constants are a block's last W values "
                    "(ElasticOperator::element_loop() leaves them out of its "
                    "prefetch where the kernel does not damp)");
    } // namespace SingleField

    /** The kernel's view of a batch's element data in double precision
     *  (the layout of Field), lanes @p lane to @p lane + lanes_of<V> - 1. */
    template <typename V = kernel_vector>
    struct DoubleData
    {
      typedef V          vector;
      const double      *data;
      const unsigned int lane = 0;
      /** The double kernel sums the gradient over all eight vertices. */
      static constexpr bool translation_free = false;
      /** Element data read again where the kernel needs them again: a load. */
      static constexpr bool reload_cheap = true;
      WHEELRAIL_ALWAYS_INLINE V
      b(const unsigned int a, const unsigned int j) const
      {
        return load<V>(data + (Field::b + a * 3 + j) * W + lane);
      }
      WHEELRAIL_ALWAYS_INLINE V
      c(const unsigned int alpha, const unsigned int j) const
      {
        return load<V>(data + (Field::c + alpha * 3 + j) * W + lane);
      }
      WHEELRAIL_ALWAYS_INLINE V
      volume() const
      {
        return load<V>(data + Field::volume * W + lane);
      }
      WHEELRAIL_ALWAYS_INLINE V
      kappa() const
      {
        return load<V>(data + Field::kappa * W + lane);
      }
      WHEELRAIL_ALWAYS_INLINE V
      beta() const
      {
        return load<V>(data + Field::beta * W + lane);
      }
    };

    /**
     * The kernel's view of a batch's element data with single-precision
     * geometric factors (layout SingleField). Rounded to floats, the b_a no
     * longer sum to zero exactly, and a rigid translation u_a = U would give
     * a strain of order |U| |b| 6e-8 (1e-5 for the wheel after 150 mm of
     * rolling); the gradient is therefore summed over u_a - u_0, which is
     * the same sum for exact b_a and leaves only the rounding of the
     * deformation and rotation within the cell (doc/notes/performance.md).
     */
    template <typename V = kernel_vector>
    struct SingleData
    {
      typedef V             vector;
      const double         *data;
      const unsigned int    lane             = 0;
      static constexpr bool translation_free = true;
      /** Element data read again where the kernel needs them again: a
       *  load and a conversion, which contends with the arithmetic. */
      static constexpr bool reload_cheap = false;
      WHEELRAIL_ALWAYS_INLINE const float *
      geometry() const
      {
        return reinterpret_cast<const float *>(data) + lane;
      }
      WHEELRAIL_ALWAYS_INLINE V
      b(const unsigned int a, const unsigned int j) const
      {
        return load_widened<V>(geometry() + (Field::b + a * 3 + j) * W);
      }
      WHEELRAIL_ALWAYS_INLINE V
      c(const unsigned int alpha, const unsigned int j) const
      {
        return load_widened<V>(geometry() + (Field::c + alpha * 3 + j) * W);
      }
      WHEELRAIL_ALWAYS_INLINE V
      volume() const
      {
        return load<V>(data + SingleField::volume + lane);
      }
      WHEELRAIL_ALWAYS_INLINE V
      kappa() const
      {
        return load<V>(data + SingleField::kappa + lane);
      }
      WHEELRAIL_ALWAYS_INLINE V
      beta() const
      {
        return load<V>(data + SingleField::beta + lane);
      }
    };

    /**
     * Between the phases of the force kernel: the element data and nodal
     * values that a phase reads again are loaded again, not kept from the
     * phase before. With 16 vector registers (AVX2, SSE2) the compiler would
     * otherwise keep every loaded b_a, c_alpha and u_a for its second use and
     * move most of them to the stack and back (a store and a load where one
     * load does). It orders no arithmetic: the results are the same bits.
     * Nothing is done with 32 registers (AVX-512), nor where a second read
     * costs a conversion (@p Data with single-precision geometry).
     */
    template <typename Data>
    WHEELRAIL_ALWAYS_INLINE void
    reload_barrier()
    {
      if constexpr (!WHEELRAIL_EIGHT_LANE_REGISTERS && Data::reload_cheap)
        asm volatile("" ::: "memory");
    }

  } // namespace ElementKernel
} // namespace WheelRail

#endif
