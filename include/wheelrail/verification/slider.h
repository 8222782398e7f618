/**
 * @file verification/slider.h
 * The 1D slider: a block of mass m held by a spring K and a dashpot C to a
 * fixed support, pressed with F_n onto a plate that moves at speed V, the
 * contact through a tangential penalty spring k_t and the friction step of
 * the FE contact (FrictionModel). Integrated by central differences like
 * the FE program; its steady sliding and the linear stability of that state
 * are known in closed form, so the growth or decay of a perturbation the
 * explicit run shows can be checked against theory for each slip-rate and
 * friction option (doc/notes/friction_regularisation.md).
 */
#ifndef wheelrail_verification_slider_h
#define wheelrail_verification_slider_h

#include <wheelrail/contact/friction_model.h>

#include <complex>
#include <vector>

namespace WheelRail
{
  namespace Slider
  {
    struct Parameters
    {
      double mass                 = 1;    ///< m [kg]
      double stiffness            = 1e6;  ///< K [N/m]
      double damping              = 0;    ///< C [N s/m]
      double normal_force         = 1000; ///< F_n [N]
      double speed                = 0.1;  ///< V of the plate [m/s]
      double tangential_stiffness = 1e9;  ///< k_t [N/m]
      double time_step            = 1e-6; ///< dt [s]
    };

    /** What a run of the slider shows. */
    struct Run
    {
      double x_steady     = 0;     ///< steady sliding position f(V) F_n / K [m]
      double rate         = 0;     ///< growth rate of the perturbation fitted to the run [1/s]
      double end_time     = 0;     ///< time run [s]
      double largest_slip = 0;     ///< largest slip rate the law saw [m/s]
      bool   stuck        = false; ///< the contact stuck at some step
    };

    /**
     * The linearised equations of the perturbation of steady sliding
     * (or of rest when V = 0, the contact sticking): the roots of their
     * characteristic polynomial, largest real part first. With
     * D = -F_n f'(V):
     * - stick (V = 0): m l^2 + (C + c_t) l + K + k_t = 0;
     * - slip rate total, no relaxation: m l^2 + (C - D) l + K = 0;
     * - with relaxation rate r = V / L + 1 / tau:
     *   (m l^2 + C l + K)(l + r) - D r l = 0;
     * - irreversible slip rate, no relaxation (the spring's elastic rate
     *   taken out of s): (m l^2 + C l + K)(1 - b l) - D l = 0, b = D / k_t.
     */
    std::vector<std::complex<double>>
    characteristic_roots(const FrictionModel &model, const Parameters &p);

    /**
     * Runs the slider from its steady state displaced by @p perturbation
     * [m] (the tangential spring stretched by it at rest) until @p end_time
     * or until the block's speed, 0 in the steady state, exceeds
     * @p velocity_limit [m/s] (the end of the linear regime), and fits the
     * growth rate to the maxima of |v| over windows of @p window [s] in the
     * later 60 % of the run.
     */
    Run
    run(const FrictionModel &model,
        const Parameters    &p,
        const double         perturbation,
        const double         end_time,
        const double         window,
        const double         velocity_limit);
  } // namespace Slider
} // namespace WheelRail

#endif
