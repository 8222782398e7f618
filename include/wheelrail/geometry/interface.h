/**
 * @file geometry/interface.h
 * The geometry models: what the rest of wheelrail asks of the bodies it
 * meshes (Problem/Geometry), as one abstract class, and the registry that
 * makes a model by its name.
 *
 * A geometry is one file source/geometry/NAME.cc that derives from
 * GeometryModel, defines a factory (and, for entries of its own, a
 * declaration function) in namespace GeometryModels and has one line in the
 * registry of source/geometry/interface.cc (the name there is the value of
 * Problem/Geometry). The mesh is built by Geometry::build() from the
 * model's parts: coarse mesh, boundary ids, manifolds, local refinement.
 * The three geometries of today read the shared GeometryParameters (their
 * entries are declared in parameters/problem_geometry.cc, where they have
 * always been); a new one may declare and read its own.
 */
#ifndef wheelrail_geometry_interface_h
#define wheelrail_geometry_interface_h

#include <deal.II/base/point.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/grid/tria.h>

#include <wheelrail/geometry/rigid_contact.h>
#include <wheelrail/parameters/parameters.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    /** A body of a geometry: its material id and its name in the reports. */
    struct Body
    {
      types::material_id material;
      const char        *name;
    };

    /** The cells of one body that reach into its solution zone. */
    struct ZoneCells
    {
      /** Cells whose bounding box in the refinement's chart coordinates
       *  shares a volume with the zone (all ranks). */
      types::global_cell_index n_cells = 0;
      /** Largest longest edge among them [m] (0 without such cells). */
      double max_longest_edge = 0;
    };

    /**
     * The coarse mesh's size, counted from the parameters before it is
     * built, and what the refusal of a too large one says.
     */
    struct CoarseCellEstimate
    {
      /** Number of coarse cells. */
      double n_cells;
      /** What makes them, e.g. "Geometry/Bar/Cells = 4, 2, 2 make a bar of 16 cells". */
      std::string cause;
      /** The entries to change, e.g. "reduce Geometry/Bar/Cells.". */
      std::string remedy;
    };

    /**
     * The radii of relative curvature of the two surfaces at the main
     * contact point, for the Hertz solution: along the rolling direction
     * (the wheel's rolling radius; the rail is straight) and across, in the
     * tangent plane (the rail's crown radius for the cylindrical wheel;
     * 1 / (z_w'' - z_r'') cos^-3(delta) for profiles).
     */
    struct ContactRadii
    {
      double wheel_rolling; ///< [m]
      double rail_crown;    ///< across [m]
    };

    /** An axis-aligned box [first, second] [m]. */
    using Box = std::pair<Point<dim>, Point<dim>>;

    /**
     * A geometry: the bodies, their coarse mesh with boundary, material and
     * manifold ids, the local refinement, the exact volumes and the
     * properties that the solver, the contact and the checks ask for.
     * A model keeps a copy of the Geometry parameters it was made with.
     */
    class GeometryModel
    {
    public:
      /** What a geometry file defines: make the model from the Geometry
       *  parameters and, for the entries it declared itself, @p prm (at the
       *  top level of the parameter file, already parsed). */
      using Factory = std::unique_ptr<GeometryModel>(const GeometryParameters &parameters,
                                                     ParameterHandler         &prm);

      /** What a geometry file with entries of its own defines: declare them
       *  into @p prm (at the top level; by convention in a subsection of
       *  Geometry named after the geometry). */
      using Declarations = void(ParameterHandler &prm);

      /** Declare the entries of every registered geometry that has any
       *  (all of them, whichever Problem/Geometry selects). */
      static void
      declare_parameters(ParameterHandler &prm);

      /** The model registered as @p name (a value of Problem/Geometry). */
      static std::unique_ptr<GeometryModel>
      create(const std::string &name, const GeometryParameters &parameters, ParameterHandler &prm);

      /** The registered names, "a|b|c", in the registry's order. */
      static std::string
      names();

      explicit GeometryModel(const GeometryParameters &parameters);

      virtual ~GeometryModel() = default;

      /** The value of Problem/Geometry that made this model. */
      const std::string &
      name() const;

      /** The bodies, in the order the reports list them. */
      virtual std::vector<Body>
      bodies() const = 0;

      /** The name of the body with material id @p material ("unknown body"
       *  for an id of none). */
      const char *
      body_name(const types::material_id material) const;

      /** Each body's axis-aligned bounding box, undeformed [m]. */
      virtual std::vector<Box>
      bounding_boxes() const = 0;

      /** Exact volume of the body with material id @p material [m^3]. */
      virtual double
      exact_volume(const types::material_id material) const = 0;

      /** The coarse mesh's cell count, before it is built. */
      virtual CoarseCellEstimate
      coarse_cell_estimate() const = 0;

      /** Append the coarse mesh's vertices and cells (with material ids).
       *  The bodies are separate: they share no vertex. */
      virtual void
      create_coarse_mesh(std::vector<Point<dim>>    &vertices,
                         std::vector<CellData<dim>> &cells) const = 0;

      /** Set the boundary ids (Geometry::BoundaryIds) of the coarse mesh. */
      virtual void
      set_boundary_ids(Triangulation<dim> &coarse) const = 0;

      /** Set the manifold ids of the coarse mesh's cells (none by default:
       *  flat). */
      virtual void
      set_manifold_ids(Triangulation<dim> &coarse) const;

      /** Attach the manifolds of those ids to @p triangulation (none by
       *  default). */
      virtual void
      attach_manifolds(parallel::distributed::Triangulation<dim> &triangulation) const;

      /** Refine locally towards the region of interest (none by default). */
      virtual void
      refine(parallel::distributed::Triangulation<dim> &triangulation) const;

      /** The cells of body @p material in its solution zone, or none where
       *  the geometry has no solution zone (the default). Collective. */
      virtual std::optional<ZoneCells>
      zone_cells(const types::material_id                         material,
                 const parallel::distributed::Triangulation<dim> &triangulation) const;

      /** The lateral span of the solution zones [m] (by default -Solution
       *  zone half width .. half width). */
      virtual std::pair<double, double>
      zone_span() const;

      /** Whether two bodies can touch (Contact/Enabled acts). */
      virtual bool
      has_contact() const = 0;

      /** Whether a wheel rolls on a rail: the wheelset, the static contact,
       *  the Hertz checks and the wheel and rail's consistency checks. */
      virtual bool
      has_wheel() const;

      /** The undeformed wheel centre [m] of Geometry/Wheel (by default
       *  Geometry::wheel_centre() of the parameters, whatever the bodies). */
      virtual Point<dim>
      wheel_centre() const;

      /** The wheel's undeformed rolling radius at O [m] (by default
       *  Geometry/Wheel/Radius). */
      virtual double
      rolling_radius() const;

      /** What the bodies' shapes are, for the run's summary (lines; empty
       *  by default). */
      virtual std::string
      description() const;

      /** The local radii of the surfaces at the contact (where
       *  has_wheel()). */
      virtual ContactRadii
      contact_radii() const;

      /** The rigid contact points of the undeformed bodies in the mesh's
       *  frame, the main one (at O) first; none by default. */
      virtual std::vector<RigidContact>
      rigid_contacts() const;

      /** Whether the bodies' shapes are profiles read from files (false by
       *  default). */
      virtual bool
      has_profile_files() const;

      /** Whether the contact results are reported per patch, one patch per
       *  rigid contact point (postprocess/contact_patches.h): with profile
       *  files or more than one rigid contact point. */
      bool
      reports_patches() const
      {
        return has_profile_files() || rigid_contacts().size() > 1;
      }

      /** The contact angle delta [rad] of the main rigid contact
       *  (RigidContact::contact_angle, the rail's normal from z towards +y
       *  for delta > 0) where the shapes come from profile files; none for
       *  the analytic shapes (delta = 0): from has_profile_files() and
       *  rigid_contacts(). */
      std::optional<double>
      profile_contact_angle() const;

      /** Whether the bodies are a block on a plate, the case of the sliding
       *  block checks (MaterialIds::block on MaterialIds::plate). */
      virtual bool
      is_block_on_plate() const;

      /** The body that Problem/Mode = rigid rotation turns, and the centre
       *  of the rotation: by default the wheel about wheel_centre() (a
       *  geometry without a wheel then turns nothing). */
      virtual std::pair<types::material_id, Point<dim>>
      rotating_body() const;

    protected:
      /** The parameters the model was made with. */
      const GeometryParameters p;

    private:
      /** Set by create(). */
      std::string model_name;
    };



    /**
     * Build the mesh of @p model into @p triangulation: refuse a too large
     * coarse mesh, create it with its boundary and manifold ids, attach
     * the manifolds and refine locally.
     */
    void
    build(const GeometryModel &model, parallel::distributed::Triangulation<dim> &triangulation);
  } // namespace Geometry
} // namespace WheelRail

#endif
