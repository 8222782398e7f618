/**
 * @file explicit_solver.h
 * Central-difference time integration (SPEC 2) of the elastic operator
 * (elastic_operator.h) with penalty contact, prescribed and loaded
 * boundaries and a rigid body coupled through forces (the wheelset:
 * rigid_body_coupling.h).
 */
#ifndef wheelrail_solver_explicit_solver_h
#define wheelrail_solver_explicit_solver_h

#include <deal.II/base/function.h>

#include <wheelrail/base/checkpoint.h>
#include <wheelrail/contact/penalty_contact.h>
#include <wheelrail/parameters/parameters.h>
#include <wheelrail/solver/boundary_conditions.h>
#include <wheelrail/solver/elastic_operator.h>
#include <wheelrail/solver/energies.h>
#include <wheelrail/solver/nodal_damping.h>
#include <wheelrail/solver/nodal_update.h>
#include <wheelrail/solver/rigid_body_coupling.h>
#include <wheelrail/solver/step_times.h>

#include <functional>
#include <memory>

namespace WheelRail
{
  /**
   * The explicit elastodynamics core: the elastic operator it derives from
   * (DoFs, constraints, element data, lumped mass) plus the state of the
   * time integration, u (at t_n) and v (at t_{n-1/2}), advanced by step().
   */
  class ExplicitSolver : public ElasticOperator
  {
  public:
    ExplicitSolver(const Parameters                          &parameters,
                   parallel::distributed::Triangulation<dim> &triangulation);

    /** Distribute DoFs, build constraints, element data, mass and loads. */
    void
    setup();

    void
    set_time_step(const double dt);
    double
    time_step() const
    {
      return dt;
    }

    /** Set u everywhere (on cells of @p material, or all if invalid id). */
    void
    set_displacement(const std::function<Tensor<1, dim>(const Point<dim> &)> &u_of_X,
                     const types::material_id material = numbers::invalid_material_id);
    /** Set the initial velocity v_0 (the first step is a half step). */
    void
    set_velocity(
      const std::function<Tensor<1, dim>(const Point<dim> &, const types::material_id)> &v_of_X);

    /** Let @p contact add its forces in every step (nullptr: none). */
    void
    attach_contact(PenaltyContact *contact)
    {
      this->contact = contact;
    }
    /** Let the prescribed DoFs of kind BoundaryKind::rigid_axle move with
     *  @p body and drive it (nullptr: none); connects it to the DoFs
     *  (RigidBodyCoupling::connect()). After setup(). Collective. */
    void
    attach_rigid_body(RigidBodyCoupling *body);
    /** Set the owned entries of u from a vector with the same layout (e.g.
     *  a static solution); hanging DoFs follow their masters. */
    void
    set_displacement(const VectorType &displacement);
    /** f_int(u) - f_contact(u) (frictionless) - f_ext, condensed and compressed. */
    void
    compute_residual(VectorType &residual);
    /** The same at the displacement @p w (ghosted, hanging DoFs
     *  distributed) instead of u; u is not touched. */
    void
    compute_residual(const VectorType &w, VectorType &residual);
    /** Momentum (from v at t_{n-1/2}) of the cells of @p material [kg m/s]. */
    Tensor<1, dim>
    momentum(const types::material_id material) const;
    /** Mean displacement of the nodes of @p material [m]. */
    Tensor<1, dim>
    mean_displacement(const types::material_id material) const;

    /**
     * Add the centrifugal load m omega^2 (x - c) of a wheel spinning at
     * @p omega about the axle through @p centre to the external force, for
     * a static solve of the steadily rolling wheel (it expands by about
     * 30 um at the tread at 140 km/h; without the load the rolling run
     * starts with that expansion as a radial vibration that presses the
     * wheel into the rail).
     */
    void
    add_centrifugal_load(const Point<dim> &centre, const double omega);
    /** The external force as it was before add_centrifugal_load(), to the
     *  bit (not the load subtracted again, which rounds). */
    void
    remove_centrifugal_load();

