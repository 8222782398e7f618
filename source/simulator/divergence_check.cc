#include <deal.II/base/mpi.h>

#include <wheelrail/mesh/geometry.h>
#include <wheelrail/parameters/consistency.h>
#include <wheelrail/simulator/divergence_check.h>
#include <wheelrail/simulator/format.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace WheelRail
{
  using Report::fmt;



  DivergenceCheck::DivergenceCheck(const SimulatorAccess       &access,
                                   const EnergyBalance         &balance,
                                   const std::function<void()> &write_records)
    : access(access)
    , balance(balance)
    , write_records(write_records)
  {}



  void
  DivergenceCheck::record_initial_velocities()
  {
    velocity_spread     = 0;
    const VectorType &v = access.solver.velocity();
    for (unsigned int d = 0; d < dim; ++d)
      {
        double lo = std::numeric_limits<double>::max(), hi = -lo;
        for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
          if (access.solver.dof_component(i) == d)
            {
              lo = std::min(lo, v.local_element(i));
              hi = std::max(hi, v.local_element(i));
            }
        velocity_spread = std::max(velocity_spread,
                                   Utilities::MPI::max(hi, access.mpi_communicator) -
                                     Utilities::MPI::min(lo, access.mpi_communicator));
      }
  }



  void
  DivergenceCheck::execute(const StepInfo &step)
  {
    if (access.contact)
      {
        const ContactSummary &cs = access.contact->summary();
        if (std::isfinite(cs.max_penetration))
          deepest_penetration = std::max(deepest_penetration, cs.max_penetration);
        most_contact_nodes = std::max(most_contact_nodes, cs.n_contact);
      }
    if (step.energies == nullptr)
      return;
    const Energies &e = *step.energies;
    if (!std::isfinite(e.kinetic) || !std::isfinite(e.internal) || !std::isfinite(e.hourglass) ||
        balance.max_balance_error() > access.parameters.output.divergence_limit)
      {
        write_records();
        AssertThrow(false, ExcMessage(explain(step.step, e)));
      }
  }



  std::string
  DivergenceCheck::explain(const unsigned long n, const Energies &e) const
  {
    const std::string  location = worst_node();
    const double       dt       = access.solver.time_step();
    std::ostringstream message;
    message << "The solution diverged at step " << n << ", t = " << fmt(n * dt) << " s: "
            << (std::isfinite(e.kinetic) && std::isfinite(e.internal) ?
                  "the energy balance error " + fmt(balance.max_balance_error(), 3) +
                    " exceeds Output/Divergence limit " +
                    fmt(access.parameters.output.divergence_limit) :
                  std::string("NaN or infinite energy"))
            << "; " << location << ". Likely cause: ";
    likely_cause(n, message);
    message << ". The statistics and probes up to the last statistics row were written.";
    return message.str();
  }



  std::string
  DivergenceCheck::worst_node() const
  {
    // the first non-finite (or, if all are finite, the fastest) DoF of
    // each rank; the rank with the worst one tells
    const VectorType &u = access.solver.displacement(), &v = access.solver.velocity();
    unsigned int      worst       = numbers::invalid_unsigned_int;
    double            worst_value = -1;
    for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
      {
        const double ui = u.local_element(i), vi = v.local_element(i);
        const double value = (!std::isfinite(ui) || !std::isfinite(vi)) ?
                               std::numeric_limits<double>::infinity() :
                               std::abs(vi);
        if (value > worst_value)
          {
            worst_value = value;
            worst       = i;
          }
      }
    const double       global_worst = Utilities::MPI::max(worst_value, access.mpi_communicator);
    const unsigned int my_rank      = Utilities::MPI::this_mpi_process(access.mpi_communicator);
    const unsigned int teller =
      Utilities::MPI::min(worst_value == global_worst ?
                            my_rank :
                            Utilities::MPI::n_mpi_processes(access.mpi_communicator),
                          access.mpi_communicator);
    std::ostringstream where;
    if (my_rank == teller && worst != numbers::invalid_unsigned_int)
      {
        const Point<dim> &X    = access.solver.support_points()[worst];
        const char       *body = Geometry::body_name(access.solver.dof_material(worst));
        where << (std::isfinite(global_worst) ? "fastest node" : "first non-finite value")
              << " at X = (" << fmt(X[0] * 1e3) << ", " << fmt(X[1] * 1e3) << ", "
              << fmt(X[2] * 1e3) << ") mm of the " << body << ", component "
              << "xyz"[access.solver.dof_component(worst)]
              << ", u = " << fmt(u.local_element(worst), 4)
              << " m, v = " << fmt(v.local_element(worst), 4) << " m/s"
              << (access.solver.boundary_dof_mask()[worst] ? " (a surface node)" : "");
      }
    return Utilities::MPI::broadcast(access.mpi_communicator, where.str(), teller);
  }



  double
  DivergenceCheck::body_extent() const
  {
    // the body's size, for the strain that gravity alone would cause
    double      extent = 0;
    const auto &points = access.solver.support_points();
    for (unsigned int d = 0; d < dim; ++d)
      {
        double lo = std::numeric_limits<double>::max(), hi = -lo;
        for (const Point<dim> &p : points)
          {
            lo = std::min(lo, p[d]);
            hi = std::max(hi, p[d]);
          }
        lo     = Utilities::MPI::min(lo, access.mpi_communicator);
        hi     = Utilities::MPI::max(hi, access.mpi_communicator);
        extent = std::max(extent, hi - lo);
      }
    return extent;
  }



  void
  DivergenceCheck::likely_cause(const unsigned long n, std::ostream &message) const
  {
    const double extent = body_extent();
    const MaterialParameters &material = access.parameters.material;
    const double              c        = material.wave_speed();
    const double              gravity_strain =
      material.density * access.parameters.solver.gravity.norm() * extent / material.youngs_modulus;
    const double dt = access.solver.time_step();
    // the applied force and the prescribed velocity at their largest so far
    const Parameters &prm     = access.parameters;
    const double      t       = n * dt;
    const auto        section = Consistency::body_size(prm).cross_section();
    Consistency::Peak force, velocity;
    if (!prm.boundary.applied_force_ids.empty())
      force = Consistency::peak_over_run(prm,
                                         prm.boundary.applied_force_expression,
                                         prm.boundary.applied_force_constants,
                                         "Boundary conditions/Applied force",
                                         t,
                                         false);
    if (!prm.boundary.prescribed_velocity_ids.empty())
      velocity = Consistency::peak_over_run(prm,
                                            prm.boundary.prescribed_velocity_expression,
                                            prm.boundary.prescribed_velocity_constants,
                                            "Boundary conditions/Prescribed velocity",
                                            t,
                                            true);
    const double       force_strain = force.magnitude / (material.youngs_modulus * section);
    const double       stable       = access.solver.stable_time_step();
    const double       critical     = stable / access.parameters.solver.courant_factor;
    const double       h_min        = critical * c; // the smallest element length
    // the causes in the order in which one hides the next: a load (gravity,
    // the applied force, the prescribed velocity) or an initial state
    // beyond small strains, a contact the search missed, the
    // contact penalty, the time step
    if (velocity_spread > 0.05 * c)
      message << "the initial velocity: its components differ by up to " << fmt(velocity_spread, 4)
              << " m/s over the nodes, " << fmt(100 * velocity_spread / c, 3)
              << " % of the wave speed " << fmt(c, 4)
              << " m/s, i.e. strains of that order at once (Initial conditions)";
    else if (gravity_strain > 1e-2)
      message << "the gravity " << fmt(access.parameters.solver.gravity.norm(), 4)
              << " m/s^2: its weight alone strains a body of " << fmt(extent, 3) << " m by about "
              << fmt(gravity_strain, 3) << " (Time integration/Gravity)";
    else if (force_strain > 1e-2)
      message << "the applied force, up to " << fmt(force.magnitude, 4)
              << " N (at t = " << fmt(force.t) << " s): on the mean cross-section "
              << fmt(section, 3) << " m^2 of the bodies it alone strains them by about "
              << fmt(force_strain, 3) << " (Boundary conditions/Applied force = '"
              << prm.boundary.applied_force_expression << "')";
    else if (velocity.magnitude > 0.05 * c)
      message << "the prescribed velocity, up to " << fmt(velocity.magnitude, 4)
              << " m/s (at t = " << fmt(velocity.t) << " s), "
              << fmt(100 * velocity.magnitude / c, 3) << " % of the wave speed " << fmt(c, 4)
              << " m/s, i.e. strains of that order at once (Boundary conditions/Prescribed "
                 "velocity = '"
              << prm.boundary.prescribed_velocity_expression << "')";
    else if (access.contact && deepest_penetration > 0.5 * h_min)
      message << "a contact missed or overrun: slave nodes reached "
              << fmt(deepest_penetration * 1e3, 3)
              << " mm into the master surface, more than half the smallest element length "
              << fmt(h_min * 1e3, 3)
              << " mm (Contact/Search margin, Search interval; or Penalty scale factor too soft)";
    else if (access.contact && most_contact_nodes > 0)
      message << "the contact (up to " << most_contact_nodes
              << " nodes in contact so far), penalty scale factor "
              << fmt(access.parameters.contact.penalty_scale) << " (too stiff for the time step "
              << fmt(dt)
              << " s, or too soft for the load: Contact/Penalty scale factor, Time "
                 "integration/Courant factor)";
    else if (dt > 0.95 * critical)
      message << "the time step " << fmt(dt) << " s at the critical step " << fmt(critical)
              << " s of the mesh (Time integration/Time step, Courant factor)";
    else
      message << "an unconstrained body or an initial condition far from equilibrium";
  }
} // namespace WheelRail
