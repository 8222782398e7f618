#include <wheelrail/solver/nodal_damping.h>

#include <algorithm>

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



  void
  NodalDamping::prepare_fix_up(const VectorType                &u,
                               const std::vector<unsigned int> &overwritten)
  {
    const unsigned int n_owned = u.locally_owned_size();
    const unsigned int n_ghost = u.get_partitioner()->n_ghost_indices();
    fix_up_dofs.assign(overwritten.begin(), overwritten.end());
    std::sort(fix_up_dofs.begin(), fix_up_dofs.end());
    fix_up_dofs.erase(std::unique(fix_up_dofs.begin(), fix_up_dofs.end()), fix_up_dofs.end());
    ghost_begin = n_owned;
    ghost_end   = n_owned + n_ghost;
  }



  void
  NodalDamping::fix_up(const VectorType &u, const VectorType &v, VectorType &w) const
  {
    const double *__restrict U = u.begin();
    const double *__restrict V = v.begin();
    const double *__restrict B = beta.begin();
    double *__restrict W       = w.begin();
    for (const unsigned int i : fix_up_dofs)
      W[i] = U[i] + B[i] * V[i];
#pragma omp simd
    for (unsigned int i = ghost_begin; i < ghost_end; ++i)
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
