/**
 * @file rigid_body_coupling.h
 * What the explicit solver knows of a rigid body that is coupled to the
 * finite elements through forces (the wheelset: WheelsetCoupling).
 */
#ifndef wheelrail_solver_rigid_body_coupling_h
#define wheelrail_solver_rigid_body_coupling_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <wheelrail/solver/boundary_conditions.h>
#include <wheelrail/solver/elastic_operator.h>
#include <wheelrail/solver/energies.h>

#include <functional>
#include <vector>

namespace WheelRail
{
  /**
   * A rigid body coupled to the finite elements through forces. The body
   * owns the prescribed DoFs of kind BoundaryKind::rigid_axle: the FE net
   * forces on them drive it (advance()), and they follow its motion
   * (coupled_motion()). It may also add forces of its own to FE DoFs
   * (add_damping(): the run-up damping of the wheel relative to the
   * wheelset). ExplicitSolver::step() calls, in this order: damps() and
   * add_damping() with the internal forces, advance() after the update of
   * the free DoFs, coupled_motion() while it moves the prescribed DoFs,
   * add_energies() at statistics steps.
   */
  class RigidBodyCoupling
  {
  public:
    virtual ~RigidBodyCoupling() = default;

    /** Once, after the solver's setup: take the coupled nodes' masses and
     *  inertia from @p fe (its lumped mass, support points, components and
     *  materials) and @p prescribed. Collective. */
    virtual void
    connect(const ElasticOperator &fe, const std::vector<PrescribedDof> &prescribed) = 0;

    /** Whether add_damping() acts in the step that starts at @p t. */
    virtual bool
    damps(const double t) const = 0;

    /** Add the body's damping forces on the FE DoFs to @p f (the sign of
     *  internal forces) at displacement @p u and velocity @p v; returns
     *  their dissipated power on this rank, and sets @p work to their
     *  work on the rigid motion over the step of length @p h. Collective. */
    virtual double
    add_damping(const VectorType &u,
                const VectorType &v,
                VectorType       &f,
                const double      h,
                double           &work) = 0;

    /** Advance the body over the step: @p prescribed carry the FE net
     *  forces (PrescribedDof::net_force) on the coupled DoFs at the
     *  displacement @p u. Collective. */
    virtual void
    advance(const std::vector<PrescribedDof> &prescribed,
            const VectorType                 &u,
            const double                      h,
            const double                      dt,
            const double                      t) = 0;

    /** The displacement of a coupled node, as a function of its reference
     *  position, in the body's current state. */
    virtual std::function<Tensor<1, dim>(const Point<dim> &)>
    coupled_motion() const = 0;

    /** Add the body's own energies (replicated on all ranks: no sum). */
    virtual void
    add_energies(Energies &energies) const = 0;
  };
} // namespace WheelRail

#endif
