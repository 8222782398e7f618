#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/postprocess/contact_patch.h>
#include <wheelrail/verification/samples.h>

namespace WheelRail
{
  SampleRecorder::SampleRecorder(const SimulatorAccess &access)
    : access(access)
  {}



  void
  SampleRecorder::execute(const StepInfo &step)
  {
    if (access.contact)
      violations += access.contact->summary().n_violation;
    if (step.energies != nullptr)
      record(*step.energies);
  }



  void
  SampleRecorder::record(const Energies &e)
  {
    if (!access.contact)
      return;
    const bool block = access.parameters.geometry_model->is_block_on_plate();
    Sample     s;
    s.t = e.time;
    if (block)
      {
        s.block_momentum     = access.solver.momentum(Geometry::MaterialIds::block);
        s.plate_momentum     = access.solver.momentum(Geometry::MaterialIds::plate);
        s.block_displacement = access.solver.mean_displacement(Geometry::MaterialIds::block);
      }
    s.contact_force = access.contact ? access.contact->summary().force : Tensor<1, dim>();
    s.relative_displacement =
      access.contact ? access.contact->summary().relative_displacement : Tensor<1, dim>();
    s.n_contact            = access.contact ? access.contact->summary().n_contact : 0;
    s.kinetic              = e.kinetic;
    s.external_work        = e.external_work;
    s.friction             = e.friction;
    s.total                = e.total();
    s.tangential_stiffness = 0;
    for (const auto &p : access.contact->active_pairs())
      s.tangential_stiffness += access.parameters.contact.tangential_factor * p.stiffness;
    double fn = 0, ffn = 0;
    for (const NodalContact &n : access.contact->slave_node_results())
      if (n.in_contact())
        {
          fn += n.normal_force;
          ffn += n.cof * n.normal_force;
        }
    s.mean_cof                  = fn > 0 ? ffn / fn : 0.;
    const TrailingSlip trailing = trailing_micro_slip(*access.contact);
    s.trailing_slip             = trailing.magnitude;
    s.trailing_slip_rate        = trailing.rate;
    recorded.push_back(s);
  }
} // namespace WheelRail
