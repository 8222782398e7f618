// The 1D slider (verification/slider.h) with the exponential law of the
// paper (f_S = 0.5, f_D = 0.32, k = 6 s/m) and each slip-rate and friction
// option of Contact: the growth or decay rate of a perturbation of steady
// sliding (or of rest) in the explicit run against the largest real part
// of the roots of the linearised equations. A block of 1 kg on a spring of
// 1e6 N/m, F_n = 1 kN, the plate at 0.1 m/s; D = -F_n f'(V) = 592.7 N s/m,
// so C = D / 2 leaves the instantaneous law unstable (negative damping) and
// the relaxed law stable where its relaxation rate V / L + 1 / tau is below
// about 860 1/s.
#include <wheelrail/verification/slider.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace WheelRail;

namespace
{
  unsigned int failures = 0;

  void
  check(const char *label, const FrictionModel::Options &options, const Slider::Parameters &p)
  {
    const auto          law = FrictionLaw::create("exponential", 0.5, 0.32, 6.);
    const FrictionModel model(*law, options);
    const auto          roots = Slider::characteristic_roots(model, p);
    const double        sigma = roots.front().real();
    // windows of half a period of the leading mode, or a tenth of its
    // e-folding time where it does not oscillate
    const double omega  = std::abs(roots.front().imag());
    const double window = omega > 0 ? M_PI / omega : 0.1 / std::abs(sigma);
    const double end    = sigma > 0 ? 1. : 12. / std::abs(sigma);
    // sliding: 0.1 nm, a speed perturbation of about 0.1 um/s, followed
    // to 0.1 mm/s; at rest: 0.1 um on the tangential spring
    const double start = p.speed > 0 ? 1e-10 : 1e-7;
    const auto   run   = Slider::run(model, p, start, end, window, p.speed > 0 ? 1e-4 : 1.);
    const double error = std::abs(run.rate - sigma) / std::abs(sigma);
    const bool   ok    = error < 0.02 && (run.rate > 0) == (sigma > 0);
    failures += !ok;
    std::printf("%-44s closed form %9.1f 1/s (%s), run %9.1f 1/s, error %4.1f %%  %s\n",
                label,
                sigma,
                sigma > 0 ? "grows" : "decays",
                run.rate,
                100 * error,
                ok ? "OK" : "FAILED");
  }
} // namespace

int
main()
{
  const auto   law = FrictionLaw::create("exponential", 0.5, 0.32, 6.);
  const double D   = 1000. * 6. * 0.18 * std::exp(-0.6);
  std::printf("steady sliding at V = 0.1 m/s: f(V) = %.4f, D = -F_n f'(V) = %.1f N s/m\n",
              law->coefficient(0.1),
              D);

  Slider::Parameters     p;
  FrictionModel::Options paper;
  std::printf("\nsteady sliding, slip rate |de| / dt (paper)\n");
  p.damping = 0;
  check("  instantaneous law, C = 0", paper, p);
  p.damping = 0.5 * D;
  check("  instantaneous law, C = D / 2", paper, p);
  p.damping = 2 * D;
  check("  instantaneous law, C = 2 D", paper, p);

  std::printf("\nsteady sliding, C = D / 2, relaxing friction state\n");
  p.damping = 0.5 * D;
  FrictionModel::Options relax;
  relax.relaxation_length = 5e-4;
  check("  L = 0.5 mm", relax, p);
  relax.relaxation_length = 5e-5;
  check("  L = 50 um (relaxation too fast)", relax, p);
  relax.relaxation_length = 0;
  relax.relaxation_time   = 2e-3;
  check("  tau = 2 ms", relax, p);

  std::printf("\nsteady sliding, C = D / 2, irreversible slip rate\n");
  FrictionModel::Options irreversible;
  irreversible.irreversible_slip_rate = true;
  {
    // alone: the steady sliding of the continuous model is unstable (a
    // positive real root near k_t / D), and the explicit step does not keep
    // it at all: the trial force f(V) F_n + k_t V dt lies within the static
    // cone f_S F_n, so the contact sticks at the first step
    Slider::Parameters soft   = p;
    soft.tangential_stiffness = D / (100 * p.time_step);
    const FrictionModel model(*law, irreversible);
    const auto          roots = Slider::characteristic_roots(model, soft);
    const auto          run   = Slider::run(model, soft, 1e-10, 1e-3, 1e-5, 1e-4);
    std::printf("  alone, k_t = D / (100 dt): closed form %.1f 1/s (%s); the run sticks: %s\n",
                roots.front().real(),
                roots.front().real() > 0 ? "grows" : "decays",
                run.stuck ? "yes" : "no");
    failures += !(roots.front().real() > 0 && run.stuck);
  }
  irreversible.relaxation_length = 5e-4;
  check("  with L = 0.5 mm, k_t = 1e9 N/m", irreversible, p);

  std::printf("\nsticking at rest (V = 0), k_t = 1e9 N/m, dt = 1e-8 s\n");
  Slider::Parameters rest = p;
  rest.speed              = 0;
  rest.damping            = 0;
  rest.time_step          = 1e-8;
  FrictionModel::Options damped;
  damped.damping_ratio = 0.05;
  check("  tangential damping 0.05", damped, rest);
  // what the law sees in adhesion: the spring's oscillation as slip, or none
  for (const bool irreversible_rate : {false, true})
    {
      FrictionModel::Options o;
      o.irreversible_slip_rate = irreversible_rate;
      const FrictionModel model(*law, o);
      const auto          run = Slider::run(model, rest, 1e-7, 1e-3, 1e-4, 1.);
      std::printf("  no damping, slip rate %-12s: stuck %s, largest s_n %.3g m/s, rate %.1f 1/s\n",
                  irreversible_rate ? "irreversible" : "|de| / dt",
                  run.stuck ? "yes" : "no",
                  run.largest_slip,
                  run.rate);
      failures +=
        !run.stuck || (irreversible_rate && run.largest_slip != 0) || std::abs(run.rate) > 1.;
    }

  std::printf("\n%s\n", failures == 0 ? "all OK" : "FAILED");
  return failures == 0 ? 0 : 1;
}
