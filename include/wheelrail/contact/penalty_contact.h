/**
 * @file contact/penalty_contact.h
 * Penalty node-to-segment contact with friction (SPEC 4): slave nodes on one
 * boundary against the bilinear faces of another, LS-DYNA style.
 *
 * Parallel design: the contact state is replicated, its computation is
 * shared. Every rank knows the list of all slave nodes and master faces
 * (small: surfaces only). At a search, the current positions of all contact
 * nodes are gathered and the candidate slaves and faces (within the search
 * margin) are chosen; at every step only the candidates' positions are
 * gathered (one allgatherv). Each rank then computes the closest point,
 * penalty force and friction return map of its block of the candidate
 * slaves (ordered by position), with the face bounds and averaged nodal
 * normals of the faces its block needs (computed on first use), these
 * states are exchanged (one allgatherv), and
 * every rank sums the totals and adds the forces on the DoFs it owns, in the
 * same slave order. Results are therefore independent of the number of
 * ranks, and a slave node and its master face may live on any ranks.
 */
#ifndef wheelrail_contact_penalty_contact_h
#define wheelrail_contact_penalty_contact_h

#include <deal.II/base/partitioner.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/la_parallel_vector.h>

#include <wheelrail/base/checkpoint.h>
#include <wheelrail/base/stopwatch.h>
#include <wheelrail/contact/bilinear_face.h>
#include <wheelrail/contact/contact_state.h>
#include <wheelrail/contact/friction_law.h>
#include <wheelrail/contact/friction_model.h>
#include <wheelrail/parameters/parameters.h>

