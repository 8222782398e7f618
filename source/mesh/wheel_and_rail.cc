/**
 * @file mesh/wheel_and_rail.cc
 * The coarse mesh of the wheel on the rail (SPEC 1): the wheel as a
 * closed (theta, y, radial) block, the rail head as a block mapped onto
 * its profile, with coarse lines aligned with the solution zone on request.
 */

#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <wheelrail/mesh/coarse_mesh.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/mesh/rail_chart.h>
#include <wheelrail/mesh/refinement.h>
#include <wheelrail/mesh/wheel_chart.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    using namespace internal;

    namespace
    {
      /**
       * Coarse mesh lines on [a, b] (Align coarse cells with zone): cells of
       * exactly @p h over the zone [lo, hi] - anchored at a or b where the
       * zone reaches it, else centred on the zone - and the rest of the
       * interval on either side divided into the fewest equal cells no
       * larger than h. A block that would leave a sliver (less than h / 5)
       * at one end is moved to that end if it still covers the zone.
       */
      std::vector<double>
      aligned_lines(const double a,
                    const double b,
                    const double lo,
                    const double hi,
                    const double h)
      {
        const double       tol = 1e-9 * (b - a);
        const double       l = std::max(lo, a), r = std::min(hi, b);
        const unsigned int n  = std::max(1., std::ceil((r - l) / h - 1e-9));
        double             z0 = 0.5 * (l + r) - 0.5 * n * h;
        if (lo <= a + tol || (z0 - a < 0.2 * h && a + n * h >= r - tol))
          z0 = a;
        else if (hi >= b - tol || (b - (z0 + n * h) < 0.2 * h && b - n * h <= l + tol))
          z0 = b - n * h;
        z0              = std::max(z0, a);
        const double z1 = std::min(z0 + n * h, b);

        std::vector<double> x;
        const auto          divide = [&](const double from, const double to) {
          const unsigned int m = std::max(1., std::ceil((to - from) / h - 1e-9));
          for (unsigned int i = 0; i < m; ++i)
            x.push_back(from + i * (to - from) / m);
        };
        if (z0 > a + tol)
          divide(a, z0);
        divide(z0, z1);
        if (z1 < b - tol)
          divide(z1, b);
        x.push_back(b);
        return x;
      }



      /**
       * The wheel as one closed (theta, y, radial) block: theta from the
       * lowest point towards +x in equal steps, radial index from the tread
       * inwards in geometric layers; coarse cells of about 4 x the coarse
       * size @p coarse at the tread, refined later.
       */
      void
      add_wheel_uniform(const GeometryParameters   &p,
                        const WheelRailShape       &shape,
                        const double                coarse,
                        std::vector<Point<dim>>    &vertices,
                        std::vector<CellData<dim>> &cells)
      {
        const double R  = shape.rolling_radius();
        const double y0 = shape.wheel_y_lo, width = shape.wheel_y_hi - shape.wheel_y_lo;
        unsigned int n_theta = p.wheel_circumferential_cells;
        if (n_theta == 0)
          n_theta = 4 * static_cast<unsigned int>(std::ceil(2 * M_PI * R / (4 * 4 * coarse)));
        n_theta              = std::max(n_theta, 8u);
        const double d_theta = 2 * M_PI / n_theta;
        // geometric radial layers with about square cells in (r, theta)
        const unsigned int n_radial =
          std::max<unsigned int>(1,
                                 std::round(std::log(p.bore_radius / R) / std::log(1 - d_theta)));
        const double       ratio = std::pow(p.bore_radius / R, 1. / n_radial);
        const unsigned int n_y = std::max<unsigned int>(1, std::ceil(width / (4 * coarse) - 1e-9));
        const Point<dim>   centre = shape.wheel_centre();
        add_block(
          n_theta,
          n_y,
          n_radial,
          true,
          MaterialIds::wheel,
          [&](unsigned int i, unsigned int j, unsigned int k) {
            const double r = R * std::pow(ratio, k);
            const double t = i * d_theta;
            return Point<dim>(centre[0] + r * std::sin(t),
                              y0 + j * width / n_y,
                              centre[2] - r * std::cos(t));
          },
          vertices,
          cells);
      }



      /**
       * How much longer than on the cylinder of the rolling radius at O an
       * edge of the revolved profile is, at most, over [y_lo, y_hi]:
       * circumferential edges scale with r(y) / r_O, radial ones with
       * (r(y) - r_b) / (r_O - r_b), lateral ones with sqrt(1 + r'(y)^2).
       */
      double
      tread_stretch(const WheelRailShape &shape,
                    const double          bore_radius,
                    const double          y_lo,
                    const double          y_hi)
      {
        const double r_O     = shape.rolling_radius();
        double       stretch = 1;
        for (unsigned int i = 0; i <= 400; ++i)
          {
            const double y = y_lo + i * (y_hi - y_lo) / 400;
            const double r = shape.wheel_radius(y);
            const double slope =
              shape.wheel_curve()->slope(std::min(std::max(y, shape.wheel_y_lo), shape.wheel_y_hi));
            stretch = std::max({stretch,
                                r / r_O,
                                (r - bore_radius) / (r_O - bore_radius),
                                std::sqrt(1 + slope * slope)});
          }
        return stretch;
      }



      /**
       * The wheel with coarse lines aligned with the solution zone (Align
       * coarse cells with zone): arc length s = R theta from the lowest
       * point, one turn from the zone's arc on (chart coordinates, see
       * refinement_boxes()); lateral lines half a zone cell off the
       * rail's; radii in a top layer over the zone's depth, then geometric
       * layers down to the bore.
       */
      void
      add_wheel_aligned(const GeometryParameters   &p,
                        const WheelRailShape       &shape,
                        const double                coarse,
                        std::vector<Point<dim>>    &vertices,
                        std::vector<CellData<dim>> &cells)
      {
        const double     R      = shape.rolling_radius();
        const Point<dim> centre = shape.wheel_centre();
        const double     w = p.zone_half_width, turn = 2 * M_PI * R;
        // the zones of every contact point; on a revolved profile, cells
        // that refine onto at most h_min over them
        const auto [zone_lo, zone_hi] = shape.zone_span(w);
        const double hw =
          shape.cylindrical_wheel() ?
            4 * coarse :
            4 * coarse /
              tread_stretch(shape, p.bore_radius, zone_lo - 2 * p.h_min, zone_hi + 2 * p.h_min) *
              (1 - 1e-9);
        const double        sO = -p.wheel_centre_x;
        std::vector<double> s  = aligned_lines(sO - 0.5 * p.zone_length - 0.5 * turn,
                                              sO - 0.5 * p.zone_length + 0.5 * turn,
                                              sO - 0.5 * p.zone_length,
                                              sO + 0.5 * p.zone_length,
                                              hw);
        s.pop_back(); // periodic: the last line is the first
        // the lateral lines half a zone cell off the rail's (see the
        // rail's lines): symmetric about y = 0, at +-h_min / 2, ...
        const double              shift = 0.5 * p.h_min;
        const std::vector<double> y =
          aligned_lines(shape.wheel_y_lo, shape.wheel_y_hi, zone_lo + shift, zone_hi + shift, hw);
        // radii: the top layer hw thick over the zone's depth, then
        // geometric layers of about square cells down to the bore
        std::vector<double> r     = {R};
        const unsigned int  n_top = std::max(1., std::ceil(p.zone_depth / hw - 1e-9));
        for (unsigned int k = 1; k <= n_top; ++k)
          r.push_back(R - hw * k);
        const double       r1     = r.back();
        const double       d_mean = 2 * M_PI / s.size();
        const unsigned int n_lower =
          std::max<unsigned int>(1,
                                 std::round(std::log(p.bore_radius / r1) / std::log(1 - d_mean)));
        for (unsigned int k = 1; k <= n_lower; ++k)
          r.push_back(k == n_lower ? p.bore_radius :
                                     r1 * std::pow(p.bore_radius / r1, double(k) / n_lower));
        add_block(
          s.size(),
          y.size() - 1,
          r.size() - 1,
          true,
          MaterialIds::wheel,
          [&](unsigned int i, unsigned int j, unsigned int k) {
            const double t = s[i] / R;
            return Point<dim>(centre[0] + r[k] * std::sin(t), y[j], centre[2] - r[k] * std::cos(t));
          },
          vertices,
          cells);
      }



      /** The rail head as one box (x, y, zeta) of equal cells of about the
       *  coarse size @p coarse, pushed onto the arc top by @p chart. */
      void
      add_rail_uniform(const GeometryParameters   &p,
                       const WheelRailShape       &shape,
                       const double                coarse,
                       const RailChart            &chart,
                       std::vector<Point<dim>>    &vertices,
                       std::vector<CellData<dim>> &cells)
      {
        const double       L  = p.rail_end_x - p.rail_start_x;
        const unsigned int nx = std::ceil(L / coarse - 1e-9);
        const double       y0 = shape.rail_y_lo, width = shape.rail_y_hi - shape.rail_y_lo;
        const unsigned int ny = std::ceil(width / coarse - 1e-9);
        const unsigned int nz = std::ceil(p.rail_head_height / coarse - 1e-9);
        add_block(
          nx,
          ny,
          nz,
          false,
          MaterialIds::rail,
          [&](unsigned int i, unsigned int j, unsigned int k) {
            return chart.push_forward(
              Point<dim>(p.rail_start_x + i * L / nx,
                         y0 + j * width / ny,
                         -p.rail_head_height + k * p.rail_head_height / nz));
          },
          vertices,
          cells);
      }



      /** The rail head with coarse lines aligned with the solution zone
       *  (Align coarse cells with zone), pushed onto the arc top by
       *  @p chart. */
      void
      add_rail_aligned(const GeometryParameters   &p,
                       const WheelRailShape       &shape,
                       const double                coarse,
                       const RailChart            &chart,
                       std::vector<Point<dim>>    &vertices,
                       std::vector<CellData<dim>> &cells)
      {
        // on the curved top a lateral edge is longer than its chart
        // length (slope s at the aligned block's sides): cells of
        // coarse / sqrt(1 + s^2) refine onto at most h_min there
        const double w = p.zone_half_width;
        // over the zones of every contact point
        const auto [zone_lo, zone_hi] = shape.zone_span(w);
        const double        middle    = 0.5 * (zone_lo + zone_hi);
        const unsigned int  n_w   = std::max(1., std::ceil((zone_hi - zone_lo) / coarse - 1e-9));
        const double        right = std::min(middle + 0.5 * n_w * coarse, shape.rail_y_hi);
        const double        left  = std::max(middle - 0.5 * n_w * coarse, shape.rail_y_lo);
        const ProfileCurve &top   = *shape.rail_curve();
        const double        slope = std::max(std::abs(top.slope(left)), std::abs(top.slope(right)));
        // and a vertical edge is longer by (H + z_top) / H where the top
        // lies above O (an inclined or off-centre profile)
        double highest = 0;
        for (unsigned int i = 0; i <= 400; ++i)
          highest = std::max(highest, shape.rail_top(left + i * (right - left) / 400));
        const double stretch = std::max(std::sqrt(1 + slope * slope),
                                        (p.rail_head_height + highest) / p.rail_head_height);
        const double h       = coarse / stretch * (1 - 1e-9);
        // Wheel (slave) and rail (master) nodes must not coincide: with
        // equal grids each slave force lands on one master node, and
        // the pressure takes the one-point elements' checkerboard mode
        // (measured on the paper case: +-300 MPa from node to node,
        // peak 1,850 MPa against Hertz 1,385). Across, the wheel's lines
        // lie half a cell off the rail's; along x, where rolling moves
        // the one over the other, the rail's cells are 4 % shorter, so
        // that the offsets run through a whole cell every 25 nodes.
        const std::vector<double> x = aligned_lines(
          p.rail_start_x, p.rail_end_x, -0.5 * p.zone_length, 0.5 * p.zone_length, 0.96 * h);
        const std::vector<double> y =
          aligned_lines(shape.rail_y_lo, shape.rail_y_hi, zone_lo, zone_hi, h);
        const std::vector<double> z = aligned_lines(-p.rail_head_height, 0, -p.zone_depth, 0, h);
        add_block(
          x.size() - 1,
          y.size() - 1,
          z.size() - 1,
          false,
          MaterialIds::rail,
          [&](unsigned int i, unsigned int j, unsigned int k) {
            return chart.push_forward(Point<dim>(x[i], y[j], z[k]));
          },
          vertices,
          cells);
      }



      /** Move the wheel's vertices from @p first on (built on the cylinder
       *  of the rolling radius at O) onto the revolved profile: the
       *  push-forward of RevolvedProfileChart. */
      void
      revolve_profile(const WheelRailShape    &shape,
                      const double             bore_radius,
                      const std::size_t        first,
                      std::vector<Point<dim>> &vertices)
      {
        const RevolvedProfileChart chart(shape.wheel_centre(),
                                         shape.rolling_radius(),
                                         bore_radius,
                                         shape.wheel_curve());
        const Point<dim>           c = shape.wheel_centre();
        for (std::size_t v = first; v < vertices.size(); ++v)
          {
            const double dx = vertices[v][0] - c[0], dz = vertices[v][2] - c[2];
            vertices[v] = chart.push_forward(
              Point<dim>(std::atan2(dx, -dz), vertices[v][1], std::sqrt(dx * dx + dz * dz)));
          }
      }
    } // namespace



    namespace internal
    {
      void
      build_wheel_and_rail(const GeometryParameters   &p,
                           const WheelRailShape       &shape,
                           std::vector<Point<dim>>    &vertices,
                           std::vector<CellData<dim>> &cells)
      {
        const double coarse = effective_coarse_size(p);
        const bool   align  = p.align_zone && p.zone_length > 0;
        // the wheel's cells first, then the rail's
        const std::size_t first_wheel_vertex = vertices.size();
        if (align)
          add_wheel_aligned(p, shape, coarse, vertices, cells);
        else
          add_wheel_uniform(p, shape, coarse, vertices, cells);
        if (!shape.cylindrical_wheel())
          revolve_profile(shape, p.bore_radius, first_wheel_vertex, vertices);
        const RailChart chart(p.rail_head_height, shape.rail_curve());
        if (align)
          add_rail_aligned(p, shape, coarse, chart, vertices, cells);
        else
          add_rail_uniform(p, shape, coarse, chart, vertices, cells);
      }
    } // namespace internal
  }   // namespace Geometry
} // namespace WheelRail
