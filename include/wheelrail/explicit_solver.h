/**
 * @file explicit_solver.h
 * One-point hexahedra with Flanagan-Belytschko stiffness hourglass control,
 * total-Lagrangian St. Venant-Kirchhoff material, element stiffness damping,
 * lumped mass condensed over hanging nodes and central-difference time
 * integration (SPEC 2).
 */
#ifndef wheelrail_explicit_solver_h
#define wheelrail_explicit_solver_h

#include <deal.II/base/aligned_vector.h>
#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <wheelrail/checkpoint.h>
#include <wheelrail/contact.h>
#include <wheelrail/parameters.h>
#include <wheelrail/wheelset.h>

#include <functional>
#include <memory>

namespace WheelRail
{
  using VectorType = LinearAlgebra::distributed::Vector<double>;

  /** Energies of the whole model at one instant [J]. */
  struct Energies
  {
    double        time      = 0; ///< t_n, the instant of these values [s]
    unsigned long step      = 0; ///< n
    double        kinetic   = 0; ///< with the mid-step velocity v_n
    double        internal  = 0; ///< St. Venant-Kirchhoff strain energy
    double        hourglass = 0; ///< energy stored in the hourglass springs
    /** Hourglass-mode energy with the reference coefficient QM = 0.1,
     *  also when the control is off: shows spurious modes. */
    double hourglass_reference = 0;
    double damping             = 0; ///< dissipated by damping, accumulated
    double contact             = 0; ///< stored in the penalty springs
    double friction            = 0; ///< dissipated by friction, accumulated
    double external_work       = 0; ///< gravity, applied forces, prescribed boundaries

    /** KE + IE + HG + D + contact + friction - W_ext. */
    double
    total() const
    {
      return kinetic + internal + hourglass + damping + contact + friction - external_work;
    }
  };

  /** Wall seconds of this rank spent in the parts of the explicit steps. */
  struct StepTimes
  {
    double        elements      = 0; ///< element kernel: gather, forces, scatter
    double        contact       = 0; ///< search, projection, friction, contact forces
    double        update        = 0; ///< central-difference update, constraints, axle
    double        communication = 0; ///< ghost exchange and force compression
    double        energies      = 0; ///< energies at statistics steps
    unsigned long steps         = 0; ///< steps timed
  };

  /** Mesh size and quality figures over all cells (all ranks). */
  struct MeshQuality
  {
    double min_edge            = 0; ///< shortest edge [m]
    double min_longest_edge    = 0; ///< h_min: smallest cell size [m]
    double min_length          = 0; ///< smallest L_e = V/A_max [m]
    double min_scaled_jacobian = 0; ///< at the corners, 1 for a cube [-]
    double max_aspect_ratio    = 0; ///< longest / shortest edge [-]
  };

  /** Per-cell stress measures computed from the current displacement. */
  struct CellStress
  {
    Tensor<2, dim> second_piola_kirchhoff;
    double         von_mises; ///< of the Cauchy stress
  };

  /**
   * The explicit elastodynamics core. It owns the DoFHandler, the hanging
   * node constraints, the lumped mass, and the state vectors u (at t_n) and
   * v (at t_{n-1/2}), and advances them by step().
   */
  class ExplicitSolver
  {
  public:
    /** Lanes of a cell batch; the kernel vectorises across them. */
    static constexpr unsigned int n_lanes = 8;

    ExplicitSolver(const Parameters                          &parameters,
                   parallel::distributed::Triangulation<dim> &triangulation);

    /** Distribute DoFs, build constraints, element data, mass and loads. */
    void
    setup();

    /** Stable step C min_e(L_e/c) with the damping reduction [s]. */
    double
    stable_time_step() const
    {
      return stable_dt;
    }
    /** Sizes and quality of the mesh. */
    const MeshQuality &
    mesh_quality() const
    {
      return quality;
    }
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
    /** Let the bore nodes move with @p wheelset (Wheel bore = rigid axle):
     *  passes it the bore nodes' mass and inertia. */
    void
    attach_wheelset(Wheelset *wheelset);
    /** Set the displacement of the DoFs of material @p material from a
     *  vector with the same layout (e.g. a static solution). */
    void
    set_displacement(const VectorType &displacement);
    /** f_int(u) - f_contact(u) (frictionless) - f_ext, condensed and compressed. */
    void
    compute_residual(VectorType &residual);
    /** Momentum (from v at t_{n-1/2}) of the cells of @p material [kg m/s]. */
    Tensor<1, dim>
    momentum(const types::material_id material) const;
    /** Mean displacement of the nodes of @p material [m]. */
    Tensor<1, dim>
    mean_displacement(const types::material_id material) const;
    const VectorType &
    lumped_mass() const
    {
      return mass;
    }
    const AffineConstraints<double> &
    get_hanging_constraints() const
    {
      return hanging_constraints;
    }
    /**
     * Assemble the stiffness of the one-point element with hourglass
     * control at u = 0 (the small-strain tangent) into @p matrix through
     * @p constraints, one cell at a time.
     */
    void
    assemble_stiffness(TrilinosWrappers::SparseMatrix  &matrix,
                       const AffineConstraints<double> &constraints) const;

