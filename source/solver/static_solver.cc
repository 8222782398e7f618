#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/numerics/vector_tools.h>

#include <wheelrail/base/stop_signal.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/solver/static_solver.h>

#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <tuple>

namespace WheelRail
{
  namespace
  {
    /** @p x with 6 significant digits. */
    std::string
    fmt(const double x)
    {
      std::ostringstream s;
      s << std::setprecision(6) << x;
      return s.str();
    }
  } // namespace



  StaticContactSolver::StaticContactSolver(const Parameters &parameters,
                                           ExplicitSolver   &solver,
                                           PenaltyContact   &contact,
                                           MPI_Comm          comm)
    : parameters(parameters)
    , solver(solver)
    , contact(contact)
    , mpi_communicator(comm)
    , tangent(stiffness_matrix, comm)
  {
    const DoFHandler<dim> &dof_handler = solver.get_dof_handler();
    IndexSet               relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    make_constraints(relevant);
    bore_dofs = DoFTools::extract_boundary_dofs(dof_handler,
                                                ComponentMask(),
                                                {Geometry::BoundaryIds::wheel_bore});
    bore_dofs = bore_dofs & dof_handler.locally_owned_dofs();
    u.reinit(solver.partitioner());
    state.reinit(solver.partitioner());
    assemble_stiffness(relevant);
    initialize_amg();
  }



  void
  StaticContactSolver::make_constraints(const IndexSet &relevant)
  {
    const DoFHandler<dim> &dof_handler = solver.get_dof_handler();
    // the operator's hanging-node constraints and the homogeneous Dirichlet
    // conditions of the fixed boundaries and the bore
    constraints.clear();
    constraints.reinit(relevant);
    constraints.merge(solver.get_hanging_constraints());
    const Functions::ZeroFunction<dim> zero(dim);
    for (const auto &[id, components] : parameters.boundary.fixed)
      {
        std::vector<bool> mask(dim, false);
        for (unsigned int d = 0; d < dim; ++d)
          mask[d] = components.find("xyz"[d]) != std::string::npos;
        VectorTools::interpolate_boundary_values(
          dof_handler, id, zero, constraints, ComponentMask(mask));
      }
    VectorTools::interpolate_boundary_values(dof_handler,
                                             Geometry::BoundaryIds::wheel_bore,
                                             zero,
                                             constraints);
    constraints.close();
  }



  void
  StaticContactSolver::assemble_stiffness(const IndexSet &relevant)
  {
    // K and its AMG, once: the contact tangent stays outside (StaticTangent)
    const DoFHandler<dim> &dof_handler = solver.get_dof_handler();
    {
      const IndexSet                   &owned = dof_handler.locally_owned_dofs();
      TrilinosWrappers::SparsityPattern sparsity(owned, owned, relevant, mpi_communicator);
      DoFTools::make_sparsity_pattern(dof_handler,
                                      sparsity,
                                      constraints,
                                      false,
                                      Utilities::MPI::this_mpi_process(mpi_communicator));
      sparsity.compress();
      stiffness_matrix.reinit(sparsity);
    }
    solver.assemble_stiffness(stiffness_matrix, constraints);
    stiffness_matrix.compress(VectorOperation::add);
  }



  void
  StaticContactSolver::initialize_amg()
  {
    const DoFHandler<dim>                            &dof_handler = solver.get_dof_handler();
    TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
    amg_data.elliptic              = true;
    amg_data.higher_order_elements = false;
    // Chebyshev of degree 1: more CG iterations than degree 2 but fewer
    // products with K in all (doc/notes/performance_update.md)
    amg_data.smoother_sweeps = 1;
    if (parameters.statics.amg_null_space == AmgNullSpace::translations)
      {
        amg_data.aggregation_threshold = 0.02;
        std::vector<std::vector<bool>> modes;
        DoFTools::extract_constant_modes(dof_handler, ComponentMask(), modes);
        amg_data.constant_modes = modes;
        amg.initialize(stiffness_matrix, amg_data);
      }
    else
      {
        // The near null space of elasticity: the three translations and the
        // three rotations from the nodes' positions (deal.II 9.4's
        // AdditionalData takes constant modes only): fewer CG iterations
        // than with the translations alone, at more memory.
        amg_data.aggregation_threshold = 1e-4;
        Teuchos::ParameterList              ml_parameters;
        std::unique_ptr<Epetra_MultiVector> constant_modes;
        amg_data.set_parameters(ml_parameters, constant_modes, stiffness_matrix);
        const Epetra_MultiVector modes = rigid_body_modes(dof_handler, stiffness_matrix);
        ml_parameters.set("null space: type", "pre-computed");
        ml_parameters.set("null space: dimension", modes.NumVectors());
        ml_parameters.set("null space: vectors", modes.Values());
        amg.initialize(stiffness_matrix, ml_parameters);
      }
  }



