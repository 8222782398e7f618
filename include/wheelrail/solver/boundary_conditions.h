/**
 * @file boundary_conditions.h
 * The boundary conditions of the explicit run (SPEC 3) as DoF lists:
 * prescribed DoFs with their kind, and the DoFs of the applied-force
 * boundaries with their share of the force.
 */
#ifndef wheelrail_solver_boundary_conditions_h
#define wheelrail_solver_boundary_conditions_h

#include <deal.II/grid/tria.h>

#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/elastic_operator.h>

#include <tuple>
#include <vector>

namespace WheelRail
{
  /**
   * How a prescribed DoF moves. Where a DoF lies on boundaries of several
   * kinds, the first in this order wins (a fixed DoF stays fixed).
   */
  enum class BoundaryKind : unsigned int
  {
    fixed               = 0, ///< u = u at the start
    prescribed_velocity = 1, ///< Boundary conditions/Prescribed velocity (x, t)
    spinning_axle       = 2, ///< wheel bore turning at the initial angular velocity
    rigid_axle          = 3  ///< wheel bore moving with the Wheelset's axle
  };

  /** A prescribed DoF (owned, local index) and its state in the step. */
  struct PrescribedDof
  {
    unsigned int index;
    unsigned int component;
    BoundaryKind kind;
    double       u_prev = 0; ///< u at the start of the step
    double       v_prev = 0; ///< v at the previous half step
    /** f_ext - f at this DoF (and, for the x-DoF of a rigid-axle bore
     *  node, at its y- and z-DoFs) in the current step: taken before
     *  the update clears f. */
    double net_force[3] = {0, 0, 0};
  };

  /** An applied-force DoF: local index, component, area fraction. */
  using AppliedForceDof = std::tuple<unsigned int, unsigned int, double>;

  /**
   * Throw if an entry of Boundary conditions names a boundary id that the
   * mesh does not have. Collective.
   */
  void
  check_boundary_ids(const Parameters &prm, const Triangulation<dim> &triangulation);

  /**
   * The owned, unconstrained DoFs on the fixed, prescribed-velocity and
   * wheel-bore boundaries, by local index; @p bore_dofs gets the owned DoFs
   * of the wheel bore (sorted, all components).
   */
  std::vector<PrescribedDof>
  prescribed_dofs(const Parameters          &prm,
                  const ElasticOperator     &op,
                  std::vector<unsigned int> &bore_dofs);

  /**
   * The owned DoFs of the applied-force boundaries, each with its share of
   * the boundaries' area (condensed nodal areas / total area). Collective.
   */
  std::vector<AppliedForceDof>
  applied_force_dofs(const Parameters &prm, const ElasticOperator &op);
} // namespace WheelRail

#endif
