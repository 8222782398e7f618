/**
 * @file wheelset_coupling.h
 * The wheelset (wheelset.h) as the rigid body of the explicit run: the
 * wheel bore's nodes move with its axle, their FE forces drive it, and
 * during the run-up it damps the wheel's motion relative to it.
 */
#ifndef wheelrail_solver_wheelset_coupling_h
#define wheelrail_solver_wheelset_coupling_h

#include <deal.II/base/mpi.h>

#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/rigid_body_coupling.h>
#include <wheelrail/solver/wheelset.h>

#include <string>
#include <vector>

namespace WheelRail
{
  /** Wheelset/Run-up damping shape, parsed once. */
  enum class RunupDampingShape
  {
    nodes,             ///< "nodes": every node's v - v_rigid
    wheel_rigid_motion ///< "wheel rigid motion": its rigid-motion part over the wheel
  };

  /** The shape named @p name (a value of Wheelset/Run-up damping shape). */
  RunupDampingShape
  parse_runup_damping_shape(const std::string &name);

  /**
   * The Wheelset coupled to the FE wheel (Wheel bore = rigid axle): the
   * bore nodes are the prescribed DoFs of kind BoundaryKind::rigid_axle,
   * the wheel's nodes those of material Geometry::MaterialIds::wheel.
   */
  class WheelsetCoupling : public RigidBodyCoupling
  {
  public:
    /** Couple @p wheelset, whose axle passes through @p axle_centre in the
     *  reference configuration, with the run-up damping of @p parameters. */
    WheelsetCoupling(Wheelset                 &wheelset,
                     const WheelsetParameters &parameters,
                     const Point<dim>         &axle_centre,
                     const MPI_Comm            mpi_communicator);

    /** Passes the bore nodes' and the FE wheel's mass and polar inertia to
     *  the wheelset; takes the wheel's nodes for the run-up damping. */
    void
    connect(const ElasticOperator &fe, const std::vector<PrescribedDof> &prescribed) override;

    /** Until Wheelset/Run-up time, if Wheelset/Run-up damping > 0. */
    bool
    damps(const double t) const override;

    /** The run-up damping (runup_damping.cc). */
    double
    add_damping(const VectorType &u,
                const VectorType &v,
                VectorType       &f,
                const double      h,
                double           &work) override;

    /** The FE forces on the bore nodes and their moment about the axle
     *  move the wheelset over the step. */
    void
    advance(const std::vector<PrescribedDof> &prescribed,
            const VectorType                 &u,
            const double                      h,
            const double                      dt,
            const double                      t) override;

    /** The bore's rigid motion (Wheelset::bore_motion()). */
    std::function<Tensor<1, dim>(const Point<dim> &)>
    coupled_motion() const override;

    /** Axle and sprung mass, suspension, torque. */
    void
    add_energies(Energies &energies) const override;

    RunupDampingShape
    damping_shape() const
    {
      return shape;
    }

  private:
    /** The run-up damping forces' power on this rank: on the motion
     *  relative to the rigid one (dissipated) and on the rigid motion. */
    struct DampingSums
    {
      double power = 0, rigid_power = 0;
    };
    /** Run-up damping of every node relative to the rigid motion. */
    void
    damp_nodes(const VectorType &u, const VectorType &v, VectorType &f, DampingSums &sums) const;
    /** The mass-weighted rigid fit of the wheel's motion in the rolling
     *  plane: centre of mass r_c relative to the axle, its velocity V_c and
     *  the mean angular velocity about it less the wheelset's. */
    struct RigidFit
    {
      double rcx = 0, rcz = 0, Vcx = 0, Vcz = 0, dOmega = 0;
    };
    /** The rigid fit over the wheel's nodes (all ranks). */
    RigidFit
    wheel_rigid_fit(const VectorType &u, const VectorType &v) const;
    /** Run-up damping of the wheel's rigid motion relative to the wheelset. */
    void
    damp_wheel_rigid_motion(const VectorType &u,
                            const VectorType &v,
                            VectorType       &f,
                            DampingSums      &sums) const;

    /** A locally owned node of the wheel: its reference x and z and its x
     *  DoF (y and z follow). */
    struct WheelNode
    {
      double       x, z;
      unsigned int dof;
    };

    Wheelset                &wheelset;
    const double             runup_damping; ///< alpha [1/s]
    const double             runup_time;    ///< [s]
    const RunupDampingShape  shape;
    const Point<dim>         centre; ///< reference axle centre
    const MPI_Comm           mpi_communicator;
    const ElasticOperator   *fe = nullptr;
    std::vector<WheelNode>   wheel_nodes;
  };
} // namespace WheelRail

#endif
