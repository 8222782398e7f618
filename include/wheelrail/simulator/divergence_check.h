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
#include <ostream>
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
    /** Where the first non-finite value, or the fastest node, is (the
     *  rank that has it tells all ranks). */
    std::string
    worst_node() const;
    /** The largest extent of the bodies along an axis (all ranks) [m]. */
    double
    body_extent() const;
    /** The likely cause of a divergence at step @p n into @p message: the
     *  causes in the order in which one hides the next. */
    void
    likely_cause(const unsigned long n, std::ostream &message) const;

    const SimulatorAccess      &access;
    const EnergyBalance        &balance;
    const std::function<void()> write_records;
    double                      velocity_spread     = 0; ///< [m/s]
    double                      deepest_penetration = 0; ///< in this run [m]
    unsigned int                most_contact_nodes  = 0; ///< largest contact node count so far
  };
} // namespace WheelRail

#endif
