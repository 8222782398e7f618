/**
 * @file mesh/cell_estimate.h
 * The guards of the mesh's size: the coarse mesh's cell count and the
 * refinement's final cell count against deal.II's cell numbers per rank
 * and the physical memory of the machines.
 */
#ifndef wheelrail_mesh_cell_estimate_h
#define wheelrail_mesh_cell_estimate_h

#include <deal.II/base/mpi.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/parameters/parameters.h>

#include <string>
#include <vector>

namespace WheelRail
{
  namespace Geometry
  {
    namespace internal
    {
      /** "a, b, c" of a list of three cell counts. */
      std::string
      cell_list(const std::vector<unsigned int> &n);



      /** Product of a list of cell counts, in double (no overflow). */
      double
      product(const std::vector<unsigned int> &n);



      /**
       * Stop the run when the final cell count @p estimate of the
       * refinement, estimated before cycle @p cycle, is more than deal.II
       * numbers on a rank or needs more than the @p memory bytes of
       * physical memory of the machines of @p comm.
       */
      void
      check_cell_estimate(const GeometryParameters &p,
                          const double              estimate,
                          const unsigned int        cycle,
                          const MPI_Comm            comm,
                          const double              memory);



      /** Physical memory of the machines that run @p comm [bytes]. */
      double
      physical_memory(const MPI_Comm comm);



      /**
       * Stop the run before its coarse mesh is built when the coarse mesh
       * of @p estimate (GeometryModel::coarse_cell_estimate()) has more
       * than the cells that wheelrail takes (every rank holds the whole
       * coarse mesh) or needs more than the physical memory of the
       * machines of @p comm.
       */
      void
      check_coarse_cell_estimate(const CoarseCellEstimate &estimate, const MPI_Comm comm);
    } // namespace internal
  }   // namespace Geometry
} // namespace WheelRail

#endif
