/**
 * @file parameters/parameters.h
 * Run-time parameters of wheelrail, one plain struct per subsystem.
 *
 * Every struct has a static declare_parameters(), a parse_parameters() and
 * (where values depend on each other) a check(). Nothing reads the
 * ParameterHandler after Parameters::parse() returned. All values are SI
 * (m, kg, s, N, Pa) inside the program; every entry's help text gives its
 * unit and allowed range.
 */
#ifndef wheelrail_parameters_parameters_h
#define wheelrail_parameters_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <wheelrail/parameters/selection.h>
#include <wheelrail/postprocess/registry.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace WheelRail
{
  using namespace dealii;

  /** Space dimension: wheelrail is a 3D program only. */
  constexpr unsigned int dim = 3;

  /** Time integration/Damping model: the stiffness-proportional damping
   *  coefficient beta_e of each cell (SPEC 2). */
  enum class DampingModel
  {
    none,
    stiffness, ///< beta_e = 2 COEF / omega_e, omega_e = 2 c / L_e
    rayleigh   ///< beta_e = Rayleigh beta for every cell
  };
  inline constexpr SelectionNames<DampingModel, 3> damping_model_names{
    {{"none", "stiffness", "Rayleigh"}}};

  /** Time integration/Damping form: how the explicit step evaluates the
   *  stiffness damping of the Damping model (SPEC 2). */
  enum class DampingForm
  {
    strain_rate, ///< the viscous stress beta_e C : dE/dt in each element
    nodal_field  ///< the internal force at w = u + beta_n v, beta_n per node
  };
  inline constexpr SelectionNames<DampingForm, 2> damping_form_names{
    {{"strain rate", "nodal field"}}};

  /** Time integration/Element geometry sharing: which batches share one
   *  copy of the single-precision element data. */
  enum class GeometrySharing
  {
    identical,      ///< blocks that are the same bit for bit
    within_rounding ///< blocks the same after rounding to the floats' precision
  };
  inline constexpr SelectionNames<GeometrySharing, 2> geometry_sharing_names{
    {{"identical", "within rounding"}}};

  /** Problem/Mode: the explicit run or one of the static runs. */
  enum class RunMode
  {
    explicit_dynamics,
    static_contact,
    patch_test,
    rigid_rotation
  };
  inline constexpr SelectionNames<RunMode, 4> run_mode_names{
    {{"explicit dynamics", "static contact", "patch test", "rigid rotation"}}};

  /** Problem/Partition: how the cells are split between the ranks. */
  enum class PartitionBy
  {
    work,
    cells
  };
  inline constexpr SelectionNames<PartitionBy, 2> partition_by_names{{{"work", "cells"}}};

  /** Boundary conditions/Wheel bore: the motion of the bore nodes. */
  enum class WheelBore
  {
    free,
    fixed,
    spinning_axle,
    rigid_axle
  };
  inline constexpr SelectionNames<WheelBore, 4> wheel_bore_names{
    {{"free", "fixed", "spinning axle", "rigid axle"}}};

  /** Contact/Penalty stiffness. */
  enum class PenaltyStiffness
  {
    segment,
    area
  };
  inline constexpr SelectionNames<PenaltyStiffness, 2> penalty_stiffness_names{
    {{"segment", "area"}}};

  /** Contact/Slip rate: what the friction law is evaluated at. */
  enum class SlipRate
  {
    total,
    irreversible
  };
  inline constexpr SelectionNames<SlipRate, 2> slip_rate_names{{{"total", "irreversible"}}};

  /** Static solve/AMG near null space. */
  enum class AmgNullSpace
  {
    translations,
    rigid_body_modes
  };
  inline constexpr SelectionNames<AmgNullSpace, 2> amg_null_space_names{
    {{"translations", "rigid body modes"}}};

  /** Output/VTU compression. */
  enum class VtuCompression
  {
    fast,
    best,
    none
  };
  inline constexpr SelectionNames<VtuCompression, 3> vtu_compression_names{
    {{"fast", "best", "none"}}};

  /** What is computed and where it goes ("subsection Problem"). */
  struct ProblemParameters
  {
    /** The geometry model's name: "wheel and rail" (the paper's model),
     *  "bar" or "block on plate" (verification bodies); the names are
     *  GeometryModel::names(). */
    std::string geometry;
    /** The explicit run or one of the static verification modes. */
    RunMode     mode;
    std::string output_directory;
    /** Reproducible screen output for the test suite: no timings, no paths. */
    bool test_mode;
    /** Parse, build the mesh, print the summary and stop. */
    bool dry_run;
    /** Equal work (Mesh::partition_by_work()) or equal cells per rank. */
    PartitionBy partition;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Wheel, rail and mesh refinement (SPEC section 1). */
  struct GeometryParameters
  {
    // wheel
    double       wheel_radius;
    double       bore_radius;
    double       tread_width;
    double       wheel_centre_x;
    double       initial_gap;
    unsigned int wheel_circumferential_cells;
    // rail
    double rail_head_height;
    double rail_head_width;
    double rail_profile_radius;
    double rail_start_x;
    double rail_end_x;
    // mesh
    double coarse_cell_size;
    double h_min;
    double zone_length;
    double zone_half_width;
    /** Lateral span of the solution zones [m]: -half width .. half width,
     *  widened by the geometry to the zones of every rigid contact point
     *  (Parameters::parse(), GeometryModel::zone_span()). */
    double zone_y_lo = 0, zone_y_hi = 0;
    double zone_depth;
    double grading;
    bool   refine_wheel;
    double path_cell_size; ///< along the whole rolling path, 0 = off [m]
    /** Coarse cells that refine onto h_min in every direction over the zone. */
    bool align_zone;
    // bar (verification geometry)
    double                    bar_length;
    double                    bar_width;
    double                    bar_height;
    std::vector<unsigned int> bar_cells;
    double                    bar_distortion;
    // block on plate (contact verification geometry)
    Tensor<1, 3>              plate_size;
    std::vector<unsigned int> plate_cells;
    Tensor<1, 3>              block_size;
    std::vector<unsigned int> block_cells;
    double                    block_x;
    double                    block_gap;
    /** The directory a relative file name given by @p entry of subsection
     *  @p section is read from: that of the parameter file that set it. */
    std::function<std::string(const std::string &section, const std::string &entry)> file_directory;

    /** Height of the undeformed wheel centre above O. */
    double
    wheel_centre_z() const
    {
      return wheel_radius + initial_gap;
    }

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
    void
    check() const;
  };

  /** Linear elastic material, the same for wheel and rail (SPEC 2). */
  struct MaterialParameters
  {
    double youngs_modulus;
    double poisson_ratio;
    double density;

    double
    lambda() const
    {
      return youngs_modulus * poisson_ratio / ((1. + poisson_ratio) * (1. - 2. * poisson_ratio));
    }
    double
    mu() const
    {
      return youngs_modulus / (2. * (1. + poisson_ratio));
    }
    /** Dilatational wave speed sqrt((lambda+2mu)/rho). */
    double
    wave_speed() const;
    /** Bar wave speed sqrt(E/rho). */
    double
    bar_wave_speed() const;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Element, damping and central-difference integration (SPEC 2). */
  struct SolverParameters
  {
    double          end_time;
    double          time_step;       ///< 0 = automatic
    bool            allow_long_runs; ///< confirms > 1e8 steps or a step < 1e-3 of the stable one
    double          courant_factor;
    double          hourglass_coefficient;
    DampingModel    damping_model;
    DampingForm     damping_form;
    double          stiffness_damping_coefficient;
    double          rayleigh_beta;
    Tensor<1, 3>    gravity;
    bool            single_precision_geometry; ///< Element geometry precision = single
    GeometrySharing geometry_sharing;          ///< Element geometry sharing

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Dirichlet conditions and prescribed motions. */
  struct BoundaryParameters
  {
    /** boundary id -> fixed components as a mask "xyz". */
    std::map<types::boundary_id, std::string> fixed;
    /** Fixed boundaries holds its default (the rail's ids 11 and 12), which
     *  the other geometries do not have: their runs ignore it. */
    bool fixed_is_default = true;
    /** Boundary ids whose velocity is prescribed by the function below. */
    std::vector<types::boundary_id> prescribed_velocity_ids;
    /** Expression of the prescribed velocity, "vx; vy; vz" in (x,y,z,t). */
    std::string prescribed_velocity_expression;
    std::string prescribed_velocity_constants;
    /** The motion of the wheel bore. */
    WheelBore wheel_bore;
    /** Boundary ids loaded by the applied force (empty = none). */
    std::vector<types::boundary_id> applied_force_ids;
    /** Total force "Fx; Fy; Fz" [N] as functions of t, spread by area. */
    std::string applied_force_expression;
    std::string applied_force_constants;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  class FrictionLaw;

  /** Penalty node-to-segment contact and friction (SPEC 4). */
  struct ContactParameters
  {
    bool               enabled;
    types::boundary_id slave_boundary;
    types::boundary_id master_boundary;
    bool               two_pass;
    double             penalty_scale;
    PenaltyStiffness   penalty_stiffness;
    double             penalty_reference_length; ///< h_ref of "area" [m], 0: finest master cell
    double             tangential_factor;
    double             damping_ratio;
    unsigned int       search_interval;
    double             search_margin;
    double             rebuild_fraction;
    double             initial_overlap_tolerance; ///< [m], see check_initial_overlap()
    std::string        friction_law;              ///< its name, "none" for no friction
    /** The law with its coefficients (FrictionLaw::create()), null for
     *  "none". */
    std::shared_ptr<const FrictionLaw> law;
    SlipRate                           slip_rate;         ///< total (paper) or irreversible
    double                             relaxation_length; ///< L of the friction state [m], 0: off
    double                             relaxation_time;   ///< tau of the friction state [s], 0: off
    double                             tangential_damping; ///< fraction of critical on k_t [-]

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Axle, primary suspension, sprung mass and driving torque (SPEC 3). */
  struct WheelsetParameters
  {
    double unsprung_mass;
    double sprung_mass;
    double suspension_stiffness;
    double suspension_damping;
    double axle_inertia;
    double rolling_speed;
    double traction_coefficient;
    double torque_ramp_time;
    double initial_creepage;      ///< xi_0 = (V - omega r) / V at the start [-]
    double creepage_control_time; ///< omega follows v_x (1 - xi_0) / r until then [s]
    double lateral_creepage;      ///< eta: the axle moves laterally at eta V [-]
    double yaw_angle;             ///< psi about z [rad]: the axle moves laterally at -psi V
    double runup_damping;         ///< alpha of the run-up damping [1/s]
    double runup_time;            ///< the run-up damping acts until then [s]
    /** "nodes" (each node's v - v_rigid) or "wheel rigid motion" (its
     *  rigid-motion part over the wheel), see add_runup_damping() */
    std::string runup_damping_shape;
    bool        static_start;
    /** Directory of the static start's state: read if there, else
     *  written ("": neither) */
    std::string static_start_state;

    /** The axle's lateral velocity per unit rolling speed, eta - psi [-]:
     *  Lateral creepage and Yaw angle set the same lateral motion
     *  (small-angle kinematics; at most one of them is non-zero). */
    double
    axle_lateral_creepage() const
    {
      return lateral_creepage - yaw_angle;
    }

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** The implicit static contact solve (SPEC 5.2). */
  struct StaticParameters
  {
    /** Default of Axle load [N]: (13.4 t + 0.9 t) g, the paper's. A run
     *  that does not use the Axle load takes this value as "not given". */
    static constexpr double default_axle_load = 140300;

    double       axle_load;
    double       load_tolerance;
    double       newton_tolerance;
    unsigned int max_newton_iterations;
    double       linear_tolerance;
    bool         inexact_newton; ///< CG tolerance from the Newton residual
    AmgNullSpace amg_null_space;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Initial velocity fields. */
  struct InitialParameters
  {
    Tensor<1, 3> wheel_velocity;
    double       wheel_angular_velocity; ///< about +y, rad/s
    std::string  velocity_expression;    ///< "vx; vy; vz" in (x,y,z)
    std::string  velocity_constants;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Screen reports, statistics file, VTU snapshots, probes. */
  struct OutputParameters
  {
    unsigned int   report_interval;
    unsigned int   statistics_interval;
    unsigned int   vtu_interval;
    VtuCompression vtu_compression;
    double         patch_window;          ///< window of the patch means [s], 0 = none
    unsigned int   patch_series_interval; ///< steps between patch-series frames, 0 = none
    bool           patch_series_tread;    ///< the series holds the tread's frames too
    Point<3>       probe_point;
    unsigned int   probe_component;
    unsigned int   timing_warmup_steps;
    double         divergence_limit;    ///< largest relative energy balance error
    unsigned int   checkpoint_interval; ///< steps between checkpoints, 0 = none
    double         checkpoint_minutes;  ///< wall minutes between checkpoints, 0 = none
    unsigned long  stop_after_step;     ///< stop (with a checkpoint) after this step, 0 = never
    bool           resume = false;      ///< continue from OUTDIR/checkpoint (--resume)
    /** Output/Postprocessors: the selected ones, each by name with its
     *  parsed parameters (postprocess/registry.h). */
    std::vector<std::pair<std::string, PostprocessorFactory>> postprocessors;

    static void
    declare_parameters(ParameterHandler &prm);
    /** Output/Checkpoint interval, whose documentation lists the entries
     *  marked resumable: declared after all others. */
    static void
    declare_checkpoint_interval(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** Checks against analytic solutions, used by the test suite. */
  struct VerificationParameters
  {
    std::string  check;
    Tensor<2, 3> displacement_gradient;
    double       rotation_angle; ///< rad
    Tensor<1, 3> rotation_axis;  ///< unit vector
    double       tolerance;
    double       wave_threshold;
    double       hourglass_limit;
    bool         round_off_sensitive; ///< test mode prints robust values only
    bool         bar_clamped;
    bool         expect_failure; ///< Expected verdict = no: a test of a failing check

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /**
   * A three-component muparser function of @p variables ("x,y,z" or
   * "x,y,z,t") from @p expression ("vx; vy; vz") and @p constants
   * ("name=value, ..."; pi is predefined). It is evaluated once here so
   * that a malformed expression is reported with the name of its
   * parameter @p entry.
   */
  std::unique_ptr<FunctionParser<3>>
  make_vector_function(const std::string &expression,
                       const std::string &constants,
                       const std::string &variables,
                       const std::string &entry);

  namespace Geometry
  {
    class GeometryModel;
  }

  /** All parameters of a run. */
  struct Parameters
  {
    ProblemParameters      problem;
    GeometryParameters     geometry;
    MaterialParameters     material;
    SolverParameters       solver;
    BoundaryParameters     boundary;
    InitialParameters      initial;
    ContactParameters      contact;
    StaticParameters       statics;
    WheelsetParameters     wheelset;
    OutputParameters       output;
    VerificationParameters verification;
    /** The geometry model of Problem/Geometry, made by parse() from the
     *  Geometry subsection (geometry/interface.h). */
    std::shared_ptr<const Geometry::GeometryModel> geometry_model;

    static void
    declare_parameters(ParameterHandler &prm);
    /** Read @p filename into @p prm and fill all structs; throws on bad input. */
    void
    parse(ParameterHandler &prm, const std::string &filename);
  };
} // namespace WheelRail

#endif
