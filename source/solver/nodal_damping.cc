#include <wheelrail/solver/nodal_damping.h>

namespace WheelRail
{
  void
  NodalDamping::setup(const ElasticOperator &op)
  {
    op.smallest_cell_beta(beta);
    have_sample = false;
    last_time   = 0;
    last_power  = 0;
    dissipated  = 0;
  }



  void
  NodalDamping::damped_displacement(const VectorType &u, const VectorType &v, VectorType &w) const
  {
    const std::size_t n = u.locally_owned_size() + u.get_partitioner()->n_ghost_indices();
    AssertDimension(beta.locally_owned_size() + beta.get_partitioner()->n_ghost_indices(), n);
    const double *__restrict U = u.begin();
    const double *__restrict V = v.begin();
    const double *__restrict B = beta.begin();
    double *__restrict W       = w.begin();
#pragma omp simd
    for (std::size_t i = 0; i < n; ++i)
      W[i] = U[i] + B[i] * V[i];
  }



  double
  NodalDamping::power(const VectorType &v, const VectorType &f_w, const VectorType &f_u)
  {
    const std::size_t n = v.locally_owned_size() + v.get_partitioner()->n_ghost_indices();
    const double     *V = v.begin(), *Fw = f_w.begin(), *Fu = f_u.begin();
    double            p = 0;
    for (std::size_t i = 0; i < n; ++i)
      p += V[i] * (Fw[i] - Fu[i]);
    return p;
  }



  void
  NodalDamping::sample(const double t, const double p)
  {
    if (have_sample)
      dissipated += 0.5 * (t - last_time) * (last_power + p);
    have_sample = true;
    last_time   = t;
    last_power  = p;
  }
} // namespace WheelRail
