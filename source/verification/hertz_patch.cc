#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <wheelrail/simulator/format.h>
#include <wheelrail/verification/hertz.h>
#include <wheelrail/verification/hertz_patch.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace WheelRail
{
  namespace Verification
  {
    using Report::fmt;



    void
    compare_patch_with_hertz(const SimulatorAccess &access, const double contact_force)
    {
      // contact patch: least-squares fit p^2 = p0^2 (1 - (x-xc)^2/a^2 - y^2/b^2)
      // over the nodes with p > 25 % of the largest (the edge nodes' tributary
      // areas reach beyond the patch)
      // the wheel nodes with the forces of every pass; the penetrations are
      // those of the first pass
      const auto  &gaps   = access.contact->slave_states();
      const auto   states = access.contact->slave_node_results();
      double       p_max = 0, force = 0, xc = 0, max_pen = 0;
      unsigned int n_contact = 0;
      for (unsigned int i = 0; i < states.size(); ++i)
        if (states[i].in_contact())
          {
            const NodalContact &s = states[i];
            p_max                 = std::max(p_max, s.pressure());
            force += s.normal_force;
            xc += s.normal_force * s.X[0];
            if (gaps[i].in_contact)
              max_pen = std::max(max_pen, -gaps[i].gap);
            ++n_contact;
          }
      AssertThrow(n_contact > 0, ExcMessage("The static contact solve found no contact."));
      double rail_force = 0;
      for (const NodalContact &m : access.contact->master_node_results())
        rail_force += m.normal_force;
      xc /= force;
      FullMatrix<double> M(3, 3);
      Vector<double>     rhs(3), c(3);
      double             x_extent = 0, y_extent = 0, pen_at_peak = 0;
      for (unsigned int i = 0; i < states.size(); ++i)
        if (states[i].in_contact())
          {
            const NodalContact &s = states[i];
            x_extent              = std::max(x_extent, std::abs(s.X[0] - xc));
            y_extent              = std::max(y_extent, std::abs(s.X[1]));
            if (s.pressure() == p_max)
              pen_at_peak = -gaps[i].gap;
            if (s.pressure() < 0.25 * p_max)
              continue;
            const double phi[3] = {1., (s.X[0] - xc) * (s.X[0] - xc), s.X[1] * s.X[1]};
            for (unsigned int i = 0; i < 3; ++i)
              {
                rhs(i) += phi[i] * s.pressure() * s.pressure();
                for (unsigned int j = 0; j < 3; ++j)
                  M(i, j) += phi[i] * phi[j];
              }
          }
      M.gauss_jordan();
      M.vmult(c, rhs);
      const double p0 = std::sqrt(c(0)), a = std::sqrt(-c(0) / c(1)), b = std::sqrt(-c(0) / c(2));

      const GeometryParameters &g      = access.parameters.geometry;
      const double              E_star = access.parameters.material.youngs_modulus /
                            (2 * (1 - access.parameters.material.poisson_ratio *
                                        access.parameters.material.poisson_ratio));
      const HertzSolution h =
        hertz_contact(0.5 / g.wheel_radius, 0.5 / g.rail_profile_radius, contact_force, E_star);
      const double tol  = access.parameters.verification.tolerance;
      const auto   line = [&](const std::string &what,
                            const double       fe,
                            const double       ref,
                            const double       scale,
                            const std::string &unit) {
        const double       err = std::abs(fe - ref) / ref;
        std::ostringstream error;
        error << std::fixed << std::setprecision(3) << err;
        access.pcout << "  " << std::left << std::setw(34) << what << std::right << std::setw(10)
                     << fmt(fe * scale, 4) << " " << std::setw(10) << fmt(ref * scale, 4) << " "
                     << unit << "   error " << error.str()
                     << (err <= tol ? "  ok" : "  OUT OF TOLERANCE") << std::endl;
      };
      access.pcout << "Contact patch against Hertz (E* = " << fmt(E_star * 1e-9, 5)
                   << " GPa, A = 1/(2 R_w), "
                   << "B = 1/(2 R_rail))" << std::endl
                   << "  nodes in contact " << n_contact << ", total normal force "
                   << fmt(force * 1e-3, 5) << " kN, largest nodal pressure " << fmt(p_max * 1e-6, 4)
                   << " MPa" << std::endl
                   << "  the same force on the rail-top nodes: " << fmt(rail_force * 1e-3, 5)
                   << " kN" << std::endl
                   << "  penetration at peak pressure " << fmt(pen_at_peak * 1e6, 3)
                   << " um, largest penetration " << fmt(max_pen * 1e6, 3) << " um, Hertz approach "
                   << fmt(h.approach * 1e6, 4) << " um" << std::endl
                   << "  extent of the contact nodes: x +/- " << fmt(x_extent * 1e3, 4)
                   << " mm, y +/- " << fmt(y_extent * 1e3, 4) << " mm" << std::endl
                   << "  quantity (fit p^2 = p0^2 (1 - x^2/a^2 - y^2/b^2))   FE     Hertz"
                   << std::endl;
      line("semi-axis a (rolling, x)", a, h.a, 1e3, "mm");
      line("semi-axis b (lateral, y)", b, h.b, 1e3, "mm");
      line("peak pressure p0", p0, h.p0, 1e-6, "MPa");
      access.pcout << "  within tolerance " << fmt(tol) << ": "
                   << (std::abs(a - h.a) <= tol * h.a && std::abs(b - h.b) <= tol * h.b &&
                           std::abs(p0 - h.p0) <= tol * h.p0 ?
                         "yes" :
                         "no")
                   << std::endl;
    }
  } // namespace Verification
} // namespace WheelRail
