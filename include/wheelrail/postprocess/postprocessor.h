/**
 * @file postprocess/postprocessor.h
 * The interface of the postprocessors of an explicit run (statistics,
 * probes, contact patch, VTU output, the samples of the verification
 * checks) and what they may read of the run (SimulatorAccess).
 *
 * The time loop calls execute() of each postprocessor after every step,
 * in a fixed order; a postprocessor owns its state and lists the fields
 * of that state once, in a serialize(Archive &) that save() and load()
 * call for the two directions of the checkpoint.
 */
#ifndef wheelrail_postprocess_postprocessor_h
#define wheelrail_postprocess_postprocessor_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <deal.II/distributed/tria.h>

#include <wheelrail/base/checkpoint.h>
#include <wheelrail/contact/penalty_contact.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/explicit_solver.h>
#include <wheelrail/solver/wheelset.h>

#include <string>

namespace WheelRail
{
  /**
   * What the postprocessors may read of the run: the parameters, the
   * mesh, the solver and the optional contact and wheelset (null when the
   * case has none), the screen and the output directory.
   */
  struct SimulatorAccess
  {
    const Parameters                                &parameters;
    MPI_Comm                                         mpi_communicator;
    const ConditionalOStream                        &pcout;
    const std::string                               &output_directory;
    const parallel::distributed::Triangulation<dim> &triangulation;
    const ExplicitSolver                            &solver;
    const PenaltyContact                            *contact;
    const Wheelset                                  *wheelset;

    /** Write @p content to @p name in the output directory atomically
     *  (temporary file, then rename), from rank 0. */
    void
    write_file(const std::string &name, const std::string &content) const;

    /** Test mode of a round-off sensitive (chaotic) run: print only what
     *  is robust (Verification/Round-off sensitive). */
    bool
    robust_output_only() const
    {
      return parameters.problem.test_mode && parameters.verification.round_off_sensitive;
    }
  };

  /** The step just taken, as the postprocessors see it. */
  struct StepInfo
  {
    unsigned long   step;        ///< n: the step from t_n to t_n+1 was taken
    unsigned long   n_steps;     ///< the steps of the whole run
    const Energies *energies;    ///< at a statistics step, else nullptr
    bool            report_step; ///< a step of Output/Report interval
  };

  class StatisticsTable;

  /**
   * One postprocessor: records after each step what it needs, writes its
   * files, adds its columns to the statistics, and saves and restores its
   * state with the checkpoint.
   */
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /** Called after every step of the time loop. */
    virtual void
    execute(const StepInfo &step) = 0;

    /** Write this postprocessor's files as they stand (before a
     *  checkpoint, at a divergence, at the end); most have none. */
    virtual void
    write_files() const
    {}

    /** At a statistics step, after execute(): add this postprocessor's
     *  columns to the row of @p table (StatisticsTable::add_number());
     *  most have none. */
    virtual void
    add_statistics(StatisticsTable &table) const
    {
      (void)table;
    }

    /** The state for the checkpoint: both call the same
     *  serialize(Archive &), which lists the fields once. */
    virtual void
    save(Checkpoint::Writer &out) = 0;
    virtual void
    load(Checkpoint::Reader &in) = 0;
  };



  /**
   * A postprocessor whose checkpoint is its `template <class Archive> void
   * serialize(Archive &ar)`: save() and load() both call it.
   */
  template <class Derived>
  class SerializedPostprocessor : public Postprocessor
  {
  public:
    void
    save(Checkpoint::Writer &out) override
    {
      static_cast<Derived &>(*this).serialize(out);
    }
    void
    load(Checkpoint::Reader &in) override
    {
      static_cast<Derived &>(*this).serialize(in);
    }
  };
} // namespace WheelRail

#endif
