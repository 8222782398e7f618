#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>

#include <wheelrail/simulator/format.h>
#include <wheelrail/verification/checks.h>
#include <wheelrail/verification/verdict.h>

#include <cmath>

namespace WheelRail
{
  namespace Verification
  {
    using Report::fmt;

    namespace
    {
      /**
       * Mean period from the zero crossings of the signal s(t) (linear
       * interpolation between samples); 0 if fewer than three crossings.
       */
      double
      mean_period(const std::vector<double> &t, const std::vector<double> &s)
      {
        std::vector<double> crossings;
        for (unsigned int i = 1; i < s.size(); ++i)
          if ((s[i - 1] < 0 && s[i] >= 0) || (s[i - 1] > 0 && s[i] <= 0))
            crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * s[i - 1] / (s[i - 1] - s[i]));
        if (crossings.size() < 3)
          return 0;
        return 2. * (crossings.back() - crossings.front()) / (crossings.size() - 1);
      }
    } // namespace



    void
    CheckInput::result(const std::string &what,
                       const double       measured,
                       const double       reference,
                       const std::string &unit,
                       const double       scale) const
    {
      const double       tol    = access.parameters.verification.tolerance;
      const double       error  = std::abs(measured - reference) / std::abs(reference);
      const unsigned int digits = access.robust_output_only() ? 2 : 6;
      access.pcout << "Check: " << what << std::endl
                   << "  measured  : " << fmt(measured * scale, digits) << " " << unit << std::endl
                   << "  reference : " << fmt(reference * scale, digits) << " " << unit
                   << std::endl;
      if (!access.robust_output_only())
        access.pcout << "  relative error " << fmt(error, 2) << ", ";
      else
        access.pcout << "  ";
      access.pcout << "tolerance " << fmt(tol)
                   << ", within tolerance: " << Verification::verdict(error <= tol) << std::endl;
    }



    void
    CheckInput::bound(const std::string &what, const double value, const double limit) const
    {
      access.pcout << "  " << what;
      if (!access.robust_output_only())
        access.pcout << " " << fmt(value, 2);
      access.pcout << " (limit " << fmt(limit)
                   << "), within: " << Verification::verdict(std::abs(value) <= limit) << std::endl;
    }



    void
    CheckInput::report(const std::string &what, const double value, const std::string &unit) const
    {
      if (!access.robust_output_only())
        access.pcout << "  " << what << " " << fmt(value, 2) << " " << unit << " (reported)"
                     << std::endl;
    }



    const std::map<std::string, Check> &
    checks()
    {
      static const std::map<std::string, Check> table = {{"wave arrival", wave_arrival},
                                                         {"longitudinal frequency",
                                                          longitudinal_frequency},
                                                         {"bending frequency", bending_frequency},
                                                         {"energy balance", energy_balance},
                                                         {"inclined plane", inclined_plane},
                                                         {"tangential sliding", tangential_sliding},
                                                         {"impact", impact},
                                                         {"free rolling", free_rolling},
                                                         {"static start", static_start},
                                                         {"traction", traction},
                                                         {"creep forces", creep_forces}};
      return table;
    }



    void
    run_final_check(const SimulatorAccess &access,
                    const Probes          &probes,
                    const EnergyBalance   &balance,
                    const SampleRecorder  &samples)
    {
      const std::string &name = access.parameters.verification.check;
      if (name == "none")
        return;

      // the probe history lives on its owner: bring it to every rank
      const Probe        &probe = probes.nodes()[0];
      std::vector<double> history =
        Utilities::MPI::broadcast(access.mpi_communicator, probe.history, probe.owner);
      const unsigned int comp = access.parameters.output.probe_component;
      CheckInput         in{access, balance, samples, {}, {}, {}, probe.location};
      for (unsigned int i = 0; i < history.size(); i += 7)
        {
          in.t.push_back(history[i]);
          in.u.push_back(history[i + 1 + comp]);
          in.v.push_back(history[i + 4 + comp]);
        }
      const auto check = checks().find(name);
      if (check != checks().end())
        check->second(in);
    }



