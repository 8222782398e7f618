/**
 * @file simulator/format.h
 * Numbers in the screen reports and messages.
 */
#ifndef wheelrail_simulator_format_h
#define wheelrail_simulator_format_h

#include <iomanip>
#include <sstream>
#include <string>

namespace WheelRail
{
  namespace Report
  {
    /** @p x with @p digits significant digits (the stream's default
     *  notation). */
    inline std::string
    fmt(const double x, const unsigned int digits = 6)
    {
      std::ostringstream s;
      s << std::setprecision(digits) << x;
      return s.str();
    }
  } // namespace Report
} // namespace WheelRail

#endif