#include <array>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace WheelRail
{
  /**
   * Penalty contact between the slave boundary and the master boundary
   * (and back, with two-pass contact).
   */
  class PenaltyContact
  {
  public:
    /** The contact and friction state (replicated on every rank) and the
     *  search state, so that a restart continues exactly; listed once for
     *  both directions (@p ar a Checkpoint::Writer or Reader, the same
     *  mesh and rank count). After reading, the search structures that
     *  follow from it are rebuilt. */
    template <class Archive>
    void
    serialize(Archive &ar);

    PenaltyContact(const ContactParameters  &contact,
                   const MaterialParameters &material,
                   MPI_Comm                  comm);

    /**
     * Collect slave nodes and master faces of the mesh. @p point_mass: per
     * DoF the mass a force at the node accelerates (a hanging node's through
     * its masters), for the contact damping.
     */
    void
    setup(const DoFHandler<dim>                                    &dof_handler,
          const std::shared_ptr<const Utilities::MPI::Partitioner> &partitioner,
          const LinearAlgebra::distributed::Vector<double>         &point_mass);

    /**
     * Add the contact forces for the displacement @p u (ghosted) to the
     * owned entries of @p f, with the sign of internal forces (f -= f_c).
     * With @p advance the friction state and the micro-slip are updated for
     * a step of length @p dt; without, friction is left out (static solve).
     */
    void
    add_forces(const LinearAlgebra::distributed::Vector<double> &u,
               const double                                      dt,
               const bool                                        advance,
               LinearAlgebra::distributed::Vector<double>       &f);

    /**
     * With @p every, add_forces() computes every candidate slave, also the
     * separated ones that cannot reach their faces yet and are otherwise
     * left as they are (select_slaves()): their gaps are then current, for
     * the output of the run's last step.
     */
    void
    evaluate_every_slave(const bool every)
    {
      every_slave = every;
    }

    /** Active pairs of the last add_forces() (replicated on all ranks). */
    const std::vector<ContactPair> &
    active_pairs() const
    {
      return pairs;
    }
    /** Slave node states of pass @p p, the first by default (replicated on
     *  all ranks). A state in contact carries the force F = normal_force
     *  normal + tangential_force on its own node: F on the first pass's
     *  slave body (the wheel) in the first pass, -F in the second, as
     *  summary() sums them. */
    const std::vector<ContactNodeState> &
    slave_states(const unsigned int p = 0) const
    {
      return passes[p].slaves;
    }
    /**
     * The slave nodes of the first pass (the wheel tread), in the order of
     * slave_states(), with the forces and states of every pass.
     */
    std::vector<NodalContact>
    slave_node_results() const;
    /**
     * The master nodes of the first pass (the rail top), sorted by
     * position, with the forces of every pass and the slave states mapped
     * onto them: the first pass's slaves with the shape functions N_j of
     * their contact points, as the penalty forces are distributed; in
     * two-pass contact the node's own state as a slave of the second pass.
     */
    std::vector<NodalContact>
    master_node_results() const;
    /** The master faces of the first pass (the rail top): the indices of
     *  each face's four nodes (lexicographic) in master_node_results(). */
    std::vector<std::array<unsigned int, 4>>
    master_face_nodes() const;
    /** The slave faces of the first pass (the wheel tread) whose four nodes
     *  are candidates of the last search, so that their current positions
     *  are known: the indices of each face's four nodes (lexicographic) in
     *  slave_node_results(). */
    std::vector<std::array<unsigned int, 4>>
    candidate_slave_faces() const;
    /** The tolerance eps_T of eq. 5 for the slaves of pass @p p: 0.3 % of
     *  their largest |F_t| [N]. */
    double
    adhesion_tolerance(const unsigned int p) const;
    /** Force-weighted mean x of the contact points of every pass [m] (NaN
     *  without contact). */
    double
    patch_centre() const;

    /** 1, or 2 with two-pass contact. */
    unsigned int
    n_passes() const
    {
      return passes.size();
    }
    /** Totals of the last add_forces(). */
    const ContactSummary &
    summary() const
    {
      return totals;
    }
    /** Energy dissipated by contact damping so far [J]. */
    double
    damping_dissipation() const
    {
      return damping_loss;
    }
    /** Friction dissipation accumulated so far [J]. */
    double
    friction_dissipation() const
    {
      return dissipation;
    }
    /** Number of candidate searches so far. */
    unsigned int
    n_searches() const
    {
      return searches;
    }
    /** Candidate slaves and candidate slave-face pairs of the last search
     *  (all passes). */
    std::pair<unsigned int, unsigned int>
    n_candidates() const;
    /** Searches so far that the approach bound (contact/approach_trigger.cc)
     *  called for, and no other trigger. */
    unsigned int
    n_approach_searches() const
    {
      return approach_searches;
    }
    /**
     * The deepest penetration [m] that a slave node had at the step its
     * contact began (a slave found in contact that was not at the step
     * before), over all steps so far and all ranks. A search that never
     * misses an approaching body finds every contact within about one
     * step's relative motion of the surfaces. Collective.
     */
    double
    deepest_new_contact() const;
    /** Wall seconds spent in searches (candidate rebuilds) so far. */
    double
    search_seconds() const
    {
      return search_time;
    }
    /** Times of the calls since the last reset_times(). */
    const ContactTimes &
    times() const
    {
      return timing;
    }
    void
    reset_times()
    {
      timing = ContactTimes();
    }
    /** h_ref of Contact/Penalty stiffness = area [m] (0 with 'segment'). */
    double
    penalty_reference_length() const
    {
      return reference_length;
    }
    const FrictionLaw *
    friction_law() const
    {
      return law.get();
    }

  private:
    struct MasterFace
    {
      unsigned int node[4];   ///< contact-node indices, lexicographic
      double       stiffness; ///< SF K A^2 / V ('segment') or SF K A / h_ref ('area')
      double       sign;      ///< orientation making x_xi x x_eta outward
    };
    /**
     * What a slave's projection onto a master face can be, bounded cheaply
     * (see compute_face_bound()): the face extended to |xi|, |eta| <= 1.1
     * lies in the ball (centre, radius), and its normals within the angle
     * asin(sin_angle) of @p normal.
     */
    struct alignas(64) FaceBound
    {
      Point<dim>     centre; ///< the face's point at xi = eta = 0
      Tensor<1, dim> normal; ///< unit normal at xi = eta = 0
      double         radius = 0;
      /** Infinite where the face is degenerate or its normal turns by more
       *  than the bound covers. */
      double sin_angle = std::numeric_limits<double>::infinity();
      /** Nearly flat and not degenerate: the bound holds. */
      bool
      usable() const
      {
        return sin_angle <= 0.1;
      }
    };
    struct Pass
    {
      std::vector<unsigned int>     slave_node; ///< contact-node index per slave
      std::vector<ContactNodeState> slaves;
      /** The slave boundary's faces: their four slaves (lexicographic). */
      std::vector<std::array<unsigned int, 4>> slave_faces;
      std::vector<MasterFace>                  faces;
      std::vector<unsigned int>                candidate_slaves;
      std::vector<unsigned int>                candidate_faces;
      std::vector<unsigned int>                face_offsets; ///< CSR: slave -> faces
      std::vector<unsigned int>                face_lists;
      /** Per face, computed at its first use in an evaluation: the bound
       *  (one cache line, read for every candidate face of a slave), the
       *  face in closed form (read for the faces the bound keeps), and the
       *  evaluation they were computed in. */
      std::vector<FaceBound>                  bounds;
      std::vector<ContactGeometry::FaceFrame> frames;
      std::vector<unsigned long>              bound_evaluation;
      /** Per slave: how far [m] its listed faces and it may still move
       *  towards each other before it can touch one (select_slaves());
       *  -infinity: compute it at the next evaluation. The same on every
       *  rank. */
      std::vector<double> clearance;
      /** Per face: the largest motion of its corners in the last step
       *  (select_slaves() workspace; candidate faces only). */
      std::vector<double> face_motion;
      /** The positions in candidate_slaves computed at this evaluation. */
      std::vector<unsigned int> evaluated;
      /** Per entry of evaluated: found separated with its closest point
       *  inside a face. */
      std::vector<unsigned char> separated_inside;
    };
    /** A candidate master face at a contact node: what its averaged normal sums. */
    struct NormalEntry
    {
      unsigned int pass;
      unsigned int face;
      unsigned int corner;
    };

    /** The contact-node indices of the first pass's master nodes, in the
     *  order of master_node_results() (by position). */
    std::vector<unsigned int>
    master_order() const;
    void
    collect_pass(const DoFHandler<dim>   &dof_handler,
                 const types::boundary_id slave_id,
                 const types::boundary_id master_id,
                 Pass                    &pass);
    /** collect_pass(): this rank's boundary faces packed as doubles,
     *  slaves (dof, X, area / 4), master faces (4 dofs, 4 X, area, cell
     *  volume, sign) ... */
    void
    pack_boundary_faces(const DoFHandler<dim>   &dof_handler,
                        const types::boundary_id slave_id,
                        const types::boundary_id master_id,
                        std::vector<double>     &slaves,
                        std::vector<double>     &faces) const;
    /** ... all ranks' slaves (shared nodes' areas summed), ordered by
     *  position, with their faces ... */
    void
    add_slaves(const std::vector<std::vector<double>> &slave_parts, Pass &pass);
    /** ... all ranks' master faces by centroid, with their stiffness. */
    void
    add_master_faces(const std::vector<std::vector<double>> &face_parts, Pass &pass);
    unsigned int
    node_index(const types::global_dof_index dof, const Point<dim> &X);
    /** Every rank's @p send, concatenated in rank order, into @p recv on
     *  every rank (MPI type @p type of T). */
    template <typename T>
    void
    all_gather_concatenated(const std::vector<T> &send,
                            const MPI_Datatype    type,
                            std::vector<T>       &recv);
    void
    search(const LinearAlgebra::distributed::Vector<double> &u);
    /** The master faces within Search margin of each slave of @p pass (an
     *  rtree of the faces' boxes; this rank's block of the slaves, then all
     *  ranks'), packed as (slave, number of faces, faces ascending). */
    std::vector<unsigned int>
    query_candidates(const Pass &pass);
    /** The candidates of @p pass from @p found; marks their nodes and
     *  those of their faces in @p active. */
    void
    assign_candidates(const std::vector<unsigned int> &found,
                      const std::vector<bool>         &was_candidate,
                      Pass                            &pass,
                      std::vector<bool>               &active);
    /** The clearances and motion allowances of this rank's contact nodes
     *  for approach_bound_exceeded(), from the positions at the last
     *  search (contact/approach_trigger.cc). */
    void
    plan_approach_trigger();
    /**
     * Whether a slave and a master face that are not candidates could have
     * come closer than (1 - Rebuild fraction) x Search margin since the last
     * search, judged from this step's motion of all contact nodes; reduced
     * over the ranks (one allreduce, where the ranks meet after their
     * element loops). Stops the run when the nodes move too far in one step
     * for any search to see a crossing. The local part is timed in
     * @p clock as positions, the reduction as wait.
     */
    bool
    approach_bound_exceeded(const LinearAlgebra::distributed::Vector<double> &u,
                            const bool                                        advance,
                            Clock::time_point                                &clock);
    /** add_forces(), in its order: the contact nodes' positions, by a
     *  search where needed (timed in @p clock) ... */
    void
    update_positions(const LinearAlgebra::distributed::Vector<double> &u,
                     const bool                                        advance,
                     Clock::time_point                                &clock);
    /** ... the candidates' motion since the last evaluation and search
     *  (a rebuild at the next step where one moved too far) ... */
    void
    track_candidate_motion();
    /** ... every pass's slaves, computed and exchanged, the totals ... */
    void
    evaluate_passes(const double dt, const bool advance, Clock::time_point &clock);
    /** ... and their forces on the owned DoFs of @p f (the sign of
     *  internal forces). */
    void
    scatter_forces(LinearAlgebra::distributed::Vector<double> &f) const;
    /** At the first evaluation after setup(): stop the run when a slave
     *  penetrates its master face deeper than the faceting of the surfaces
     *  explains (contact/approach_trigger.cc). */
    void
    check_initial_overlap() const;
    /** The FaceBound of face @p f of @p pass at the current positions,
     *  computed at its first use in this evaluation (with the face's
     *  FaceFrame, pass.frames[f]). */
    const FaceBound &
    face_bound(Pass &pass, const unsigned int f)
    {
      if (pass.bound_evaluation[f] != evaluation)
        compute_face_bound(pass, f);
      return pass.bounds[f];
    }
    void
    compute_face_bound(Pass &pass, const unsigned int f);
    /** The axis-aligned box (lowest, highest corner) of master face @p face
     *  with its nodes at @p x. */
    static std::pair<Point<dim>, Point<dim>>
    face_box(const MasterFace &face, const std::vector<Point<dim>> &x);
    /** The averaged normal of the candidate master faces at contact node
     *  @p n at the current positions, computed at its first use in this
     *  evaluation. */
    const Tensor<1, dim> &
    averaged_normal(const unsigned int n)
    {
      if (normal_evaluation[n] != evaluation)
        compute_averaged_normal(n);
      return node_normal[n];
    }
    void
    compute_averaged_normal(const unsigned int n);
    /** The candidate faces at each contact node (after a search or load). */
    void
    build_normal_adjacency();
    /** The candidates [first, second) of @p n that rank @p rank computes. */
    std::pair<unsigned int, unsigned int>
    candidate_block(const unsigned int n, const unsigned int rank) const;
    /** candidate_block() of this rank. */
    std::pair<unsigned int, unsigned int>
    own_candidates(const unsigned int n) const;
    void
    plan_gather(const std::vector<unsigned int> &nodes, GatherPlan &plan);
    /** node_x = X + u of the plan's nodes on every rank. */
    void
    gather_positions(const LinearAlgebra::distributed::Vector<double> &u, const GatherPlan &plan);
    /**
     * The penalty stiffness of slave @p s of @p pass on @p face. Under
     * 'segment' the face's k = SF K A^2 / V (LS-DYNA). Under 'area' the
     * smaller of the face's SF K A_m / h_ref and the slave's own
     * SF K A_s / h_ref: a slave node smaller than the face it meets (a fine
     * mesh against a coarse one) gets the pressure per penetration
     * SF K / h_ref of its own area, not a spring as stiff as the large face
     * (which would raise the pressure there A_m / A_s times and take the
     * light node's frequency beyond the explicit step's limit); a slave
     * larger than the face takes the face's stiffness, so that the face's
     * light nodes get no stiffer a spring. This is the rule of LS-DYNA's
     * stability-based stiffness (SOFT = 1), the smaller of the two sides,
     * in areas instead of nodal masses.
     */
    double
    slave_stiffness(const ContactNodeState &slave, const MasterFace &face) const
    {
      return area_penalty ? std::min(face.stiffness, area_stiffness(slave.area)) : face.stiffness;
    }
    /** (1 - Rebuild fraction) x Search margin [m]: how close a slave and a
     *  master face that are not candidates of each other can come before a
     *  search (approach_trigger.cc). */
    double
    kept_distance() const
    {
      return (1. - prm.rebuild_fraction) * prm.search_margin;
    }
    /** SF K A / h_ref: the 'area' penalty stiffness of the area @p area [N/m]. */
    double
    area_stiffness(const double area) const
    {
      return prm.penalty_scale * bulk_modulus * area / reference_length;
    }
    /** The candidate slaves of @p pass this evaluation computes
     *  (Pass::evaluated): with @p skip_separated, not those that cannot
     *  have reached their faces since they were found separated, whose
     *  state stays (slave_forces.cc). */
    void
    select_slaves(Pass &pass, const bool advance, const bool skip_separated);
    /** Closest point, penalty force and friction of this rank's share of
     *  the slaves of @p pass to compute (a block of Pass::evaluated): their
     *  states only. */
    void
    compute_slaves(Pass &pass, const double dt, const bool advance);
    /** The slave Pass::evaluated[@p e] of @p pass: its closest point, and,
     *  in contact, its penalty force, normal damping and friction. */
    void
    compute_slave(Pass &pass, const unsigned int e, const double dt, const bool advance);
    /** The closest point of the slave at @p xs over the candidate faces
     *  of candidate @p c: a projection inside a face wins, otherwise the
     *  nearest face edge. */
    ClosestPoint
    closest_point(Pass &pass, const unsigned int c, const Point<dim> &xs);
    /** The viscous normal force of Contact/Damping ratio on the closing
     *  rate of the gap, added to the slave's normal force. */
    void
    add_normal_damping(ContactNodeState &state,
                       const double      k,
                       const double      gap,
                       const double      dt) const;
    /** The slip increment of the step: the contact point @p best now
     *  minus the old contact point (for a new contact the previous position
     *  @p x_prev projected) on the current master geometry. */
    Tensor<1, dim>
    slip_increment(const Pass             &pass,
                   const ContactNodeState &state,
                   const ClosestPoint     &best,
                   const Point<dim>       &x_prev) const;
    /** The friction law's return map over the slip increment: the
     *  tangential force, slip and friction dissipation of the slave. */
    void
    add_friction(const Pass         &pass,
                 ContactNodeState   &state,
                 const ClosestPoint &best,
                 const Point<dim>   &x_prev,
                 const double        k,
                 const double        dt);
    /** After the states of all ranks are in: Pass::clearance of the
     *  slaves computed. */
    void
    set_clearance(Pass &pass, const bool advance);
    /** Every rank computed its share of the candidates: gather all. */
    void
    exchange_states(Pass &pass, const bool advance);
    /** The (contact, gap) pairs of every rank's block of the candidates
     *  to all ranks (exchange_gaps, with exchange_counts and _displs). */
    void
    all_gather_gaps(Pass &pass);
    /** The states in contact of every rank's block to all ranks
     *  (exchange_buffer, in candidate order). */
    void
    all_gather_contact_states(const Pass &pass);
    /** The state of a candidate slave at @p xs that is not in contact
     *  (gap @p gap >= 0, or no face within reach), as compute_slaves()
     *  leaves it. */
    static void
    separate(ContactNodeState &state, const Point<dim> &xs, const double gap, const bool advance);
    /** Totals, dissipation and active pairs from the states, in slave order. */
    void
    accumulate(const Pass &pass, const bool advance);

    const ContactParameters           &prm;
    MPI_Comm                           mpi_communicator;
    std::shared_ptr<const FrictionLaw> law;
    /** The friction step at a slave node (law, slip rate, relaxation). */
    std::unique_ptr<FrictionModel> friction;
    double                         bulk_modulus;
    bool                           area_penalty;         ///< Contact/Penalty stiffness = area
    double                         reference_length = 0; ///< h_ref of the 'area' penalty [m]
    std::shared_ptr<const Utilities::MPI::Partitioner> partitioner;

    // contact nodes: slaves and face corners of all passes (replicated)
    std::vector<types::global_dof_index> node_dof;
    std::vector<Point<dim>>              node_X;
    std::vector<Point<dim>>              node_x;            ///< current positions
    std::vector<Point<dim>>              node_x_search;     ///< at the last search
    std::vector<Tensor<1, dim>>          node_normal;       ///< averaged master normals
    std::vector<unsigned long>           normal_evaluation; ///< when node_normal[n] was computed
    std::vector<unsigned int>            normal_offsets;    ///< CSR: node -> NormalEntry
    std::vector<NormalEntry>             normal_entries;
    unsigned long                        evaluation = 0; ///< add_forces() calls
    std::vector<double>                  node_area;      ///< master tributary area (first pass)
    std::vector<unsigned int>            active_nodes;   ///< gathered every step
    GatherPlan                           all_gather, active_gather;
    std::vector<std::pair<types::global_dof_index, unsigned int>> dof_to_node;

    /** A contact node owned by this rank, for approach_bound_exceeded(). */
    struct TriggerNode
    {
      unsigned int   local_dof; ///< first local DoF
      Tensor<1, dim> u_search;  ///< x - X at the last search
      Tensor<1, dim> dx;        ///< x - x_search at the last evaluation
      /** Motion allowance e [m] as slave (2 p) and as master-face corner
       *  (2 p + 1) of pass p; the largest double where it has no role. */
      double e[4];
    };
    std::vector<TriggerNode> trigger_nodes;             ///< ascending local DoFs
    bool                     step_motion_known = false; ///< TriggerNode::dx is of the last step
    /** Per contact node: its motion [m] since the evaluation before
     *  (active nodes; track_candidate_motion()). */
    std::vector<double> node_motion;
    std::vector<Point<dim>> active_x_previous; ///< node_x of active_nodes at the last evaluation
    /** Pass::clearance holds (no search, restart or static evaluation
     *  since it was set). */
    bool         resume_valid      = false;
    bool         every_slave       = false; ///< evaluate_every_slave()
    bool         overlap_checked   = false; ///< check_initial_overlap() done
    unsigned int approach_searches = 0;
    double       new_contact_depth = 0; ///< this rank's block, see deepest_new_contact()

    std::vector<ContactNodeState> exchange_buffer; ///< exchange_states() workspace
    std::vector<double>           exchange_gaps;   ///< (in contact, gap) per candidate
    // workspaces of gather_positions() and exchange_states(), kept so that a
    // step allocates nothing
    std::vector<double>      gather_send, gather_recv;
    std::vector<int>         exchange_counts, exchange_displs;
    std::vector<Pass>        passes;
    std::vector<ContactPair> pairs;
    ContactSummary           totals;
    double                   dissipation        = 0;
    double                   damping_loss       = 0;
    unsigned long            steps_since_search = 0;
    bool                     need_search        = true;
    unsigned int             searches           = 0;
    double                   search_time        = 0;
    ContactTimes             timing;
  };
} // namespace WheelRail

#endif
