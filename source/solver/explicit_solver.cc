#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/base/stopwatch.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/solver/explicit_solver.h>
#include <wheelrail/solver/rotation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

namespace WheelRail
{
  ExplicitSolver::ExplicitSolver(const Parameters                          &parameters,
                                 parallel::distributed::Triangulation<dim> &tria)
    : ElasticOperator(parameters, tria)
  {}



  void
  ExplicitSolver::setup()
  {
    check_boundary_ids(prm, triangulation);
    ElasticOperator::setup();

    for (VectorType *vec : {&u, &v, &f, &v_old, &inv_mass, &f_ext, &u0})
      vec->reinit(vector_partitioner);
    f_cleared = false;

    // gravity load: g times the condensed row-sum mass (= condensed rho g N)
    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      {
        f_ext.local_element(i)    = mass.local_element(i) * prm.solver.gravity[node_component[i]];
        inv_mass.local_element(i) = mass.local_element(i) > 0 ? 1. / mass.local_element(i) : 0.;
      }
    // hanging DoFs carry neither mass nor load: they follow their masters
    for (const unsigned int i : constrained_local_dofs())
      if (i < inv_mass.locally_owned_size())
        {
          inv_mass.local_element(i) = 0;
          f_ext.local_element(i)    = 0;
        }

    prescribed = prescribed_dofs(prm, *this, bore_dofs);
    for (const PrescribedDof &p : prescribed)
      inv_mass.local_element(p.index) = 0;
    prescribed_velocity.reset();
    if (!prm.boundary.prescribed_velocity_ids.empty())
      prescribed_velocity = make_vector_function(prm.boundary.prescribed_velocity_expression,
                                                 prm.boundary.prescribed_velocity_constants,
                                                 "x,y,z,t",
                                                 "Boundary conditions/Prescribed velocity");

    applied = applied_force_dofs(prm, *this);
    applied_force.reset();
    if (!prm.boundary.applied_force_ids.empty())
      applied_force = make_vector_function(prm.boundary.applied_force_expression,
                                           prm.boundary.applied_force_constants,
                                           "x,y,z,t",
                                           "Boundary conditions/Applied force");

    nodal_damping_active = prm.solver.damping_form == DampingForm::nodal_field &&
                           damping_model() != DampingModel::none;
    if (nodal_damping_active)
      {
        nodal_damping.setup(*this);
        w.reinit(vector_partitioner);
        f_u.reinit(vector_partitioner);
      }

    nodal_update_prepared = false;
    w_current             = false;
    t                     = 0;
    n_steps               = 0;
    damping_dissipation   = 0;
    boundary_work         = 0;
  }


  void
  ExplicitSolver::attach_rigid_body(RigidBodyCoupling *body)
  {
    rigid_body = body;
    if (rigid_body != nullptr)
      rigid_body->connect(*this, prescribed);
  }


  void
  ExplicitSolver::set_time_step(const double time_step)
  {
    AssertThrow(time_step > 0, ExcMessage("Internal error: time step <= 0."));
    dt = time_step;
  }



  double
  ExplicitSolver::assemble_forces(const VectorType &u_in,
                                  const VectorType *v_in,
                                  VectorType       &f_out,
                                  const bool        with_contact,
                                  const bool        advance,
                                  const bool        f_is_zero,
                                  StrainEnergies   *strain)
  {
    double power;
    {
      const ScopedTime timer(times.elements);
      power = element_forces(u_in, v_in, f_out, f_is_zero, strain);
    }
    add_contact_and_compress(u_in, f_out, with_contact, advance);
    return power;
  }



  void
  ExplicitSolver::add_contact_and_compress(const VectorType &u_in,
                                           VectorType       &f_out,
                                           const bool        with_contact,
                                           const bool        advance)
  {
    if (with_contact && contact != nullptr)
      {
        const ScopedTime timer(times.contact);
        contact->add_forces(u_in, dt, advance, f_out);
      }
    {
      const ScopedTime timer(times.update), part(times.constraints);
      condense(f_out);
    }
    const ScopedTime timer(times.communication);
    f_out.compress(VectorOperation::add);
  }



