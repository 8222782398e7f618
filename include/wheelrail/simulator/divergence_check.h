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
    struct Measures;

    /** Where and why the run diverged at step @p n with energies @p e
     *  (all ranks call it): the step and time, the energy that failed,
     *  worst_node() and likely_cause(). */
    std::string
    explain(const unsigned long n, const Energies &e) const;
    /** Where the solution is worst: the first non-finite (or, if all are
     *  finite, the fastest) DoF over the ranks, with its position, body,
     *  component, displacement and velocity (all ranks call it; the rank
     *  that holds it broadcasts the text). */
    std::string
    worst_node() const;
    /** The bodies' longest side [m] over the support points of all ranks. */
    double
    extent() const;
    /** The measures likely_cause() judges by, for a divergence at step
     *  @p n (all ranks call it). */
    Measures
    measures(const unsigned long n) const;
    /** The likely cause of the divergence, the first of the initial
     *  velocity, gravity, the applied force, the prescribed velocity, a
     *  missed contact, the contact penalty and the time step whose
     *  measure in @p m (or in this check's records) is too large; else an
     *  unconstrained body. */
    std::string
    likely_cause(const Measures &m) const;

    const SimulatorAccess      &access;
    const EnergyBalance        &balance;
    const std::function<void()> write_records;
    double                      velocity_spread     = 0; ///< [m/s]
    double                      deepest_penetration = 0; ///< in this run [m]
    unsigned int                most_contact_nodes  = 0; ///< largest contact node count so far
  };
} // namespace WheelRail

#endif