    /**
     * Add (factor 1) or remove (factor -1) the centrifugal load
     * m omega^2 (x - c) of a wheel spinning at @p omega about the axle
     * through @p centre to the external force, for a static solve of the
     * steadily rolling wheel (it expands by about 30 um at the tread at
     * 140 km/h; without the load the rolling run starts with that
     * expansion as a radial vibration that presses the wheel into the rail).
     */
    void
    add_centrifugal_load(const Point<dim> &centre, const double omega, const double factor);

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

    /** One central-difference step; energies at t_n if @p energies. */
    void
    step(Energies *energies = nullptr);

    /** Internal force f_int(u) without damping, condensed and compressed. */
    void
    compute_internal_force(VectorType &force);

    /** Write the state of the time integration (this rank's part). */
    void
    save(Checkpoint::Writer &out) const;
    /** Read what save() wrote, on the same mesh and partition. */
    void
    load(Checkpoint::Reader &in);

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
    cell_stresses() const;

    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
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
    /** Sum of the condensed lumped mass [kg] of cells of @p material. */
    double
    total_mass(const types::material_id material = numbers::invalid_material_id) const;
    /** Sum of the reference cell volumes of @p material [m^3]. */
    double
    mesh_volume(const types::material_id material = numbers::invalid_material_id) const;
    /** Number of locally owned cells (all ranks: use MPI sum). */
    unsigned int
    n_local_cells() const
    {
      return n_cells;
    }
    /** Number of locally owned cells in family batches (8 children of one
     *  parent, 27 nodes gathered and scattered instead of 64). */
    unsigned int
    n_family_cells() const
    {
      return 8 * (family_nodes.size() / 27);
    }
    /** Reference position of the support point of local DoF index i. */
    const std::vector<Point<dim>> &
    support_points() const
    {
      return node_points;
    }
    /** Component (0, 1, 2) of the DoF with local index i. */
    unsigned int
    dof_component(const unsigned int i) const
    {
      return node_component[i];
    }
    /** Material id of the cells around the DoF with local index i. */
    types::material_id
    dof_material(const unsigned int i) const
    {
      return node_material[i];
    }
    /** DoFs on the boundary (local indices of locally relevant DoFs). */
    const std::vector<bool> &
    boundary_dof_mask() const
    {
      return on_boundary;
    }
    /** Mean displacement of the wheel bore nodes (zero if none). */
    Tensor<1, dim>
    bore_displacement() const;
    const std::shared_ptr<const Utilities::MPI::Partitioner> &
    partitioner() const
    {
      return vector_partitioner;
    }

  private:
    /** Move hanging vertices to the mean of their masters (see .cc). */
    void
    make_hanging_vertices_conforming();
    void
    setup_cell_data();
    void
    setup_mass_and_loads();
    void
    setup_prescribed_dofs();
    /** f = f_int(u) + f_damp(v) - f_contact(u); returns the damping power.
     *  Contact is evaluated for a step (friction advanced) if @p advance.
     *  With @p f_is_zero the caller guarantees f = 0 already (owned and
     *  ghost entries), and the pass that would zero it is left out. */
    double
    assemble_forces(const VectorType &u,
                    const VectorType *v,
                    VectorType       &f,
                    const bool        with_contact,
                    const bool        advance,
                    const bool        f_is_zero = false);
    /** Request the element data of @p batch into the cache. */
    void
    prefetch_batch(const unsigned int batch) const;
    /** Batches ahead of the one computed that prefetch_batch() requests. */
    static constexpr unsigned int prefetch_distance = 2;
    void
    setup_applied_forces();
    /** Add hanging-node entries of @p f to their masters and zero them. */
    void
    condense(VectorType &f) const;
    /** Set hanging-node entries of @p x (and of @p y) from their masters. */
    void
    distribute(VectorType &x, VectorType *y = nullptr) const;
    /** Internal and hourglass energy at the current u. */
    void
    strain_energies(Energies &e) const;

