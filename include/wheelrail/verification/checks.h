/**
 * @file verification/checks.h
 * The analytic comparisons at the end of an explicit run
 * (Verification/Check, SPEC 8): one function per check, chosen by name.
 */
#ifndef wheelrail_verification_checks_h
#define wheelrail_verification_checks_h

#include <wheelrail/postprocess/energy_balance.h>
#include <wheelrail/postprocess/probes.h>
#include <wheelrail/verification/samples.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace WheelRail
{
  namespace Verification
  {
    /** What the checks evaluate. */
    struct CheckInput
    {
      const SimulatorAccess &access;
      const EnergyBalance   &balance;
      const SampleRecorder  &samples;
      /** The probe's time series, on every rank: t, and the displacement
       *  and velocity component Output/Probe component. */
      std::vector<double> t, u, v;
      /** Reference position of the probe node. */
      Point<dim> probe_location;

      /** Print one comparison: measured against reference (both times
       *  @p scale, in @p unit) and whether it is within the tolerance. */
      void
      result(const std::string &what,
             const double       measured,
             const double       reference,
             const std::string &unit,
             const double       scale) const;

      /** Print one bound: "  WHAT VALUE (limit LIMIT), within: yes" when
       *  |value| <= limit. A round-off sensitive run's test output leaves the
       *  value out and keeps the verdict. */
      void
      bound(const std::string &what, const double value, const double limit) const;

      /** Print a value that is only reported, not checked ("  WHAT VALUE UNIT
       *  (reported)"); left out of a round-off sensitive run's test output. */
      void
      report(const std::string &what, const double value, const std::string &unit) const;
    };

    using Check = std::function<void(const CheckInput &)>;

    /** The checks by their Verification/Check name ('none' has none). */
    const std::map<std::string, Check> &
    checks();

    /** Run the check Verification/Check names, if any (all ranks). */
    void
    run_final_check(const SimulatorAccess &access,
                    const Probes          &probes,
                    const EnergyBalance   &balance,
                    const SampleRecorder  &samples);

    /** The checks, one function each (the bar and energy checks in
     *  checks.cc, the contact checks in checks_contact.cc). */
    void
    wave_arrival(const CheckInput &in);
    void
    longitudinal_frequency(const CheckInput &in);
    void
    bending_frequency(const CheckInput &in);
    void
    energy_balance(const CheckInput &in);
    void
    inclined_plane(const CheckInput &in);
    void
    tangential_sliding(const CheckInput &in);
    void
    impact(const CheckInput &in);
    void
    free_rolling(const CheckInput &in);
    void
    static_start(const CheckInput &in);
    void
    traction(const CheckInput &in);
    /** Creep forces against Kalker's linear theory (check_creep_forces.cc). */
    void
    creep_forces(const CheckInput &in);
  } // namespace Verification
} // namespace WheelRail

#endif
