/**
 * @file mesh/cell_estimate.cc
 * The guards of the mesh's size: the coarse cell count estimated from the
 * parameters before the coarse mesh is built, and the final cell count of
 * the refinement estimated before each cycle, against deal.II's cell
 * numbers per rank and the physical memory of the machines.
 */

#include <deal.II/base/mpi.h>

#include <wheelrail/mesh/cell_estimate.h>
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



    } // namespace



    namespace internal
    {
      std::string
      cell_list(const std::vector<unsigned int> &n)
      {
        std::string s;
        for (const unsigned int i : n)
          s += (s.empty() ? "" : ", ") + std::to_string(i);
        return s;
      }



      double
      product(const std::vector<unsigned int> &n)
      {
        double x = 1;
        for (const unsigned int i : n)
          x *= i;
        return x;
      }



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



      void
      check_coarse_cell_estimate(const CoarseCellEstimate &estimate, const MPI_Comm comm)
      {
        const double       n      = estimate.n_cells;
        std::string        cause  = estimate.cause;
        const std::string &remedy = estimate.remedy;
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