  Epetra_MultiVector
  StaticContactSolver::rigid_body_modes(const DoFHandler<dim>                &dof_handler,
                                        const TrilinosWrappers::SparseMatrix &matrix)
  {
    const IndexSet    &owned = dof_handler.locally_owned_dofs();
    Epetra_MultiVector modes(matrix.trilinos_matrix().OperatorDomainMap(), 2 * dim);
    AssertThrow(modes.ConstantStride() && modes.MyLength() == int(owned.n_elements()),
                ExcInternalError());
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            {
              if (!owned.is_element(dofs[i]))
                continue;
              const unsigned int row       = owned.index_within_set(dofs[i]);
              const unsigned int component = fe.system_to_component_index(i).first;
              // Q1: the base element's shape functions are the vertices
              const Point<dim> &x = cell->vertex(fe.system_to_component_index(i).second);
              for (unsigned int m = 0; m < dim; ++m)
                modes[m][row] = (m == component ? 1. : 0.);
              // rotation about axis r: e_r x x, component 'component'
              for (unsigned int r = 0; r < dim; ++r)
                {
                  const unsigned int a = (r + 1) % dim, b = (r + 2) % dim;
                  modes[dim + r][row] = component == a ? -x[b] : component == b ? x[a] : 0.;
                }
            }
        }
    return modes;
  }



  double
  StaticContactSolver::solve_at(const double delta, StaticResult &result, std::ostream &log)
  {
    prescribe_bore(delta);
    VectorType   residual;
    double       force         = 0;
    double       previous_norm = std::numeric_limits<double>::max();
    const double load_scale    = std::max(parameters.statics.axle_load, 1.);
    double       norm          = residual_norm(u, residual);
    VectorType   trial(u);
    for (unsigned int it = 0; it <= parameters.statics.max_newton_iterations; ++it)
      {
        // SIGTERM or SIGINT: the ranks agree here, where all of them are
        StopSignal::stop_if_received(mpi_communicator,
                                     "during the static solve",
                                     "nothing of it was written; run the case again");
        force = contact.summary().force[2];
        if (newton_converged(it, norm, previous_norm, load_scale, log))
          return force;
        check_newton_progress(it, norm, previous_norm, delta, load_scale);
        // the residual's reduction by the last step (the forcing term)
        const double reduction = it == 0 ? 1. : norm / previous_norm;
        previous_norm          = norm;
        ++result.newton_iterations;
        const TrilinosWrappers::MPI::Vector du =
          newton_increment(residual, linear_tolerance(it == 0, reduction, norm, load_scale), result);
        norm = line_search(du, norm, trial, residual, log);
      }
    return force;
  }



  void
  StaticContactSolver::prescribe_bore(const double delta)
  {
    // the bore moves down rigidly by delta
    const auto &part = *solver.partitioner();
    for (const auto dof : bore_dofs)
      {
        const unsigned int i = part.global_to_local(dof);
        u.local_element(i)   = (solver.dof_component(i) == 2) ? -delta : 0.;
      }
  }



  double
  StaticContactSolver::residual_norm(const VectorType &v, VectorType &residual)
  {
    // residual norm over the free DoFs at the displacement v (its owned
    // entries; ghosts and hanging DoFs follow)
    const auto &part = *solver.partitioner();
    for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
      state.local_element(i) = v.local_element(i);
    state.update_ghost_values();
    solver.distribute(state);
    solver.compute_residual(state, residual); // f_int - f_c - f_ext
    double n = 0;
    for (unsigned int i = 0; i < residual.locally_owned_size(); ++i)
      if (!constraints.is_constrained(part.local_to_global(i)))
        n += residual.local_element(i) * residual.local_element(i);
    return std::sqrt(Utilities::MPI::sum(n, mpi_communicator));
  }



  bool
  StaticContactSolver::newton_converged(const unsigned int it,
                                        const double       norm,
                                        const double       previous_norm,
                                        const double       load_scale,
                                        std::ostream      &log) const
  {
    log << "    Newton " << std::setw(2) << it << ": residual " << std::setprecision(3)
        << std::scientific << norm / load_scale << std::defaultfloat << std::setprecision(6)
        << ", contact nodes " << contact.summary().n_contact << ", contact force "
        << contact.summary().force[2] * 1e-3 << " kN" << std::endl;
    if (norm <= parameters.statics.newton_tolerance * load_scale)
      return true;
    // A node projecting onto a face edge or corner makes the contact
    // force non-smooth; Newton then stalls at a tiny residual. Accept a
    // stalled iteration below 10 x the tolerance.
    if (it > 2 && norm > 0.9 * previous_norm &&
        norm <= 10 * parameters.statics.newton_tolerance * load_scale)
      {
        log << "    (stalled at " << norm / load_scale << " of the load: accepted)" << std::endl;
        return true;
      }
    return false;
  }



  void
  StaticContactSolver::check_newton_progress(const unsigned int it,
                                             const double       norm,
                                             const double       previous_norm,
                                             const double       delta,
                                             const double       load_scale) const
  {
    AssertThrow(
      it < parameters.statics.max_newton_iterations,
      ExcMessage(
        "The static contact solve did not converge in Static solve/Max Newton iterations = " +
        std::to_string(parameters.statics.max_newton_iterations) +
        " iterations at the axle "
        "displacement " +
        fmt(delta * 1e6) + " um: residual " + fmt(norm / load_scale) + " of the load (" +
        fmt(previous_norm / load_scale) +
        " in the iteration before) against Static solve/Newton tolerance = " +
        fmt(parameters.statics.newton_tolerance) + ". " +
        (norm > 0.5 * previous_norm ?
           "Newton stagnates: the tolerance is finer than the steps reach with Static "
           "solve/Linear solver tolerance = " +
             fmt(parameters.statics.linear_tolerance) +
             " (or the contact set switches between iterations)." :
           "The residual still falls: raise Max Newton iterations.")));
  }



  double
  StaticContactSolver::linear_tolerance(const bool   first,
                                        const double reduction,
                                        const double norm,
                                        const double load_scale) const
  {
    // Inexact Newton (Eisenstat & Walker 1996): CG has to bring the
    // linear residual only to half the Newton tolerance, i.e. relative
    // 0.5 tol / |r|, which the next iterate can use; and not much below
    // what the nonlinearity leaves of the step, relative 0.9 (|r| /
    // |r_previous|)^2 (their choice 2), while the contact set or the
    // axle's position still moves the residual (and at the first step
    // of each axle position, which is the bore's prescribed motion).
    // The forcing term is kept at most 1e-2, so that the step's error
    // stays below what Newton's quadratic term leaves; the tolerance
    // term may reach 0.5: within a few tolerances of convergence the
    // step is small, its quadratic term negligible, and a linear
    // residual of half the tolerance is all the last iterate needs.
    double eta = parameters.statics.linear_tolerance;
    if (parameters.statics.inexact_newton)
      {
        const double eta_max = 1e-2;
        const double forcing = first ? eta_max : std::min(0.9 * reduction * reduction, eta_max);
        const double tolerance_term =
          std::min(0.5 * parameters.statics.newton_tolerance * load_scale / norm, 0.5);
        eta = std::max({forcing, tolerance_term, parameters.statics.linear_tolerance});
      }
    return eta;
  }



  TrilinosWrappers::MPI::Vector
  StaticContactSolver::newton_increment(const VectorType &residual,
                                        const double      eta,
                                        StaticResult     &result)
  {
    const auto     &part  = *solver.partitioner();
    const IndexSet &owned = solver.get_dof_handler().locally_owned_dofs();
    tangent.set_contact_pairs(contact.active_pairs(), constraints, owned);

    TrilinosWrappers::MPI::Vector rhs(owned, mpi_communicator), du(owned, mpi_communicator);
    for (unsigned int i = 0; i < residual.locally_owned_size(); ++i)
      if (!constraints.is_constrained(part.local_to_global(i)))
        rhs[part.local_to_global(i)] = -residual.local_element(i);
    rhs.compress(VectorOperation::insert);

    SolverControl                           control(5000, eta * rhs.l2_norm());
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    try
      {
        cg.solve(tangent, du, rhs, amg);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        AssertThrow(false,
                    ExcMessage("CG with AMG did not converge in the static contact solve "
                               "(residual " +
                               fmt(e.last_residual) + " after " + std::to_string(e.last_step) +
                               " iterations): check the boundary conditions."));
      }
    result.linear_iterations += control.last_step();
    return du;
  }



  double
  StaticContactSolver::line_search(const TrilinosWrappers::MPI::Vector &du,
                                   const double                         norm,
                                   VectorType                          &trial,
                                   VectorType                          &residual,
                                   std::ostream                        &log)
  {
    // Backtracking on the residual norm: a full step can switch the
    // contact set back and forth (the set then cycles); halve it until
    // the residual decreases. Hanging DoFs of the increment follow their
    // masters in set_displacement.
    const auto &part  = *solver.partitioner();
    double      alpha = 1;
    for (unsigned int ls = 0;; ++ls)
      {
        for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
          trial.local_element(i) =
            u.local_element(i) + (constraints.is_constrained(part.local_to_global(i)) ?
                                    0. :
                                    alpha * du[part.local_to_global(i)]);
        const double trial_norm = residual_norm(trial, residual);
        if (trial_norm < norm || ls == 8)
          {
            u = trial;
            if (alpha < 1)
              log << "      (step length " << alpha << ")" << std::endl;
            return trial_norm;
          }
        alpha *= 0.5;
      }
  }



  StaticResult
  StaticContactSolver::solve(const double target, std::ostream &log)
  {
    AssertThrow(target > 0,
                ExcMessage("The static contact solve needs a positive wheel load, got " +
                           fmt(target) +
                           " N: Static solve/Axle load (Problem/Mode = static contact) or, "
                           "with Wheelset/Static start, the wheelset's masses and Time "
                           "integration/Gravity."));
    StaticResult result;
    // The wheel touches O once the axle is lowered by the initial gap; the
    // first guess lies beyond that by the approach of a Hertzian contact of
    // this size with 50 % added for the compliance of the bodies.
    const double gap      = parameters.geometry.initial_gap;
    const double approach = 1e-4 * std::pow(target / 1.4e5, 2. / 3.);
    double       d0       = gap + approach;
    drop_wheel(gap);
    log << "Static contact solve for a wheel load of " << target * 1e-3 << " kN" << std::endl;
    log << "  axle displacement " << d0 * 1e6 << " um" << std::endl;
    // the converged state of the axle position before, first the rigid drop
    VectorType u_before(u);
    double     d_before = gap;
    double     F0       = solve_at(d0, result, log);
    ++result.load_iterations;
    double d1 = F0 > 0 ? gap + (d0 - gap) * std::pow(target / F0, 2. / 3.) : gap + 2 * approach;
    double F1 = F0;

    // Without contact the axle goes down by 2, 4, ... 2^max_closing
    // approaches beyond the gap: a wheel that touches nothing then is not
    // where the entries place it. With contact, at most max_load secant
    // iterations.
    const unsigned int max_closing = 6, max_load = 30;
    unsigned int       n_closing = 1, n_load = 0;
    while (true)
      {
        log << "  axle displacement " << d1 * 1e6 << " um" << std::endl;
        extrapolate(d0 != d_before ? (d1 - d0) / (d0 - d_before) : 0., u_before);
        d_before = d0;
        F1       = solve_at(d1, result, log);
        ++result.load_iterations;
        if (std::abs(F1 - target) <= parameters.statics.load_tolerance * target)
          break;
        if (F1 <= 0)
          {
            AssertThrow(n_closing < max_closing, no_contact_message(d1, gap, max_closing));
            ++n_closing;
            d0 = d1;
            F0 = F1;
            d1 = gap + std::pow(2., n_closing) * approach;
            continue;
          }
        ++n_load;
        AssertThrow(n_load < max_load, load_message(target, F0, F1, d1, gap, max_load));
        // secant on F^(2/3), nearly linear in the approach for Hertz
        const double g0 = std::cbrt(F0 * F0) - std::cbrt(target * target);
        const double g1 = std::cbrt(F1 * F1) - std::cbrt(target * target);
        const double d2 = (g1 != g0) ? d1 - g1 * (d1 - d0) / (g1 - g0) : gap + 1.1 * (d1 - gap);
        d0              = d1;
        F0              = F1;
        d1              = d2 > gap ? d2 : gap + 0.5 * (d1 - gap);
      }
    // the solution into the integrator, ready for an explicit run (the
    // contact state is that of the last residual, which was at u)
    solver.set_displacement(u);
    result.axle_displacement = d1;
    result.contact_force     = F1;
    return result;
  }



  void
  StaticContactSolver::drop_wheel(const double gap)
  {
    // the whole wheel drops by the gap at once, so that Newton (with the
    // tangent of the undeformed state) starts from a rigid motion instead
    // of a bore displaced against the rest of the wheel
    if (gap != 0)
      for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
        if (solver.dof_material(i) == Geometry::MaterialIds::wheel && solver.dof_component(i) == 2)
          u.local_element(i) = -gap;
  }



  void
  StaticContactSolver::extrapolate(const double s, VectorType &u_before)
  {
    // Newton starts from the line through the last two converged states
    // (the field's response to the axle, extrapolated) instead of the
    // last state with only the bore moved, where the axle goes on in
    // the direction of the last step: the first residual is then the
    // curvature of that response, not the bore's whole step. Going
    // back, the line would open the nodes at the edge of the contact
    // set that the last state closed, and Newton would have to close
    // them again.
    for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
      {
        const double u0 = u.local_element(i);
        if (s > 0)
          u.local_element(i) += s * (u0 - u_before.local_element(i));
        u_before.local_element(i) = u0;
      }
  }



  ExcMessage
  StaticContactSolver::no_contact_message(const double       d1,
                                          const double       gap,
                                          const unsigned int max_closing) const
  {
    return ExcMessage("The static contact solve found no contact with the axle lowered by " +
                      fmt(d1) + " m, " + fmt(d1 - gap) +
                      " m beyond Geometry/Wheel/Initial gap = " + fmt(gap) + " m (" +
                      std::to_string(1 << max_closing) +
                      " x the Hertz approach of the load): the wheel does not meet the "
                      "rail where Geometry/Wheel/Initial gap and Centre x and "
                      "Geometry/Rail place it, or Contact/Slave boundary and Master "
                      "boundary are not the surfaces that touch.");
  }



  ExcMessage
  StaticContactSolver::load_message(const double       target,
                                    const double       F0,
                                    const double       F1,
                                    const double       d1,
                                    const double       gap,
                                    const unsigned int max_load) const
  {
    return ExcMessage(
      "The static contact solve did not reach Static solve/Axle load within Static "
      "solve/Load tolerance = " +
      fmt(parameters.statics.load_tolerance) + " in " + std::to_string(max_load) +
      " load iterations: contact force " + fmt(F1 * 1e-3) + " kN against the target " +
      fmt(target * 1e-3) + " kN (relative error " + fmt(std::abs(F1 - target) / target) + ", " +
      fmt(std::abs(F0 - target) / target) + " in the iteration before), axle lowered by " +
      fmt(d1 * 1e6) + " um, " + fmt((d1 - gap) * 1e6) + " um beyond the initial gap. " +
      (std::abs(F1 - F0) <= 2 * parameters.statics.load_tolerance * target ?
         "The force has stopped changing: Load tolerance is finer than the Newton "
         "solves resolve the force (Static solve/Newton tolerance, Linear solver "
         "tolerance)." :
         "The force still changes: the contact does not stiffen like a Hertzian "
         "one (Contact/Penalty scale factor, or the contact set switching between "
         "load iterations)."));
  }
} // namespace WheelRail
