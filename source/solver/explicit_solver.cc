#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>

#include <wheelrail/base/stopwatch.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/solver/explicit_solver.h>

#include <algorithm>
#include <array>
#include <cmath>

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

    // the wheel's nodes for the run-up damping of its rigid motion: their
    // x DoFs in DoF order (a node's y and z DoFs follow its x DoF)
    runup_nodes.clear();
    for (unsigned int k = 0; k < mass.locally_owned_size(); ++k)
      if (node_material[k] == Geometry::MaterialIds::wheel && node_component[k] == 0)
        {
          AssertThrow(k + 2 < mass.locally_owned_size() && node_component[k + 2] == 2 &&
                        node_material[k + 2] == Geometry::MaterialIds::wheel,
                      ExcInternalError());
          runup_nodes.push_back({node_points[k][0], node_points[k][2], k});
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

    nodal_update_prepared = false;
    t                     = 0;
    n_steps               = 0;
    damping_dissipation   = 0;
    boundary_work         = 0;
  }


  void
  ExplicitSolver::attach_wheelset(Wheelset *ws)
  {
    wheelset = ws;
    if (wheelset == nullptr)
      return;
    const Point<dim> centre   = Geometry::wheel_centre(prm.geometry);
    double           local[2] = {0, 0};
    for (const auto &p : prescribed)
      if (p.kind == BoundaryKind::rigid_axle && p.component == 0)
        {
          const Tensor<1, dim> r = node_points[p.index] - centre;
          local[0] += mass.local_element(p.index);
          local[1] += mass.local_element(p.index) * (r[0] * r[0] + r[2] * r[2]);
        }
    // polar inertia of the whole FE wheel about the axle
    double wheel_inertia = 0;
    for (unsigned int i = 0; i < mass.locally_owned_size(); ++i)
      if (node_material[i] == Geometry::MaterialIds::wheel && node_component[i] == 0)
        {
          const Tensor<1, dim> r = node_points[i] - centre;
          wheel_inertia += mass.local_element(i) * (r[0] * r[0] + r[2] * r[2]);
        }
    double global[2];
    Utilities::MPI::sum(ArrayView<const double>(local, 2),
                        mpi_communicator,
                        ArrayView<double>(global, 2));
    wheelset->set_bore_inertia(global[0],
                               global[1],
                               total_mass(Geometry::MaterialIds::wheel),
                               Utilities::MPI::sum(wheel_inertia, mpi_communicator));
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
    Clock::time_point clock = Clock::now();
    const double      power = element_forces(u_in, v_in, f_out, f_is_zero, strain);
    times.elements += lap(clock);
    if (with_contact && contact != nullptr)
      {
        contact->add_forces(u_in, dt, advance, f_out);
        times.contact += lap(clock);
      }
    condense(f_out);
    times.update += lap(clock);
    f_out.compress(VectorOperation::add);
    times.communication += lap(clock);
    return power;
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
    const bool   first = (n_steps == 0);
    const double h     = first ? 0.5 * dt : dt; // v_{1/2} = v_0 + dt/2 a_0

    Clock::time_point clock        = Clock::now();
    double            gravity_work = 0;
    if (energies)
      {
        energies->time = t;
        energies->step = n_steps;
        for (unsigned int i = 0; i < u.locally_owned_size(); ++i)
          gravity_work += f_ext.local_element(i) * (u.local_element(i) - u0.local_element(i));
        times.energies += lap(clock);
      }

    // the strain energies at t_n come from the force pass over the cells
    const bool     damping = damping_model() != DampingModel::none;
    StrainEnergies strain;
    double         power = assemble_forces(
      u, damping ? &v : nullptr, f, true, true, f_cleared, energies ? &strain : nullptr);
    if (energies)
      {
        energies->internal            = strain.internal;
        energies->hourglass           = strain.hourglass;
        energies->hourglass_reference = strain.hourglass_reference;
      }
    double runup_work = 0;
    if (wheelset && t < prm.wheelset.runup_time && prm.wheelset.runup_damping > 0)
      power += add_runup_damping(h, runup_work);
    clock = Clock::now();

    // applied forces at t_n (enter f with the sign of internal forces)
    Tensor<1, dim> applied_total;
    double         work_step = apply_forces(h, applied_total) + runup_work;

    double       *U = u.begin();
    double       *V = v.begin();
    double       *F = f.begin();
    const double *G = f_ext.begin();
    // the net forces that the prescribed DoFs and the axle need after the
    // update, which clears f behind itself (f = 0 for the next step's
    // assembly without a pass of its own over the vector)
    for (auto &p : prescribed)
      {
        const unsigned int n_components =
          (p.kind == BoundaryKind::rigid_axle && p.component == 0) ? 3 : 1;
        for (unsigned int c = 0; c < n_components; ++c)
          p.net_force[c] = G[p.index + c] - F[p.index + c];
      }
    const double      *IM = inv_mass.begin();
    const double      *M  = mass.begin();
    const unsigned int n  = u.locally_owned_size();
    double             ke = 0;
    if (energies == nullptr)
      {
        if (!nodal_update_prepared)
          prepare_nodal_update();
        if (nodal_update.active())
          nodal_update.apply(h, dt, U, V, F);
        else
          NodalUpdate::apply_per_dof(h, dt, IM, G, n, U, V, F);
      }
    else
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            const double vo = V[i];
            V[i] += h * IM[i] * (G[i] - F[i]);
            U[i] += dt * V[i];
            F[i]            = 0;
            const double va = first ? vo : 0.5 * (vo + V[i]);
            if (IM[i] > 0)
              ke += 0.5 * M[i] * va * va;
          }
      }

    f_cleared = true;
    for (const auto &[i, d, w] : applied)
      work_step += 0.5 * h * w * applied_total[d] * V[i];

    if (wheelset)
      advance_wheelset(h);
    const double t_new = t + dt;
    update_prescribed(h, first, energies != nullptr, work_step, ke);
    if (energies)
      collect_energies(*energies, ke, gravity_work, power, h, work_step, first);
    damping_dissipation += h * power;
    boundary_work += work_step;
    times.update += lap(clock);

    u.update_ghost_values();
    v.update_ghost_values();
    times.communication += lap(clock);
    distribute(u, &v);
    times.update += lap(clock);
    t = t_new;
    ++n_steps;
    ++times.steps;
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
  ExplicitSolver::advance_wheelset(const double h)
  {
    // the rigid axle: the FE forces on the bore nodes and their moment
    const double    *U        = u.begin();
    const Point<dim> axle     = wheelset->axle_position();
    double           local[4] = {0, 0, 0, 0};
    // per bore vertex (its x-DoF; y and z follow contiguously)
    for (const auto &p : prescribed)
      if (p.kind == BoundaryKind::rigid_axle && p.component == 0)
        {
          const unsigned int i  = p.index;
          const double       fx = p.net_force[0], fy = p.net_force[1], fz = p.net_force[2];
          const double       rx = node_points[i][0] + U[i] - axle[0];
          const double       rz = node_points[i][2] + U[i + 2] - axle[2];
          local[0] += fx;
          local[1] += fy;
          local[2] += fz;
          local[3] += rz * fx - rx * fz;
        }
    double global[4];
    Utilities::MPI::sum(ArrayView<const double>(local, 4),
                        mpi_communicator,
                        ArrayView<double>(global, 4));
    wheelset->advance(Tensor<1, dim>({global[0], global[1], global[2]}), global[3], h, dt, t);
  }


  void
  ExplicitSolver::update_prescribed(const double h,
                                    const bool   first,
                                    const bool   with_energies,
                                    double      &work,
                                    double      &ke)
  {
    double       *U = u.begin();
    double       *V = v.begin();
    const double *M = mass.begin();
    // prescribed DoFs: fixed, velocity function (at the middle of the
    // step), spinning axle, rigid axle
    if (prescribed_velocity)
      prescribed_velocity->set_time(t + 0.5 * dt);
    const double     t_new  = t + dt;
    const Point<dim> centre = Geometry::wheel_centre(prm.geometry);
    const double     omega  = prm.initial.wheel_angular_velocity;
    // the axle's angle at t_new, its cosine and sine once for all its DoFs
    const double spin_c = std::cos(omega * t_new), spin_s = std::sin(omega * t_new);
    const auto   bore = wheelset ? wheelset->bore_motion() : Wheelset::BoreMotion{};
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
        else if (p.kind == BoundaryKind::rigid_axle)
          u_new = bore(node_points[p.index])[p.component];
        const double v_new = (u_new - p.u_prev) / dt;
        // reaction that enforces the motion, and its work over the step
        // over [t_{n-1/2}, t_{n+1/2}] (the first step: [0, dt/2])
        // (the rigid axle's bore nodes are part of the wheelset's balance)
        if (p.kind != BoundaryKind::rigid_axle)
          {
            const double r = M[p.index] * (v_new - p.v_prev) / h - p.net_force[0];
            work += r * h * 0.5 * (p.v_prev + v_new);
          }
        const double va = first ? p.v_prev : 0.5 * (p.v_prev + v_new);
        if (with_energies)
          ke += 0.5 * M[p.index] * va * va;
        U[p.index] = u_new;
        V[p.index] = v_new;
        p.u_prev   = u_new;
        p.v_prev   = v_new;
      }
  }


  void
  ExplicitSolver::collect_energies(Energies    &energies,
                                   const double ke,
                                   const double gravity_work,
                                   const double damping_power,
                                   const double h,
                                   const double work_step,
                                   const bool   first) const
  {
    // dissipation and boundary work up to t_n: all earlier steps plus
    // half of the current one (none at t_0)
    const double half     = first ? 0. : 0.5;
    const double local[7] = {ke,
                             gravity_work,
                             damping_dissipation + half * h * damping_power,
                             boundary_work + half * work_step,
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
    if (wheelset)
      {
        // replicated: axle, sprung mass, suspension, torque
        energies.kinetic += wheelset->kinetic();
        energies.internal += wheelset->spring_energy();
        energies.damping += wheelset->damper_dissipation();
        energies.external_work += wheelset->external_work();
      }
  }



} // namespace WheelRail
