/**
 * @file contact/penalty_contact.cc
 * PenaltyContact: collecting the slave nodes and master faces of the mesh,
 * one evaluation of the contact forces (add_forces()), the contact state
 * carried to the master nodes, and the checkpoint of the contact state.
 */

#include <deal.II/base/mpi.h>

#include <wheelrail/base/stopwatch.h>
#include <wheelrail/contact/bilinear_face.h>
#include <wheelrail/contact/penalty_contact.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace WheelRail
{
  using namespace ContactGeometry;



  PenaltyContact::PenaltyContact(const ContactParameters  &contact,
                                 const MaterialParameters &material,
                                 MPI_Comm                  comm)
    : prm(contact)
    , mpi_communicator(comm)
    , bulk_modulus(material.lambda() + 2. / 3. * material.mu())
    , area_penalty(contact.penalty_stiffness == PenaltyStiffness::area)
  {
    if (prm.law)
      {
        law = prm.law;
        FrictionModel::Options options;
        options.irreversible_slip_rate = prm.slip_rate == SlipRate::irreversible;
        options.relaxation_length      = prm.relaxation_length;
        options.relaxation_time        = prm.relaxation_time;
        options.damping_ratio          = prm.tangential_damping;
        friction                       = std::make_unique<FrictionModel>(*law, options);
      }
  }



  unsigned int
  PenaltyContact::node_index(const types::global_dof_index dof, const Point<dim> &X)
  {
    const auto it =
      std::lower_bound(dof_to_node.begin(),
                       dof_to_node.end(),
                       std::make_pair(dof, 0u),
                       [](const auto &a, const auto &b) { return a.first < b.first; });
    if (it != dof_to_node.end() && it->first == dof)
      return it->second;
    const unsigned int index = node_dof.size();
    node_dof.push_back(dof);
    node_X.push_back(X);
    dof_to_node.insert(it, std::make_pair(dof, index));
    return index;
  }



  void
  PenaltyContact::collect_pass(const DoFHandler<dim>   &dof_handler,
                               const types::boundary_id slave_id,
                               const types::boundary_id master_id,
                               Pass                    &pass)
  {
    std::vector<double> slaves, faces;
    pack_boundary_faces(dof_handler, slave_id, master_id, slaves, faces);
    add_slaves(Utilities::MPI::all_gather(mpi_communicator, slaves), pass);
    add_master_faces(Utilities::MPI::all_gather(mpi_communicator, faces), pass);
  }



  void
  PenaltyContact::pack_boundary_faces(const DoFHandler<dim>   &dof_handler,
                                      const types::boundary_id slave_id,
                                      const types::boundary_id master_id,
                                      std::vector<double>     &slaves,
                                      std::vector<double>     &faces) const
  {
    // local contributions, packed as doubles for one all_gather each:
    // slaves (dof, X, partial area), faces (4 dofs, 4 X, k, sign)
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto   face = cell->face(f);
              const double area = 0.5 * cross_product_3d(face->vertex(3) - face->vertex(0),
                                                         face->vertex(2) - face->vertex(1))
                                          .norm();
              if (face->boundary_id() == slave_id)
                for (unsigned int v = 0; v < 4; ++v)
                  {
                    slaves.push_back(face->vertex_dof_index(v, 0));
                    for (unsigned int d = 0; d < dim; ++d)
                      slaves.push_back(face->vertex(v)[d]);
                    slaves.push_back(0.25 * area);
                  }
              if (face->boundary_id() == master_id)
                {
                  for (unsigned int v = 0; v < 4; ++v)
                    {
                      faces.push_back(face->vertex_dof_index(v, 0));
                      for (unsigned int d = 0; d < dim; ++d)
                        faces.push_back(face->vertex(v)[d]);
                    }
                  const Tensor<1, dim> n = cross_product_3d(face->vertex(1) - face->vertex(0),
                                                            face->vertex(2) - face->vertex(0));
                  faces.push_back(area);
                  faces.push_back(cell->measure());
                  faces.push_back(n * (face->center() - cell->center()) > 0 ? 1. : -1.);
                }
            }
  }



  void
  PenaltyContact::add_slaves(const std::vector<std::vector<double>> &slave_parts, Pass &pass)
  {
    // slaves: sum the partial areas of shared nodes, order by position
    std::map<types::global_dof_index, std::pair<Point<dim>, double>> slave_map;
    for (const auto &part : slave_parts)
      for (unsigned int i = 0; i < part.size(); i += 5)
        {
          auto &entry = slave_map[static_cast<types::global_dof_index>(part[i])];
          entry.first = Point<dim>(part[i + 1], part[i + 2], part[i + 3]);
          entry.second += part[i + 4];
        }
    std::vector<std::tuple<Point<dim>, types::global_dof_index, double>> sorted_slaves;
    for (const auto &s : slave_map)
      sorted_slaves.emplace_back(s.second.first, s.first, s.second.second);
    std::sort(sorted_slaves.begin(), sorted_slaves.end(), [](const auto &a, const auto &b) {
      return lexicographic_less(std::get<0>(a), std::get<0>(b));
    });
    for (const auto &s : sorted_slaves)
      {
        ContactNodeState state;
        state.X    = std::get<0>(s);
        state.x    = state.X;
        state.area = std::get<2>(s);
        pass.slave_node.push_back(node_index(std::get<1>(s), state.X));
        pass.slaves.push_back(state);
      }
    // the slave faces (four consecutive vertex entries each), in slave indices
    std::map<types::global_dof_index, unsigned int> slave_of_dof;
    for (unsigned int k = 0; k < sorted_slaves.size(); ++k)
      slave_of_dof[std::get<1>(sorted_slaves[k])] = k;
    pass.slave_faces.clear();
    for (const auto &part : slave_parts)
      for (unsigned int i = 0; i + 20 <= part.size(); i += 20)
        {
          std::array<unsigned int, 4> face;
          for (unsigned int v = 0; v < 4; ++v)
            face[v] = slave_of_dof.at(static_cast<types::global_dof_index>(part[i + 5 * v]));
          pass.slave_faces.push_back(face);
        }
  }



  void
  PenaltyContact::add_master_faces(const std::vector<std::vector<double>> &face_parts, Pass &pass)
  {
    // faces, ordered by centroid
    std::vector<std::pair<Point<dim>, std::vector<double>>> sorted_faces;
    double thinnest = std::numeric_limits<double>::max(); // smallest V / A
    for (const auto &part : face_parts)
      for (unsigned int i = 0; i < part.size(); i += 19)
        {
          Point<dim> c;
          for (unsigned int v = 0; v < 4; ++v)
            c += 0.25 * Point<dim>(part[i + 4 * v + 1], part[i + 4 * v + 2], part[i + 4 * v + 3]);
          sorted_faces.emplace_back(c,
                                    std::vector<double>(part.begin() + i, part.begin() + i + 19));
          thinnest = std::min(thinnest, part[i + 17] / part[i + 16]);
        }
    // penalty stiffness per face (SPEC 4; Contact/Penalty stiffness)
    if (area_penalty && &pass == &passes.front())
      reference_length = prm.penalty_reference_length > 0 ? prm.penalty_reference_length : thinnest;
    const auto stiffness = [&](const double area, const double volume) {
      return area_penalty ? area_stiffness(area) :
                            prm.penalty_scale * bulk_modulus * area * area / volume;
    };
    std::sort(sorted_faces.begin(), sorted_faces.end(), [](const auto &a, const auto &b) {
      return lexicographic_less(a.first, b.first);
    });
    for (const auto &f : sorted_faces)
      {
        MasterFace face;
        for (unsigned int v = 0; v < 4; ++v)
          face.node[v] =
            node_index(static_cast<types::global_dof_index>(f.second[4 * v]),
                       Point<dim>(f.second[4 * v + 1], f.second[4 * v + 2], f.second[4 * v + 3]));
        face.stiffness = stiffness(f.second[16], f.second[17]);
        face.sign      = f.second[18];
        pass.faces.push_back(face);
        if (&pass == &passes.front())
          {
            node_area.resize(node_dof.size(), 0.);
            const Point<dim> &p0 = node_X[face.node[0]], &p1 = node_X[face.node[1]],
                             &p2 = node_X[face.node[2]], &p3 = node_X[face.node[3]];
            const double area = 0.5 * cross_product_3d(p3 - p0, p2 - p1).norm();
            for (unsigned int v = 0; v < 4; ++v)
              node_area[face.node[v]] += 0.25 * area;
          }
      }
  }



  void
  PenaltyContact::setup(
    const DoFHandler<dim>                                    &dof_handler,
    const std::shared_ptr<const Utilities::MPI::Partitioner> &vector_partitioner,
    const LinearAlgebra::distributed::Vector<double>         &point_mass)
  {
    partitioner = vector_partitioner;
    node_dof.clear();
    node_X.clear();
    dof_to_node.clear();
    passes.clear();
    passes.resize(prm.two_pass ? 2 : 1);
    collect_pass(dof_handler, prm.slave_boundary, prm.master_boundary, passes[0]);
    if (prm.two_pass)
      collect_pass(dof_handler, prm.master_boundary, prm.slave_boundary, passes[1]);
    AssertThrow(!passes[0].slaves.empty(),
                ExcMessage("Contact/Slave boundary " + std::to_string(prm.slave_boundary) +
                           " has no faces in this geometry."));
    AssertThrow(!passes[0].faces.empty(),
                ExcMessage("Contact/Master boundary " + std::to_string(prm.master_boundary) +
                           " has no faces in this geometry."));
    // the slaves' point masses (contact damping), replicated; a hanging
    // slave's comes from its masters, so that it is damped like the others
    std::vector<double> owned_mass(node_dof.size(), 0.), mass(node_dof.size(), 0.);
    for (unsigned int n = 0; n < node_dof.size(); ++n)
      if (partitioner->in_local_range(node_dof[n]))
        owned_mass[n] = point_mass.local_element(partitioner->global_to_local(node_dof[n]));
    Utilities::MPI::sum(owned_mass, mpi_communicator, mass);
    for (Pass &pass : passes)
      for (unsigned int s = 0; s < pass.slaves.size(); ++s)
        {
          pass.slaves[s].mass       = mass[pass.slave_node[s]];
          pass.slaves[s].x_previous = pass.slaves[s].X;
        }
    node_area.resize(node_dof.size(), 0.);
    for (Pass &pass : passes)
      {
        pass.bounds.assign(pass.faces.size(), FaceBound());
        pass.frames.assign(pass.faces.size(), ContactGeometry::FaceFrame());
        pass.bound_evaluation.assign(pass.faces.size(), 0);
      }
    node_normal.assign(node_dof.size(), Tensor<1, dim>());
    normal_evaluation.assign(node_dof.size(), 0);
    normal_offsets.assign(node_dof.size() + 1, 0);
    normal_entries.clear();
    evaluation    = 0;
    node_x        = node_X;
    node_x_search = node_X;
    std::vector<unsigned int> all(node_dof.size());
    for (unsigned int n = 0; n < all.size(); ++n)
      all[n] = n;
    plan_gather(all, all_gather);
    active_nodes.clear();
    plan_gather(active_nodes, active_gather);
    need_search  = true;
    dissipation  = 0;
    damping_loss = 0;
    searches     = 0;
    search_time  = 0;
    trigger_nodes.clear();
    step_motion_known = false;
    resume_valid      = false;
    overlap_checked   = false;
    approach_searches = 0;
    new_contact_depth = 0;
  }



  void
  PenaltyContact::add_forces(const LinearAlgebra::distributed::Vector<double> &u,
                             const double                                      dt,
                             const bool                                        advance,
                             LinearAlgebra::distributed::Vector<double>       &f)
  {
    Clock::time_point clock = Clock::now();
    update_positions(u, advance, clock);
    track_candidate_motion();
    // the averaged nodal normals and the face bounds of this evaluation are
    // computed where compute_slaves() first needs them
    ++evaluation;
    ++timing.evaluations;
    evaluate_passes(dt, advance, clock);
    scatter_forces(f);
    if (advance)
      ++steps_since_search;
    timing.forces += lap(clock);
  }



  void
  PenaltyContact::update_positions(const LinearAlgebra::distributed::Vector<double> &u,
                                   const bool                                        advance,
                                   Clock::time_point                                &clock)
  {
    // the ranks meet here first after their element loops, in the reduction
    // of the approach bound: what one waits for the other (imbalance, and
    // the noise of single steps) is timed on its own
    const bool approach = approach_bound_exceeded(u, advance, clock);
    if (need_search || steps_since_search >= prm.search_interval || approach)
      {
        if (!need_search && steps_since_search < prm.search_interval)
          ++approach_searches;
        search(u);
        resume_valid = false;
        timing.search += lap(clock);
      }
    else
      {
        gather_positions(u, active_gather);
        timing.positions += lap(clock);
      }
  }



  void
  PenaltyContact::track_candidate_motion()
  {
    // In one pass over the candidates (replicated positions: the same on
    // every rank): the motion of each candidate slave and corner of its
    // faces since the last evaluation, for select_slaves(), and whether one
    // moved too far since the search (a rebuild at the next step).
    const bool   motion_known = active_x_previous.size() == active_nodes.size() && resume_valid;
    const double limit        = prm.rebuild_fraction * prm.search_margin;
    bool         moved_far    = false;
    active_x_previous.resize(active_nodes.size());
    node_motion.resize(node_dof.size());
    for (unsigned int k = 0; k < active_nodes.size(); ++k)
      {
        const unsigned int n = active_nodes[k];
        const Point<dim>  &x = node_x[n];
        if (motion_known)
          node_motion[n] = x.distance(active_x_previous[k]);
        moved_far = moved_far || x.distance_square(node_x_search[n]) > limit * limit;
        active_x_previous[k] = x;
      }
    if (!motion_known)
      resume_valid = false;
    need_search = need_search || moved_far;
  }



  void
  PenaltyContact::evaluate_passes(const double dt, const bool advance, Clock::time_point &clock)
  {
    // each rank a block of the candidates (ordered by position: a rank's
    // slaves share faces and nodal normals), then all states everywhere
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
    for (Pass &pass : passes)
      {
        select_slaves(pass, advance, advance && resume_valid && !every_slave);
        timing.candidates += pass.candidate_slaves.size();
        timing.computed += pass.evaluated.size();
        compute_slaves(pass, dt, advance);
        timing.slaves += lap(clock);
        if (n_ranks > 1)
          {
            exchange_states(pass, advance);
            timing.exchange += lap(clock);
          }
        set_clearance(pass, advance);
      }
    resume_valid = advance;
    pairs.clear();
    totals = ContactSummary();
    for (const Pass &pass : passes)
      accumulate(pass, advance);
    if (totals.n_contact > 0)
      totals.relative_displacement /= totals.n_contact;
    if (!overlap_checked)
      {
        overlap_checked = true;
        check_initial_overlap();
      }
  }



  void
  PenaltyContact::scatter_forces(LinearAlgebra::distributed::Vector<double> &f) const
  {
    // forces on the owned DoFs, with the sign of internal forces; only the
    // slaves evaluated at this step can be in contact (accumulate())
    for (const Pass &pass : passes)
      for (const unsigned int c : pass.evaluated)
        {
          const unsigned int      s     = pass.candidate_slaves[c];
          const ContactNodeState &state = pass.slaves[s];
          if (!state.in_contact)
            continue;
          const Tensor<1, dim> F   = state.normal_force * state.normal + state.tangential_force;
          const auto           add = [&](const types::global_dof_index dof, const double weight) {
            if (partitioner->in_local_range(dof))
              {
                const unsigned int i = partitioner->global_to_local(dof);
                for (unsigned int d = 0; d < dim; ++d)
                  f.local_element(i + d) -= weight * F[d];
              }
          };
          add(node_dof[pass.slave_node[s]], 1.);
          const MasterFace &face = pass.faces[state.face];
          double            N[4];
          BilinearFace::shape(state.xi, state.eta, N);
          for (unsigned int v = 0; v < 4; ++v)
            add(node_dof[face.node[v]], -N[v]);
        }
  }



  template <class Archive>
  void
  PenaltyContact::serialize(Archive &ar)
  {
    ar.vector(node_x);
    ar.vector(node_x_search);
    ar.vector(active_nodes);
    std::uint64_t n_passes = passes.size();
    ar.pod(n_passes);
    if constexpr (Archive::is_loading)
      AssertThrow(n_passes == passes.size(),
                  ExcMessage("The checkpoint does not fit this run (contact passes differ)."));
    for (Pass &pass : passes)
      {
        const std::size_t n_slaves = pass.slaves.size();
        ar.vector(pass.slaves);
        if constexpr (Archive::is_loading)
          AssertThrow(pass.slaves.size() == n_slaves,
                      ExcMessage("The checkpoint does not fit this run (slave nodes differ)."));
        ar.vector(pass.candidate_slaves);
        ar.vector(pass.candidate_faces);
        ar.vector(pass.face_offsets);
        ar.vector(pass.face_lists);
      }
    ar.pod(totals);
    ar.pod(dissipation);
    ar.pod(damping_loss);
    ar.pod(steps_since_search);
    ar.pod(need_search);
    ar.pod(searches);
    if constexpr (Archive::is_loading)
      {
        // the search structures that follow from the state read
        build_normal_adjacency();
        plan_gather(active_nodes, active_gather);
        plan_approach_trigger();
        // the motion of the last step before the checkpoint is not known here
        step_motion_known = false;
        resume_valid      = false;
        overlap_checked   = true;
      }
  }



  template void
  PenaltyContact::serialize(Checkpoint::Writer &);
  template void
  PenaltyContact::serialize(Checkpoint::Reader &);
} // namespace WheelRail
