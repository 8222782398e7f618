/**
 * @file verification/check_creep_forces.cc
 * The check 'creep forces': the rolling wheel's creep forces at small held
 * creepages against Kalker's linear theory (SPEC 8 and 10).
 */

#include <wheelrail/simulator/format.h>
#include <wheelrail/solver/wheelset_creepages.h>
#include <wheelrail/verification/checks.h>
#include <wheelrail/verification/hertz_patch.h>
#include <wheelrail/verification/verdict.h>

#include <cmath>

namespace WheelRail
{
  namespace Verification
  {
    using Report::fmt;

    namespace
    {
      /** Kalker's C11 and C22 for b/a = 0.752, nu = 0.3 (the paper's pair),
       *  CONTACT's interpolation of Kalker's Table E.3 (a parabola in 1/C
       *  through nu = 0, 0.25, 0.5; doc/manual/halfspace.md). */
      constexpr double c11 = 4.623, c22 = 4.175, b_over_a = 0.752, nu = 0.3;

      /** One creep force against the linear theory: F / F_N measured
       *  (@p measured) and -G c^2 C creepage / F_N (@p reference). */
      void
      compare(const CheckInput  &in,
              const std::string &what,
              const double       measured,
              const double       reference)
      {
        in.result(what, measured, reference, "", 1.);
        in.access.pcout << "  sign of the linear theory's: "
                        << Verification::verdict(measured * reference > 0) << std::endl;
        in.report("measured / linear theory", measured / reference, "");
      }
    } // namespace



    void
    creep_forces(const CheckInput &in)
    {
      const Parameters          &prm     = in.access.parameters;
      const std::vector<Sample> &samples = in.samples.samples();
      const double               eta     = prm.wheelset.axle_lateral_creepage();
      const bool                 held = prm.wheelset.creepage_control_time >= prm.solver.end_time &&
                        prm.wheelset.initial_creepage != 0;
      AssertThrow(in.access.wheelset && samples.size() > 4 && (held || eta != 0),
                  ExcMessage("Verification/Check = creep forces needs Boundary conditions/Wheel "
                             "bore = rigid axle, at least five statistics rows, and Wheelset/"
                             "Lateral creepage, Yaw angle or an Initial creepage held for the "
                             "whole run (Creepage control time >= End time)."));
      // means over the second half, after the start transient
      const unsigned int first = samples.size() / 2;
      Tensor<1, dim>     f;
      for (unsigned int i = first; i < samples.size(); ++i)
        f += samples[i].contact_force / double(samples.size() - first);
      const HertzSolution h = wheel_rail_hertz(prm, f[2]);
      AssertThrow(std::abs(h.b / h.a - b_over_a) < 0.01 &&
                    std::abs(prm.material.poisson_ratio - nu) < 1e-3,
                  ExcMessage("Verification/Check = creep forces holds Kalker's coefficients for "
                             "b/a = 0.752 and nu = 0.3 (the paper's pair) only; this run's Hertz "
                             "patch has b/a = " +
                             fmt(h.b / h.a, 4) + ", Poisson's ratio " +
                             fmt(prm.material.poisson_ratio) + "."));
      // G c^2 with c^2 = a b at the run's mean F_N
      const double Gc2 = prm.material.mu() * h.a * h.b;
      const double xi  = in.access.wheelset->creepage();
      // the kinematic eta at the end: eta - psi (v_y constant, v_x nearly)
      const double eta_end = kinematic_creepages(*in.access.wheelset, 0.).lateral;
      // a and b to two digits where round-off changes the run's last ones
      const unsigned int digits = in.access.robust_output_only() ? 2 : 4;
      in.access.pcout << "Check: creep forces against Kalker's linear theory, means over the "
                      << "second half" << std::endl
                      << "  Hertz at the mean F_N " << fmt(f[2] * 1e-3, digits) << " kN: a "
                      << fmt(h.a * 1e3, digits) << " mm, b " << fmt(h.b * 1e3, digits)
                      << " mm, G c^2 = " << fmt(Gc2, digits) << " N; C11 " << fmt(c11, 4)
                      << ", C22 " << fmt(c22, 4) << std::endl;
      if (held)
        compare(in,
                "F_L / F_N against -G c^2 C11 xi / F_N, xi = " + fmt(xi, 3),
                f[0] / f[2],
                -Gc2 * c11 * xi / f[2]);
      if (eta != 0)
        compare(in,
                "F_lateral / F_N against -G c^2 C22 eta / F_N, eta = " + fmt(eta_end, 3),
                f[1] / f[2],
                -Gc2 * c22 * eta_end / f[2]);
    }
  } // namespace Verification
} // namespace WheelRail