  void
  ExplicitSolver::nodal_damped_forces(StrainEnergies *strain)
  {
    {
      const ScopedTime timer(times.elements);
      if (!w_current)
        nodal_damping.damped_displacement(u, v, w);
      w_current = false;
      element_forces(w, nullptr, f, f_cleared);
      if (strain)
        {
          element_forces(u, nullptr, f_u, false, strain);
          nodal_damping.sample(t, NodalDamping::power(v, f, f_u));
        }
    }
    add_contact_and_compress(u, f, true, true);
  }


  void
  ExplicitSolver::compute_internal_force(VectorType &force)
  {
    force.reinit(vector_partitioner);
    assemble_forces(u, nullptr, force, false, false);
  }


  void
  ExplicitSolver::compute_residual(VectorType &residual)
  {
    residual.reinit(vector_partitioner);
    assemble_forces(u, nullptr, residual, true, false);
    for (unsigned int i = 0; i < residual.locally_owned_size(); ++i)
      residual.local_element(i) -= f_ext.local_element(i);
  }


  void
  ExplicitSolver::compute_residual(const VectorType &w, VectorType &residual)
  {
    residual.reinit(vector_partitioner);
    assemble_forces(w, nullptr, residual, true, false);
    for (unsigned int i = 0; i < residual.locally_owned_size(); ++i)
      residual.local_element(i) -= f_ext.local_element(i);
  }



  void
  ExplicitSolver::step(Energies *energies)
  {
    Assert(dt > 0, ExcInternalError());
    StepTerms terms(n_steps == 0, dt);
    if (energies)
      begin_energies(*energies, terms);
    terms.damping_power = internal_and_contact_forces(energies);
    bool w_formed       = false;
    {
      const ScopedTime timer(times.update);
      add_rigid_body_damping(terms);
      add_applied_forces(terms);
      take_net_forces();
      w_formed = update_free_dofs(terms, energies != nullptr);
      add_applied_work(terms);
      if (rigid_body)
        {
          const ScopedTime part(times.rigid_body);
          rigid_body->advance(prescribed, u, terms.h, dt, t);
        }
      update_prescribed(terms, energies != nullptr);
    }
    if (energies)
      collect_energies(*energies, terms);
    accumulate(terms);
    exchange_ghosts(w_formed);
    w_current = w_formed;
    t += dt;
    ++n_steps;
    ++times.steps;
  }



  ExplicitSolver::StepTerms::StepTerms(const bool first, const double dt)
    : first(first)
    , h(first ? 0.5 * dt : dt) // v_{1/2} = v_0 + dt/2 a_0
  {}



  void
  ExplicitSolver::begin_energies(Energies &energies, StepTerms &terms)
  {
    const ScopedTime timer(times.energies);
    energies.time = t;
    energies.step = n_steps;
    for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
      terms.gravity_work += f_ext.local_element(i) * (u.local_element(i) - u0.local_element(i));
  }



  double
  ExplicitSolver::internal_and_contact_forces(Energies *energies)
  {
    // the strain energies at t_n come from the force pass over the cells
    const bool     damping = damping_model() != DampingModel::none;
    StrainEnergies strain;
    double         power = 0; // of the strain-rate form; the nodal one is sampled
    if (nodal_damping_active)
      nodal_damped_forces(energies ? &strain : nullptr);
    else
      power = assemble_forces(
        u, damping ? &v : nullptr, f, true, true, f_cleared, energies ? &strain : nullptr);
    if (energies)
      {
        energies->internal            = strain.internal;
        energies->hourglass           = strain.hourglass;
        energies->hourglass_reference = strain.hourglass_reference;
      }
    return power;
  }



  void
  ExplicitSolver::add_rigid_body_damping(StepTerms &terms)
  {
    if (rigid_body && rigid_body->damps(t))
      terms.damping_power += rigid_body->add_damping(u, v, f, terms.h, terms.rigid_body_work);
  }



  void
  ExplicitSolver::add_applied_forces(StepTerms &terms)
  {
    // applied forces at t_n (enter f with the sign of internal forces)
    terms.work = apply_forces(terms.h, terms.applied_total) + terms.rigid_body_work;
  }



  void
  ExplicitSolver::take_net_forces()
  {
    // the net forces that the prescribed DoFs and the rigid body need after
    // the update, which clears f behind itself (f = 0 for the next step's
    // assembly without a pass of its own over the vector)
    const double *force          = f.begin();
    const double *external_force = f_ext.begin();
    for (auto &p : prescribed)
      {
        const unsigned int n_components =
          (p.kind == BoundaryKind::rigid_axle && p.component == 0) ? 3 : 1;
        for (unsigned int c = 0; c < n_components; ++c)
          p.net_force[c] = external_force[p.index + c] - force[p.index + c];
      }
  }



