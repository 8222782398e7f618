/**
 * @file verification/hertz_patch.h
 * A contact patch of the wheel on the rail against Hertz's solution
 * (SPEC 8): semi-axes and peak pressure of an ellipse fitted to the nodal
 * pressures, for the static solve and for the rolling snapshots.
 */
#ifndef wheelrail_verification_hertz_patch_h
#define wheelrail_verification_hertz_patch_h

#include <wheelrail/postprocess/postprocessor.h>
#include <wheelrail/verification/hertz.h>

#include <vector>

namespace WheelRail
{
  namespace Verification
  {
    /** Contact modulus E* = E / (2 (1 - nu^2)) of two bodies of @p material [Pa]. */
    double
    effective_modulus(const MaterialParameters &material);

    /** Hertz's solution for the wheel on the rail head under the normal
     *  force @p normal_force [N]: curvatures 1/(2 R_w) along the rail and
     *  1/(2 R_rail) across it, the parameters' material; a is the
     *  semi-axis along the rail (x), b across it (y), whichever is longer. */
    HertzSolution
    wheel_rail_hertz(const Parameters &parameters, const double normal_force);

    /** A node of a contact patch: reference position, pressure [Pa], normal force [N]. */
    struct PatchNode
    {
      double x, y, pressure, force;
    };

    /** The Hertzian ellipse p^2 = p0^2 (1 - (x - xc)^2/a^2 - y^2/b^2) fitted
     *  by least squares to the nodes with p > 25 % of the largest (the edge
     *  nodes' tributary areas reach beyond the patch); xc is the
     *  force-weighted centre. */
    struct EllipseFit
    {
      double       p0 = 0, a = 0, b = 0, xc = 0;
      double       force = 0, p_max = 0; ///< sum of the nodal forces [N], largest pressure [Pa]
      unsigned int n_contact = 0;        ///< nodes with p > 0
      unsigned int n_fitted  = 0;        ///< nodes with p >= 25 % of the largest
      /** Whether the fit is an ellipse (p0^2 > 0 and p^2 falling off in x
       *  and in y); a patch of a few nodes, or one in the first steps of
       *  an impact, need not give one, and then a, b, p0 are 0. */
      bool elliptic = false;
    };
    EllipseFit
    fit_hertz_ellipse(const std::vector<PatchNode> &nodes);

    /** Print the fit's a, b, p0 against Hertz's for the normal force
     *  @p normal_force [N] (the parameters' radii and material), each with
     *  its relative error and the verdict: for @p tolerance, or, where the
     *  smallest cell size @p h [m] is given, for what the convergence study
     *  expects at that h (expected_errors.h). Returns whether all three are
     *  within their limits. */
    bool
    report_hertz_fit(const SimulatorAccess &access,
                     const EllipseFit      &fit,
                     const double           normal_force,
                     const double           tolerance,
                     const double           h = 0);

    /** Print the comparison for the normal force @p contact_force [N] of
     *  the static solve. */
    void
    compare_patch_with_hertz(const SimulatorAccess &access, const double contact_force);
  } // namespace Verification
} // namespace WheelRail

#endif
