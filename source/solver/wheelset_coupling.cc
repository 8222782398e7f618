#include <deal.II/base/mpi.h>

#include <wheelrail/mesh/geometry.h>
#include <wheelrail/solver/wheelset_coupling.h>

namespace WheelRail
{
  RunupDampingShape
  parse_runup_damping_shape(const std::string &name)
  {
    if (name == "nodes")
      return RunupDampingShape::nodes;
    AssertThrow(name == "wheel rigid motion",
                ExcMessage("Wheelset/Run-up damping shape: unknown value '" + name + "'."));
    return RunupDampingShape::wheel_rigid_motion;
  }



  WheelsetCoupling::WheelsetCoupling(Wheelset                 &wheelset,
                                     const WheelsetParameters &parameters,
                                     const Point<dim>         &axle_centre,
                                     const MPI_Comm            mpi_communicator)
    : wheelset(wheelset)
    , runup_damping(parameters.runup_damping)
    , runup_time(parameters.runup_time)
    , shape(parse_runup_damping_shape(parameters.runup_damping_shape))
    , centre(axle_centre)
    , mpi_communicator(mpi_communicator)
  {}



  void
  WheelsetCoupling::connect(const ElasticOperator &fe_model, const std::vector<PrescribedDof> &prescribed)
  {
    fe                                   = &fe_model;
    const VectorType              &mass  = fe->lumped_mass();
    const std::vector<Point<dim>> &nodes = fe->support_points();
    const unsigned int             n     = mass.locally_owned_size();
    // the bore nodes: their mass and polar inertia about the axle
    double local[2] = {0, 0};
    for (const auto &p : prescribed)
      if (p.kind == BoundaryKind::rigid_axle && p.component == 0)
        {
          const Tensor<1, dim> r = nodes[p.index] - centre;
          local[0] += mass.local_element(p.index);
          local[1] += mass.local_element(p.index) * (r[0] * r[0] + r[2] * r[2]);
        }
    // polar inertia of the whole FE wheel about the axle
    double wheel_inertia = 0;
    for (unsigned int i = 0; i < n; ++i)
      if (fe->dof_material(i) == Geometry::MaterialIds::wheel && fe->dof_component(i) == 0)
        {
          const Tensor<1, dim> r = nodes[i] - centre;
          wheel_inertia += mass.local_element(i) * (r[0] * r[0] + r[2] * r[2]);
        }
    double global[2];
    Utilities::MPI::sum(ArrayView<const double>(local, 2),
                        mpi_communicator,
                        ArrayView<double>(global, 2));
    wheelset.set_bore_inertia(global[0],
                              global[1],
                              fe->total_mass(Geometry::MaterialIds::wheel),
                              Utilities::MPI::sum(wheel_inertia, mpi_communicator));

    // the wheel's nodes for the run-up damping of its rigid motion: their
    // x DoFs in DoF order (a node's y and z DoFs follow its x DoF)
    wheel_nodes.clear();
    for (unsigned int k = 0; k < n; ++k)
      if (fe->dof_material(k) == Geometry::MaterialIds::wheel && fe->dof_component(k) == 0)
        {
          AssertThrow(k + 2 < n && fe->dof_component(k + 2) == 2 &&
                        fe->dof_material(k + 2) == Geometry::MaterialIds::wheel,
                      ExcInternalError());
          wheel_nodes.push_back({nodes[k][0], nodes[k][2], k});
        }
  }



  bool
  WheelsetCoupling::damps(const double t) const
  {
    return t < runup_time && runup_damping > 0;
  }



  void
  WheelsetCoupling::advance(const std::vector<PrescribedDof> &prescribed,
                            const VectorType                 &u,
                            const double                      h,
                            const double                      dt,
                            const double                      t)
  {
    const std::vector<Point<dim>> &nodes    = fe->support_points();
    const Point<dim>               axle     = wheelset.axle_position();
    double                         local[4] = {0, 0, 0, 0};
    // per bore vertex (its x-DoF; y and z follow contiguously): force and
    // moment about the axle
    for (const auto &p : prescribed)
      if (p.kind == BoundaryKind::rigid_axle && p.component == 0)
        {
          const unsigned int i  = p.index;
          const double       fx = p.net_force[0], fy = p.net_force[1], fz = p.net_force[2];
          const double       rx = nodes[i][0] + u.local_element(i) - axle[0];
          const double       rz = nodes[i][2] + u.local_element(i + 2) - axle[2];
          local[0] += fx;
          local[1] += fy;
          local[2] += fz;
          local[3] += rz * fx - rx * fz;
        }
    double global[4];
    Utilities::MPI::sum(ArrayView<const double>(local, 4),
                        mpi_communicator,
                        ArrayView<double>(global, 4));
    wheelset.advance(Tensor<1, dim>({global[0], global[1], global[2]}), global[3], h, dt, t);
  }



  std::function<Tensor<1, dim>(const Point<dim> &)>
  WheelsetCoupling::coupled_motion() const
  {
    return wheelset.bore_motion();
  }



  void
  WheelsetCoupling::add_energies(Energies &energies) const
  {
    // replicated: axle, sprung mass, suspension, torque
    energies.kinetic += wheelset.kinetic();
    energies.internal += wheelset.spring_energy();
    energies.damping += wheelset.damper_dissipation();
    energies.external_work += wheelset.external_work();
  }
} // namespace WheelRail
