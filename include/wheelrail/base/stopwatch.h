/**
 * @file stopwatch.h
 * The per-part step timings (elements, contact, update, ...): a steady
 * clock read between the parts of a step (lap()), or around one part
 * (ScopedTime).
 */
#ifndef wheelrail_stopwatch_h
#define wheelrail_stopwatch_h

#include <chrono>

namespace WheelRail
{
  using Clock = std::chrono::steady_clock;

  /** Seconds since @p t0; sets @p t0 to now. */
  inline double
  lap(Clock::time_point &t0)
  {
    const Clock::time_point t1 = Clock::now();
    const double            s  = std::chrono::duration<double>(t1 - t0).count();
    t0                         = t1;
    return s;
  }

  /**
   * Adds the wall seconds of its own lifetime to a sum: a block of a step
   * opened with `const ScopedTime timer(times.update);` is timed as that
   * part, without clock calls between the lines of the physics.
   */
  class ScopedTime
  {
  public:
    explicit ScopedTime(double &sum)
      : sum(sum)
      , start(Clock::now())
    {}
    ~ScopedTime()
    {
      sum += std::chrono::duration<double>(Clock::now() - start).count();
    }
    ScopedTime(const ScopedTime &) = delete;
    ScopedTime &
    operator=(const ScopedTime &) = delete;

  private:
    double                 &sum;
    const Clock::time_point start;
  };
} // namespace WheelRail

#endif
