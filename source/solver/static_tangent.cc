#include <deal.II/base/mpi.h>

#include <wheelrail/solver/static_tangent.h>

#include <algorithm>
#include <tuple>

namespace WheelRail
{
  StaticTangent::StaticTangent(const TrilinosWrappers::SparseMatrix &K, MPI_Comm comm)
    : K(K)
    , comm(comm)
  {}



  void
  StaticTangent::set_contact_pairs(const std::vector<ContactPair>  &pairs,
                                   const AffineConstraints<double> &constraints,
                                   const IndexSet                  &owned)
  {
    // the owner of a DoF knows its constraint; its entries (pair, DoF,
    // coefficient) go to every rank, which keeps those on its owned DoFs
    using Entry = std::tuple<unsigned int, types::global_dof_index, double>;
    std::vector<Entry> mine;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        const ContactPair &pair = pairs[p];
        const double c[5] = {1., -pair.shape[0], -pair.shape[1], -pair.shape[2], -pair.shape[3]};
        const types::global_dof_index node[5] = {
          pair.slave, pair.master[0], pair.master[1], pair.master[2], pair.master[3]};
        for (unsigned int a = 0; a < 5; ++a)
          for (unsigned int i = 0; i < dim; ++i)
            {
              const types::global_dof_index dof = node[a] + i;
              if (!owned.is_element(dof))
                continue;
              const double value = c[a] * pair.normal[i];
              if (!constraints.is_constrained(dof))
                mine.emplace_back(p, dof, value);
              else // hanging: its masters; fixed: no entries
                for (const auto &[master, weight] : *constraints.get_constraint_entries(dof))
                  mine.emplace_back(p, master, value * weight);
            }
      }
    std::vector<Entry> all;
    for (const auto &part : Utilities::MPI::all_gather(comm, mine))
      all.insert(all.end(), part.begin(), part.end());
    std::stable_sort(all.begin(), all.end(), [](const Entry &x, const Entry &y) {
      return std::get<0>(x) < std::get<0>(y);
    });

    stiffness.resize(pairs.size());
    offsets.assign(1, 0);
    local_index.clear();
    coefficient.clear();
    auto e = all.begin();
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        stiffness[p] = pairs[p].stiffness;
        for (; e != all.end() && std::get<0>(*e) == p; ++e)
          if (owned.is_element(std::get<1>(*e)))
            {
              local_index.push_back(owned.index_within_set(std::get<1>(*e)));
              coefficient.push_back(std::get<2>(*e));
            }
        offsets.push_back(local_index.size());
      }
    gaps.resize(pairs.size());
  }



  void
  StaticTangent::vmult(TrilinosWrappers::MPI::Vector       &dst,
                       const TrilinosWrappers::MPI::Vector &src) const
  {
    K.vmult(dst, src);
    if (stiffness.empty())
      return;
    const double *x = src.trilinos_vector()[0];
    double       *y = dst.trilinos_vector()[0];
    for (unsigned int p = 0; p < stiffness.size(); ++p)
      {
        double g = 0;
        for (unsigned int k = offsets[p]; k < offsets[p + 1]; ++k)
          g += coefficient[k] * x[local_index[k]];
        gaps[p] = g;
      }
    Utilities::MPI::sum(gaps, comm, gaps);
    for (unsigned int p = 0; p < stiffness.size(); ++p)
      for (unsigned int k = offsets[p]; k < offsets[p + 1]; ++k)
        y[local_index[k]] += stiffness[p] * gaps[p] * coefficient[k];
  }
} // namespace WheelRail
