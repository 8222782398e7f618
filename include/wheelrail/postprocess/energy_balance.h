/**
 * @file postprocess/energy_balance.h
 * The energy balance of the run (SPEC 7): the energies at the first
 * statistics step, the largest balance error so far, and the time
 * integrals of the internal and hourglass energies for the hourglass
 * check.
 */
#ifndef wheelrail_postprocess_energy_balance_h
#define wheelrail_postprocess_energy_balance_h

#include <wheelrail/postprocess/postprocessor.h>

namespace WheelRail
{
  /** At each statistics step: balance = total - initial total, relative to
   *  the largest energy scale of the step. */
  class EnergyBalance : public SerializedPostprocessor<EnergyBalance>
  {
  public:
    void
    execute(const StepInfo &step) override;

    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar.pod(initial_energies);
      ar.pod(have_initial_energies);
      ar.pod(max_error);
      ar.pod(hourglass_time_integral);
      ar.pod(hourglass_reference_time_integral);
      ar.pod(internal_time_integral);
      // a slot of the checkpoint format that no code sets (always 0): kept
      // so that the checkpoint's bytes stay those of the format
      ar.pod(unused_slot);
    }

    /** Largest |balance| / scale over the statistics steps so far. */
    double
    max_balance_error() const
    {
      return max_error;
    }
    /** Balance of the last statistics step [J] and its relative error. */
    double
    balance() const
    {
      return last_balance;
    }
    double
    balance_error() const
    {
      return last_error;
    }
    /** Sums over the statistics steps of E_int, E_hg and of the
     *  hourglass-mode energy at QM = 0.1 (their ratios are time means). */
    double
    internal_integral() const
    {
      return internal_time_integral;
    }
    double
    hourglass_integral() const
    {
      return hourglass_time_integral;
    }
    double
    hourglass_reference_integral() const
    {
      return hourglass_reference_time_integral;
    }

  private:
    Energies initial_energies;
    bool     have_initial_energies             = false;
    double   max_error                         = 0;
    double   hourglass_time_integral           = 0;
    double   hourglass_reference_time_integral = 0;
    double   internal_time_integral            = 0;
    double   unused_slot                       = 0;
    double   last_balance                      = 0;
    double   last_error                        = 0;
  };
} // namespace WheelRail

#endif
