#include <wheelrail/postprocess/energy_balance.h>

#include <algorithm>
#include <cmath>

namespace WheelRail
{
  void
  EnergyBalance::execute(const StepInfo &step)
  {
    if (step.energies == nullptr)
      return;
    const Energies &e = *step.energies;
    if (!have_initial_energies)
      {
        initial_energies      = e;
        have_initial_energies = true;
      }
    const double scale = std::max({std::abs(initial_energies.total()),
                                   e.kinetic + e.internal + e.hourglass + e.damping,
                                   std::abs(e.external_work),
                                   1e-300});
    last_balance       = e.total() - initial_energies.total();
    last_error         = std::abs(last_balance) / scale;
    max_error          = std::max(max_error, std::abs(last_balance) / scale);
    internal_time_integral += e.internal;
    hourglass_time_integral += e.hourglass;
    hourglass_reference_time_integral += e.hourglass_reference;
  }
} // namespace WheelRail
