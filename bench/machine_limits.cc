// The two limits of this machine that bound the explicit step, measured the
// way the element loop would see them:
//   - the floating-point peak: independent chains of 8-lane fused
//     multiply-adds (the kernel's vector type), per core and on all cores;
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
  typedef double v8d __attribute__((vector_size(64)));

  double
  seconds_since(const std::chrono::steady_clock::time_point &start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  // n_iter times 24 independent FMA chains of 8 lanes: 2 * 8 * 24 flops each
  constexpr unsigned int n_chains = 24;

  double
  fma_chains(const long n_iter, const double seed)
  {
    v8d acc[n_chains];
    for (unsigned int c = 0; c < n_chains; ++c)
      for (unsigned int l = 0; l < 8; ++l)
        acc[c][l] = seed + 1e-3 * (c * 8 + l);
    const v8d a = {0.999999, 0.999998, 0.999997, 0.999996, 0.999995, 0.999994, 0.999993, 0.999992};
    const v8d b = {1e-7, 2e-7, 3e-7, 4e-7, 5e-7, 6e-7, 7e-7, 8e-7};
    // the chains as separate registers: with an array GCC interchanges the
    // loops and runs one dependent chain at a time (latency, not throughput)
    v8d r0 = acc[0], r1 = acc[1], r2 = acc[2], r3 = acc[3], r4 = acc[4], r5 = acc[5], r6 = acc[6],
        r7 = acc[7], r8 = acc[8], r9 = acc[9], r10 = acc[10], r11 = acc[11], r12 = acc[12],
        r13 = acc[13], r14 = acc[14], r15 = acc[15], r16 = acc[16], r17 = acc[17], r18 = acc[18],
        r19 = acc[19], r20 = acc[20], r21 = acc[21], r22 = acc[22], r23 = acc[23];
#define WHEELRAIL_FMA(r) r = r * a + b; // one FMA with -ffp-contract=fast
    for (long i = 0; i < n_iter; ++i)
      {
        // clang-format off
        WHEELRAIL_FMA(r0) WHEELRAIL_FMA(r1) WHEELRAIL_FMA(r2) WHEELRAIL_FMA(r3) WHEELRAIL_FMA(r4) WHEELRAIL_FMA(r5)
        WHEELRAIL_FMA(r6) WHEELRAIL_FMA(r7) WHEELRAIL_FMA(r8) WHEELRAIL_FMA(r9) WHEELRAIL_FMA(r10) WHEELRAIL_FMA(r11)
        WHEELRAIL_FMA(r12) WHEELRAIL_FMA(r13) WHEELRAIL_FMA(r14) WHEELRAIL_FMA(r15) WHEELRAIL_FMA(r16) WHEELRAIL_FMA(r17)
        WHEELRAIL_FMA(r18) WHEELRAIL_FMA(r19) WHEELRAIL_FMA(r20) WHEELRAIL_FMA(r21) WHEELRAIL_FMA(r22) WHEELRAIL_FMA(r23)
        // clang-format on
      }
#undef WHEELRAIL_FMA
    const v8d out[n_chains] = {r0,  r1,  r2,  r3,  r4,  r5,  r6,  r7,  r8,  r9,  r10, r11,
                               r12, r13, r14, r15, r16, r17, r18, r19, r20, r21, r22, r23};
    double    sum           = 0;
    for (unsigned int c = 0; c < n_chains; ++c)
      for (unsigned int l = 0; l < 8; ++l)
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
        best           = std::max(best, 2. * 8 * n_chains * double(n_iter) * n_threads / s * 1e-9);
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
              "  floating point, 8-lane FMA chains : %.1f GFLOP/s on 1 core, %.1f on %u\n"
              "  memory bandwidth, STREAM triad   : %.1f GB/s on 1 core, %.1f on %u\n"
              "  (checksum %.6g)\n",
              f1,
              fn,
              n_all,
              b1,
              bn,
              n_all,
              checksum);
  return 0;
}
