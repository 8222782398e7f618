/**
 * @file verification/hertz_patch.cc
 * The contact patch against Hertz: the ellipse fitted to the nodal
 * pressures, its report, and the static solve's comparison.
 */

#include <wheelrail/geometry/interface.h>
#include <wheelrail/simulator/format.h>
#include <wheelrail/verification/expected_errors.h>
#include <wheelrail/verification/hertz.h>
#include <wheelrail/verification/hertz_patch.h>
#include <wheelrail/verification/verdict.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

#include <Eigen/Dense>

namespace WheelRail
{
  namespace Verification
  {
    using Report::fmt;



    double
    effective_modulus(const MaterialParameters &material)
    {
      // two bodies of the same steel: 1/E* = 2 (1 - nu^2) / E
      return material.youngs_modulus / (2 * (1 - material.poisson_ratio * material.poisson_ratio));
    }



    HertzSolution
    wheel_rail_hertz(const Parameters &parameters, const double normal_force)
    {
      // curvatures 1/(2 R_w) along the rail, 1/(2 R_rail) across it;
      // hertz_contact() takes the smaller first, so a crown flatter than the
      // wheel swaps the semi-axes back to a along x, b along y
      const Geometry::ContactRadii r      = parameters.geometry_model->contact_radii();
      const double                 along  = 0.5 / r.wheel_rolling;
      const double                 across = 0.5 / r.rail_crown;
      const double                 E_star = effective_modulus(parameters.material);
      if (along <= across)
        return hertz_contact(along, across, normal_force, E_star);
      HertzSolution h = hertz_contact(across, along, normal_force, E_star);
      std::swap(h.a, h.b);
      return h;
    }



    EllipseFit
    fit_hertz_ellipse(const std::vector<PatchNode> &nodes)
    {
      EllipseFit fit;
      for (const PatchNode &n : nodes)
        if (n.pressure > 0)
          {
            fit.p_max = std::max(fit.p_max, n.pressure);
            fit.force += n.force;
            fit.xc += n.force * n.x;
            ++fit.n_contact;
          }
      if (fit.n_contact == 0)
        return fit;
      fit.xc /= fit.force;
      // least squares p^2 = c0 + c1 (x - xc)^2 + c2 y^2 by a column-pivoting
      // QR of the design matrix: its columns differ in scale by about 1e5
      // (1 and squares of mm in m), which the normal equations would square
      std::vector<const PatchNode *> used;
      for (const PatchNode &n : nodes)
        if (n.pressure > 0 && n.pressure >= 0.25 * fit.p_max)
          used.push_back(&n);
      Eigen::MatrixXd A(used.size(), 3);
      Eigen::VectorXd rhs(used.size());
      for (unsigned int k = 0; k < used.size(); ++k)
        {
          const PatchNode &n = *used[k];
          A(k, 0)            = 1.;
          A(k, 1)            = (n.x - fit.xc) * (n.x - fit.xc);
          A(k, 2)            = n.y * n.y;
          rhs(k)             = n.pressure * n.pressure;
        }
      fit.n_fitted = used.size();
      if (used.size() < 3)
        return fit;
      const Eigen::Vector3d c = A.colPivHouseholderQr().solve(rhs);
      fit.elliptic            = c(0) > 0 && c(1) < 0 && c(2) < 0;
      if (!fit.elliptic)
        return fit;
      fit.p0 = std::sqrt(c(0));
      fit.a  = std::sqrt(-c(0) / c(1));
      fit.b  = std::sqrt(-c(0) / c(2));
      return fit;
    }



