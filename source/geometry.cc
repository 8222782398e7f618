#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>

#include <wheelrail/geometry.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace WheelRail
{
  namespace Geometry
  {
    namespace
    {
      /**
       * The rail head as a chart: the box (x, y, zeta), zeta in [-H, 0],
       * is mapped to z = -H + (zeta + H)/H (z_top(y) + H), so that zeta = 0
       * is the circular top z_top(y) = sqrt(rho^2 - y^2) - rho and the
       * bottom stays flat. Refinement thus stays on the true profile.
       */
      class RailChart : public ChartManifold<dim>
      {
      public:
        RailChart(const double height, const double profile_radius)
          : height(height)
          , radius(profile_radius)
        {}

        double
        top(const double y) const
        {
          return std::sqrt(radius * radius - y * y) - radius;
        }

        Point<dim>
        pull_back(const Point<dim> &p) const override
        {
          return Point<dim>(p[0], p[1], -height + (p[2] + height) * height / (top(p[1]) + height));
        }

        Point<dim>
        push_forward(const Point<dim> &q) const override
        {
          return Point<dim>(q[0], q[1], -height + (q[2] + height) / height * (top(q[1]) + height));
        }

        std::unique_ptr<Manifold<dim>>
        clone() const override
        {
          return std::make_unique<RailChart>(height, radius);
        }

      private:
        const double height;
        const double radius;
      };



      /** Coarse cell size that halves exactly onto h_min. */
      double
      effective_coarse_size(const GeometryParameters &p)
      {
        const double levels = std::round(std::log2(p.coarse_cell_size / p.h_min));
        return p.h_min * std::pow(2., std::max(0., levels));
      }



      /**
       * Memory an explicit run needs per cell at least [bytes]: the peak
       * resident set of the paper case's mesh (217,767 cells) in 10
       * explicit steps without the static start, 375 MB per rank on 2
       * ranks. The static start needs several times more (its matrix and
       * AMG); a mesh beyond the physical memory at this rate cannot run.
       */
      constexpr double bytes_per_cell = 3.4e3;



      /** Physical memory of the machines that run @p comm [bytes]. */
      double
      physical_memory(const MPI_Comm comm)
      {
        MPI_Comm node;
        MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
        const bool first = Utilities::MPI::this_mpi_process(node) == 0;
        MPI_Comm_free(&node);
        const double bytes = first ? static_cast<double>(sysconf(_SC_PHYS_PAGES)) *
                                       static_cast<double>(sysconf(_SC_PAGE_SIZE)) :
                                     0.;
        return Utilities::MPI::sum(bytes, comm);
      }



      /** @p x with @p digits significant digits. */
      std::string
      fmt(const double x, const unsigned int digits = 6)
      {
        std::ostringstream s;
        s << std::setprecision(digits) << x;
        return s.str();
      }



      /**
       * Append a structured block of nx x ny x nz hexahedra whose vertex
       * (i, j, k) lies at position(i, j, k). With @p periodic_i the index
       * i = nx is identified with i = 0 (the closed wheel).
       */
      template <typename PositionFunction>
      void
      add_block(const unsigned int          nx,
                const unsigned int          ny,
                const unsigned int          nz,
                const bool                  periodic_i,
                const types::material_id    material,
                const PositionFunction     &position,
                std::vector<Point<dim>>    &vertices,
                std::vector<CellData<dim>> &cells)
      {
        const unsigned int offset = vertices.size();
        const unsigned int vx     = periodic_i ? nx : nx + 1;
        for (unsigned int k = 0; k <= nz; ++k)
          for (unsigned int j = 0; j <= ny; ++j)
            for (unsigned int i = 0; i < vx; ++i)
              vertices.push_back(position(i, j, k));
        const auto index = [&](unsigned int i, unsigned int j, unsigned int k) {
          return offset + (i % vx) + vx * (j + (ny + 1) * k);
        };
        for (unsigned int k = 0; k < nz; ++k)
          for (unsigned int j = 0; j < ny; ++j)
            for (unsigned int i = 0; i < nx; ++i)
              {
                CellData<dim> cell;
                for (unsigned int v = 0; v < 8; ++v)
                  cell.vertices[v] = index(i + (v & 1), j + ((v >> 1) & 1), k + ((v >> 2) & 1));
                cell.material_id = material;
                cells.push_back(cell);
              }
      }



      /** Distance of (a, b, c) to the box [a0,a1] x [b0,b1] x [c0,c1]. */
      double
      box_distance(const double a,
                   const double b,
                   const double c,
                   const double a0,
                   const double a1,
                   const double b0,
                   const double b1,
                   const double c0,
                   const double c1)
      {
        const double da = std::max({a0 - a, 0., a - a1});
        const double db = std::max({b0 - b, 0., b - b1});
        const double dc = std::max({c0 - c, 0., c - c1});
        return std::sqrt(da * da + db * db + dc * dc);
      }



      /** Longest edge of a cell (the size the refinement targets). */
      template <typename CellIterator>
      double
      longest_edge(const CellIterator &cell)
      {
        double h = 0;
        for (unsigned int l = 0; l < GeometryInfo<dim>::lines_per_cell; ++l)
          h = std::max(h, cell->line(l)->vertex(0).distance(cell->line(l)->vertex(1)));
        return h;
      }



      /**
       * The refinement's chart coordinates of a point: (x, y, depth below
       * the rail top) on the rail, (arc length s from the lowest tread
       * point, positive towards +x, y, depth below the tread) on the wheel.
       * On the wheel, s is taken on the branch nearest to the angle
       * @p theta_ref, so that the points of one cell do not straddle the
       * cut of atan2 at the top of the wheel.
       */
      std::array<double, 3>
      chart_coordinates(const GeometryParameters &p,
                        const types::material_id  material,
                        const Point<dim>         &x,
                        const double              theta_ref)
      {
        if (material == MaterialIds::rail)
          {
            const double top =
              std::sqrt(p.rail_profile_radius * p.rail_profile_radius - x[1] * x[1]) -
              p.rail_profile_radius;
            return {{x[0], x[1], top - x[2]}};
          }
        const Point<dim> centre = wheel_centre(p);
        const double     dx     = x[0] - centre[0];
        const double     dz     = x[2] - centre[2];
        const double theta = theta_ref + std::remainder(std::atan2(dx, -dz) - theta_ref, 2 * M_PI);
        return {{p.wheel_radius * theta, x[1], p.wheel_radius - std::sqrt(dx * dx + dz * dz)}};
      }



      /**
       * A box [lo, hi] in chart coordinates: the zone, the rolling path,
       * or the bounding box of a cell's vertices.
       */
      struct ChartBox
      {
        std::array<double, 3> lo;
        std::array<double, 3> hi;

        /** Distance of the point @p c to the box (0 inside). */
        double
        distance(const std::array<double, 3> &c) const
        {
          return box_distance(c[0], c[1], c[2], lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
        }

        /** Whether the two boxes share a volume (touching does not count). */
        bool
        overlaps(const ChartBox &other) const
        {
          const double eps = 1e-9; // [m]
          for (unsigned int d = 0; d < 3; ++d)
            if (other.hi[d] <= lo[d] + eps || other.lo[d] >= hi[d] - eps)
              return false;
          return true;
        }
      };



      /** The solution zone and the rolling path of one body, in chart space. */
      struct RefinementBoxes
      {
        bool     has_zone = false;
        ChartBox zone;
        bool     has_path = false;
        ChartBox path;
      };



      RefinementBoxes
      refinement_boxes(const GeometryParameters &p, const types::material_id material)
      {
        RefinementBoxes b;
        const double    w = p.zone_half_width;
        if (material == MaterialIds::rail)
          {
            b.has_zone = p.zone_length > 0;
            b.zone = {{{-0.5 * p.zone_length, -w, 0}}, {{0.5 * p.zone_length, w, p.zone_depth}}};
            b.has_path = p.path_cell_size > 0;
            b.path     = {{{p.rail_start_x, -w, 0}}, {{p.rail_end_x, w, p.zone_depth}}};
          }
        else if (material == MaterialIds::wheel)
          {
            // the arc that meets the zone when the wheel rolls from Centre x
            // to O, and the arc that meets the rail: from just before the
            // initial contact point to the rail's end
            const double sO = -p.wheel_centre_x;
            b.has_zone      = p.zone_length > 0 && p.refine_wheel;
            b.zone          = {{{sO - 0.5 * p.zone_length, -w, 0}},
                               {{sO + 0.5 * p.zone_length, w, p.zone_depth}}};
            b.has_path      = p.path_cell_size > 0;
            b.path          = {{{-w, -w, 0}}, {{p.rail_end_x - p.wheel_centre_x, w, p.zone_depth}}};
          }
        return b;
      }



      /**
       * Target size of a cell (SPEC 1 local refinement): h_min + Grading d,
       * d the distance of the cell's centre from the solution zone in chart
       * coordinates (the rolling path likewise with its own size), capped
       * by the coarse size (wheel: growing inwards with the depth). With
       * @p whole_zone, a cell whose chart bounding box overlaps the zone
       * (path) gets the zone's (path's) size whatever the grading: with the
       * centre's distance alone, a cell that reaches into the zone from
       * outside keeps h > h_min once Grading exceeds about 0.5 (at 2.5 the
       * wheel's coarse cells were not refined at all). For wheel and rail
       * cells only (the caller below returns the bar's "no refinement").
       */
      double
      target_size(const GeometryParameters    &p,
                  const types::material_id     material,
                  const std::array<double, 3> &centre,
                  const ChartBox              &cell_box,
                  const double                 coarse,
                  const bool                   whole_zone)
      {
        const double          g = p.grading;
        const RefinementBoxes b = refinement_boxes(p, material);
        double                h = (material == MaterialIds::rail) ? coarse : coarse + g * centre[2];
        if (b.has_zone)
          h = std::min(h,
                       whole_zone && cell_box.overlaps(b.zone) ?
                         p.h_min :
                         p.h_min + g * b.zone.distance(centre));
        if (b.has_path)
          {
            const double hp = std::max(p.path_cell_size, p.h_min);
            h               = std::min(
              h, whole_zone && cell_box.overlaps(b.path) ? hp : hp + g * b.path.distance(centre));
          }
        return h;
      }



      /**
       * A cell's centre in chart coordinates and the bounding box of its
       * centre and vertices there.
       */
      template <typename CellIterator>
      std::pair<std::array<double, 3>, ChartBox>
      cell_in_chart(const GeometryParameters &p, const CellIterator &cell)
      {
        const Point<dim> c         = cell->center();
        const Point<dim> axle      = wheel_centre(p);
        const double     theta_ref = std::atan2(c[0] - axle[0], -(c[2] - axle[2]));
        const auto       centre    = chart_coordinates(p, cell->material_id(), c, theta_ref);
        ChartBox         box{centre, centre};
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto q = chart_coordinates(p, cell->material_id(), cell->vertex(v), theta_ref);
            for (unsigned int d = 0; d < 3; ++d)
              {
                box.lo[d] = std::min(box.lo[d], q[d]);
                box.hi[d] = std::max(box.hi[d], q[d]);
              }
          }
        return {centre, box};
      }



      /** target_size() of a cell, from its centre and vertices. */
      template <typename CellIterator>
      double
      target_size(const GeometryParameters &p,
                  const CellIterator       &cell,
                  const double              coarse,
                  const bool                whole_zone)
      {
        const types::material_id material = cell->material_id();
        if (material != MaterialIds::rail && material != MaterialIds::wheel)
          return std::numeric_limits<double>::max(); // the bar is not refined
        const auto [centre, box] = cell_in_chart(p, cell);
        return target_size(p, material, centre, box, coarse, whole_zone);
      }



      void
      set_boundary_ids(const GeometryParameters &p, Triangulation<dim> &tria)
      {
        const Point<dim> centre = wheel_centre(p);
        const RailChart  chart(p.rail_head_height, p.rail_profile_radius);
        for (const auto &cell : tria.active_cell_iterators())
          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const Point<dim>   c   = cell->face(f)->center();
                const double       eps = 1e-6;
                types::boundary_id id;
                switch (cell->material_id())
                  {
                    case MaterialIds::wheel:
                      {
                        const double r = std::hypot(c[0] - centre[0], c[2] - centre[2]);
                        if (std::abs(std::abs(c[1]) - 0.5 * p.tread_width) < eps * p.tread_width)
                          id = BoundaryIds::wheel_side;
                        else if (r > 0.5 * (p.wheel_radius + p.bore_radius))
                          id = BoundaryIds::wheel_tread;
                        else
                          id = BoundaryIds::wheel_bore;
                        break;
                      }
                    case MaterialIds::rail:
                      {
                        // classify by the face's vertices in chart space: a
                        // curved face's centre lies below the arc
                        const double H   = p.rail_head_height;
                        bool         top = true, bottom = true, side = true;
                        for (unsigned int v = 0; v < 4; ++v)
                          {
                            const Point<dim> q = chart.pull_back(cell->face(f)->vertex(v));
                            top                = top && std::abs(q[2]) < eps * H;
                            bottom             = bottom && std::abs(q[2] + H) < eps * H;
                            side = side && std::abs(std::abs(q[1]) - 0.5 * p.rail_head_width) <
                                             eps * p.rail_head_width;
                          }
                        id = top    ? BoundaryIds::rail_top :
                             bottom ? BoundaryIds::rail_bottom :
                             side   ? BoundaryIds::rail_side :
                                      BoundaryIds::rail_end;
                        break;
                      }
                    case MaterialIds::block:
                    case MaterialIds::plate:
                      {
                        const bool   block    = cell->material_id() == MaterialIds::block;
                        const double z_bottom = block ? p.block_gap : -p.plate_size[2];
                        const double z_top    = block ? p.block_gap + p.block_size[2] : 0.;
                        const double h        = block ? p.block_size[2] : p.plate_size[2];
                        if (std::abs(c[2] - z_bottom) < eps * h)
                          id = block ? BoundaryIds::block_bottom : BoundaryIds::plate_bottom;
                        else if (std::abs(c[2] - z_top) < eps * h)
                          id = block ? BoundaryIds::block_top : BoundaryIds::plate_top;
                        else
                          id = block ? BoundaryIds::block_side : BoundaryIds::plate_side;
                        break;
                      }
                    default:
                      {
                        if (std::abs(c[0]) < eps * p.bar_length)
                          id = BoundaryIds::bar_start;
                        else if (std::abs(c[0] - p.bar_length) < eps * p.bar_length)
                          id = BoundaryIds::bar_end;
                        else
                          id = BoundaryIds::bar_side;
                      }
                  }
                cell->face(f)->set_boundary_id(id);
              }
      }



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



      void
      build_wheel_and_rail(const GeometryParameters   &p,
                           std::vector<Point<dim>>    &vertices,
                           std::vector<CellData<dim>> &cells)
      {
        const double coarse = effective_coarse_size(p);

        // Wheel: (theta, y, radial) block, theta from the lowest point
        // towards +x, radial index from the tread inwards; coarse cells of
        // about 4 x the coarse size at the tread, refined later.
        const double R       = p.wheel_radius;
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
        const unsigned int n_y =
          std::max<unsigned int>(1, std::ceil(p.tread_width / (4 * coarse) - 1e-9));
        const Point<dim> centre = wheel_centre(p);
        const bool       align  = p.align_zone && p.zone_length > 0;
        if (!align)
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
                                -0.5 * p.tread_width + j * p.tread_width / n_y,
                                centre[2] - r * std::cos(t));
            },
            vertices,
            cells);
        else
          {
            // arc length s = R theta from the lowest point, one turn from
            // the zone's arc on (chart coordinates, see refinement_boxes())
            const double        hw = 4 * coarse, sO = -p.wheel_centre_x;
            const double        w = p.zone_half_width, turn = 2 * M_PI * R;
            std::vector<double> s = aligned_lines(sO - 0.5 * p.zone_length - 0.5 * turn,
                                                  sO - 0.5 * p.zone_length + 0.5 * turn,
                                                  sO - 0.5 * p.zone_length,
                                                  sO + 0.5 * p.zone_length,
                                                  hw);
            s.pop_back(); // periodic: the last line is the first
            // the lateral lines half a zone cell off the rail's (see the
            // rail below): symmetric about y = 0, at +-h_min / 2, ...
            const double              shift = 0.5 * p.h_min;
            const std::vector<double> y =
              aligned_lines(-0.5 * p.tread_width, 0.5 * p.tread_width, -w + shift, w + shift, hw);
            // radii: the top layer hw thick over the zone's depth, then
            // geometric layers of about square cells down to the bore
            std::vector<double> r     = {R};
            const unsigned int  n_top = std::max(1., std::ceil(p.zone_depth / hw - 1e-9));
            for (unsigned int k = 1; k <= n_top; ++k)
              r.push_back(R - hw * k);
            const double       r1      = r.back();
            const double       d_mean  = 2 * M_PI / s.size();
            const unsigned int n_lower = std::max<unsigned int>(
              1, std::round(std::log(p.bore_radius / r1) / std::log(1 - d_mean)));
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
                return Point<dim>(centre[0] + r[k] * std::sin(t),
                                  y[j],
                                  centre[2] - r[k] * std::cos(t));
              },
              vertices,
              cells);
          }

        // Rail head: box (x, y, zeta) pushed onto the arc top.
        const RailChart    chart(p.rail_head_height, p.rail_profile_radius);
        const double       L  = p.rail_end_x - p.rail_start_x;
        const unsigned int nx = std::ceil(L / coarse - 1e-9);
        const unsigned int ny = std::ceil(p.rail_head_width / coarse - 1e-9);
        const unsigned int nz = std::ceil(p.rail_head_height / coarse - 1e-9);
        if (!align)
          add_block(
            nx,
            ny,
            nz,
            false,
            MaterialIds::rail,
            [&](unsigned int i, unsigned int j, unsigned int k) {
              return chart.push_forward(
                Point<dim>(p.rail_start_x + i * L / nx,
                           -0.5 * p.rail_head_width + j * p.rail_head_width / ny,
                           -p.rail_head_height + k * p.rail_head_height / nz));
            },
            vertices,
            cells);
        else
          {
            // on the arc top a lateral edge is longer than its chart
            // length (slope s at the aligned block's side): cells of
            // coarse / sqrt(1 + s^2) refine onto at most h_min there
            const double       w     = p.zone_half_width;
            const unsigned int n_w   = std::max(1., std::ceil(2 * w / coarse - 1e-9));
            const double       side  = std::min(0.5 * n_w * coarse, 0.5 * p.rail_head_width);
            const double       rho   = p.rail_profile_radius;
            const double       slope = side / std::sqrt(rho * rho - side * side);
            const double       h     = coarse / std::sqrt(1 + slope * slope) * (1 - 1e-9);
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
              aligned_lines(-0.5 * p.rail_head_width, 0.5 * p.rail_head_width, -w, w, h);
            const std::vector<double> z =
              aligned_lines(-p.rail_head_height, 0, -p.zone_depth, 0, h);
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
      }



      void
      build_bar(const GeometryParameters   &p,
                std::vector<Point<dim>>    &vertices,
                std::vector<CellData<dim>> &cells)
      {
        const unsigned int nx = p.bar_cells[0], ny = p.bar_cells[1], nz = p.bar_cells[2];
        const double       hx = p.bar_length / nx, hy = p.bar_width / ny, hz = p.bar_height / nz;
        add_block(
          nx,
          ny,
          nz,
          false,
          MaterialIds::bar,
          [&](unsigned int i, unsigned int j, unsigned int k) {
            Point<dim> x(i * hx, -0.5 * p.bar_width + j * hy, -0.5 * p.bar_height + k * hz);
            const bool interior = i > 0 && i < nx && j > 0 && j < ny && k > 0 && k < nz;
            if (interior && p.bar_distortion > 0)
              {
                // deterministic pseudo-random direction per vertex
                const double a = std::sin(12.9898 * i + 78.233 * j + 37.719 * k);
                const double b = std::sin(93.989 * i + 67.345 * j + 11.135 * k);
                const double c = std::sin(41.235 * i + 24.414 * j + 73.156 * k);
                x[0] += p.bar_distortion * hx * a;
                x[1] += p.bar_distortion * hy * b;
                x[2] += p.bar_distortion * hz * c;
              }
            return x;
          },
          vertices,
          cells);
      }



      void
      build_block_on_plate(const GeometryParameters   &p,
                           std::vector<Point<dim>>    &vertices,
                           std::vector<CellData<dim>> &cells)
      {
        const auto box = [&](const Point<dim>                &lower,
                             const Tensor<1, dim>            &size,
                             const std::vector<unsigned int> &n,
                             const types::material_id         material) {
          add_block(
            n[0],
            n[1],
            n[2],
            false,
            material,
            [&](unsigned int i, unsigned int j, unsigned int k) {
              return Point<dim>(lower[0] + i * size[0] / n[0],
                                lower[1] + j * size[1] / n[1],
                                lower[2] + k * size[2] / n[2]);
            },
            vertices,
            cells);
        };
        box(Point<dim>(0, -0.5 * p.plate_size[1], -p.plate_size[2]),
            p.plate_size,
            p.plate_cells,
            MaterialIds::plate);
        box(Point<dim>(p.block_x, -0.5 * p.block_size[1], p.block_gap),
            p.block_size,
            p.block_cells,
            MaterialIds::block);
      }
    } // namespace



    Point<dim>
    wheel_centre(const GeometryParameters &p)
    {
      return Point<dim>(p.wheel_centre_x, 0., p.wheel_centre_z());
    }



    ZoneCells
    zone_cells(const GeometryParameters                        &p,
               const types::material_id                         material,
               const parallel::distributed::Triangulation<dim> &triangulation)
    {
      ZoneCells             z;
      const RefinementBoxes b = refinement_boxes(p, material);
      if (b.has_zone)
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && cell->material_id() == material)
            {
              const ChartBox box = cell_in_chart(p, cell).second;
              if (box.overlaps(b.zone))
                {
                  ++z.n_cells;
                  z.max_longest_edge = std::max(z.max_longest_edge, longest_edge(cell));
                }
            }
      const MPI_Comm comm = triangulation.get_communicator();
      z.n_cells           = Utilities::MPI::sum(z.n_cells, comm);
      z.max_longest_edge  = Utilities::MPI::max(z.max_longest_edge, comm);
      return z;
    }



    double
    exact_volume(const GeometryParameters &p, const types::material_id material)
    {
      switch (material)
        {
          case MaterialIds::wheel:
            return M_PI * (p.wheel_radius * p.wheel_radius - p.bore_radius * p.bore_radius) *
                   p.tread_width;
          case MaterialIds::rail:
            {
              const double a   = 0.5 * p.rail_head_width;
              const double rho = p.rail_profile_radius;
              // integral over y of (z_top(y) + H), z_top = sqrt(rho^2-y^2)-rho
              const double area = a * std::sqrt(rho * rho - a * a) +
                                  rho * rho * std::asin(a / rho) - 2 * a * rho +
                                  2 * a * p.rail_head_height;
              return area * (p.rail_end_x - p.rail_start_x);
            }
          case MaterialIds::block:
            return p.block_size[0] * p.block_size[1] * p.block_size[2];
          case MaterialIds::plate:
            return p.plate_size[0] * p.plate_size[1] * p.plate_size[2];
          default:
            return p.bar_length * p.bar_width * p.bar_height;
        }
    }



    void
    build(const GeometryParameters                  &p,
          const std::string                         &geometry_type,
          parallel::distributed::Triangulation<dim> &triangulation)
    {
      std::vector<Point<dim>>    vertices;
      std::vector<CellData<dim>> cells;
      if (geometry_type == "bar")
        build_bar(p, vertices, cells);
      else if (geometry_type == "block on plate")
        build_block_on_plate(p, vertices, cells);
      else
        build_wheel_and_rail(p, vertices, cells);

      // The two bodies are separate coarse meshes in one triangulation:
      // vertices are not merged, so wheel and rail never share a node.
      Triangulation<dim> coarse;
      coarse.create_triangulation(vertices, cells, SubCellData());
      for (const auto &cell : coarse.active_cell_iterators())
        AssertThrow(cell->measure() > 0, ExcMessage("Internal error: inverted coarse cell."));
      set_boundary_ids(p, coarse);
      for (const auto &cell : coarse.active_cell_iterators())
        if (cell->material_id() == MaterialIds::wheel)
          cell->set_all_manifold_ids(ManifoldIds::wheel);
        else if (cell->material_id() == MaterialIds::rail)
          cell->set_all_manifold_ids(ManifoldIds::rail);

      triangulation.copy_triangulation(coarse);
      triangulation.set_manifold(ManifoldIds::wheel,
                                 CylindricalManifold<dim>(Tensor<1, dim>({0., 1., 0.}),
                                                          wheel_centre(p)));
      triangulation.set_manifold(ManifoldIds::rail,
                                 RailChart(p.rail_head_height, p.rail_profile_radius));

      if (geometry_type != "wheel and rail")
        return;

      // Two passes: the grading from the cells' centres first (the meshes
      // of Grading <= 0.5 end here, cell for cell and in the same order as
      // before the second pass existed), then the same with the cells that
      // reach into the zone or the path at their size; with a steeper
      // grading the first pass leaves such cells coarser.
      const double   coarse_size = effective_coarse_size(p);
      const MPI_Comm comm        = triangulation.get_communicator();
      const double   memory      = physical_memory(comm);
      for (const bool whole_zone : {false, true})
        for (unsigned int cycle = 0;; ++cycle)
          {
            AssertThrow(cycle < 20,
                        ExcMessage("The local refinement of the wheel and rail did not "
                                   "reach its target sizes in 20 cycles: Geometry/Mesh/"
                                   "Minimum cell size is too small for Coarse cell size "
                                   "(at most 2^20 times smaller)."));
            // Final cell count, estimated before each cycle: a flagged cell
            // of longest edge l and target size h becomes 8^k cells, k =
            // ceil(log2(l / h)) (h at its centre); the others stay.
            unsigned int n_flagged = 0;
            double       estimate  = 0;
            for (const auto &cell : triangulation.active_cell_iterators())
              if (cell->is_locally_owned())
                {
                  const double l = longest_edge(cell);
                  const double h = target_size(p, cell, coarse_size, whole_zone);
                  if (l > (1 + 1e-6) * h)
                    {
                      cell->set_refine_flag();
                      ++n_flagged;
                      estimate += std::pow(8., std::ceil(std::log2(l / ((1 + 1e-6) * h))));
                    }
                  else
                    estimate += 1;
                }
            if (Utilities::MPI::sum(n_flagged, comm) == 0)
              break;
            estimate = Utilities::MPI::sum(estimate, comm);
            const std::string cause =
              "Geometry/Mesh/Minimum cell size = " + fmt(p.h_min) +
              " m with Grading = " + fmt(p.grading) +
              " would refine the wheel and rail into about " + fmt(estimate, 2) +
              " cells (estimated from the target sizes before cycle " + std::to_string(cycle) +
              "), needing at least " + fmt(estimate * bytes_per_cell * 1e-9, 3) + " GB at " +
              fmt(bytes_per_cell * 1e-3, 2) + " kB per cell (an explicit run's least)";
            const std::string remedy =
              ": increase Minimum cell size or Grading, or reduce the solution zone "
              "(Solution zone length, half width, depth) or Rolling path cell size.";
            // deal.II counts a rank's cells in an unsigned int
            const double ranks = Utilities::MPI::n_mpi_processes(comm);
            AssertThrow(estimate <= ranks * std::numeric_limits<unsigned int>::max(),
                        ExcMessage(cause + ", " + fmt(estimate / ranks, 2) +
                                   " cells per rank, more than deal.II numbers on one rank "
                                   "(2^32 - 1)" +
                                   remedy));
            AssertThrow(estimate * bytes_per_cell <= memory,
                        ExcMessage(cause + ", more than the " + fmt(memory * 1e-9, 3) +
                                   " GB of physical memory of the machine(s)" + remedy));
            triangulation.execute_coarsening_and_refinement();
          }
    }
  } // namespace Geometry
} // namespace WheelRail