    /**
     * Initial velocity of steady rolling superposed on the current (static)
     * displacement u: the deformation pattern stays with the axle while the
     * material moves through it. Wheel: v = V + w + H w, w = omega e_y x
     * (X - c); rail: v = -V H e_x (H = grad u, averaged at the nodes).
     * Without the convective terms H w and -V H e_x the start from the static
     * state is a jolt (the rail's deflection does not travel with the load).
     */
    void
    set_rolling_velocity(const Tensor<1, dim> &V, const Point<dim> &centre, const double omega);

    /**
     * One central-difference step; energies at t_n if @p energies. Its
     * parts: the internal and contact forces at t_n, the rigid body's
     * damping and the applied forces, the update of the free DoFs (the
     * per-node NodalUpdate, or per DoF with the kinetic energy), the rigid
     * body and the prescribed DoFs, the energies, the ghost exchange. Each
     * part is timed as one of StepTimes.
     */
    void
    step(Energies *energies = nullptr);

    /** Internal force f_int(u) without damping, condensed and compressed. */
    void
    compute_internal_force(VectorType &force);

    /** The state of the time integration (this rank's part), in the order
     *  of the checkpoint file, for Checkpoint::Writer and Reader. */
    template <class Archive>
    void
    serialize(Archive &ar);

    /** Times of the steps since the last reset_times(). */
    const StepTimes &
    step_times() const
    {
      return times;
    }
    void
    reset_times()
    {
      times = StepTimes();
    }

    /** Stress of every locally owned cell (in active cell index order). */
    std::vector<CellStress>
    cell_stresses() const
    {
      return stresses(u);
    }

    const VectorType &
    displacement() const
    {
      return u;
    }
    const VectorType &
    velocity() const
    {
      return v;
    }
    /** Damping form = nodal field: w = u + beta_n v, which the next force
     *  pass reads as it is if damped_field_current() (formed by the last
     *  step), and beta_n per DoF. */
    const VectorType &
    damped_field() const
    {
      return w;
    }
    bool
    damped_field_current() const
    {
      return w_current;
    }
    const VectorType &
    nodal_beta() const
    {
      return nodal_damping.beta_per_dof();
    }
    double
    time() const
    {
      return t;
    }
    unsigned long
    step_number() const
    {
      return n_steps;
    }
    /** Mean displacement of the wheel bore nodes (zero if none). */
    Tensor<1, dim>
    bore_displacement() const;

  private:
    /** The terms of one step that its parts pass on: the half or full
     *  step, the balances of damping and boundary work, the kinetic
     *  energy. */
    struct StepTerms
    {
      StepTerms(const bool first, const double dt);
      const bool   first; ///< the first step (a half step from v_0)
      const double h;     ///< the velocity's step: dt/2 in the first step, else dt
      double       gravity_work  = 0; ///< f_ext . (u - u_0) at t_n (with energies)
      double       damping_power = 0; ///< dissipated power of the damping forces
      double       rigid_body_work = 0; ///< the rigid body's damping's work
      double       work    = 0; ///< boundary work over the step
      double       kinetic = 0; ///< this rank's kinetic energy (with energies)
      Tensor<1, dim> applied_total; ///< applied force at t_n
    };

