/**
 * @file verification/hertz_patch.h
 * The static contact patch of the wheel on the rail against Hertz's
 * solution (SPEC 8): semi-axes and peak pressure of an ellipse fitted to
 * the nodal pressures.
 */
#ifndef wheelrail_verification_hertz_patch_h
#define wheelrail_verification_hertz_patch_h

#include <wheelrail/postprocess/postprocessor.h>

namespace WheelRail
{
  namespace Verification
  {
    /** Print the comparison for the normal force @p contact_force [N] of
     *  the static solve. */
    void
    compare_patch_with_hertz(const SimulatorAccess &access, const double contact_force);
  } // namespace Verification
} // namespace WheelRail

#endif
