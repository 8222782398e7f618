/**
 * @file contact/slave_forces.cc
 * The contact of the candidate slave nodes at one evaluation: each rank's
 * block of the candidates (closest point, penalty force, friction return
 * map), the exchange of the blocks' states, and the totals summed in slave
 * order on every rank.
 */

#include <deal.II/base/mpi.h>

#include <wheelrail/base/stopwatch.h>
#include <wheelrail/contact/bilinear_face.h>
#include <wheelrail/contact/penalty_contact.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace WheelRail
{
  using namespace ContactGeometry;



  std::pair<unsigned int, unsigned int>
  PenaltyContact::candidate_block(const unsigned int n, const unsigned int rank) const
  {
    const unsigned long n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    return {static_cast<unsigned int>(n * static_cast<unsigned long>(rank) / n_ranks),
            static_cast<unsigned int>(n * (rank + 1ul) / n_ranks)};
  }



  std::pair<unsigned int, unsigned int>
  PenaltyContact::own_candidates(const unsigned int n) const
  {
    return candidate_block(n, Utilities::MPI::this_mpi_process(mpi_communicator));
  }



  // Separated slaves that cannot touch yet. A slave found separated at an
  // explicit step, with its closest point inside a face at the gap g > 0,
  // is at least g from the surface of its candidate faces, and at least
  // (1 - Rebuild fraction) m from every face that is not a candidate
  // (approach_trigger.cc). The distance of a point from a bilinear face
  // changes in one step by at most the motion of the point plus the largest
  // motion of the face's corners (the face's point of the same face
  // coordinates moves by a convex combination of its corners' motions).
  // Pass::clearance starts at d / 2, d = min(g, (1 - Rebuild fraction) m),
  // and loses at every step the slave's motion plus the largest corner
  // motion over its listed faces. While it is positive, the slave is still
  // more than d / 2 from each of those faces, and a face that
  // compute_slaves() left out for a gap below -margin stays left out (it
  // requires such faces to be more than d beyond -margin before it marks
  // the slave). So the slave is separated, with the state separate() gave
  // it but for the gap, which stays as it was found (only
  // write_contact_nodes() prints it, at the run's last step, where
  // evaluate_every_slave() has every slave computed). Its position and
  // previous position are updated as for any slave. The forces, and
  // everything else, are those of a computation at every step.
  void
  PenaltyContact::select_slaves(Pass &pass, const bool advance, const bool skip_separated)
  {
    if (pass.clearance.size() != pass.slaves.size())
      pass.clearance.assign(pass.slaves.size(), -std::numeric_limits<double>::infinity());
    if (skip_separated)
      {
        pass.face_motion.resize(pass.faces.size());
        for (const unsigned int f : pass.candidate_faces)
          {
            const unsigned int *v = pass.faces[f].node;
            pass.face_motion[f]   = std::max(std::max(node_motion[v[0]], node_motion[v[1]]),
                                           std::max(node_motion[v[2]], node_motion[v[3]]));
          }
      }
    pass.evaluated.clear();
    for (unsigned int c = 0; c < pass.candidate_slaves.size(); ++c)
      {
        const unsigned int s = pass.candidate_slaves[c];
        if (skip_separated && pass.clearance[s] > 0)
          {
            double corners = 0;
            for (unsigned int k = pass.face_offsets[c]; k < pass.face_offsets[c + 1]; ++k)
              corners = std::max(corners, pass.face_motion[pass.face_lists[k]]);
            pass.clearance[s] -= node_motion[pass.slave_node[s]] + corners;
            if (pass.clearance[s] > 0)
              {
                ContactNodeState &state = pass.slaves[s];
                state.x                 = node_x[pass.slave_node[s]];
                if (advance)
                  state.x_previous = state.x;
                continue;
              }
          }
        pass.evaluated.push_back(c);
      }
    pass.separated_inside.assign(pass.evaluated.size(), 0);
  }



  void
  PenaltyContact::set_clearance(Pass &pass, const bool advance)
  {
    const double reach = kept_distance();
    for (unsigned int k = 0; k < pass.evaluated.size(); ++k)
      {
        const unsigned int      s     = pass.candidate_slaves[pass.evaluated[k]];
        const ContactNodeState &state = pass.slaves[s];
        pass.clearance[s]             = (advance && pass.separated_inside[k] && state.gap > 0) ?
                                          0.5 * std::min(state.gap, reach) :
                                          -std::numeric_limits<double>::infinity();
      }
  }



  void
  PenaltyContact::compute_slaves(Pass &pass, const double dt, const bool advance)
  {
    const auto own = own_candidates(pass.evaluated.size());
    for (unsigned int e = own.first; e < own.second; ++e)
      compute_slave(pass, e, dt, advance);
  }



  void
  PenaltyContact::compute_slave(Pass &pass, const unsigned int e, const double dt, const bool advance)
  {
    const unsigned int c     = pass.evaluated[e];
    const unsigned int s     = pass.candidate_slaves[c];
    ContactNodeState  &state = pass.slaves[s];
    const Point<dim>  &xs    = node_x[pass.slave_node[s]];
    state.x                  = xs;
    const Point<dim> x_prev  = state.x_previous;
    state.friction_loss      = 0;
    state.damping_work       = 0;
    if (advance)
      state.x_previous = xs;

    const ClosestPoint best = closest_point(pass, c, xs);
    state.gap               = best.face >= 0 ? best.gap : 0.;
    if (best.face < 0 || best.gap >= 0)
      {
        separate(state, xs, state.gap, advance);
        pass.separated_inside[e] = best.face >= 0 && best.out == 0 &&
                                   best.ignored_slack > std::min(best.gap, kept_distance());
        return;
      }

    // the penalty force, with the normal damping
    const MasterFace &face = pass.faces[best.face];
    const double      k    = slave_stiffness(state, face);
    if (advance && state.face < 0)
      new_contact_depth = std::max(new_contact_depth, -best.gap);
    state.in_contact   = true;
    state.normal       = best.normal;
    state.normal_force = -k * best.gap;
    if (advance && prm.damping_ratio > 0 && state.face >= 0 && std::isfinite(state.gap_previous))
      add_normal_damping(state, k, best.gap, dt);

    if (law && advance)
      add_friction(pass, state, best, x_prev, k, dt);
    else
      {
        // frictionless, or a static evaluation (no time step to slip in)
        state.tangential_force = Tensor<1, dim>();
        state.slip_velocity    = 0;
        state.slip_rate        = Tensor<1, dim>();
        state.cof              = law ? law->coefficient(0.) : 0.;
        state.slipping         = false;
      }
    state.face         = best.face;
    state.xi           = best.xi;
    state.eta          = best.eta;
    state.gap_previous = advance ? best.gap : std::numeric_limits<double>::quiet_NaN();
  }



  ClosestPoint
  PenaltyContact::closest_point(Pass &pass, const unsigned int c, const Point<dim> &xs)
  {
    // closest point over the candidate faces; a projection inside a
    // face wins, otherwise the nearest face edge takes over
    const double margin = prm.search_margin;
    ClosestPoint best;
    for (unsigned int k = pass.face_offsets[c]; k < pass.face_offsets[c + 1]; ++k)
      {
        const unsigned int f     = pass.face_lists[k];
        const FaceBound   &bound = face_bound(pass, f);
        if (bound.usable())
          {
            // the projection cannot lie within 1.1 of this face (see
            // compute_face_bound()): project() would give out > 0.1,
            // skipped below; most candidates are neighbours of the
            // face under the slave and end here
            const Tensor<1, dim> d  = xs - bound.centre;
            const double         dd = d.norm_square();
            const double         dn = d * bound.normal;
            const double         reach =
              1.01 * (bound.radius + (std::sqrt(dd) + bound.radius) * bound.sin_angle);
            if (dd - dn * dn > reach * reach)
              continue;
          }
        const MasterFace &face = pass.faces[f];
        BilinearFace      bf{{&node_x[face.node[0]],
                              &node_x[face.node[1]],
                              &node_x[face.node[2]],
                              &node_x[face.node[3]]}};
        // a projection beyond 1.1 is not used: on a nearly flat face
        // Newton may stop as soon as it is clearly there
        double xi, eta;
        pass.frames[f].project(xs,
                               xi,
                               eta,
                               bound.usable() ? 0.1 : std::numeric_limits<double>::infinity());
        const double out = std::max(std::abs(xi), std::abs(eta)) - 1.;
        if (out > 0.1)
          continue;
        if (out > 0)
          bf.project_to_boundary(xs, xi, eta);
        Point<dim>     x;
        Tensor<1, dim> dxi, deta;
        double         N[4];
        bf.evaluate(xi, eta, x, dxi, deta, N);
        Tensor<1, dim> n;
        for (unsigned int j = 0; j < 4; ++j)
          n += N[j] * averaged_normal(face.node[j]);
        n /= n.norm();
        const double gap = n * (xs - x);
        if (gap < -margin)
          {
            best.ignored_slack = std::min(best.ignored_slack, -margin - gap);
            continue;
          }
        const double o      = std::max(out, 0.);
        const bool   better = (o < best.out - 1e-12) ||
                            (o <= best.out + 1e-12 && std::abs(gap) < std::abs(best.gap));
        if (best.face < 0 || better)
          {
            best.face   = f;
            best.xi     = xi;
            best.eta    = eta;
            best.gap    = gap;
            best.out    = o;
            best.normal = n;
          }
      }
    return best;
  }



  void
  PenaltyContact::add_normal_damping(ContactNodeState &state,
                                     const double      k,
                                     const double      gap,
                                     const double      dt) const
  {
    // viscous normal force on the closing rate of the gap over the
    // last explicit step (a static evaluation in between leaves the
    // rate unknown: no damping this step); the total stays
    // compressive. Central differences with a damper on the last
    // step's rate keep a mode of frequency w stable while
    // (w dt)^2 + 4 zeta w dt < 4. With w^2 = 4 k / m of the pair (two
    // nodes, both springs in two passes), zeta is limited so that the
    // left side stays below 2, half the limit: the other half is left
    // for the surface cells' own stiffness, which the pair's estimate
    // leaves out. A spring stiff for the step (the coarse meshes at
    // the stable step, w dt up to 1.8) is left undamped; at h 0.66 mm
    // (w dt 0.26) and in the contact block tests (1.01) a zeta of 0.2
    // acts in full
    const double w_dt = 2. * std::sqrt(k / state.mass) * dt;
    const double zeta = std::min(prm.damping_ratio, std::max(0., (2. - w_dt * w_dt) / (4. * w_dt)));
    const double c    = 2. * zeta * std::sqrt(k * state.mass);
    const double rate = (gap - state.gap_previous) / dt;
    const double fd   = std::max(-c * rate, -state.normal_force);
    state.normal_force += fd;
    state.damping_work = -fd * rate * dt;
  }



  Tensor<1, dim>
  PenaltyContact::slip_increment(const Pass             &pass,
                                 const ContactNodeState &state,
                                 const ClosestPoint     &best,
                                 const Point<dim>       &x_prev) const
  {
    // the contact point now minus the old contact point on the current
    // master geometry
    const MasterFace &face = pass.faces[best.face];
    BilinearFace      bn{{&node_x[face.node[0]],
                          &node_x[face.node[1]],
                          &node_x[face.node[2]],
                          &node_x[face.node[3]]}};
    Point<dim>        x_old, x_new;
    Tensor<1, dim>    dxi, deta;
    double            N[4];
    if (state.face < 0)
      {
        // a new contact: the slip of this step is the motion of the slave
        // relative to the face, from its previous position projected onto
        // the same face
        double xi_p, eta_p;
        bn.project(x_prev, xi_p, eta_p);
        bn.evaluate(xi_p, eta_p, x_old, dxi, deta, N);
      }
    else
      {
        const MasterFace &old = pass.faces[state.face];
        BilinearFace      bf{{&node_x[old.node[0]],
                              &node_x[old.node[1]],
                              &node_x[old.node[2]],
                              &node_x[old.node[3]]}};
        bf.evaluate(state.xi, state.eta, x_old, dxi, deta, N);
      }
    bn.evaluate(best.xi, best.eta, x_new, dxi, deta, N);
    return x_new - x_old;
  }



  void
  PenaltyContact::add_friction(const Pass         &pass,
                               ContactNodeState   &state,
                               const ClosestPoint &best,
                               const Point<dim>   &x_prev,
                               const double        k,
                               const double        dt)
  {
    const double kt = prm.tangential_factor * k;
    // a new contact: the friction memory starts afresh
    if (state.face < 0)
      state.friction = friction->new_contact();
    const Tensor<1, dim>        de = slip_increment(pass, state, best, x_prev);
    const FrictionModel::Result r =
      friction->step(de, best.normal, state.normal_force, kt, state.mass, dt, state.friction);
    state.slip_rate        = r.slip_rate;
    state.slip_velocity    = r.slip;
    state.cof              = r.cof;
    state.tangential_force = r.force;
    state.slipping         = r.slipping;
    state.friction_loss    = r.friction_loss;
    state.damping_work += r.damping_work;
  }



  void
  PenaltyContact::separate(ContactNodeState &state,
                           const Point<dim> &xs,
                           const double      gap,
                           const bool        advance)
  {
    state.x             = xs;
    state.friction_loss = 0;
    state.damping_work  = 0;
    if (advance)
      state.x_previous = xs;
    state.gap              = gap;
    state.in_contact       = false;
    state.normal_force     = 0;
    state.tangential_force = Tensor<1, dim>();
    state.slip_velocity    = 0;
    state.slip_rate        = Tensor<1, dim>();
    state.slipping         = false;
    if (advance)
      state.face = -1;
  }



  void
  PenaltyContact::exchange_states(Pass &pass, const bool advance)
  {
    // Rank r computed the block own_candidates() gives it. Most candidates
    // are not in contact, and their state follows from the gap alone
    // (separate(), with the position every rank has): only the states in
    // contact travel whole. First the (contact, gap) pairs of all blocks,
    // then the contact states, whose number per rank the pairs tell.
    all_gather_gaps(pass);
    all_gather_contact_states(pass);
    const unsigned int n   = pass.evaluated.size();
    const auto         own = own_candidates(n);
    for (unsigned int c = 0, i = 0; c < n; ++c)
      {
        const bool in_contact = exchange_gaps[2 * c] == 1.;
        if (c < own.first || c >= own.second)
          {
            const unsigned int s     = pass.candidate_slaves[pass.evaluated[c]];
            pass.separated_inside[c] = exchange_gaps[2 * c] == 2.;
            if (in_contact)
              pass.slaves[s] = exchange_buffer[i];
            else
              separate(pass.slaves[s],
                       node_x[pass.slave_node[s]],
                       exchange_gaps[2 * c + 1],
                       advance);
          }
        i += in_contact;
      }
  }



  void
  PenaltyContact::all_gather_gaps(Pass &pass)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    const unsigned int n       = pass.evaluated.size();
    const auto         own     = own_candidates(n);
    std::vector<int>  &counts = exchange_counts, &displs = exchange_displs;
    counts.resize(n_ranks);
    displs.resize(n_ranks);
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        const auto block = candidate_block(n, r);
        counts[r]        = 2 * (block.second - block.first);
        displs[r]        = 2 * block.first;
      }
    exchange_gaps.resize(2 * n);
    // 1: in contact, 2: separated with the closest point inside a face, 0: else
    for (unsigned int c = own.first; c < own.second; ++c)
      {
        const ContactNodeState &state = pass.slaves[pass.candidate_slaves[pass.evaluated[c]]];
        exchange_gaps[2 * c]     = state.in_contact ? 1. : (pass.separated_inside[c] ? 2. : 0.);
        exchange_gaps[2 * c + 1] = state.gap;
      }
    int ierr = MPI_Allgatherv(MPI_IN_PLACE,
                              0,
                              MPI_DATATYPE_NULL,
                              exchange_gaps.data(),
                              counts.data(),
                              displs.data(),
                              MPI_DOUBLE,
                              mpi_communicator);
    AssertThrowMPI(ierr);
  }



  void
  PenaltyContact::all_gather_contact_states(const Pass &pass)
  {
    // exchange_counts and exchange_displs hold the blocks of (contact,
    // gap) pairs of all_gather_gaps()
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    const auto         own     = own_candidates(pass.evaluated.size());
    std::vector<int>  &counts = exchange_counts, &displs = exchange_displs;
    // the contact states, in candidate order
    const int    size  = sizeof(ContactNodeState);
    unsigned int total = 0;
    for (unsigned int r = 0; r < n_ranks; ++r)
      {
        const unsigned int first = displs[r] / 2, last = first + counts[r] / 2;
        unsigned int       count = 0;
        for (unsigned int c = first; c < last; ++c)
          count += exchange_gaps[2 * c] == 1.;
        counts[r] = count * size;
        displs[r] = total * size;
        total += count;
      }
    // grown when needed, never cleared: every entry up to total is written
    // below or received (a resize from empty would construct them all)
    if (exchange_buffer.size() < total)
      exchange_buffer.resize(total);
    for (unsigned int c = own.first,
                      i = displs[Utilities::MPI::this_mpi_process(mpi_communicator)] / size;
         c < own.second;
         ++c)
      if (exchange_gaps[2 * c] == 1.)
        exchange_buffer[i++] = pass.slaves[pass.candidate_slaves[pass.evaluated[c]]];
    const int ierr = MPI_Allgatherv(MPI_IN_PLACE,
                                    0,
                                    MPI_DATATYPE_NULL,
                                    exchange_buffer.data(),
                                    counts.data(),
                                    displs.data(),
                                    MPI_BYTE,
                                    mpi_communicator);
    AssertThrowMPI(ierr);
  }



  void
  PenaltyContact::accumulate(const Pass &pass, const bool advance)
  {
    // the slaves evaluated at this step, in candidate order: a slave that
    // select_slaves() left out was separated when it was last evaluated
    // (separate() zeroed its losses) and adds nothing
    for (const unsigned int c : pass.evaluated)
      {
        const unsigned int      s     = pass.candidate_slaves[c];
        const ContactNodeState &state = pass.slaves[s];
        damping_loss += state.damping_work;
        dissipation += state.friction_loss;
        if (!state.in_contact)
          continue;
        const MasterFace &face = pass.faces[state.face];
        const double      k    = slave_stiffness(state, face);
        totals.max_penetration = std::max(totals.max_penetration, -state.gap);
        totals.elastic_energy += 0.5 * k * state.gap * state.gap;
        if (law && advance)
          totals.elastic_energy +=
            0.5 * state.friction.elastic_force.norm_square() / (prm.tangential_factor * k);

        const Tensor<1, dim> F = state.normal_force * state.normal + state.tangential_force;
        // the force on the first pass's slave body: in the second pass the
        // slaves belong to the other body
        totals.force += (&pass == &passes.front()) ? F : -F;
        ++totals.n_contact;
        double N[4];
        BilinearFace::shape(state.xi, state.eta, N);
        {
          Point<dim> X_c, x_c;
          for (unsigned int j = 0; j < 4; ++j)
            {
              X_c += N[j] * node_X[face.node[j]];
              x_c += N[j] * node_x[face.node[j]];
            }
          totals.relative_displacement += (state.x - state.X) - (x_c - X_c);
        }
        if (state.slipping)
          ++totals.n_slip;
        if (law &&
            state.tangential_force.norm() > state.cof * state.normal_force * (1 + 1e-12) + 1e-300)
          ++totals.n_violation;

        ContactPair pair;
        pair.slave = node_dof[pass.slave_node[s]];
        for (unsigned int v = 0; v < 4; ++v)
          {
            pair.master[v] = node_dof[face.node[v]];
            pair.shape[v]  = N[v];
          }
        pair.normal    = state.normal;
        pair.stiffness = k;
        pairs.push_back(pair);
      }
  }
} // namespace WheelRail
