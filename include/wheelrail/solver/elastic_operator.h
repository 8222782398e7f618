/**
 * @file elastic_operator.h
 * The discretised elastic bodies (SPEC 2): DoFs, partitioner and hanging
 * node constraints (built once, used by the explicit and the static solve),
 * the per-cell element data in batches, the condensed lumped mass, and the
 * operations on them: internal forces (one-point hexahedra, St.
 * Venant-Kirchhoff, stiffness hourglass control, element stiffness damping),
 * the small-strain stiffness matrix, strain energies and cell stresses.
 * It holds no time-integration state: the displacement and velocity are
 * arguments.
 */
#ifndef wheelrail_solver_elastic_operator_h
#define wheelrail_solver_elastic_operator_h

#include <deal.II/base/aligned_vector.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/partitioner.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <wheelrail/parameters/parameters.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace WheelRail
{
  using VectorType = LinearAlgebra::distributed::Vector<double>;

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

  /** Strain energies of the bodies at one displacement [J]. */
  struct StrainEnergies
  {
    double internal            = 0; ///< St. Venant-Kirchhoff strain energy
    double hourglass           = 0; ///< stored in the hourglass springs
    double hourglass_reference = 0; ///< hourglass energy with QM = 0.1
  };

  namespace ElementKernel
  {
    struct BatchEnergies;
  } // namespace ElementKernel

  /** Time Integration/Damping model, decided once at setup. */
  /**
   * The elastic operator on a distributed mesh of trilinear hexahedra.
   * Vectors are LinearAlgebra::distributed::Vector on partitioner(): the
   * locally relevant DoFs and every master of a hanging-node constraint are
   * ghosts. Element data are stored in batches of n_lanes cells (structure
   * of arrays) for the vectorised kernel of element_kernel.h.
   */
  class ElasticOperator
  {
  public:
    /** Lanes of a cell batch; the kernel vectorises across them. */
    static constexpr unsigned int n_lanes = 8;

    ElasticOperator(const Parameters                          &parameters,
                    parallel::distributed::Triangulation<dim> &triangulation);

    /** Distribute DoFs, build the constraints, element data and mass. */
    void
    setup();

    /**
     * f = f_int(u) + f_damp(v) over the cells, not condensed, not
     * compressed (the caller adds contact forces, then condenses). Damping
     * forces only if @p v is given and the damping model is not none.
     * With @p f_is_zero the caller guarantees f = 0 already (owned and ghost
     * entries). With @p energies, also this rank's strain energies at u
     * (of the operator the forces come from: with single-precision
     * geometry, its rounded factors). Returns the damping power.
     */
    double
    element_forces(const VectorType &u,
                   const VectorType *v,
                   VectorType       &f,
                   const bool        f_is_zero,
                   StrainEnergies   *energies = nullptr) const;
    /** Add hanging-node entries of @p f to their masters and zero them. */
    void
    condense(VectorType &f) const;
    /** Set hanging-node entries of @p x (and of @p y) from their masters;
     *  with @p beta and @p z, also z = x + beta y on those entries. */
    void
    distribute(VectorType       &x,
               VectorType       *y    = nullptr,
               const VectorType *beta = nullptr,
               VectorType       *z    = nullptr) const;

    /**
     * Assemble the stiffness of the one-point element with hourglass
     * control at u = 0 (the small-strain tangent) into @p matrix through
     * @p constraints, one cell at a time.
     */
    void
    assemble_stiffness(TrilinosWrappers::SparseMatrix  &matrix,
                       const AffineConstraints<double> &constraints) const;
    /** Stress at @p u of every locally owned cell (in active cell index order). */
    std::vector<CellStress>
    stresses(const VectorType &u) const;
    /** Volume-weighted nodal sums of H = grad u: @p gradient[j] holds
     *  V H_ij at DoF (node, i), @p weight the volumes V (compressed). */
    void
    nodal_gradient(const VectorType            &u,
                   std::array<VectorType, dim> &gradient,
                   VectorType                  &weight) const;
    /** Set the entries of @p x at the nodes of the locally owned cells of
     *  @p material (all if invalid id) to @p value_of_X at the node; ghost
     *  entries are not exchanged. */
    void
    interpolate(const std::function<Tensor<1, dim>(const Point<dim> &)> &value_of_X,
                const types::material_id                                 material,
                VectorType                                              &x) const;

    /** The damping coefficient of the nodal form (Damping form = nodal
     *  field) per DoF: beta_n, the smallest beta_e [s] of the cells around
     *  the node over all ranks (no cell is damped more than its beta_e);
     *  on every locally relevant DoF, ghosted. Collective. */
    void
    smallest_cell_beta(VectorType &beta) const;

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
    DampingModel
    damping_model() const
    {
      return damping;
    }
    /** Condensed lumped mass, per DoF (0 on hanging DoFs). */
    const VectorType &
    lumped_mass() const
    {
      return mass;
    }
    /**
     * The mass that a force applied at a node accelerates, per DoF: the
     * lumped mass, and on a hanging DoF with masters j and weights w_j
     * 1 / sum_j (w_j^2 / m_j) (its acceleration under a point force f is
     * sum_j w_j (w_j f) / m_j). Ghosted. The contact's damping and the
     * stability of its springs take it.
     */
    VectorType
    point_mass() const;
    const AffineConstraints<double> &
    get_hanging_constraints() const
    {
      return hanging_constraints;
    }
    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }
    const std::shared_ptr<const Utilities::MPI::Partitioner> &
    partitioner() const
    {
      return vector_partitioner;
    }
    /** Sum of the condensed lumped mass [kg] of cells of @p material. */
    double
    total_mass(const types::material_id material = numbers::invalid_material_id) const;
    /** Sum of the reference cell volumes of @p material [m^3]. */
    double
    mesh_volume(const types::material_id material = numbers::invalid_material_id) const;
    /** Number of locally owned cells in family batches (8 children of one
     *  parent, 27 nodes gathered and scattered instead of 64). */
    unsigned int
    n_family_cells() const
    {
      return 8 * (family_nodes.size() / 27);
    }
    /** Distinct blocks of single-precision element data that the force
     *  loop streams, and the batches that read them (0 and n_batches of
     *  this rank; 0 with double geometry). */
    std::pair<unsigned int, unsigned int>
    n_single_blocks_and_batches() const;
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
    /** Local indices (owned and ghost) of every DoF with a hanging-node
     *  constraint, every component of a constrained node. */
    std::vector<unsigned int>
    constrained_local_dofs() const;

  protected:
    const Parameters                                  &prm;
    parallel::distributed::Triangulation<dim>         &triangulation;
    MPI_Comm                                           mpi_communicator;
    std::shared_ptr<const Utilities::MPI::Partitioner> vector_partitioner;
    /** Reference position, material and component of each DoF (local
     *  indices of the ghosted vectors). */
    std::vector<Point<dim>>         node_points;
    std::vector<types::material_id> node_material;
    std::vector<unsigned char>      node_component; ///< 0, 1, 2 = x, y, z
    VectorType                      mass;           ///< condensed lumped mass, per DoF

  private:
    /** Move hanging vertices to the mean of their masters (see .cc). */
    void
    make_hanging_vertices_conforming();
    /** Ghost set, partitioner and the flat copy of the constraints. */
    void
    setup_partitioner();
    /** Reference position, material, component, boundary flag per DoF. */
    void
    setup_node_data();
    /** Locally owned cells in batch order: families first (see .cc). */
    std::vector<DoFHandler<dim>::active_cell_iterator>
    cells_in_batch_order() const;
    /** Element data of every batch, the mesh quality and the stable step. */
    void
    setup_cell_data();
    /** Batches that hold a family: their 27 grid nodes. */
    void
    find_families();
    void
    setup_lumped_mass();
    /** The parts of setup_cell_data(): the element data of @p cell in
     *  lane @p lane of its batch's @p data (mean gradients, hourglass base
     *  vectors), with its volume @p V0 and sum |B_a|^2 @p BB ... */
    void
    cell_geometry(const FEValues<dim>                         &fe_values,
                  const DoFHandler<dim>::active_cell_iterator &cell,
                  const unsigned int                           lane,
                  double                                      *data,
                  double                                      &V0,
                  double                                      &BB) const;
    /** ... the mesh quality and the stable step over the ranks ... */
    void
    reduce_mesh_quality(const MeshQuality &local, const double min_dt);
    /** ... and the force loop's copy with single-precision geometric
     *  factors, one per distinct block (Time integration/Element geometry
     *  precision and sharing; single_element_data.cc). */
    void
    copy_single_precision();
    /** The element force loop over the batches, whose element data are
     *  the blocks of @p batch_blocks (@p block_size doubles each) in batch
     *  order, or block @p block_of[batch] where @p block_of is given, read
     *  through @p Data (DoubleData or SingleData of element_data.h);
     *  @p with_damping: the stiffness
     *  damping stress from the velocities @p V; @p with_energies: the
     *  strain energies into @p energies as well. One instantiation per
     *  combination, so that the hot loop holds one kernel and no branch on
     *  them. */
    template <typename Data, bool with_damping, bool with_energies>
    double
    element_loop(const double       *batch_blocks,
                 const unsigned int *block_of,
                 const unsigned int  block_size,
                 const double       *U,
                 const double       *V,
                 double             *F,
                 StrainEnergies     *energies) const;
    /** The parts of element_loop(), force-inlined into it but for the
     *  gather: the buffers of the nodal values gathered one batch
     *  ahead ... */
    struct GatherSlots;
    /** ... the gather of batch @p batch into slot @p slot ... */
    template <bool with_damping>
    void
    gather_batch(const unsigned int batch,
                 const unsigned int slot,
                 const double      *U,
                 const double      *V,
                 GatherSlots       &slots) const;
    /** ... the kernel on the batch's values in slot @p slot (a family's
     *  expanded from its grid), forces into @p fb; returns the damping
     *  power ... */
    template <typename Data, bool with_damping, bool with_energies>
    double
    batch_kernel(const Data                           &data,
                 const bool                            in_family,
                 const unsigned int                    slot,
                 GatherSlots                          &slots,
                 double                               *fb,
                 ElementKernel::BatchEnergies         &batch_energies,
                 const double                         *kappa_ref) const;
    /** ... and the scatter of the forces @p fb of a batch that is not a
     *  family into @p F. */
    void
    scatter_batch(const unsigned int batch, const double *fb, double *F) const;
    /** Request a batch's element data (@p size doubles) into the cache. */
    static void
    prefetch_block(const double *block, const unsigned int size);
    /** Batches ahead of the one computed that prefetch_block() requests
     *  (bench of 2026-11-25, doc/notes/performance.md: 4 or 6 batches are within
     *  the noise of 2, none requested is 60 % slower). */
    static constexpr unsigned int prefetch_distance = 2;
    /** Request u, v (with damping) and f of the nodes of @p batch into the
     *  cache: a family's 27 grid nodes, or the 8 W vertices of other cells. */
    void
    prefetch_nodes(const unsigned int batch,
                   const double      *U,
                   const double      *V,
                   const double      *F,
                   const bool         with_damping) const;
    /** Batches ahead of the one computed whose nodal values
     *  prefetch_nodes() requests (doc/notes/performance.md, 2026-11-26). */
    static constexpr unsigned int node_prefetch_distance = 4;

    FESystem<dim>             fe;
    DoFHandler<dim>           dof_handler;
    AffineConstraints<double> hanging_constraints;
    DampingModel              damping = DampingModel::none;

    /** Hanging-node constraints in local indices, flat (CSR) and grouped
     *  by node: group k constrains the constraint_width DoFs
     *  constrained_dofs[k] + d to the masters constraint_masters[j] + d
     *  with weights constraint_weights[j], j in [constraint_offsets[k],
     *  constraint_offsets[k + 1]). constraint_width is dim where every
     *  node's lines share masters and weights (FE_Q(1)^dim, node-blocked
     *  DoFs), else 1 (one group per line). */
    unsigned int              constraint_width = 1;
    std::vector<unsigned int> constrained_dofs;
    std::vector<unsigned int> constraint_offsets;
    std::vector<unsigned int> constraint_masters;
    std::vector<double>       constraint_weights;

    // Element data, batches of n_lanes cells, structure of arrays.
    unsigned int          n_cells   = 0;
    unsigned int          n_batches = 0;
    AlignedVector<double> batch_data; ///< [batch][field][lane]
    /** With Time integration/Element geometry precision = single the force
     *  loop reads this copy (layout ElementKernel::SingleField), everything
     *  else batch_data; empty otherwise. */
    AlignedVector<double> batch_single;
    /** The block of batch_single of each batch. */
    std::vector<unsigned int> batch_single_block;
    std::vector<unsigned int> batch_nodes;      ///< [batch][vertex][lane]
    std::vector<unsigned int> batch_cell_index; ///< active cell index
    /** Batches whose 8 cells are the 8 children of one parent, in child
     *  order (lane l = child l): their 27 distinct nodes, the x-DoF of each
     *  in the parent's 3x3x3 lexicographic grid ([family][27]). */
    std::vector<unsigned int> family_nodes;
    /** Per family: 1 if all its nodes are 4 values or more before the end
     *  of the nodal vectors (gather_family_grid()'s 4-wide loads), else 0. */
    std::vector<unsigned char> family_wide_loads;
    /** Index into family_nodes / 27 of each batch, or invalid_unsigned_int. */
    std::vector<unsigned int>       batch_family;
    std::vector<types::material_id> batch_material;
    std::vector<double>             batch_kappa_ref; ///< hourglass stiffness with QM = 0.1
    double                          lame_lambda = 0; ///< of the one material [Pa]
    double                          lame_mu     = 0;

    std::vector<bool> on_boundary;
    double            stable_dt = 0;
    MeshQuality       quality;
  };
} // namespace WheelRail

#endif
