/**
 * @file single_element_data.cc
 * The force loop's copy of the element data with single-precision
 * geometric factors (layout ElementKernel::SingleField), stored once per
 * distinct block: batches whose blocks are the same, bit for bit, share one
 * copy, and with Time integration/Element geometry sharing = within rounding
 * the factors are first rounded to a grid fine enough that only cells
 * differing by less than the floats' rounding come to share.
 */
#include <deal.II/base/mpi.h>

#include <wheelrail/solver/elastic_operator.h>
#include <wheelrail/solver/element_data.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

namespace WheelRail
{
  using namespace ElementKernel;

  namespace
  {
    /** @p x on the grid of spacing @p step (a power of two times 2^-23):
     *  the nearest multiple, zero as +0 (a tiny factor of either sign
     *  becomes the same bits). */
    double
    on_grid(const double x, const double step)
    {
      return std::nearbyint(x / step) * step + 0.;
    }

    /** The power of two at or below |@p x| (1 for zero). */
    double
    binade(const double x)
    {
      return x == 0 ? 1. : std::exp2(std::floor(std::log2(std::abs(x))));
    }

    /**
     * A batch's block (its float factors @p g, its doubles in @p block)
     * rounded so that blocks closer than the floats' rounding become the
     * same, lane by lane: the gradient factors b to
     * multiples of 2^-23 times the binade of the lane's largest |b| (half
     * a float unit of that factor at most), the hourglass factors c to
     * multiples of 2^-23 over that binade (c has the unit of a length, 1/b
     * its scale), V0, kappa and beta each to 24 bits (a float's
     * precision, kept as a double). The grid depends on the lane's own
     * values only: the same on every rank and in every batch order.
     */
    void
    round_to_grid(float (&g)[SingleField::n_geometry * W], double *block)
    {
      constexpr double unit = 0x1p-23;
      for (unsigned int l = 0; l < W; ++l)
        {
          double b_max = 0;
          for (unsigned int k = Field::b; k < Field::c; ++k)
            b_max = std::max(b_max, std::abs(double(g[k * W + l])));
          const double scale = binade(b_max);
          for (unsigned int k = Field::b; k < Field::c; ++k)
            g[k * W + l] = static_cast<float>(on_grid(g[k * W + l], unit * scale));
          for (unsigned int k = Field::c; k < SingleField::n_geometry; ++k)
            g[k * W + l] = static_cast<float>(on_grid(g[k * W + l], unit / scale));
          for (const unsigned int field :
               {SingleField::volume, SingleField::kappa, SingleField::beta})
            block[field + l] = on_grid(block[field + l], unit * binade(block[field + l]));
        }
    }
  } // namespace



  void
  ElasticOperator::copy_single_precision()
  {
    batch_single.clear();
    batch_single_block.clear();
    if (!prm.solver.single_precision_geometry)
      return;
    // each batch's block made in turn and appended only if it is new (the
    // distinct blocks in the order of their first batch), so that set-up
    // holds no copy of all blocks
    constexpr std::size_t                         bytes = SingleField::n_double * sizeof(double);
    std::unordered_map<std::string, unsigned int> index_of;
    alignas(64) double                            block[SingleField::n_double];
    batch_single_block.resize(n_batches);
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      {
        const double *data = &batch_data[std::size_t(batch) * Field::n_fields * W];
        float         geometry[SingleField::n_geometry * W];
        for (unsigned int k = 0; k < SingleField::n_geometry * W; ++k)
          geometry[k] = static_cast<float>(data[k]);
        for (unsigned int l = 0; l < W; ++l)
          {
            block[SingleField::volume + l] = data[Field::volume * W + l];
            block[SingleField::kappa + l]  = data[Field::kappa * W + l];
            block[SingleField::beta + l]   = data[Field::beta * W + l];
          }
        if (prm.solver.geometry_sharing == GeometrySharing::within_rounding)
          round_to_grid(geometry, block);
        std::memcpy(block, geometry, sizeof(geometry));
        const auto [it, inserted] =
          index_of.emplace(std::string(reinterpret_cast<const char *>(block), bytes),
                           index_of.size());
        if (inserted)
          batch_single.insert_back(block, block + SingleField::n_double);
        batch_single_block[batch] = it->second;
      }
  }



  std::pair<unsigned int, unsigned int>
  ElasticOperator::n_single_blocks_and_batches() const
  {
    return {static_cast<unsigned int>(batch_single.size() / SingleField::n_double),
            batch_single_block.empty() ? 0u : n_batches};
  }
} // namespace WheelRail
