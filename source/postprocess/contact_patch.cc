#include <wheelrail/geometry/interface.h>
#include <wheelrail/postprocess/contact_patch.h>
#include <wheelrail/simulator/format.h>
#include <wheelrail/verification/expected_errors.h>
#include <wheelrail/verification/hertz_patch.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace WheelRail
{
  using Report::fmt;



  TrailingSlip
  trailing_micro_slip(const PenaltyContact &contact)
  {
    TrailingSlip result;
    const double centre = contact.patch_centre();
    if (std::isnan(centre))
      return result;
    unsigned int n = 0;
    for (const NodalContact &s : contact.slave_node_results())
      if (s.in_contact() && s.x[0] < centre)
        {
          result.magnitude += s.slip_velocity;
          result.rate += s.slip_rate;
          ++n;
        }
    if (n > 0)
      {
        result.magnitude /= n;
        result.rate /= n;
      }
    return result;
  }



  void
  write_contact_nodes(const SimulatorAccess &access, const std::string &name)
  {
    // replicated on every rank: rank 0 writes
    const PenaltyContact &contact = *access.contact;
    const auto           &states  = contact.slave_states();
    const auto            nodes   = contact.slave_node_results();
    const double          eps_t   = contact.adhesion_tolerance(0);
    const double          eps_s   = NodalContact::slip_velocity_threshold;
    std::ostringstream    out;
    out << std::setprecision(9) << "# slave-node contact state at t = " << access.solver.time()
        << " s; SI units; x, y, z current position; "
        << (access.parameters.contact.two_pass ?
              "two-pass contact: F_n, F_t are this node's own penalty force plus the reactions "
              "N_j F of the other pass's slaves on its faces, the state columns weighted the "
              "same way; " :
              "")
        << "adhesion by eq. 5 (f|F_n| - |F_t| > " << eps_t << " N), slip by eq. 6 (s_n > " << eps_s
        << " m/s)\n"
        << "X,Y,Z,x,y,z,in_contact,gap,F_n,F_t_x,F_t_y,F_t_z,area,pressure,shear_x,shear,"
           "slip_velocity,cof,adhesion_eq5,slip_eq6\n";
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const NodalContact &s = nodes[i];
        if (!s.in_contact() && !(states[i].gap < access.parameters.contact.search_margin))
          continue;
        const double shear = s.area > 0 ? s.tangential_force.norm() / s.area : 0.;
        out << s.X[0] << ',' << s.X[1] << ',' << s.X[2] << ',' << s.x[0] << ',' << s.x[1] << ','
            << s.x[2] << ',' << s.in_contact() << ',' << states[i].gap << ',' << s.normal_force
            << ',' << s.tangential_force[0] << ',' << s.tangential_force[1] << ','
            << s.tangential_force[2] << ',' << s.area << ',' << s.pressure() << ','
            << (s.area > 0 ? s.tangential_force[0] / s.area : 0.) << ',' << shear << ','
            << s.slip_velocity << ',' << s.cof << ',' << s.adhesion() << ',' << s.slip_eq6()
            << '\n';
      }
    access.write_file(name, out.str());
  }



  ContactPatch::ContactPatch(const SimulatorAccess &access)
    : access(access)
  {
    if (access.parameters.geometry_model->reports_patches())
      patches.emplace(access.parameters.geometry_model->rigid_contacts());
  }



  namespace
  {
    const double      sampling_interval = 5.7e-6; // s, the paper's 175 kHz sampling
    const std::string snapshot_names[3] = {"t-5.7us", "t", "t+5.7us"};
  } // namespace



  void
  ContactPatch::execute(const StepInfo &)
  {
    if (!access.wheelset || !access.contact)
      return;
    const double centre = access.contact->patch_centre();
    if (std::isnan(centre))
      return;
    if (access.parameters.output.patch_window > 0)
      average(centre);
    if (next_snapshot >= 3)
      return;
    const double target = (static_cast<double>(next_snapshot) - 1.) *
                          access.parameters.wheelset.rolling_speed * sampling_interval;
    if (!(previous_centre < target && centre >= target))
      {
        previous_centre = centre;
        return;
      }
    previous_centre        = centre;
    const std::string name = snapshot_names[next_snapshot];
    ++next_snapshot;
    write_snapshot(name, centre);
  }



  void
  ContactPatch::average(const double centre)
  {
    const double              V    = access.parameters.wheelset.rolling_speed;
    const double              half = 0.5 * V * access.parameters.output.patch_window;
    std::vector<NodalContact> nodes;
    for (unsigned int k = 0; k < 3; ++k)
      {
        Window      &w      = windows[k];
        const double target = (static_cast<double>(k) - 1.) * V * sampling_interval;
        if (w.done || centre < target - half)
          continue;
        if (centre >= target + half)
          {
            // the window is complete: the steps whose centre was inside it
            if (w.steps > 0)
              write_mean(k);
            w.done = 1;
            continue;
          }
        if (nodes.empty())
          nodes = access.contact->master_node_results();
        w.sums.resize(nodes.size() * n_window_fields, 0.);
        for (unsigned int i = 0; i < nodes.size(); ++i)
          {
            const NodalContact &m = nodes[i];
            if (!m.in_contact() || m.area <= 0)
              continue;
            double *sum = &w.sums[i * n_window_fields];
            sum[0] += 1.;
            sum[1] += m.pressure();
            sum[2] += m.tangential_force[0] / m.area;
            sum[3] += m.tangential_force.norm() / m.area;
            sum[4] += m.slip_velocity;
            sum[5] += m.adhesion();
            sum[6] += m.slip_eq6();
            sum[7] += m.normal_force;
          }
        ++w.steps;
      }
  }



  void
  ContactPatch::write_mean(const unsigned int k) const
  {
    const GeometryParameters &g     = access.parameters.geometry;
    const Window             &w     = windows[k];
    const auto                nodes = access.contact->master_node_results();
    AssertThrow(nodes.size() * n_window_fields == w.sums.size(), ExcInternalError());
    std::ostringstream csv;
    csv << std::setprecision(9) << "# contact patch at " << snapshot_names[k]
        << ", time means over " << w.steps << " steps (" << access.parameters.output.patch_window
        << " s centred on the instant, by the patch centre's position): rail-top nodes of the "
           "solution zone; SI units; a node out of contact counts as zero; contact, adhesion, "
           "slip_eq6: the fractions of the steps in contact, in adhesion (eq. 5) and in slip "
           "(eq. 6), decided as in patch_"
        << snapshot_names[k] << ".csv\n"
        << "x,y,contact,pressure,shear_x,shear,slip_velocity,adhesion,slip_eq6,F_n,area\n";
    const double n        = static_cast<double>(w.steps);
    unsigned int n_always = 0, n_sometimes = 0;
    double       p_max = 0, slip_nodes = 0;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const NodalContact &m = nodes[i];
        if (!in_solution_zone(g, m))
          continue;
        const double *sum = &w.sums[i * n_window_fields];
        n_always += sum[0] == n;
        n_sometimes += sum[0] > 0;
        p_max = std::max(p_max, sum[1] / n);
        slip_nodes += (sum[0] - sum[5]) / n;
        csv << m.X[0] << ',' << m.X[1];
        for (unsigned int f = 0; f < n_window_fields; ++f)
          csv << ',' << sum[f] / n;
        csv << ',' << m.area << '\n';
      }
    access.write_file("patch_" + snapshot_names[k] + "_mean.csv", csv.str());
    if (access.robust_output_only())
      return;
    access.pcout << "Contact patch at " << snapshot_names[k] << ", means over " << w.steps
                 << " steps: " << n_always << " rail-top nodes in contact in every step, "
                 << n_sometimes << " in some, peak mean pressure " << fmt(p_max * 1e-6, 5)
                 << " MPa, on average " << fmt(slip_nodes, 4) << " nodes in slip (eq. 5)"
                 << std::endl;
  }



  void
  ContactPatch::write_snapshot(const std::string &name, const double centre) const
  {
    const GeometryParameters &g       = access.parameters.geometry;
    const PenaltyContact     &contact = *access.contact;
    const auto                states  = contact.master_node_results();
    std::ostringstream        csv;
    csv << std::setprecision(9) << "# contact patch at " << name << " (t = " << access.solver.time()
        << " s, patch centre x = " << centre << " m): rail-top nodes of the solution zone; SI "
        << "units; F_n, shear: the forces of "
        << (contact.n_passes() > 1 ? "both passes (the node's own as a slave of the second pass "
                                     "plus the shares N_j F of the wheel nodes on its faces)" :
                                     "the wheel nodes on its faces, shared with N_j")
        << ", on the wheel; adhesion and slip decided on those slave nodes (eq. 5: "
        << "f|F_n| - |F_t| > " << contact.adhesion_tolerance(0)
        << " N with the node's own f; eq. 6: s_n > " << NodalContact::slip_velocity_threshold
        << " m/s) and mapped with the same weights: adhesion_share, slip_share; the flags: share > "
           "0.5"
        << (patches ? "; patch: the patch of the node's y (nearest rigid contact point, from 1)\n" :
                      "\n")
        << "x,y,in_contact,pressure,shear_x,shear,slip_velocity,cof,adhesion_eq5,slip_eq6,"
           "F_n,area,adhesion_share,slip_share"
        << (patches ? ",patch\n" : "\n");
    unsigned int n_contact = 0, n_slip = 0;
    double       p_max = 0, s_max = 0, x_min = 1e30, x_max = -1e30, y_min = 1e30, y_max = -1e30;
    std::vector<Verification::PatchNode> patch;
    for (const NodalContact &m : states)
      {
        if (!in_solution_zone(g, m))
          continue;
        const bool   in     = m.in_contact();
        const double p      = m.pressure();
        const double shear  = m.tangential_force.norm() / m.area;
        const bool   adhere = m.adhesion();
        csv << m.X[0] << ',' << m.X[1] << ',' << in << ',' << p << ','
            << m.tangential_force[0] / m.area << ',' << shear << ',' << m.slip_velocity << ','
            << m.cof << ',' << adhere << ',' << m.slip_eq6() << ',' << m.normal_force << ','
            << m.area << ',' << m.adhesion_share << ',' << m.slip_share;
        if (patches)
          csv << ',' << patches->patch_of(m.X[1]) + 1;
        csv << '\n';
        if (in)
          {
            patch.push_back({m.X[0], m.X[1], p, m.normal_force});
            ++n_contact;
            n_slip += !adhere;
            p_max = std::max(p_max, p);
            s_max = std::max(s_max, shear);
            x_min = std::min(x_min, m.X[0]);
            x_max = std::max(x_max, m.X[0]);
            y_min = std::min(y_min, m.X[1]);
            y_max = std::max(y_max, m.X[1]);
          }
      }
    access.write_file("patch_" + name + ".csv", csv.str());
    if (name == "t")
      // what the report page judges the patch at t by
      access.write_file("expected_errors.csv",
                        Verification::expected_errors_csv(access.parameters.geometry.h_min));

    write_patch_surface(access, states, "patch_" + name + ".vtu");
    write_tread_surface(access, contact.slave_node_results(), "patch_tread_" + name + ".vtu");

    if (access.robust_output_only())
      return;
    access.pcout << "Contact patch at " << name << " (t = " << fmt(access.solver.time() * 1e3, 6)
                 << " ms): " << n_contact << " rail-top nodes in contact, x from "
                 << fmt(x_min * 1e3, 4) << " to " << fmt(x_max * 1e3, 4) << " mm, y from "
                 << fmt(y_min * 1e3, 4) << " to " << fmt(y_max * 1e3, 4) << " mm, peak pressure "
                 << fmt(p_max * 1e-6, 5) << " MPa, peak shear " << fmt(s_max * 1e-6, 5)
                 << " MPa, slip (eq. 5) " << n_slip << " of " << n_contact << " nodes" << std::endl;
    if (name == "t" && !patch.empty())
      judge_patch_at_t(patch);
  }



  void
  ContactPatch::judge_patch_at_t(const std::vector<Verification::PatchNode> &patch) const
  {
    if (access.parameters.geometry_model->has_profile_files())
      {
        access.pcout << "Contact patch at t: the profiles' patch is not Hertz's; its reference is "
                        "the half-space solution of their gap (scripts/profile_reference.py "
                     << access.parameters.problem.output_directory << ")" << std::endl;
        return;
      }
    const Verification::EllipseFit fit = Verification::fit_hertz_ellipse(patch);
    access.pcout << "Contact patch at t against Hertz at the patch's normal force "
                 << fmt(fit.force * 1e-3, 5) << " kN" << std::endl;
    // a rolling patch carries its mesh's discretisation error: judged by
    // what the convergence study measured at this h
    Verification::report_hertz_fit(access,
                                   fit,
                                   fit.force,
                                   access.parameters.verification.tolerance,
                                   access.parameters.geometry.h_min);
  }



  void
  ContactPatch::print_summary() const
  {
    if (!access.wheelset || !access.contact || access.robust_output_only())
      return;
    const ContactSummary &cs    = access.contact->summary();
    double                p_max = 0, s_max = 0, x0 = 1e30, x1 = -1e30, y0 = 1e30, y1 = -1e30;
    for (const NodalContact &s : access.contact->slave_node_results())
      if (s.in_contact())
        {
          p_max = std::max(p_max, s.pressure());
          s_max = std::max(s_max, s.area > 0 ? s.tangential_force.norm() / s.area : 0.);
          x0    = std::min(x0, s.x[0]);
          x1    = std::max(x1, s.x[0]);
          y0    = std::min(y0, s.x[1]);
          y1    = std::max(y1, s.x[1]);
        }
    if (cs.n_contact == 0)
      x0 = x1 = y0 = y1 = 0;
    access.pcout << "Summary at t = " << fmt(access.solver.time() * 1e3, 6)
                 << " ms (wheel x = " << fmt(access.wheelset->axle_position()[0] * 1e3, 6)
                 << " mm): F_N " << fmt(cs.force[2] * 1e-3, 5) << " kN, F_L "
                 << fmt(cs.force[0] * 1e-3, 5) << " kN, mu_a "
                 << fmt(cs.force[2] != 0 ? cs.force[0] / cs.force[2] : 0., 4) << "; patch "
                 << fmt((x1 - x0) * 1e3, 4) << " x " << fmt((y1 - y0) * 1e3, 4)
                 << " mm (node extent), " << cs.n_contact << " nodes, peak pressure "
                 << fmt(p_max * 1e-6, 5) << " MPa, peak shear " << fmt(s_max * 1e-6, 5)
                 << " MPa, slip fraction "
                 << fmt(cs.n_contact ? double(cs.n_slip) / cs.n_contact : 0., 3)
                 << ", trailing micro-slip "
                 << fmt(trailing_micro_slip(*access.contact).magnitude, 4) << " m/s" << std::endl;
  }
} // namespace WheelRail
