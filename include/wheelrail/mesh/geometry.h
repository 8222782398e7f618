/**
 * @file mesh/geometry.h
 * The ids that the geometry models give the mesh (boundary, material and
 * manifold ids) and the wheel centre; the models themselves are
 * geometry/interface.h.
 */
#ifndef wheelrail_mesh_geometry_h
#define wheelrail_mesh_geometry_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <deal.II/distributed/tria.h>

#include <wheelrail/parameters/parameters.h>


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

    /** Manifold ids. */
    namespace ManifoldIds
    {
      constexpr types::manifold_id wheel = 1; ///< cylinder about the axle
      constexpr types::manifold_id rail  = 2; ///< box mapped to the arc top
    }                                         // namespace ManifoldIds

    /** Undeformed wheel centre. */
    Point<dim>
    wheel_centre(const GeometryParameters &parameters);

  } // namespace Geometry
} // namespace WheelRail

#endif