    /** f = f_int(u) + f_damp(v) - f_contact(u); returns the damping power.
     *  Contact is evaluated for a step (friction advanced) if @p advance.
     *  With @p f_is_zero the caller guarantees f = 0 already (owned and
     *  ghost entries), and the pass that would zero it is left out. With
     *  @p strain, this rank's strain energies at u from the same pass. */
    double
    assemble_forces(const VectorType &u,
                    const VectorType *v,
                    VectorType       &f,
                    const bool        with_contact,
                    const bool        advance,
                    const bool        f_is_zero = false,
                    StrainEnergies   *strain    = nullptr);
    /** The part of assemble_forces() after the element forces: the
     *  contact's forces at @p u (if @p with_contact), condensed and
     *  compressed. */
    void
    add_contact_and_compress(const VectorType &u,
                             VectorType       &f,
                             const bool        with_contact,
                             const bool        advance);
    /** With Damping form = nodal field: f = f_int(w) - f_contact(u),
     *  w = u + beta_n v, contact advanced; with @p strain, the strain
     *  energies at u and a sample of the damping power (a second force
     *  pass at u). */
    void
    nodal_damped_forces(StrainEnergies *strain);
    /** Applied forces at t_n into f; returns their work over the first
     *  half of the step (velocity at t_{n-1/2}). */
    double
    apply_forces(const double h, Tensor<1, dim> &applied_total);
    /** Time, step number and the gravity's work at t_n into @p energies. */
    void
    begin_energies(Energies &energies, StepTerms &terms);
    /** f = f_int(u) + f_damp(v) - f_contact(u) at t_n, contact advanced;
     *  the strain energies into @p energies if given. Returns the damping
     *  power. */
    double
    internal_and_contact_forces(Energies *energies);
    /** The rigid body's damping forces into f while it damps. */
    void
    add_rigid_body_damping(StepTerms &terms);
    /** The applied forces at t_n into f, their work over the first half of
     *  the step and the rigid body's damping's work into StepTerms::work. */
    void
    add_applied_forces(StepTerms &terms);
    /** f_ext - f on the prescribed DoFs (PrescribedDof::net_force), before
     *  the update clears f. */
    void
    take_net_forces();
    /** The central-difference update of u and v on the free DoFs; clears f.
     *  With energies, per DoF with the kinetic energy into @p terms.
     *  Returns whether it also formed the nodal damping's w on the owned
     *  DoFs (NodalUpdate::apply() with w; exchange_ghosts() forms the rest). */
    bool
    update_free_dofs(StepTerms &terms, const bool with_energies);
    /** The applied forces' work over the second half of the step (with the
     *  new velocity). */
    void
    add_applied_work(StepTerms &terms) const;
    /** The step's damping dissipation and boundary work into the sums. */
    void
    accumulate(const StepTerms &terms);
    /** Ghost values of u and v, hanging DoFs from their masters; if
     *  @p w_formed (the update formed w on the owned DoFs), w where the
     *  step changed u or v after the update. */
    void
    exchange_ghosts(const bool w_formed = false);
    /** Take the per-node update (NodalUpdate) where the DoFs allow it. */
    void
    prepare_nodal_update();
    /** Move the prescribed DoFs to t_{n+1} (those of the rigid body with
     *  it); adds their reactions' work and, with energies, their kinetic
     *  energy to @p terms. */
    void
    update_prescribed(StepTerms &terms, const bool with_energies);
    /** Sum the energies at t_n over the ranks and add contact and the
     *  rigid body. */
    void
    collect_energies(Energies &energies, const StepTerms &terms);

    std::vector<unsigned int> bore_dofs;
    VectorType             inv_mass; ///< 0 on constrained and prescribed DoFs
    VectorType             f_ext;    ///< gravity, condensed
    VectorType             u0;       ///< displacement at the start
    /** f_ext while a static start adds the centrifugal load to it */
    VectorType f_ext_without_centrifugal;
    /** The update from per-node mass data where the DoFs allow it; prepared
     *  at the first step after the loads or masses change. */
    NodalUpdate nodal_update;
    bool        nodal_update_prepared = false;

    std::vector<PrescribedDof>     prescribed;
    std::unique_ptr<Function<dim>> prescribed_velocity;
    std::vector<AppliedForceDof>   applied;
    std::unique_ptr<Function<dim>> applied_force;
    PenaltyContact                *contact  = nullptr;
    RigidBodyCoupling             *rigid_body = nullptr;

    VectorType u, v, f, v_old;
    /** Damping form = nodal field: its beta_n and sampled dissipation
     *  (active if @p nodal_damping_active), w = u + beta_n v and the
     *  force pass at u of the statistics steps. */
    NodalDamping nodal_damping;
    bool         nodal_damping_active = false;
    VectorType   w, f_u;
    /** w is u + beta_n v of the current u and v: formed by the last step
     *  and not yet used; anything else that sets u or v clears it. */
    bool w_current = false;
    /** f is zero (the update of the last step cleared it behind itself:
     *  the next step's assembly need not). */
    bool          f_cleared           = false;
    double        t                   = 0;
    double        dt                  = 0;
    unsigned long n_steps             = 0;
    double        damping_dissipation = 0;
    double        boundary_work       = 0;
    StepTimes     times;
  };
} // namespace WheelRail

#endif
