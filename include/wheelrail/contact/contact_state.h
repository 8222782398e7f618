/**
 * @file contact/contact_state.h
 * What the contact computes, as output and post-processing read it: the
 * state of a slave node (ContactNodeState), the contact results carried to
 * a surface node from all passes (NodalContact, with the stick/slip tests
 * of eqs. 5 and 6), a slave's closest point on its master faces
 * (ClosestPoint), an active slave-face pair (ContactPair), the totals of
 * one evaluation (ContactSummary) and the wall times of its parts
 * (ContactTimes).
 */
#ifndef wheelrail_contact_contact_state_h
#define wheelrail_contact_contact_state_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <wheelrail/contact/friction_model.h>
#include <wheelrail/parameters/parameters.h>

#include <limits>
#include <vector>

namespace WheelRail
{
  /** State of one slave node, available to output and post-processing. */
  struct ContactNodeState
  {
    Point<dim>     X;                  ///< reference position [m]
    Point<dim>     x;                  ///< current position [m]
    double         area       = 0;     ///< tributary area [m^2]
    bool           in_contact = false; ///< normal nodal force > 0 (paper eq. 4)
    double         gap        = 0;     ///< n.(x_s - x_c) [m], < 0 = penetration
    Tensor<1, dim> normal;             ///< outward normal of the master face
    double         normal_force = 0;   ///< |F_n| [N]
    Tensor<1, dim> tangential_force;   ///< F_t on the slave [N]
    /** Micro-slip s_n, the slip rate the friction law sees [m/s]: |de| / dt
     *  (paper), or its irreversible part (Contact/Slip rate). */
    double slip_velocity = 0;
    /** The slip rate vector: de / dt, the slave's velocity relative to the
     *  master material under it (elastic spring rate plus slip), or its
     *  irreversible part [m/s]; |slip_rate| = s_n. */
    Tensor<1, dim> slip_rate;
    double         cof      = 0;     ///< local coefficient of friction
    bool           slipping = false; ///< the return map was active
    /** Friction memory: master face and face coordinates of the contact point. */
    int                   face = -1;
    double                xi = 0, eta = 0;
    FrictionModel::Memory friction;   ///< tangential spring and friction state
    double                mass = 0;   ///< point mass (contact damping) [kg]
    Point<dim>            x_previous; ///< position at the previous step
    double                gap_previous = 0;
    /** Energy dissipated at this node in the last step by friction and by
     *  contact damping [J] (summed in slave order into the totals). */
    double friction_loss = 0;
    double damping_work  = 0;

    double
    pressure() const
    {
      return area > 0 ? normal_force / area : 0.;
    }
  };

  /**
   * The contact at one node with the forces of every pass (output and
   * post-processing; contact/nodal_results.cc). Each pass applies its
   * penalty forces in full: a node's force is its own force as a slave plus
   * the shares N_j F of the slaves of the other pass on its faces, as the
   * force on the first pass's slave body (the wheel). The adhesion/slip state
   * is decided on the slave nodes, where the return map makes it exact (eq. 5
   * with each node's own f, eq. 6 with its own s_n), and carried to the node
   * with the same weights (1 for its own state, N_j for the other pass's).
   */
  struct NodalContact
  {
    Point<dim>     X;                 ///< reference position [m]
    Point<dim>     x;                 ///< current position (slave nodes; X on masters) [m]
    double         area         = 0;  ///< tributary area [m^2]
    double         normal_force = 0;  ///< |F_n| of all passes [N]
    Tensor<1, dim> tangential_force;  ///< F_t of all passes, on the first pass's slave body [N]
    double         slip_velocity = 0; ///< weighted mean of the slaves' s_n [m/s]
    Tensor<1, dim> slip_rate;         ///< weighted mean de/dt of the first pass's slave [m/s]
    double         cof    = 0;        ///< weighted mean local COF
    double         weight = 0;        ///< sum of the weights of the slave states in contact
    /** Shares of that weight in adhesion by eq. 5 (f |F_n| - |F_t| > eps_T on
     *  the slave) and in slip by eq. 6 (s_n > eps_s) [-]. */
    double adhesion_share = 0;
    double slip_share     = 0;