    const Parameters                                  &prm;
    parallel::distributed::Triangulation<dim>         &triangulation;
    MPI_Comm                                           mpi_communicator;
    FESystem<dim>                                      fe;
    DoFHandler<dim>                                    dof_handler;
    AffineConstraints<double>                          hanging_constraints;
    std::shared_ptr<const Utilities::MPI::Partitioner> vector_partitioner;

    /** Hanging-node constraints in local indices, flat (CSR): line k
     *  constrains constrained_dofs[k] to the masters constraint_masters[j]
     *  with weights constraint_weights[j], j in [constraint_offsets[k],
     *  constraint_offsets[k + 1]). */
    std::vector<unsigned int> constrained_dofs;
    std::vector<unsigned int> constraint_offsets;
    std::vector<unsigned int> constraint_masters;
    std::vector<double>       constraint_weights;

    // Element data, batches of n_lanes cells, structure of arrays.
    unsigned int              n_cells   = 0;
    unsigned int              n_batches = 0;
    AlignedVector<double>     batch_data;       ///< [batch][field][lane]
    std::vector<unsigned int> batch_nodes;      ///< [batch][vertex][lane]
    std::vector<unsigned int> batch_cell_index; ///< active cell index
    /** Batches whose 8 cells are the 8 children of one parent, in child
     *  order (lane l = child l): their 27 distinct nodes, the x-DoF of each
     *  in the parent's 3x3x3 lexicographic grid ([family][27]). */
    std::vector<unsigned int> family_nodes;
    /** Index into family_nodes / 27 of each batch, or invalid_unsigned_int. */
    std::vector<unsigned int>       batch_family;
    std::vector<types::material_id> batch_material;
    std::vector<double>             batch_kappa_ref; ///< hourglass stiffness with QM = 0.1
    double                          lame_lambda = 0; ///< of the one material [Pa]
    double                          lame_mu     = 0;

    // Nodal data (local indices of the ghosted vectors).
    std::vector<Point<dim>>         node_points; ///< reference position of each DoF
    std::vector<bool>               on_boundary;
    std::vector<types::material_id> node_material;
    std::vector<unsigned char>      node_component; ///< 0, 1, 2 = x, y, z
    std::vector<unsigned int>       bore_dofs;
    VectorType                      mass;     ///< condensed lumped mass, per DoF
    VectorType                      inv_mass; ///< 0 on constrained DoFs
    VectorType                      f_ext;    ///< gravity, condensed
    VectorType                      u0;       ///< displacement at the start

    /** Prescribed DoFs (owned): index and function of (X, t) -> u_d. */
    struct PrescribedDof
    {
      unsigned int index;
      unsigned int component;
      unsigned int kind;       ///< 0 fixed, 1 velocity function, 2 spinning axle, 3 rigid axle
      double       u_prev = 0; ///< u at the start of the step
      double       v_prev = 0; ///< v at the previous half step
      /** f_ext - f at this DoF (and, for the x-DoF of a rigid-axle bore
       *  node, at its y- and z-DoFs) in the current step: taken before
       *  the update clears f. */
      double net_force[3] = {0, 0, 0};
    };
    std::vector<PrescribedDof>     prescribed;
    std::unique_ptr<Function<dim>> prescribed_velocity;
    /** Applied-force DoFs: local index, component, area fraction. */
    std::vector<std::tuple<unsigned int, unsigned int, double>> applied;
    std::unique_ptr<Function<dim>>                              applied_force;
    PenaltyContact                                             *contact  = nullptr;
    Wheelset                                                   *wheelset = nullptr;

    VectorType u, v, f, v_old;
    /** f is zero (the update of the last step cleared it behind itself:
     *  the next step's assembly need not). */
    bool          f_cleared = false;
    double        t         = 0;
    double        dt        = 0;
    double        stable_dt = 0;
    MeshQuality   quality;
    unsigned long n_steps             = 0;
    double        damping_dissipation = 0;
    double        boundary_work       = 0;
    StepTimes     times;
  };
} // namespace WheelRail

#endif
