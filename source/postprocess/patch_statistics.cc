#include <wheelrail/geometry/interface.h>
#include <wheelrail/postprocess/patch_statistics.h>
#include <wheelrail/postprocess/statistics.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace WheelRail
{
  namespace
  {
    /** @p x with @p decimals decimals in fixed notation ("0" for what
     *  rounds to zero, without a sign). */
    std::string
    fixed(const double x, const int decimals)
    {
      std::ostringstream s;
      const double       scale = std::pow(10., decimals);
      const double       r     = std::round(x * scale) / scale;
      s << std::fixed << std::setprecision(decimals) << (r == 0 ? 0. : r);
      return s.str();
    }

    constexpr double deg = 180. / M_PI;
  } // namespace



  PatchStatistics::PatchStatistics(const SimulatorAccess &access)
    : access(access)
    , contact_patches(access.parameters.geometry_model->rigid_contacts())
  {}



  void
  PatchStatistics::add_statistics(StatisticsTable &table) const
  {
    if (!access.contact)
      return;
    const std::vector<PatchResult> results = contact_patches.evaluate(*access.contact);
    for (unsigned int k = 0; k < results.size(); ++k)
      {
        const PatchResult &r      = results[k];
        const std::string  prefix = "patch " + std::to_string(k + 1) + " ";
        table.add_number(prefix + "F_n [N]", r.F_n);
        table.add_number(prefix + "F_x [N]", r.F_x);
        table.add_number(prefix + "F_s [N]", r.F_s);
        table.add_number(prefix + "M_n [N m]", r.M_n);
        table.add_number(prefix + "y [m]", r.centre[1]);
        table.add_number(prefix + "contact angle [rad]", r.contact_angle);
        table.add_number(prefix + "area [m^2]", r.area);
        table.add_number(prefix + "length [m]", r.length);
        table.add_number(prefix + "width [m]", r.width);
        table.add_number(prefix + "p_max [Pa]", r.p_max);
        table.add_value(prefix + "contact nodes", r.n_nodes);
        table.add_value(prefix + "joined", static_cast<unsigned int>(r.joined));
      }
  }



  void
  PatchStatistics::print_summary() const
  {
    if (!access.wheelset || !access.contact || access.robust_output_only())
      return;
    const std::vector<PatchResult> results = contact_patches.evaluate(*access.contact);
    for (unsigned int k = 0; k < results.size(); ++k)
      {
        const PatchResult            &r = results[k];
        const Geometry::RigidContact &c = contact_patches.point(k);
        access.pcout << "Patch " << k + 1 << " of " << results.size() << " (rigid contact at y "
                     << fixed(c.y * 1e3, 2) << " mm, contact angle "
                     << fixed(c.contact_angle * deg, 2) << " deg; frame x rolling, s lateral, n "
                     << "normal; on the wheel): F_n " << fixed(r.F_n * 1e-3, 2) << " kN, F_x "
                     << fixed(r.F_x * 1e-3, 2) << " kN, F_s " << fixed(r.F_s * 1e-3, 2)
                     << " kN, F_x/F_n " << fixed(r.F_n > 0 ? r.F_x / r.F_n : 0., 3) << ", F_s/F_n "
                     << fixed(r.F_n > 0 ? r.F_s / r.F_n : 0., 3) << ", M_n " << fixed(r.M_n, 1)
                     << " N m; centre of pressure y " << fixed(r.centre[1] * 1e3, 2)
                     << " mm, contact angle " << fixed(r.contact_angle * deg, 2) << " deg; "
                     << r.n_nodes << " rail-top nodes, area " << fixed(r.area * 1e6, 1)
                     << " mm^2, length " << fixed(r.length * 1e3, 2) << " mm, width "
                     << fixed(r.width * 1e3, 2) << " mm (node extents), p_max "
                     << fixed(r.p_max * 1e-6, 1) << " MPa"
                     << (r.joined ? "; joined to another patch (split at the midpoint)" : "")
                     << std::endl;
      }
    print_sum_check(results);
  }



  void
  PatchStatistics::print_sum_check(const std::vector<PatchResult> &results) const
  {
    Tensor<1, dim> sum;
    for (unsigned int k = 0; k < results.size(); ++k)
      {
        const PatchFrame &e = contact_patches.frame(k);
        sum += results[k].F_x * e.x + results[k].F_s * e.s + results[k].F_n * e.n;
      }
    const Tensor<1, dim> total = access.contact->summary().force;
    const bool           agree = (sum - total).norm() <= 1e-12 * std::max(total.norm(), 1e-300);
    access.pcout << "Patches summed in the global frame: F_N " << fixed(sum[2] * 1e-3, 2)
                 << " kN, F_L " << fixed(sum[0] * 1e-3, 2) << " kN, F_lateral "
                 << fixed(sum[1] * 1e-3, 2) << " kN; the contact's total: F_N "
                 << fixed(total[2] * 1e-3, 2) << " kN, F_L " << fixed(total[0] * 1e-3, 2)
                 << " kN, F_lateral " << fixed(total[1] * 1e-3, 2)
                 << " kN; equal to 1e-12 of |F|: " << (agree ? "yes" : "no") << std::endl;
  }
} // namespace WheelRail