    bool
    report_hertz_fit(const SimulatorAccess &access,
                     const EllipseFit      &fit,
                     const double           normal_force,
                     const double           tolerance,
                     const double           h)
    {
      const HertzSolution h_ref = wheel_rail_hertz(access.parameters, normal_force);
      bool                ok    = fit.elliptic;
      const auto          line  = [&](const std::string &what,
                            const std::string &key,
                            const double       fe,
                            const double       ref,
                            const double       scale,
                            const std::string &unit) {
        const double       err = std::abs(fe - ref) / ref;
        const double       limit = h > 0 ? expectation(expected_error(key), h).limit : tolerance;
        std::ostringstream error;
        error << std::fixed << std::setprecision(3) << err;
        access.pcout << "  " << std::left << std::setw(34) << what << std::right << std::setw(10)
                     << fmt(fe * scale, 4) << " " << std::setw(10) << fmt(ref * scale, 4) << " "
                     << unit << "   error " << error.str() << "  "
                     << (h > 0            ? expectation_verdict(key, err, h) :
                                   err <= tolerance ? "ok" :
                                                      "OUT OF TOLERANCE")
                     << std::endl;
        ok = ok && err <= limit;
      };
      // a patch that no ellipse fits (too few nodes, or not falling off
      // from its centre) is not within any tolerance
      if (fit.elliptic)
        {
          access.pcout << "  quantity (fit p^2 = p0^2 (1 - x^2/a^2 - y^2/b^2))   FE     Hertz"
                       << std::endl;
          line("semi-axis a (rolling, x)", "a", fit.a, h_ref.a, 1e3, "mm");
          line("semi-axis b (lateral, y)", "b", fit.b, h_ref.b, 1e3, "mm");
          line("peak pressure p0", "p0", fit.p0, h_ref.p0, 1e-6, "MPa");
        }
      else
        access.pcout << "  no ellipse p^2 = p0^2 (1 - x^2/a^2 - y^2/b^2) fits the " << fit.n_fitted
                     << " nodes with p >= p_max/4 (Hertz: a " << fmt(h_ref.a * 1e3, 4) << " mm, b "
                     << fmt(h_ref.b * 1e3, 4) << " mm, p0 " << fmt(h_ref.p0 * 1e-6, 4) << " MPa)"
                     << std::endl;
      if (h > 0)
        access.pcout << "  within what the convergence study expects at h = " << fmt(h * 1e3, 3)
                     << " mm (doc/convergence.md): " << Verification::verdict(ok) << std::endl;
      else
        access.pcout << "  within tolerance " << fmt(tolerance) << ": " << Verification::verdict(ok)
                     << std::endl;
      return ok;
    }



    void
    compare_patch_with_hertz(const SimulatorAccess &access, const double contact_force)
    {
      // the wheel nodes with the forces of every pass; the penetrations are
      // those of the first pass
      const auto            &gaps   = access.contact->slave_states();
      const auto             states = access.contact->slave_node_results();
      std::vector<PatchNode> nodes;
      double                 max_pen = 0;
      for (unsigned int i = 0; i < states.size(); ++i)
        if (states[i].in_contact())
          {
            const NodalContact &s = states[i];
            nodes.push_back({s.X[0], s.X[1], s.pressure(), s.normal_force});
            if (gaps[i].in_contact)
              max_pen = std::max(max_pen, -gaps[i].gap);
          }
      AssertThrow(!nodes.empty(), ExcMessage("The static contact solve found no contact."));
      const EllipseFit fit        = fit_hertz_ellipse(nodes);
      double           rail_force = 0;
      for (const NodalContact &m : access.contact->master_node_results())
        rail_force += m.normal_force;
      double x_extent = 0, y_extent = 0, pen_at_peak = 0;
      for (unsigned int i = 0; i < states.size(); ++i)
        if (states[i].in_contact())
          {
            const NodalContact &s = states[i];
            x_extent              = std::max(x_extent, std::abs(s.X[0] - fit.xc));
            y_extent              = std::max(y_extent, std::abs(s.X[1]));
            if (s.pressure() == fit.p_max)
              pen_at_peak = -gaps[i].gap;
          }

      const double        E_star = effective_modulus(access.parameters.material);
      const HertzSolution h      = wheel_rail_hertz(access.parameters, contact_force);
      access.pcout << "Contact patch against Hertz (E* = " << fmt(E_star * 1e-9, 5)
                   << " GPa, A = 1/(2 R_w), "
                   << "B = 1/(2 R_rail))" << std::endl
                   << "  nodes in contact " << fit.n_contact << ", total normal force "
                   << fmt(fit.force * 1e-3, 5) << " kN, largest nodal pressure "
                   << fmt(fit.p_max * 1e-6, 4) << " MPa" << std::endl
                   << "  the same force on the rail-top nodes: " << fmt(rail_force * 1e-3, 5)
                   << " kN" << std::endl
                   << "  penetration at peak pressure " << fmt(pen_at_peak * 1e6, 3)
                   << " um, largest penetration " << fmt(max_pen * 1e6, 3) << " um, Hertz approach "
                   << fmt(h.approach * 1e6, 4) << " um" << std::endl
                   << "  extent of the contact nodes: x +/- " << fmt(x_extent * 1e3, 4)
                   << " mm, y +/- " << fmt(y_extent * 1e3, 4) << " mm" << std::endl;
      report_hertz_fit(access, fit, contact_force, access.parameters.verification.tolerance);
    }
  } // namespace Verification
} // namespace WheelRail
