/**
 * @file mesh/cell_estimate.cc
 * The guards of the mesh's size: the coarse cell count estimated from the
 * parameters before the coarse mesh is built, and the final cell count of
 * the refinement estimated before each cycle, against deal.II's cell
 * numbers per rank and the physical memory of the machines.
 */

#include <deal.II/base/mpi.h>

#include <wheelrail/mesh/refinement.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    using namespace internal;

    namespace
    {
      /**
       * Memory an explicit run needs per cell at least [bytes]: the peak
       * resident set of the paper case's mesh (217,767 cells) in 10
       * explicit steps without the static start, 375 MB per rank on 2
       * ranks. The static start needs several times more (its matrix and
       * AMG); a mesh beyond the physical memory at this rate cannot run.
       */
      constexpr double bytes_per_cell = 3.4e3;

      /**
       * The most coarse cells wheelrail builds [-]. deal.II's distributed
       * triangulation (and p4est's connectivity under it) holds the whole
       * coarse mesh on every rank; at bytes_per_cell, 1e7 coarse cells are
       * 34 GB on each rank before any refinement. The shipped cases and
       * tests have at most 16,000 (a bar of 40 x 20 x 20).
       */
      constexpr double max_coarse_cells = 1e7;



      /** @p x with @p digits significant digits. */
      std::string
      fmt(const double x, const unsigned int digits = 6)
      {
        std::ostringstream s;
        s << std::setprecision(digits) << x;
        return s.str();
      }



      /** "a, b, c" of a list of three cell counts. */
      std::string
      cell_list(const std::vector<unsigned int> &n)
      {
        std::string s;
        for (const unsigned int i : n)
          s += (s.empty() ? "" : ", ") + std::to_string(i);
        return s;
      }



      /** Product of a list of cell counts, in double (no overflow). */
      double
      product(const std::vector<unsigned int> &n)
      {
        double x = 1;
        for (const unsigned int i : n)
          x *= i;
        return x;
      }



      /** Coarse cells of the wheel and of the rail head, as
       *  build_wheel_and_rail() divides them without alignment. */
      std::pair<double, double>
      wheel_and_rail_coarse_cells(const GeometryParameters &p)
      {
        const double coarse  = effective_coarse_size(p);
        const double R       = p.wheel_radius;
        double       n_theta = p.wheel_circumferential_cells;
        if (n_theta == 0)
          n_theta = 4 * std::ceil(2 * M_PI * R / (4 * 4 * coarse));
        n_theta              = std::max(n_theta, 8.);
        const double d_theta = 2 * M_PI / n_theta;
        const double n_radial =
          std::max(1., std::round(std::log(p.bore_radius / R) / std::log(1 - d_theta)));
        const double n_y  = std::max(1., std::ceil(p.tread_width / (4 * coarse) - 1e-9));
        const double rail = std::ceil((p.rail_end_x - p.rail_start_x) / coarse - 1e-9) *
                            std::ceil(p.rail_head_width / coarse - 1e-9) *
                            std::ceil(p.rail_head_height / coarse - 1e-9);
        return {n_theta * n_y * n_radial, rail};
      }
    } // namespace



    namespace internal
    {
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



      void
      check_cell_estimate(const GeometryParameters &p,
                          const double              estimate,
                          const unsigned int        cycle,
                          const MPI_Comm            comm,
                          const double              memory)
      {
        const std::string cause =
          "Geometry/Mesh/Minimum cell size = " + fmt(p.h_min) +
          " m with Grading = " + fmt(p.grading) + " would refine the wheel and rail into about " +
          fmt(estimate, 2) + " cells (estimated from the target sizes before cycle " +
          std::to_string(cycle) + "), needing at least " +
          fmt(estimate * bytes_per_cell * 1e-9, 3) + " GB at " + fmt(bytes_per_cell * 1e-3, 2) +
          " kB per cell (an explicit run's least)";
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
      }



      double
      coarse_cell_estimate(const GeometryParameters &p, const std::string &geometry_type)
      {
        if (geometry_type == "bar")
          return product(p.bar_cells);
        if (geometry_type == "block on plate")
          return product(p.plate_cells) + product(p.block_cells);
        const auto [wheel, rail] = wheel_and_rail_coarse_cells(p);
        return wheel + rail;
      }



      void
      check_coarse_cell_estimate(const GeometryParameters &p,
                                 const std::string        &geometry_type,
                                 const MPI_Comm            comm)
      {
        const double n = coarse_cell_estimate(p, geometry_type);
        std::string  cause, remedy;
        if (geometry_type == "bar")
          {
            cause = "Geometry/Bar/Cells = " + cell_list(p.bar_cells) + " make a bar of " +
                    fmt(n, 3) + " cells";
            remedy = "reduce Geometry/Bar/Cells.";
          }
        else if (geometry_type == "block on plate")
          {
            cause = "Geometry/Block on plate/Plate cells = " + cell_list(p.plate_cells) +
                    " and Block cells = " + cell_list(p.block_cells) + " make " + fmt(n, 3) +
                    " cells";
            remedy = "reduce Geometry/Block on plate/Plate cells or Block cells.";
          }
        else
          {
            const auto [wheel, rail] = wheel_and_rail_coarse_cells(p);
            cause = "Geometry/Mesh/Coarse cell size = " + fmt(p.coarse_cell_size) +
                    " m would divide the wheel and rail into about " + fmt(n, 2) +
                    " coarse cells (wheel " + fmt(wheel, 2) + ", rail " + fmt(rail, 2) +
                    ") before any refinement";
            remedy = "increase Geometry/Mesh/Coarse cell size (the local refinement "
                     "reaches Minimum cell size where it is needed).";
          }
        // every rank holds the whole coarse mesh
        const double ranks  = Utilities::MPI::n_mpi_processes(comm);
        const double needed = n * bytes_per_cell;
        cause += ", needing at least " + fmt(needed * 1e-9, 3) + " GB on each MPI rank at " +
                 fmt(bytes_per_cell * 1e-3, 2) +
                 " kB per cell (an explicit run's least; every rank holds the whole coarse mesh)";
        AssertThrow(n <= max_coarse_cells,
                    ExcMessage(cause + ", more than the " + fmt(max_coarse_cells, 2) +
                               " coarse cells that wheelrail builds: " + remedy));
        const double memory = physical_memory(comm);
        AssertThrow(ranks * needed <= memory,
                    ExcMessage(cause + ", more than the " + fmt(memory * 1e-9, 3) +
                               " GB of physical memory of the machine(s) for " + fmt(ranks) +
                               " rank(s): " + remedy));
      }
    } // namespace internal
  }   // namespace Geometry
} // namespace WheelRail