    void
    wave_arrival(const CheckInput &in)
    {
      const VerificationParameters &vp   = in.access.parameters.verification;
      const double                  c0   = in.access.parameters.material.bar_wave_speed();
      const unsigned int            comp = in.access.parameters.output.probe_component;
      const std::vector<double>    &t = in.t, &v = in.v;
      const auto                    vfun =
        make_vector_function(in.access.parameters.boundary.prescribed_velocity_expression,
                             in.access.parameters.boundary.prescribed_velocity_constants,
                             "x,y,z,t",
                             "Boundary conditions/Prescribed velocity");
      vfun->set_time(in.access.parameters.solver.end_time);
      const double v0        = vfun->value(Point<dim>(), comp);
      const double threshold = vp.wave_threshold * 2. * v0; // free far end doubles
      double       arrival   = 0;
      for (unsigned int i = 1; i < v.size(); ++i)
        if (v[i] / threshold >= 1.)
          {
            arrival = t[i - 1] + (t[i] - t[i - 1]) * (threshold - v[i - 1]) / (v[i] - v[i - 1]);
            break;
          }
      in.result("arrival of the front at the probe (bar wave speed sqrt(E/rho))",
                arrival,
                in.probe_location[0] / c0,
                "us",
                1e6);
    }



    void
    longitudinal_frequency(const CheckInput &in)
    {
      const VerificationParameters &vp = in.access.parameters.verification;
      const GeometryParameters     &g  = in.access.parameters.geometry;
      const double                  c0 = in.access.parameters.material.bar_wave_speed();
      const std::vector<double>    &t = in.t, &u = in.u;
      in.result(std::string("first longitudinal frequency, ") +
                  (vp.bar_clamped ? "clamped-free" : "free-free") + " bar",
                1. / mean_period(t, u),
                c0 / ((vp.bar_clamped ? 4. : 2.) * g.bar_length),
                "Hz",
                1.);
    }



    void
    bending_frequency(const CheckInput &in)
    {
      const VerificationParameters &vp = in.access.parameters.verification;
      const GeometryParameters     &g  = in.access.parameters.geometry;
      const std::vector<double>    &t = in.t, &u = in.u;
      const double                  beta_L = 1.8751040687;
      const double f_ref = beta_L * beta_L / (2 * M_PI * g.bar_length * g.bar_length) *
                           std::sqrt(in.access.parameters.material.youngs_modulus * g.bar_height *
                                     g.bar_height / (12. * in.access.parameters.material.density));
      in.result("first bending frequency of the cantilever (Euler-Bernoulli)",
                1. / mean_period(t, u),
                f_ref,
                "Hz",
                1.);
      const double ratio_ref =
        in.balance.hourglass_reference_integral() / in.balance.internal_integral();
      const double ratio = in.balance.hourglass_integral() / in.balance.internal_integral();
      in.access.pcout << "Check: hourglass modes" << std::endl
                      << "  hourglass energy / internal energy (time mean)          : "
                      << fmt(ratio, 3) << std::endl
                      << "  hourglass-mode energy at QM = 0.1 / internal energy     : "
                      << fmt(ratio_ref, 3) << std::endl
                      << "  limit " << fmt(vp.hourglass_limit) << ", within limit: "
                      << Verification::verdict(ratio_ref <= vp.hourglass_limit) << std::endl;
    }



    void
    energy_balance(const CheckInput &in)
    {
      const double tol = in.access.parameters.verification.tolerance;
      in.access.pcout << "Check: energy balance over " << in.access.solver.step_number() << " steps"
                      << std::endl
                      << "  largest |balance| / energy scale : "
                      << fmt(in.balance.max_balance_error(), 2) << std::endl
                      << "  tolerance " << fmt(tol) << ", within tolerance: "
                      << Verification::verdict(in.balance.max_balance_error() <= tol) << std::endl;
    }
  } // namespace Verification
} // namespace WheelRail
