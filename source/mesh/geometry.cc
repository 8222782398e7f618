/**
 * @file mesh/geometry.cc
 * The undeformed wheel centre of the Geometry parameters.
 */

#include <wheelrail/mesh/geometry.h>

namespace WheelRail
{
  namespace Geometry
  {
    Point<dim>
    wheel_centre(const GeometryParameters &p)
    {
      return Point<dim>(p.wheel_centre_x, 0., p.wheel_centre_z());
    }
  } // namespace Geometry
} // namespace WheelRail
