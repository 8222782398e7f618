/**
 * @file simulator/divergence_check.h
 * Stops a run whose solution diverges, with a message that says where and
 * names the likely cause.
 */
#ifndef wheelrail_simulator_divergence_check_h
#define wheelrail_simulator_divergence_check_h

#include <wheelrail/postprocess/energy_balance.h>
#include <wheelrail/postprocess/postprocessor.h>

#include <functional>
#include <string>

namespace WheelRail
{
  /**
   * At each statistics step: non-finite energies or an energy balance
   * error beyond Output/Divergence limit stop the run (all ranks), after
   * write_records() has written the files that show the run up to here.
   * Executes after the recording postprocessors and before the energy
   * balance takes this step's energies.
   */
  class DivergenceCheck : public SerializedPostprocessor<DivergenceCheck>
  {
  public:
    DivergenceCheck(const SimulatorAccess       &access,
                    const EnergyBalance         &balance,
                    const std::function<void()> &write_records);

    /** The largest spread of a velocity component over the nodes at the
     *  start of the run (all ranks). */
    void
    record_initial_velocities();

    void
    execute(const StepInfo &step) override;

    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar.pod(most_contact_nodes);
    }

  private:
    /** Where and why the run diverged at step @p n (all ranks call it). */
    std::string
    explain(const unsigned long n, const Energies &e) const;

    const SimulatorAccess      &access;
    const EnergyBalance        &balance;
    const std::function<void()> write_records;
    double                      velocity_spread     = 0; ///< [m/s]
    double                      deepest_penetration = 0; ///< in this run [m]
    unsigned int                most_contact_nodes  = 0; ///< largest contact node count so far
  };
} // namespace WheelRail

#endif
