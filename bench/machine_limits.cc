// The two limits of this machine that bound the explicit step, measured the
// way the element loop would see them:
//   - the floating-point peak: independent chains of fused multiply-adds on
//     the widest vector the registers hold (8 lanes with AVX-512, 4 with
//     AVX2, 2 with SSE2, as the element kernel), per core and on all cores;
//   - the memory bandwidth: the STREAM triad a[i] = b[i] + s c[i] over arrays
//     far larger than the caches (24 bytes counted per element, as STREAM
//     does), per core and on all cores.
// Each figure is the best of several repetitions. Run by './run.sh bench';
// no deal.II, so that it builds and runs in seconds.
//
// usage: machine_limits [threads]   (default: all hardware threads)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <thread>
#include <vector>

namespace
{
  // the chains' vector and their number: as many as the 16 (32 with
  // AVX-512) registers hold next to a and b; a wider vector than the
  // registers would be split by the compiler and its chains kept in memory
#if defined(__AVX512F__)
  typedef double         vec __attribute__((vector_size(64)));
  constexpr unsigned int n_chains = 24;
#elif defined(__AVX__)
  typedef double         vec __attribute__((vector_size(32)));
  constexpr unsigned int n_chains = 12;
#else
  typedef double         vec __attribute__((vector_size(16)));
  constexpr unsigned int n_chains = 12;
#endif
  constexpr unsigned int lanes = sizeof(vec) / sizeof(double);

