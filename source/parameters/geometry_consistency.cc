/**
 * @file parameters/geometry_consistency.cc
 * The wheel-rail geometry checked against the run before anything is
 * built: the solution zone on the rail, the contact patch on the rail
 * over the whole rolling path, and an axle load that the wheelset's
 * weight would replace.
 */

#include <deal.II/base/exceptions.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/parameters/consistency.h>
#include <wheelrail/simulator/format.h>
#include <wheelrail/verification/hertz_patch.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace WheelRail
{
  namespace Consistency
  {
    using Report::fmt;

    namespace
    {
      /** Hertz's half-length along x of the patch under the wheel load
       *  @p F [m]; 0 without a load. */
      double
      patch_half_length(const Parameters &p, const double F)
      {
        return F > 0 ? Verification::wheel_rail_hertz(p, F).a : 0.;
      }



      /** The weight of the wheelset's masses [N]: the wheel load of a run
       *  with Wheel bore = rigid axle (Wheelset::static_load()). */
      double
      wheelset_weight(const Parameters &p)
      {
        return (p.wheelset.unsprung_mass + p.wheelset.sprung_mass) * p.solver.gravity.norm();
      }



      /** The rail (Start x, End x) as the messages name it. */
      std::string
      rail_name(const GeometryParameters &g)
      {
        return "the rail (Geometry/Rail/Start x = " + fmt(g.rail_start_x) +
               " m, End x = " + fmt(g.rail_end_x) + " m)";
      }



      /** The solution zone lies on the rail head. */
      void
      check_solution_zone(const Parameters &p)
      {
        const GeometryParameters &g    = p.geometry;
        const std::string         rail = rail_name(g);
        // the solution zone, centred on O, on the rail head: across, within
        // the head's width; along x at least half of it on the rail (a zone
        // that reaches past a rail end refines nothing there: the rail's
        // part is clipped at the end, and tests have zones 10 mm past it)
        if (g.zone_length > 0)
          {
            const double on_rail = std::min(0.5 * g.zone_length, g.rail_end_x) -
                                   std::max(-0.5 * g.zone_length, g.rail_start_x);
            AssertThrow(on_rail >= 0.5 * g.zone_length,
                        ExcMessage(
                          "Geometry/Mesh/Solution zone length = " + fmt(g.zone_length) +
                          " m puts the solution zone at x = " + fmt(-0.5 * g.zone_length) + " to " +
                          fmt(0.5 * g.zone_length) + " m (centred on O), " +
                          (on_rail > 0 ? "mostly off " + rail + ": only " + fmt(on_rail, 3) +
                                           " m of it on the rail" :
                                         "wholly off " + rail) +
                          ". Move the rail (Start x, End x) to take in O = 0 and the zone, "
                          "or shorten the zone."));
            AssertThrow(g.zone_half_width <= 0.5 * g.rail_head_width * (1 + 1e-12),
                        ExcMessage(
                          "Geometry/Mesh/Solution zone half width = " + fmt(g.zone_half_width) +
                          " m makes the solution zone wider than the rail head "
                          "(Geometry/Rail/Head width = " +
                          fmt(g.rail_head_width) + " m): " +
                          (g.zone_half_width > g.rail_head_width ? "most of it" : "part of it") +
                          " lies off the rail. Reduce the half width to at most half the head "
                          "width, or widen the head."));
          }
      }



      /** Static solve/Axle load is not given where the wheelset's weight
       *  replaces it. */
      void
      check_axle_load(const Parameters &p)
      {
        const bool explicit_run = p.problem.mode == RunMode::explicit_dynamics;
        const bool rigid_axle   = p.boundary.wheel_bore == WheelBore::rigid_axle;
        // the wheel load: the masses' weight on the rigid axle, Axle load in
        // the static contact solve; the Axle load must not be given where
        // the weight replaces it
        const double weight = wheelset_weight(p);
        if (explicit_run && rigid_axle &&
            p.statics.axle_load != StaticParameters::default_axle_load &&
            std::abs(p.statics.axle_load - weight) > 1e-3 * weight)
          AssertThrow(false,
                      ExcMessage(
                        "Static solve/Axle load = " + fmt(p.statics.axle_load) +
                        " N is not the wheel load of this run: with Boundary conditions/Wheel bore "
                        "= rigid axle the load is the weight of the wheelset, (Wheelset/Unsprung "
                        "mass " +
                        fmt(p.wheelset.unsprung_mass) + " kg + Sprung mass " +
                        fmt(p.wheelset.sprung_mass) + " kg) x |Time integration/Gravity| " +
                        fmt(p.solver.gravity.norm(), 4) + " m/s^2 = " + fmt(weight) +
                        " N, which wins (Axle load is the load of Problem/Mode = static contact "
                        "alone). Remove Axle load, or set the masses for the load you want (Sprung "
                        "mass = " +
                        fmt(
                          std::max(0.,
                                   p.statics.axle_load / std::max(p.solver.gravity.norm(), 1e-300) -
                                     p.wheelset.unsprung_mass)) +
                        " kg gives it)."));
      }



      /** The contact patch stays on the rail with a margin, from the start
       *  to where the wheel rolls at End time. */
      void
      check_rail_length(const Parameters &p)
      {
        const GeometryParameters &g            = p.geometry;
        const bool                explicit_run = p.problem.mode == RunMode::explicit_dynamics;
        const bool                rigid_axle   = p.boundary.wheel_bore == WheelBore::rigid_axle;
        const double              weight       = wheelset_weight(p);
        const std::string         rail         = rail_name(g);
        // the contact patch on the rail with as much rail again beyond it
        // (the free end is soft), from Centre x to where the wheel has
        // rolled at End time
        double load = 0;
        if (p.problem.mode == RunMode::static_contact)
          load = p.statics.axle_load;
        else if (rigid_axle)
          load = weight;
        const double a      = patch_half_length(p, load);
        const double margin = 2 * a;
        const double x0     = g.wheel_centre_x;
        const double travel =
          explicit_run && rigid_axle ? p.wheelset.rolling_speed * p.solver.end_time : 0;
        const double      x1    = x0 + travel;
        const std::string patch = "the contact patch (Hertz half-length " + fmt(a * 1e3, 3) +
                                  " mm under " + fmt(load * 1e-3, 4) +
                                  " kN) and as much rail again beyond it, " + fmt(margin * 1e3, 3) +
                                  " mm in all,";
        AssertThrow(x0 - margin >= g.rail_start_x,
                    ExcMessage("Geometry/Wheel/Centre x = " + fmt(x0) +
                               " m is too close to the "
                               "rear end of " +
                               rail + ": " + patch +
                               " must lie on the rail, whose free end is soft. Move Centre x to at "
                               "least " +
                               fmt(g.rail_start_x + margin, 4) + " m or lower Start x."));
        AssertThrow(
          x1 + margin <= g.rail_end_x,
          ExcMessage(
            (travel > 0 ?
               "The wheel rolls off the rail: from Geometry/Wheel/Centre x = " + fmt(x0) +
                 " m at Wheelset/Rolling speed = " + fmt(p.wheelset.rolling_speed) +
                 " m/s until Time integration/End time = " + fmt(p.solver.end_time) +
                 " s it reaches x = " + fmt(x1, 4) + " m" :
               "Geometry/Wheel/Centre x = " + fmt(x0) + " m is too close to the front end") +
            ", but " + patch + " must stay on " + rail + ", whose free end is soft: " +
            (travel > 0 ?
               "reduce End time to at most " +
                 fmt(std::max(0., (g.rail_end_x - margin - x0) / p.wheelset.rolling_speed), 4) +
                 " s, move Centre x back, or raise End x to at least " + fmt(x1 + margin, 4) +
                 " m." :
               "move Centre x to at most " + fmt(g.rail_end_x - margin, 4) +
                 " m or raise End x.")));
      }
    } // namespace



    void
    check_wheel_and_rail(const Parameters &p)
    {
      if (!p.geometry_model->has_wheel())
        return;
      check_solution_zone(p);
      check_axle_load(p);
      check_rail_length(p);
    }
  } // namespace Consistency
} // namespace WheelRail
