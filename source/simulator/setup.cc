#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/base/stop_signal.h>
#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/mesh/partition_weights.h>
#include <wheelrail/simulator/format.h>
#include <wheelrail/simulator/simulator.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <optional>
#include <sstream>

namespace WheelRail
{
  using Report::fmt;

  namespace
  {
    /** The parameters as ParameterHandler prints them in @p style. */
    std::string
    print_parameters(const ParameterHandler &prm, const ParameterHandler::OutputStyle style)
    {
      std::ostringstream out;
      prm.print_parameters(out, style);
      return out.str();
    }
  } // namespace



  Simulator::Simulator(const Parameters &parameters, const ParameterHandler &prm, MPI_Comm comm)
    : parameters(parameters)
    , parameter_file(print_parameters(prm, ParameterHandler::PRM))
    , parameter_record(print_parameters(prm, ParameterHandler::ShortPRM))
    , mpi_communicator(comm)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
    , triangulation(comm)
    , output_directory(parameters.problem.output_directory)
  {
    prepare_output_directory();
  }



  std::ostream &
  Simulator::solver_log()
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0 && !parameters.problem.test_mode)
      return std::cout;
    silent_log.str("");
    return silent_log;
  }



  namespace
  {
    /**
     * An entry of @p directory (the first by name) that shows that it is
     * not a wheelrail output directory: "" if the directory does not exist,
     * is empty, or holds the lock file or parameters.prm of a run (the lock
     * is written first).
     */
    std::string
    foreign_entry(const std::string &directory)
    {
      std::error_code ec;
      if (!std::filesystem::is_directory(directory, ec))
        return "";
      std::string first;
      for (const auto &entry : std::filesystem::directory_iterator(directory, ec))
        {
          const std::string name = entry.path().filename().string();
          if (name == ".wheelrail.lock" || name == "parameters.prm")
            return "";
          if (first.empty() || name < first)
            first = name;
        }
      return first;
    }
  } // namespace



  void
  Simulator::prepare_output_directory()
  {
    // a resumed run continues in its directory: none means a wrong name
    AssertThrow(!parameters.output.resume || std::filesystem::is_directory(output_directory),
                ExcMessage("--resume: Problem/Output directory '" + output_directory +
                           "' does not exist: no checkpoint to resume from."));
    int         ok = 1;
    std::string message;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::error_code   ec;
        const std::string foreign = foreign_entry(output_directory);
        if (!foreign.empty())
          {
            ok      = 0;
            message = "Problem/Output directory '" + output_directory +
                      "' already holds files that no wheelrail run wrote (e.g. '" + foreign +
                      "'): the run would write its own among them. Choose a new or empty "
                      "directory, or a previous run's output directory.";
          }
        else
          {
            std::filesystem::create_directories(output_directory, ec);
            if (ec)
              {
                ok      = 0;
                message = "Cannot create Problem/Output directory '" + output_directory +
                          "': " + ec.message();
              }
          }
      }
    ok = Utilities::MPI::min(ok, mpi_communicator);
    AssertThrow(ok, ExcMessage(Utilities::MPI::broadcast(mpi_communicator, message, 0)));
    // rank 0 holds the lock; a directory in use stops every rank
    std::string error;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      try
        {
          lock = std::make_unique<DirectoryLock>(output_directory, "Problem/Output directory");
          if (!lock->warning().empty())
            std::cerr << "Warning: " << lock->warning() << std::endl;
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          error = info.str();
        }
    throw_first_error(error, mpi_communicator);
  }



  void
  Simulator::run()
  {
    pcout << "wheelrail: geometry '" << parameters.problem.geometry << "', mode '"
          << run_mode_names(parameters.problem.mode) << "'";
    if (!parameters.problem.test_mode)
      pcout << ", " << Utilities::MPI::n_mpi_processes(mpi_communicator) << " MPI rank(s)";
    pcout << std::endl;
    if (parameters.output.resume)
      check_checkpoint();

    const Geometry::GeometryModel &geometry = *parameters.geometry_model;
    Geometry::build(geometry, triangulation);
    if (parameters.problem.partition == PartitionBy::work)
      Mesh::partition_by_work(triangulation,
                              Mesh::contact_boundaries(parameters.contact, geometry.has_contact()));
    solver = std::make_unique<ExplicitSolver>(parameters, triangulation);
    solver->setup();
    if (parameters.contact.enabled && geometry.has_contact())
      {
        contact = std::make_unique<PenaltyContact>(parameters.contact,
                                                   parameters.material,
                                                   mpi_communicator);
        contact->setup(solver->get_dof_handler(), solver->partitioner(), solver->point_mass());
        solver->attach_contact(contact.get());
      }
    if (geometry.has_wheel() && parameters.boundary.wheel_bore == WheelBore::rigid_axle)
      {
        wheelset          = std::make_unique<Wheelset>(parameters.wheelset,
                                              parameters.solver,
                                              geometry.wheel_centre());
        wheelset_coupling = std::make_unique<WheelsetCoupling>(*wheelset,
                                                               parameters.wheelset,
                                                               geometry.wheel_centre(),
                                                               mpi_communicator);
        solver->attach_rigid_body(wheelset_coupling.get());
      }
    access = std::make_unique<SimulatorAccess>(SimulatorAccess{parameters,
                                                               mpi_communicator,
                                                               pcout,
                                                               output_directory,
                                                               triangulation,
                                                               *solver,
                                                               contact.get(),
                                                               wheelset.get()});

    choose_time_step();
    if (parameters.problem.mode == RunMode::explicit_dynamics)
      check_run_length();

    // a resumed run reads its checkpoint here, so that a checkpoint refused
    // for any reason (another rank count, a mesh or state that does not
    // fit) stops the run before it has written anything
    const bool explicit_run = parameters.problem.mode == RunMode::explicit_dynamics;
    if (parameters.output.resume && explicit_run && !parameters.problem.dry_run)
      {
        setup_postprocessors();
        read_checkpoint();
      }
    StopSignal::stop_if_received(mpi_communicator,
                                 "during the setup",
                                 "nothing was written in Problem/Output directory '" +
                                   output_directory + "'");

    // the setup has succeeded: from here on the run owns the directory's
    // files (a rejected run leaves the previous run's parameters.prm)
    access->write_file("parameters.prm", parameter_file);
    print_setup_summary();
    if (parameters.problem.dry_run)
      {
        pcout << "Dry run: stopping after the setup." << std::endl;
        return;
      }
    if (explicit_run)
      run_explicit();
    else if (parameters.problem.mode == RunMode::static_contact)
      run_static_contact();
    else
      run_static_check();
  }



  void
  Simulator::check_run_length() const
  {
    // the explicit step's wall time per cell on one rank, the paper case
    // in bench/results.csv (61 ns; 35.7 ns on 2 ranks): divided by the
    // ranks, a lower estimate for a larger mesh
    constexpr double        seconds_per_cell_step = 61e-9;
    constexpr double        max_steps             = 1e8;
    constexpr double        min_fraction          = 1e-3;
    const SolverParameters &sp                    = parameters.solver;
    const double            dt                    = solver->time_step();
    const double            stable                = solver->stable_time_step();
    const double            steps                 = std::ceil(sp.end_time / dt - 1e-9);
    const bool              too_many              = steps > max_steps;
    const bool              too_fine = sp.time_step > 0 && sp.time_step < min_fraction * stable;
    if (sp.allow_long_runs || !(too_many || too_fine))
      return;
    const double cells = triangulation.n_global_active_cells();
    const double ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    const double wall  = steps * cells * seconds_per_cell_step / ranks;
    std::string  cause;
    if (too_fine)
      cause = "Time integration/Time step = " + fmt(sp.time_step) + " s is " +
              fmt(sp.time_step / stable, 3) + " of the stable step " + fmt(stable) +
              " s (under the thousandth that wheelrail runs unasked), and ";
    else
      cause = "Time integration/";
    cause += "End time = " + fmt(sp.end_time) + " s takes " + fmt(steps, 3) + " steps" +
             (too_many ? " (more than 1e8)" : "") + ", at least about " +
             (wall > 2 * 86400 ? fmt(wall / 86400, 3) + " days" :
              wall > 7200      ? fmt(wall / 3600, 3) + " hours" :
                                 fmt(wall, 3) + " s") +
             " of wall time over " + fmt(cells) + " cell(s) on " + fmt(ranks) +
             " rank(s) (at 61 ns per cell and step on one rank, the paper case's "
             "benchmark, divided by the ranks; small meshes take longer per cell)";
    AssertThrow(false,
                ExcMessage(
                  cause + ": " +
                  (too_fine ? "set Time step = 0 (the stable step) or a larger one, " : "") +
                  "reduce End time" + (too_fine ? "" : " or coarsen the mesh") +
                  ", or set Time integration/Allow long runs = true to run it as it "
                  "is."));
  }



  namespace
  {
    /** The setup summary's lines on the bodies of @p geometry: the cells
     *  in each solution zone, and each body's lumped mass against rho
     *  times its mesh volume and its exact volume. */
    void
    print_bodies(const ConditionalOStream                        &pcout,
                 const Geometry::GeometryModel                   &geometry,
                 const ExplicitSolver                            &solver,
                 const parallel::distributed::Triangulation<dim> &triangulation,
                 const MaterialParameters                        &material)
    {
      for (const Geometry::Body &body : geometry.bodies())
        if (const std::optional<Geometry::ZoneCells> z =
              geometry.zone_cells(body.material, triangulation))
          {
            pcout << "  solution zone, " << std::left << std::setw(5) << body.name << std::right
                  << "        : ";
            if (z->n_cells == 0)
              pcout << "none" << std::endl;
            else
              pcout << z->n_cells << " cells, longest edge " << fmt(z->max_longest_edge * 1e3)
                    << " mm" << std::endl;
          }

      pcout << "Mass (lumped, condensed over hanging nodes)" << std::endl;
      const double rho = material.density;
      for (const Geometry::Body &body : geometry.bodies())
        {
          const double m      = solver.total_mass(body.material);
          const double m_mesh = rho * solver.mesh_volume(body.material);
          const double m_true = rho * geometry.exact_volume(body.material);
          pcout << "  " << std::left << std::setw(6) << body.name << std::right << " lumped mass "
                << fmt(m, 8) << " kg, rho x mesh volume " << fmt(m_mesh, 8) << " kg (rel. error "
                << fmt(std::abs(m - m_mesh) / m_mesh, 1) << "), rho x exact volume "
                << fmt(m_true, 8) << " kg (rel. error " << fmt(std::abs(m - m_true) / m_true, 3)
                << ")" << std::endl;
        }
    }
  } // namespace



  void
  Simulator::choose_time_step()
  {
    if (parameters.solver.time_step > 0)
      {
        AssertThrow(parameters.solver.time_step <= solver->stable_time_step() * (1 + 1e-12),
                    ExcMessage("Time integration/Time step = " + fmt(parameters.solver.time_step) +
                               " s exceeds the stable step " + fmt(solver->stable_time_step()) +
                               " s (Courant factor x min L_e/c with the damping reduction): "
                               "the explicit run would blow up. Reduce the time step, or "
                               "coarsen Geometry/Mesh/Minimum cell size."));
        solver->set_time_step(parameters.solver.time_step);
      }
    else
      solver->set_time_step(solver->stable_time_step());
  }



  void
  Simulator::print_setup_summary()
  {
    const MeshQuality &q      = solver->mesh_quality();
    const double       c      = parameters.material.wave_speed();
    const std::string  shapes = parameters.geometry_model->description();
    if (!shapes.empty())
      pcout << "Profiles" << std::endl << "  " << shapes << std::endl;
    pcout << "Mesh" << std::endl
          << "  cells                        : " << triangulation.n_global_active_cells()
          << std::endl
          << "  DoFs                         : " << solver->get_dof_handler().n_dofs() << std::endl
          << "  h_min (smallest cell size)   : " << fmt(q.min_longest_edge * 1e3) << " mm"
          << std::endl
          << "  shortest edge                : " << fmt(q.min_edge * 1e3) << " mm" << std::endl
          << "  smallest L_e = V/A_max       : " << fmt(q.min_length * 1e3) << " mm" << std::endl
          << "  smallest scaled Jacobian     : " << fmt(q.min_scaled_jacobian, 4) << std::endl
          << "  largest aspect ratio         : " << fmt(q.max_aspect_ratio, 4) << std::endl;
    print_bodies(pcout, *parameters.geometry_model, *solver, triangulation, parameters.material);

    const double dt = solver->time_step();
    pcout << "Time integration" << std::endl
          << "  dilatational wave speed c    : " << fmt(c) << " m/s" << std::endl
          << "  stable step (Courant " << fmt(parameters.solver.courant_factor, 3)
          << ")     : " << fmt(solver->stable_time_step() * 1e6) << " us" << std::endl
          << "  step used                    : " << fmt(dt * 1e6) << " us" << std::endl
          << "  Courant number c dt / L_e    : " << fmt(c * dt / q.min_length, 4) << std::endl
          << "  hourglass coefficient QM     : " << fmt(parameters.solver.hourglass_coefficient)
          << std::endl
          << "  damping                      : "
          << damping_model_names(parameters.solver.damping_model);
    if (solver->damping_model() == DampingModel::stiffness)
      pcout << " (COEF " << fmt(parameters.solver.stiffness_damping_coefficient) << ")";
    else if (solver->damping_model() == DampingModel::rayleigh)
      pcout << " (beta " << fmt(parameters.solver.rayleigh_beta) << " s)";
    if (solver->damping_model() != DampingModel::none &&
        parameters.solver.damping_form == DampingForm::nodal_field)
      pcout << ", from the nodal field u + beta_n v";
    pcout << std::endl;
    if (parameters.solver.single_precision_geometry)
      {
        pcout << "  element geometry             : single precision (force loop)";
        if (parameters.solver.geometry_sharing == GeometrySharing::within_rounding)
          {
            const auto [blocks, batches] = solver->n_single_blocks_and_batches();
            pcout << ", shared within rounding (blocks / batches "
                  << Utilities::MPI::sum(blocks, mpi_communicator) << " / "
                  << Utilities::MPI::sum(batches, mpi_communicator) << ")";
          }
        pcout << std::endl;
      }
    if (contact)
      print_contact_summary();
    if (parameters.problem.mode == RunMode::explicit_dynamics)
      pcout << "  steps                        : "
            << static_cast<unsigned long>(std::ceil(parameters.solver.end_time / dt - 1e-9))
            << " to t = " << fmt(parameters.solver.end_time * 1e3) << " ms" << std::endl;
  }



  void
  Simulator::print_contact_summary()
  {
    const ContactParameters &cp = parameters.contact;
    pcout << "Contact" << std::endl
          << "  slave boundary " << cp.slave_boundary << " (" << contact->slave_states().size()
          << " nodes), master boundary " << cp.master_boundary
          << (cp.two_pass ? ", two-pass" : ", one-pass") << std::endl
          << "  penalty scale factor SF    : " << fmt(cp.penalty_scale) << std::endl;
    if (cp.penalty_stiffness == PenaltyStiffness::area)
      pcout << "  penalty stiffness          : k = SF K min(A, A_s) / h_ref, h_ref = "
            << fmt(contact->penalty_reference_length() * 1e3, 4) << " mm" << std::endl;
    pcout << "  friction law               : " << cp.friction_law;
    if (const auto law = contact->friction_law())
      pcout << " (" << law->describe([](const double x) { return fmt(x); }) << ")";
    pcout << std::endl;
    if (contact->friction_law() && (cp.slip_rate != SlipRate::total || cp.relaxation_length > 0 ||
                                    cp.relaxation_time > 0 || cp.tangential_damping > 0))
      pcout << "  friction regularisation    : slip rate " << slip_rate_names(cp.slip_rate)
            << ", relaxation L = " << fmt(cp.relaxation_length * 1e6)
            << " um, tau = " << fmt(cp.relaxation_time * 1e6) << " us, tangential damping "
            << fmt(cp.tangential_damping) << std::endl;
  }
} // namespace WheelRail