    /** eps_T of eq. 5 as a fraction of the largest |F_t| of the pass [-]. */
    static constexpr double adhesion_tolerance_fraction = 0.003;
    /** eps_s of eq. 6 [m/s]. */
    static constexpr double slip_velocity_threshold = 0.05;

    bool
    in_contact() const
    {
      return normal_force > 0;
    }
    double
    pressure() const
    {
      return area > 0 ? normal_force / area : 0.;
    }
    /** In contact, and most of its slave states adhere (eq. 5). */
    bool
    adhesion() const
    {
      return in_contact() && adhesion_share > 0.5;
    }
    /** In contact, and most of its slave states slip by eq. 6. */
    bool
    slip_eq6() const
    {
      return in_contact() && slip_share > 0.5;
    }
  };

  /** The closest point of a slave over its candidate master faces
   *  (PenaltyContact::closest_point()). */
  struct ClosestPoint
  {
    int            face = -1;       ///< in the pass's faces (-1: none within reach)
    double         xi = 0, eta = 0; ///< its local coordinates on the face
    double         gap = 0;         ///< along the normal (< 0: penetration)
    double         out = 1e300;     ///< how far the projection lies beyond the face (0: on it)
    Tensor<1, dim> normal;          ///< the averaged nodal normal there
    /** How far the faces left out for a gap below -margin are from
     *  counting (PenaltyContact::select_slaves()). */
    double ignored_slack = std::numeric_limits<double>::infinity();
  };

  /** An active slave/master pair for the implicit tangent. */
  struct ContactPair
  {
    types::global_dof_index slave;     ///< x-DoF of the slave node
    types::global_dof_index master[4]; ///< x-DoFs of the face corners
    double                  shape[4];  ///< N_j at the contact point
    Tensor<1, dim>          normal;
    double                  stiffness; ///< penalty k [N/m]
  };

  /** Totals over all slave nodes. */
  struct ContactSummary
  {
    Tensor<1, dim> force;               ///< on the (first pass's) slave body [N]
    unsigned int   n_contact       = 0; ///< nodes with F_n > 0
    unsigned int   n_slip          = 0; ///< nodes where the return map was active
    unsigned int   n_violation     = 0; ///< |F_t| > f |F_n| (must stay 0)
    double         elastic_energy  = 0; ///< 1/2 k g^2 + 1/2 |F_t|^2 / k_t [J]
    double         max_penetration = 0; ///< [m]
    /** Mean over the contact nodes of the slave's displacement relative to
     *  the material point of the master under it [m]: elastic spring
     *  extension plus accumulated slip. */
    Tensor<1, dim> relative_displacement;
  };

  /** Wall seconds of this rank in the parts of PenaltyContact::add_forces(). */
  struct ContactTimes
  {
    double search    = 0; ///< candidate searches (their position gather included)
    double wait      = 0; ///< for the other ranks before the position gather (imbalance)
    double positions = 0; ///< position gather of the candidates between searches
    double slaves    = 0; ///< closest points, penalty and friction of this rank's block
    double exchange  = 0; ///< the blocks' states to every rank
    double forces    = 0; ///< totals, pairs and the nodal forces
    /** Evaluations (add_forces() calls), the candidate slaves they had and
     *  the slaves they computed (all ranks together, all passes). */
    unsigned long evaluations = 0, candidates = 0, computed = 0;
  };

  /** What PenaltyContact::gather_positions() sends and receives for a set
   *  of contact nodes: fixed from one search to the next. */
  struct GatherPlan
  {
    std::vector<unsigned int> local_dof;      ///< this rank's nodes: first local DoF, ascending
    std::vector<Point<dim>>   X;              ///< their reference positions
    std::vector<unsigned int> nodes;          ///< all ranks' nodes in the order they arrive
    std::vector<int>          counts, displs; ///< per rank, in doubles
  };
} // namespace WheelRail

#endif
