#include <deal.II/base/utilities.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <wheelrail/geometry/interface.h>
#include <wheelrail/mesh/geometry.h>
#include <wheelrail/postprocess/contact_patch.h>
#include <wheelrail/postprocess/statistics.h>
#include <wheelrail/solver/wheelset_creepages.h>

#include <optional>
#include <sstream>

namespace WheelRail
{
  std::vector<double>
  StatisticsTable::values(const std::string &key) const
  {
    std::vector<double> v;
    const auto          column = columns.find(key);
    if (column != columns.end())
      for (const auto &entry : column->second.entries)
        v.push_back(entry.get_numeric_value());
    return v;
  }



  void
  StatisticsTable::add_number(const std::string &key, const double value)
  {
    add_value(key, value);
    set_scientific(key, true);
    set_precision(key, 8);
  }



  Statistics::Statistics(const SimulatorAccess                    &access,
                         const EnergyBalance                      &balance,
                         const std::vector<const Postprocessor *> &selected)
    : access(access)
    , balance(balance)
    , selected(selected)
  {}



  void
  Statistics::execute(const StepInfo &step)
  {
    if (step.energies == nullptr)
      return;
    add_row(*step.energies);
    if (step.report_step)
      write_files();
  }



  void
  Statistics::add_row(const Energies &e)
  {
    const auto add = [&](const std::string &key, const double value) {
      table.add_number(key, value);
    };
    table.add_value("step", static_cast<unsigned int>(e.step));
    add("time [s]", e.time);
    if (access.wheelset)
      {
        add("wheel x [m]", access.wheelset->axle_position()[0]);
        add("axle z [m]", access.wheelset->axle_position()[2]);
        add("omega [rad/s]", access.wheelset->angular_velocity());
        add("creepage [-]", access.wheelset->creepage());
        // lateral and spin creepage at the main contact point, where the
        // run has lateral kinematics or profiles (SPEC 10)
        const std::optional<double> delta =
          access.parameters.geometry_model->profile_contact_angle();
        if (reports_kinematic_creepages(access.parameters.wheelset, delta.has_value()))
          {
            const Creepages c = kinematic_creepages(*access.wheelset, delta.value_or(0.));
            add("lateral creepage [-]", c.lateral);
            add("spin creepage [1/m]", c.spin);
          }
      }
    else if (access.parameters.geometry_model->has_wheel())
      {
        const Tensor<1, dim> ub = access.solver.bore_displacement();
        const Point<dim>     c  = access.parameters.geometry_model->wheel_centre();
        add("wheel x [m]", c[0] + ub[0]);
        add("axle z [m]", c[2] + ub[2]);
      }
    if (access.contact)
      {
        const ContactSummary &cs = access.contact->summary();
        add("F_N [N]", cs.force[2]);
        add("F_L [N]", cs.force[0]);
        add("F_lateral [N]", cs.force[1]);
        add("mu_a [-]", cs.force[2] != 0 ? cs.force[0] / cs.force[2] : 0.);
        table.add_value("contact nodes", cs.n_contact);
        table.add_value("slip nodes", cs.n_slip);
        add("max penetration [m]", cs.max_penetration);
        const TrailingSlip trailing = trailing_micro_slip(*access.contact);
        add("trailing micro-slip [m/s]", trailing.magnitude);
        add("trailing slip rate x [m/s]", trailing.rate[0]);
        add("trailing slip rate y [m/s]", trailing.rate[1]);
      }
    add("kinetic [J]", e.kinetic);
    add("internal [J]", e.internal);
    add("hourglass [J]", e.hourglass);
    add("damping dissipation [J]", e.damping);
    if (access.contact)
      {
        add("contact energy [J]", e.contact);
        add("friction dissipation [J]", e.friction);
      }
    add("external work [J]", e.external_work);
    add("balance [J]", balance.balance());
    add("balance error [-]", balance.balance_error());
    for (const Postprocessor *postprocessor : selected)
      postprocessor->add_statistics(table);
  }



  void
  Statistics::write_files() const
  {
    std::ostringstream out;
    out << "# wheelrail statistics: SI units; energies of the whole model; balance = "
           "kinetic + internal + hourglass + damping - external work - its initial value\n";
    table.write_text(out, TableHandler::table_with_separate_column_description);
    access.write_file("statistics", out.str());
  }



  template <class Archive>
  void
  Statistics::serialize(Archive &ar)
  {
    std::string bytes;
    if constexpr (!Archive::is_loading)
      {
        std::ostringstream stream;
        {
          boost::archive::binary_oarchive archive(stream);
          archive << static_cast<const TableHandler &>(table);
        }
        bytes = stream.str();
      }
    ar.string(bytes);
    if constexpr (Archive::is_loading)
      {
        std::istringstream              stream(bytes);
        boost::archive::binary_iarchive archive(stream);
        archive >> static_cast<TableHandler &>(table);
      }
  }



  void
  Statistics::save(Checkpoint::Writer &out)
  {
    serialize(out);
  }



  void
  Statistics::load(Checkpoint::Reader &in)
  {
    serialize(in);
  }
} // namespace WheelRail