  bool
  ExplicitSolver::update_free_dofs(StepTerms &terms, const bool with_energies)
  {
    bool w_formed = false;
    const double       h              = terms.h;
    double            *displacement   = u.begin();
    double            *velocity       = v.begin();
    double            *force          = f.begin();
    const double      *external_force = f_ext.begin();
    const double      *inverse_mass   = inv_mass.begin();
    const double      *lumped         = mass.begin();
    const unsigned int n              = u.locally_owned_size();
    if (!with_energies)
      {
        if (!nodal_update_prepared)
          prepare_nodal_update();
        if (nodal_damping_active && nodal_update.forms_damped_field())
          {
            nodal_update.apply(h, dt, displacement, velocity, force, w.begin());
            w_formed = true;
          }
        else if (nodal_update.active())
          nodal_update.apply(h, dt, displacement, velocity, force);
        else
          NodalUpdate::apply_per_dof(
            h, dt, inverse_mass, external_force, n, displacement, velocity, force);
      }
    else
      {
        // the same update, with the kinetic energy of the mid-step velocity
        double kinetic = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double v_old = velocity[i];
            velocity[i] += h * inverse_mass[i] * (external_force[i] - force[i]);
            displacement[i] += dt * velocity[i];
            force[i]            = 0;
            const double v_mid = terms.first ? v_old : 0.5 * (v_old + velocity[i]);
            if (inverse_mass[i] > 0)
              kinetic += 0.5 * lumped[i] * v_mid * v_mid;
          }
        terms.kinetic = kinetic;
      }
    f_cleared = true;
    return w_formed;
  }



  void
  ExplicitSolver::add_applied_work(StepTerms &terms) const
  {
    // the applied forces' work with the new velocity (the old one is in
    // apply_forces())
    const double *velocity = v.begin();
    for (const auto &[i, d, w] : applied)
      terms.work += 0.5 * terms.h * w * terms.applied_total[d] * velocity[i];
  }



  void
  ExplicitSolver::accumulate(const StepTerms &terms)
  {
    const ScopedTime timer(times.update);
    // h P rounded before it is added, not fused into one multiply-add:
    // the sum's bits as the step has always had them (the compiler paired
    // the two additions into one vector add there)
    double dissipated = terms.h * terms.damping_power;
    asm("" : "+x"(dissipated));
    damping_dissipation += dissipated;
    boundary_work += terms.work;
  }



  void
  ExplicitSolver::exchange_ghosts(const bool w_formed)
  {
    {
      const ScopedTime timer(times.communication);
      u.update_ghost_values();
      v.update_ghost_values();
    }
    const ScopedTime timer(times.update), part(times.constraints);
    if (w_formed)
      {
        // w on the hanging DoFs as they are set, then where else the step
        // changed u or v after the update (prescribed DoFs, ghosts)
        distribute(u, &v, &nodal_damping.beta_per_dof(), &w);
        nodal_damping.fix_up(u, v, w);
      }
    else
      distribute(u, &v);
  }


  void
  ExplicitSolver::prepare_nodal_update()
  {
    // the prescribed DoFs' u and v are overwritten after the update (but
    // for an applied force's DoF: its v enters the work before that)
    std::vector<bool> overwritten(u.locally_owned_size(), false);
    for (const auto &p : prescribed)
      overwritten[p.index] = true;
    for (const auto &[i, d, w] : applied)
      overwritten[i] = false;
    nodal_update.prepare(mass.begin(),
                         inv_mass.begin(),
                         f_ext.begin(),
                         node_component.data(),
                         overwritten,
                         u.locally_owned_size(),
                         prm.solver.gravity);
    if (nodal_damping_active &&
        nodal_update.set_damping(nodal_damping.beta_per_dof().begin(), u.locally_owned_size()))
      {
        std::vector<unsigned int> overwritten_dofs;
        for (const auto &p : prescribed)
          overwritten_dofs.push_back(p.index);
        nodal_damping.prepare_fix_up(u, overwritten_dofs);
      }
    nodal_update_prepared = true;
  }


  double
  ExplicitSolver::apply_forces(const double h, Tensor<1, dim> &applied_total)
  {
    double work_step = 0;
    if (applied_force)
      {
        applied_force->set_time(t);
        for (unsigned int d = 0; d < dim; ++d)
          applied_total[d] = applied_force->value(Point<dim>(), d);
        for (const auto &[i, d, w] : applied)
          f.local_element(i) -= w * applied_total[d];
      }
    // applied-force work over the step, with the old velocity (the new one
    // is added after the update)
    const double *V = v.begin();
    for (const auto &[i, d, w] : applied)
      work_step += 0.5 * h * w * applied_total[d] * V[i];
    return work_step;
  }


  void
  ExplicitSolver::update_prescribed(StepTerms &terms, const bool with_energies)
  {
    const double  h            = terms.h;
    double       *displacement = u.begin();
    double       *velocity     = v.begin();
    const double *lumped       = mass.begin();
    // prescribed DoFs: fixed, velocity function (at the middle of the
    // step), spinning axle, rigid body
    if (prescribed_velocity)
      prescribed_velocity->set_time(t + 0.5 * dt);
    const double     t_new  = t + dt;
    const Point<dim> centre = prm.geometry_model->wheel_centre();
    const double     omega  = prm.initial.wheel_angular_velocity;
    // the axle's angle at t_new, its cosine and sine once for all its DoFs
    const double spin_c = std::cos(omega * t_new), spin_s = std::sin(omega * t_new);
    const std::function<Tensor<1, dim>(const Point<dim> &)> body_motion =
      rigid_body ? rigid_body->coupled_motion() : nullptr;
    for (auto &p : prescribed)
      {
        double u_new = p.u_prev;
        if (p.kind == BoundaryKind::prescribed_velocity)
          u_new = p.u_prev + dt * prescribed_velocity->value(node_points[p.index], p.component);
        else if (p.kind == BoundaryKind::spinning_axle)
          {
            const Tensor<1, dim> r = node_points[p.index] - centre;
            u_new                  = (rotate_about_y(r, spin_c, spin_s) - r)[p.component];
          }
        else if (p.kind == BoundaryKind::rigid_axle && body_motion)
          u_new = body_motion(node_points[p.index])[p.component];
        const double v_new = (u_new - p.u_prev) / dt;
        // reaction that enforces the motion, and its work over the step
        // over [t_{n-1/2}, t_{n+1/2}] (the first step: [0, dt/2])
        // (the rigid body's nodes are part of its own balance)
        if (p.kind != BoundaryKind::rigid_axle)
          {
            const double reaction = lumped[p.index] * (v_new - p.v_prev) / h - p.net_force[0];
            terms.work += reaction * h * 0.5 * (p.v_prev + v_new);
          }
        const double v_mid = terms.first ? p.v_prev : 0.5 * (p.v_prev + v_new);
        if (with_energies)
          terms.kinetic += 0.5 * lumped[p.index] * v_mid * v_mid;
        displacement[p.index] = u_new;
        velocity[p.index]     = v_new;
        p.u_prev              = u_new;
        p.v_prev              = v_new;
      }
  }


  void
  ExplicitSolver::collect_energies(Energies &energies, const StepTerms &terms)
  {
    const ScopedTime timer(times.energies);
    // dissipation and boundary work up to t_n: all earlier steps plus
    // half of the current one (none at t_0)
    const double half     = terms.first ? 0. : 0.5;
    const double local[7] = {terms.kinetic,
                             terms.gravity_work,
                             damping_dissipation + half * terms.h * terms.damping_power +
                               (nodal_damping_active ? nodal_damping.dissipation() : 0.),
                             boundary_work + half * terms.work,
                             energies.internal,
                             energies.hourglass,
                             energies.hourglass_reference};
    double       global[7];
    Utilities::MPI::sum(ArrayView<const double>(local, 7),
                        mpi_communicator,
                        ArrayView<double>(global, 7));
    energies.kinetic             = global[0];
    energies.damping             = global[2];
    energies.external_work       = global[1] + global[3];
    energies.internal            = global[4];
    energies.hourglass           = global[5];
    energies.hourglass_reference = global[6];
    if (contact)
      {
        // replicated on every rank: no sum
        energies.contact  = contact->summary().elastic_energy;
        energies.friction = contact->friction_dissipation();
        energies.damping += contact->damping_dissipation();
      }
    if (rigid_body)
      rigid_body->add_energies(energies);
  }



} // namespace WheelRail
