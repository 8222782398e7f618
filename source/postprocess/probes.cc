#include <deal.II/base/mpi.h>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/postprocess/output_files.h>
#include <wheelrail/postprocess/probes.h>
#include <wheelrail/simulator/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace WheelRail
{
  using Report::fmt;



  Probes::Probes(const SimulatorAccess &access)
    : access(access)
  {
    probes.emplace_back();
    probes.back().file   = "probe.csv";
    probes.back().target = access.parameters.output.probe_point;
    if (access.wheelset)
      {
        // the wheel-tread node that reaches O: the arc from the lowest point
        // towards +x equals the rolling distance from A to O
        const GeometryParameters &g      = access.parameters.geometry;
        const double              radius = access.parameters.geometry_model->rolling_radius();
        const double              phi    = -g.wheel_centre_x / radius;
        const Point<dim>          c      = access.parameters.geometry_model->wheel_centre();
        probes.emplace_back();
        probes.back().file = "wheel_probe.csv";
        probes.back().target =
          Point<dim>(c[0] + radius * std::sin(phi), 0., c[2] - radius * std::cos(phi));
        probes.back().material = Geometry::MaterialIds::wheel;
      }
    const auto &points = access.solver.support_points();
    const auto &part   = *access.solver.partitioner();
    for (Probe &probe : probes)
      {
        // nearest x-DoF; ties broken by position, so that every partition
        // picks the same node
        std::array<double, 4> best     = {{std::numeric_limits<double>::max(), 0, 0, 0}};
        unsigned int          best_dof = 0;
        for (unsigned int i = 0; i < part.locally_owned_size(); ++i)
          if (access.solver.dof_component(i) == 0 &&
              (probe.material == numbers::invalid_material_id ||
               access.solver.dof_material(i) == probe.material))
            {
              const std::array<double, 4> candidate = {
                {points[i].distance(probe.target), points[i][0], points[i][1], points[i][2]}};
              if (candidate < best)
                {
                  best     = candidate;
                  best_dof = i;
                }
            }
        const auto all = Utilities::MPI::all_gather(access.mpi_communicator, best);
        probe.owner    = std::min_element(all.begin(), all.end()) - all.begin();
        probe.location = Point<dim>(all[probe.owner][1], all[probe.owner][2], all[probe.owner][3]);
        probe.dof      = best_dof;
      }
    check_inside_mesh();
  }



  void
  Probes::check_inside_mesh() const
  {
    // A point inside the mesh lies in a cell, within that cell's diameter
    // of one of its vertices; its nearest node is nearer still, and the
    // cells around that node are of the size of the containing cell. A
    // point farther from its nearest node than the largest cell around
    // that node lies outside the mesh. The owner of the node has every cell
    // at it (owned or ghost).
    const Probe &user = probes.front();
    double       h    = 0;
    if (Utilities::MPI::this_mpi_process(access.mpi_communicator) == user.owner)
      for (const auto &cell : access.triangulation.active_cell_iterators())
        if (!cell->is_artificial())
          {
            const double d  = cell->diameter();
            Point<dim>   lo = cell->vertex(0), hi = cell->vertex(0);
            for (const unsigned int v : cell->vertex_indices())
              for (unsigned int c = 0; c < dim; ++c)
                {
                  lo[c] = std::min(lo[c], cell->vertex(v)[c]);
                  hi[c] = std::max(hi[c], cell->vertex(v)[c]);
                }
            bool at_node = true;
            for (unsigned int c = 0; c < dim; ++c)
              at_node = at_node && user.location[c] >= lo[c] - 1e-9 * d &&
                        user.location[c] <= hi[c] + 1e-9 * d;
            if (at_node)
              h = std::max(h, d);
          }
    h                     = Utilities::MPI::max(h, access.mpi_communicator);
    const double distance = user.location.distance(user.target);
    AssertThrow(distance <= h,
                ExcMessage(
                  "Output/Probe point = (" + fmt(user.target[0]) + ", " + fmt(user.target[1]) +
                  ", " + fmt(user.target[2]) + ") m lies outside the mesh: its nearest node, (" +
                  fmt(user.location[0]) + ", " + fmt(user.location[1]) + ", " +
                  fmt(user.location[2]) + ") m, is " + fmt(distance) +
                  " m away, more than the largest cell at that node (diameter " + fmt(h) + " m)."));
  }



  void
  Probes::record()
  {
    for (Probe &probe : probes)
      if (Utilities::MPI::this_mpi_process(access.mpi_communicator) == probe.owner)
        {
          probe.history.push_back(access.solver.time());
          for (unsigned int d = 0; d < dim; ++d)
            probe.history.push_back(access.solver.displacement().local_element(probe.dof + d));
          for (unsigned int d = 0; d < dim; ++d)
            probe.history.push_back(access.solver.velocity().local_element(probe.dof + d));
        }
  }



  void
  Probes::execute(const StepInfo &)
  {
    record();
  }



  void
  Probes::write_files() const
  {
    for (const Probe &probe : probes)
      {
        if (Utilities::MPI::this_mpi_process(access.mpi_communicator) != probe.owner)
          continue;
        std::ostringstream out;
        out << "# node at (" << probe.location << ") m (reference); displacement and velocity "
            << "every step; velocities at the half steps\n"
            << "t [s],u_x [m],u_y [m],u_z [m],v_x [m/s],v_y [m/s],v_z [m/s]\n"
            << std::setprecision(10);
        for (unsigned int i = 0; i < probe.history.size(); i += 7)
          {
            for (unsigned int k = 0; k < 7; ++k)
              out << (k ? "," : "") << probe.history[i + k];
            out << '\n';
          }
        // written by the owner rank: not through write_file (rank 0 only)
        write_file_atomically(access.output_directory + "/" + probe.file, out.str());
      }
  }
} // namespace WheelRail
