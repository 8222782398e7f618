/**
 * @file parameters/load_checks.cc
 * The loads of a run checked before anything is built: the applied force
 * and the prescribed velocity sampled over the run, the initial velocity
 * over the bodies, and the gravity, each refused when it is not finite or
 * absurd by itself.
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/function_parser.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/parameters/consistency.h>
#include <wheelrail/simulator/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace WheelRail
{
  namespace Consistency
  {
    using Report::fmt;

    namespace
    {
      /** The largest strain a load may cause by itself on the estimate
       *  below before it is refused [-]: no elastic body reaches it, and
       *  the loads under it that still make a run diverge are named by
       *  the divergence diagnosis (DivergenceCheck). */
      constexpr double max_load_strain = 100;

      /** Corners of the bodies' common bounding box [m]. */
      std::pair<Point<3>, Point<3>>
      bounding_box(const Parameters &p)
      {
        const std::vector<Geometry::Box> boxes = p.geometry_model->bounding_boxes();
        auto                             box   = boxes.front();
        for (const auto &b : boxes)
          for (unsigned int d = 0; d < 3; ++d)
            {
              box.first[d]  = std::min(box.first[d], b.first[d]);
              box.second[d] = std::max(box.second[d], b.second[d]);
            }
        return box;
      }



      /** The centre and the corners of the bodies' bounding box. */
      std::vector<Point<3>>
      body_points(const Parameters &p)
      {
        const auto [lo, hi]          = bounding_box(p);
        std::vector<Point<3>> points = {0.5 * (lo + hi)};
        for (unsigned int c = 0; c < 8; ++c)
          points.emplace_back((c & 1) ? hi[0] : lo[0],
                              (c & 2) ? hi[1] : lo[1],
                              (c & 4) ? hi[2] : lo[2]);
        return points;
      }



      /** The largest |f| at @p points and 101 times over [0, @p t_end]
       *  (once at t = 0 if t_end is 0); the first non-finite value. */
      Peak
      peak_of(FunctionParser<3> &function, const std::vector<Point<3>> &points, const double t_end)
      {
        Peak               peak;
        const unsigned int n = t_end > 0 ? 100 : 0;
        for (unsigned int k = 0; k <= n; ++k)
          {
            const double t = n > 0 ? t_end * k / n : 0.;
            function.set_time(t);
            for (const Point<3> &x : points)
              {
                Tensor<1, 3> f;
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    f[d] = function.value(x, d);
                    if (!std::isfinite(f[d]))
                      return {std::numeric_limits<double>::infinity(), t, d, f[d]};
                  }
                // |f| scaled by its largest component: finite where f is
                unsigned int largest = 0;
                for (unsigned int d = 1; d < 3; ++d)
                  if (std::abs(f[d]) > std::abs(f[largest]))
                    largest = d;
                const double scale     = std::abs(f[largest]);
                const double magnitude = scale > 0 ? scale * (f / scale).norm() : 0.;
                if (magnitude > peak.magnitude)
                  peak = {magnitude, t, largest, f[largest]};
              }
          }
        return peak;
      }



      /** "Fx", "vy", ... */
      std::string
      component_name(const char *prefix, const unsigned int d)
      {
        return std::string(prefix) + "xyz"[d];
      }



      /** Refuses @p peak of @p entry = @p expression if it is not finite
       *  (@p prefix names the component, @p unit its unit; @p over_run
       *  says over which times it was sampled). */
      void
      check_finite(const std::string &entry,
                   const std::string &expression,
                   const Peak        &peak,
                   const char        *prefix,
                   const char        *unit,
                   const std::string &over_run)
      {
        AssertThrow(std::isfinite(peak.magnitude),
                    ExcMessage(entry + " = '" + expression + "' is not finite at t = " +
                               fmt(peak.t) + " s (" + component_name(prefix, peak.component) +
                               " = " + fmt(peak.value) + " " + unit + ")" + over_run +
                               ": give an expression that stays finite over the whole run."));
      }



      /** Refuses an applied force that is not finite over the run or that
       *  alone strains the bodies (of @p size, described by @p bodies)
       *  beyond max_load_strain. */
      void
      check_applied_force(const Parameters  &p,
                          const BodySize    &size,
                          const std::string &over_run,
                          const std::string &bodies)
      {
        const BoundaryParameters &b     = p.boundary;
        const MaterialParameters &m     = p.material;
        const std::string         entry = "Boundary conditions/Applied force";
        const Peak                peak  = peak_over_run(p,
                                        b.applied_force_expression,
                                        b.applied_force_constants,
                                        entry,
                                        p.solver.end_time,
                                        false);
        check_finite(entry, b.applied_force_expression, peak, "F", "N", over_run);
        const double strain = peak.magnitude / (m.youngs_modulus * size.cross_section());
        AssertThrow(strain <= max_load_strain,
                    ExcMessage(entry + " = '" + b.applied_force_expression + "' reaches " +
                               fmt(peak.magnitude, 3) + " N at t = " + fmt(peak.t) + " s" +
                               over_run + ": on " + bodies +
                               " the force alone gives a strain of about " + fmt(strain, 3) +
                               " (E = " + fmt(m.youngs_modulus, 3) +
                               " Pa), beyond any elastic body (limit " + fmt(max_load_strain) +
                               "): check the expression and its constants (a total force in N)."));
      }



      /** Refuses a prescribed velocity that is not finite over the run
       *  or that is faster than the dilatational wave speed. */
      void
      check_prescribed_velocity(const Parameters &p, const std::string &over_run)
      {
        const BoundaryParameters &b     = p.boundary;
        const std::string         entry = "Boundary conditions/Prescribed velocity";
        const Peak                peak  = peak_over_run(p,
                                        b.prescribed_velocity_expression,
                                        b.prescribed_velocity_constants,
                                        entry,
                                        p.solver.end_time,
                                        true);
        check_finite(entry, b.prescribed_velocity_expression, peak, "v", "m/s", over_run);
        const double c = p.material.wave_speed();
        AssertThrow(peak.magnitude <= c,
                    ExcMessage(entry + " = '" + b.prescribed_velocity_expression + "' reaches " +
                               fmt(peak.magnitude, 3) + " m/s at t = " + fmt(peak.t) + " s" +
                               over_run + ", faster than the dilatational wave speed " + fmt(c, 4) +
                               " m/s: the prescribed boundary would outrun its own wave "
                               "(a strain of v/c = " +
                               fmt(peak.magnitude / c, 3) +
                               " at once). Check the expression and its constants (a velocity "
                               "in m/s)."));
      }



      /** Refuses an initial velocity field that is not finite on the
       *  bodies or that reaches max_load_strain times the wave speed: a
       *  spread of v/c is a strain of that order at once (the divergence
       *  diagnosis names it from 5 % of c). */
      void
      check_initial_velocity(const Parameters &p)
      {
        const std::string entry    = "Initial conditions/Velocity function";
        const auto        function = make_vector_function(p.initial.velocity_expression,
                                                   p.initial.velocity_constants,
                                                   "x,y,z",
                                                   entry);
        const Peak        peak     = peak_of(*function, body_points(p), 0.);
        const double      c        = p.material.wave_speed();
        AssertThrow(std::isfinite(peak.magnitude),
                    ExcMessage(entry + " = '" + p.initial.velocity_expression +
                               "' is not finite on the bodies (" +
                               component_name("v", peak.component) + " = " + fmt(peak.value) +
                               " m/s at the centre or a corner of their bounding box): give an "
                               "expression that "
                               "is finite over the bodies."));
        AssertThrow(peak.magnitude <= max_load_strain * c,
                    ExcMessage(entry + " = '" + p.initial.velocity_expression + "' reaches " +
                               fmt(peak.magnitude, 3) +
                               " m/s on the bodies, more than 100 times the dilatational wave "
                               "speed " +
                               fmt(c, 4) +
                               " m/s: a strain of that order at once, beyond any elastic body. "
                               "Check the expression and its constants (a velocity in m/s)."));
      }



      /** Refuses a gravity that is not finite or whose weight alone
       *  strains a body of the longest side of @p size beyond
       *  max_load_strain. */
      void
      check_gravity(const Parameters &p, const BodySize &size)
      {
        const MaterialParameters &m = p.material;
        const Tensor<1, 3>       &g = p.solver.gravity;
        for (unsigned int d = 0; d < 3; ++d)
          AssertThrow(std::isfinite(g[d]),
                      ExcMessage("Time integration/Gravity = " + fmt(g[0]) + ", " + fmt(g[1]) +
                                 ", " + fmt(g[2]) +
                                 " m/s^2 is not finite: give three finite components."));
        const double strain = m.density * g.norm() * size.extent / m.youngs_modulus;
        AssertThrow(strain <= max_load_strain,
                    ExcMessage("Time integration/Gravity = " + fmt(g[0]) + ", " + fmt(g[1]) + ", " +
                               fmt(g[2]) + " m/s^2 (|g| = " + fmt(g.norm(), 3) +
                               " m/s^2): its weight alone strains a body of " +
                               fmt(size.extent, 3) + " m by about " + fmt(strain, 3) +
                               " (rho |g| L / E), beyond any elastic body (limit " +
                               fmt(max_load_strain) + "): Earth's gravity is 0, 0, -9.81."));
      }
    } // namespace



    BodySize
    body_size(const Parameters &p)
    {
      const auto [lo, hi] = bounding_box(p);
      BodySize size{0, 0};
      for (unsigned int d = 0; d < 3; ++d)
        size.extent = std::max(size.extent, hi[d] - lo[d]);
      for (const Geometry::Body &body : p.geometry_model->bodies())
        size.volume += p.geometry_model->exact_volume(body.material);
      return size;
    }



    Peak
    peak_over_run(const Parameters  &p,
                  const std::string &expression,
                  const std::string &constants,
                  const std::string &entry,
                  const double       t_end,
                  const bool         over_the_bodies)
    {
      const auto function = make_vector_function(expression, constants, "x,y,z,t", entry);
      return peak_of(*function,
                     over_the_bodies ? body_points(p) : std::vector<Point<3>>{Point<3>()},
                     t_end);
    }



    void
    check_loads(const Parameters &p)
    {
      const double      t_end = p.solver.end_time;
      const BodySize    size  = body_size(p);
      const std::string over_run =
        " (sampled over the run, t = 0 to Time integration/End time = " + fmt(t_end) + " s)";
      const std::string bodies = "the " + p.problem.geometry + " (volume " + fmt(size.volume, 3) +
                                 " m^3 over its longest side " + fmt(size.extent, 3) +
                                 " m: a mean cross-section of " + fmt(size.cross_section(), 3) +
                                 " m^2)";
      if (!p.boundary.applied_force_ids.empty())
        check_applied_force(p, size, over_run, bodies);
      if (!p.boundary.prescribed_velocity_ids.empty())
        check_prescribed_velocity(p, over_run);
      check_initial_velocity(p);
      check_gravity(p, size);
    }
  } // namespace Consistency
} // namespace WheelRail
