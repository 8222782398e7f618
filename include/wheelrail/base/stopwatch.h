/**
 * @file stopwatch.h
 * The laps of the per-part step timings (elements, contact, update, ...):
 * a steady clock read between the parts of a step.
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
} // namespace WheelRail

#endif