  double
  seconds_since(const std::chrono::steady_clock::time_point &start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // n_iter times 24 independent FMA chains (the first n_chains of them
  // run): 2 * lanes * n_chains flops each

  double
  fma_chains(const long n_iter, const double seed)
  {
    vec acc[24], a, b;
    for (unsigned int c = 0; c < 24; ++c)
      for (unsigned int l = 0; l < lanes; ++l)
        acc[c][l] = seed + 1e-3 * (c * 8 + l);
    for (unsigned int l = 0; l < lanes; ++l)
      {
        a[l] = 0.999999 - 1e-6 * l;
        b[l] = 1e-7 * (l + 1);
      }
    // the chains as separate registers: with an array GCC interchanges the
    // loops and runs one dependent chain at a time (latency, not throughput)
    vec r0 = acc[0], r1 = acc[1], r2 = acc[2], r3 = acc[3], r4 = acc[4], r5 = acc[5], r6 = acc[6],
        r7 = acc[7], r8 = acc[8], r9 = acc[9], r10 = acc[10], r11 = acc[11], r12 = acc[12],
        r13 = acc[13], r14 = acc[14], r15 = acc[15], r16 = acc[16], r17 = acc[17], r18 = acc[18],
        r19 = acc[19], r20 = acc[20], r21 = acc[21], r22 = acc[22], r23 = acc[23];
    // one FMA with -ffp-contract=fast, on the first n_chains chains
#define WHEELRAIL_FMA(k)      \
  if constexpr (k < n_chains) \
    r##k = r##k * a + b;
    for (long i = 0; i < n_iter; ++i)
      {
        // clang-format off
        WHEELRAIL_FMA(0) WHEELRAIL_FMA(1) WHEELRAIL_FMA(2) WHEELRAIL_FMA(3) WHEELRAIL_FMA(4) WHEELRAIL_FMA(5)
        WHEELRAIL_FMA(6) WHEELRAIL_FMA(7) WHEELRAIL_FMA(8) WHEELRAIL_FMA(9) WHEELRAIL_FMA(10) WHEELRAIL_FMA(11)
        WHEELRAIL_FMA(12) WHEELRAIL_FMA(13) WHEELRAIL_FMA(14) WHEELRAIL_FMA(15) WHEELRAIL_FMA(16) WHEELRAIL_FMA(17)
        WHEELRAIL_FMA(18) WHEELRAIL_FMA(19) WHEELRAIL_FMA(20) WHEELRAIL_FMA(21) WHEELRAIL_FMA(22) WHEELRAIL_FMA(23)
        // clang-format on
      }
#undef WHEELRAIL_FMA
    const vec out[24] = {r0,  r1,  r2,  r3,  r4,  r5,  r6,  r7,  r8,  r9,  r10, r11,
                         r12, r13, r14, r15, r16, r17, r18, r19, r20, r21, r22, r23};
    double    sum     = 0;
    for (unsigned int c = 0; c < n_chains; ++c)
      for (unsigned int l = 0; l < lanes; ++l)
        sum += out[c][l];
    return sum;
  }

  // GFLOP/s of n_threads threads running the FMA chains at once
  double
  flop_rate(const unsigned int n_threads, double &checksum)
  {
    const long          n_iter = 20'000'000;
    double              best   = 0;
    std::vector<double> sums(n_threads);
    for (unsigned int rep = 0; rep < 5; ++rep)
      {
        const auto               start = std::chrono::steady_clock::now();
        std::vector<std::thread> threads;
        for (unsigned int t = 0; t < n_threads; ++t)
          threads.emplace_back([&, t] { sums[t] = fma_chains(n_iter, 1. + t); });
        for (auto &th : threads)
          th.join();
        const double s = seconds_since(start);
        best = std::max(best, 2. * lanes * n_chains * double(n_iter) * n_threads / s * 1e-9);
        for (const double x : sums)
          checksum += x;
      }
    return best;
  }

  // GB/s of the triad on n_threads threads, each on its own part of the
  // arrays (first touched by the thread that uses it)
  double
  bandwidth(const unsigned int n_threads, double &checksum)
  {
    const std::size_t         n = std::size_t(1) << 25; // 3 x 256 MB
    std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
    const auto                part = [&](const unsigned int t) {
      return std::make_pair(n * t / n_threads, n * (t + 1) / n_threads);
    };
    const auto run = [&](const auto &work) {
      std::vector<std::thread> threads;
      for (unsigned int t = 0; t < n_threads; ++t)
        threads.emplace_back(work, t);
      for (auto &th : threads)
        th.join();
    };
    run([&](const unsigned int t) {
      for (std::size_t i = part(t).first; i < part(t).second; ++i)
        {
          a[i] = 0;
          b[i] = 1. + 1e-9 * i;
          c[i] = 2.;
        }
    });
    double best = 0;
    for (unsigned int rep = 0; rep < 6; ++rep)
      {
        const double s     = 1e-3 * rep;
        const auto   start = std::chrono::steady_clock::now();
        run([&](const unsigned int t) {
          double *__restrict pa       = a.get();
          const double *__restrict pb = b.get();
          const double *__restrict pc = c.get();
          for (std::size_t i = part(t).first; i < part(t).second; ++i)
            pa[i] = pb[i] + s * pc[i];
        });
        best = std::max(best, 24. * n / seconds_since(start) * 1e-9);
        checksum += a[n / 2];
      }
    return best;
  }
} // namespace

int
main(int argc, char **argv)
{
  const unsigned int n_all =
    argc > 1 ? std::max(1, std::atoi(argv[1])) : std::max(1u, std::thread::hardware_concurrency());
  double       checksum = 0;
  const double f1       = flop_rate(1, checksum);
  const double fn       = flop_rate(n_all, checksum);
  const double b1       = bandwidth(1, checksum);
  const double bn       = bandwidth(n_all, checksum);
  std::printf("Machine limits (bench/machine_limits, best of 5-6 repetitions):\n"
              "  floating point, %u-lane FMA chains : %.1f GFLOP/s on 1 core, %.1f on %u\n"
              "  memory bandwidth, STREAM triad   : %.1f GB/s on 1 core, %.1f on %u\n"
              "  (checksum %.6g)\n",
              lanes,
              f1,
              fn,
              n_all,
              b1,
              bn,
              n_all,
              checksum);
  return 0;
}
