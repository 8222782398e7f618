/**
 * @file mesh/geometry.h
 * Meshes of the wheel and the rail head (SPEC 1) and of the verification
 * bar, with their boundary and material ids, manifolds and local refinement.
 */
#ifndef wheelrail_mesh_geometry_h
#define wheelrail_mesh_geometry_h

#include <deal.II/distributed/tria.h>

#include <wheelrail/parameters/parameters.h>

#include <string>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    /**
     * Boundary ids. The README lists them too; keep both in step.
     */
    namespace BoundaryIds
    {
      constexpr types::boundary_id wheel_tread  = 1;
      constexpr types::boundary_id wheel_bore   = 2;
      constexpr types::boundary_id wheel_side   = 3;
      constexpr types::boundary_id rail_top     = 10;
      constexpr types::boundary_id rail_bottom  = 11;
      constexpr types::boundary_id rail_end     = 12;
      constexpr types::boundary_id rail_side    = 13;
      constexpr types::boundary_id bar_side     = 20;
      constexpr types::boundary_id bar_start    = 21; ///< x = 0
      constexpr types::boundary_id bar_end      = 22; ///< x = L
      constexpr types::boundary_id block_bottom = 30;
      constexpr types::boundary_id block_top    = 31;
      constexpr types::boundary_id block_side   = 32;
      constexpr types::boundary_id plate_top    = 40;
      constexpr types::boundary_id plate_bottom = 41;
      constexpr types::boundary_id plate_side   = 42;
    } // namespace BoundaryIds

    /** Material ids: which body a cell belongs to. */
    namespace MaterialIds
    {
      constexpr types::material_id wheel = 1;
      constexpr types::material_id rail  = 2;
      constexpr types::material_id bar   = 3;
      constexpr types::material_id block = 4;
      constexpr types::material_id plate = 5;
    } // namespace MaterialIds

    /** A body of a geometry: its material id and its name in the reports. */
    struct Body
    {
      types::material_id material;
      const char        *name;
    };

    /** The bodies of @p geometry_type ("wheel and rail", "bar" or "block on
     *  plate"), in the order the reports list them. */
    std::vector<Body>
    bodies(const std::string &geometry_type);

    /** The name of the body with material id @p material, whatever the
     *  geometry ("unknown body" for an id of none). */
    const char *
    body_name(const types::material_id material);

    /** Manifold ids. */
    namespace ManifoldIds
    {
      constexpr types::manifold_id wheel = 1; ///< cylinder about the axle
      constexpr types::manifold_id rail  = 2; ///< box mapped to the arc top
    }                                         // namespace ManifoldIds

    /**
     * Build the coarse mesh of @p geometry_type ("wheel and rail", "bar" or
     * "block on plate"),
     * attach manifolds and refine locally as GeometryParameters says.
     */
    void
    build(const GeometryParameters                  &parameters,
          const std::string                         &geometry_type,
          parallel::distributed::Triangulation<dim> &triangulation);

    /** Undeformed wheel centre. */
    Point<dim>
    wheel_centre(const GeometryParameters &parameters);

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
     * Count the cells of body @p material (wheel or rail) that reach into
     * its solution zone and find the largest of them: a check that the
     * whole zone is meshed at Minimum cell size whatever the grading.
     * Collective over the triangulation's communicator.
     */
    ZoneCells
    zone_cells(const GeometryParameters                        &parameters,
               const types::material_id                         material,
               const parallel::distributed::Triangulation<dim> &triangulation);

    /** Exact volume of the body with material id @p material (analytic). */
    double
    exact_volume(const GeometryParameters &parameters, const types::material_id material);
  } // namespace Geometry
} // namespace WheelRail

#endif
