/**
 * @file postprocess/statistics.h
 * OUTDIR/statistics: one row per statistics step (time, wheel position,
 * contact forces, energies, energy balance; SPEC 7).
 */
#ifndef wheelrail_postprocess_statistics_h
#define wheelrail_postprocess_statistics_h

#include <deal.II/base/table_handler.h>

#include <wheelrail/postprocess/energy_balance.h>
#include <wheelrail/postprocess/postprocessor.h>

#include <string>
#include <vector>

namespace WheelRail
{
  /** deal.II's TableHandler with its numbers readable by column. */
  class StatisticsTable : public TableHandler
  {
  public:
    /** The column keys in their order. */
    const std::vector<std::string> &
    keys() const
    {
      return column_order;
    }
    /** The values of column @p key, one per row. */
    std::vector<double>
    values(const std::string &key) const;

    /** Add @p value to column @p key of the current row, written with 8
     *  significant digits. */
    void
    add_number(const std::string &key, const double value);
  };

  /** The statistics table; the balance columns come from @p balance, and
   *  then the columns of each of @p selected, which must have executed
   *  the same step before. */
  class Statistics : public Postprocessor
  {
  public:
    Statistics(const SimulatorAccess                  &access,
               const EnergyBalance                    &balance,
               const std::vector<const Postprocessor *> &selected = {});

    /** At a statistics step: add the row; at a report step also write the
     *  file. */
    void
    execute(const StepInfo &step) override;

    void
    write_files() const override;

    void
    save(Checkpoint::Writer &out) override;
    void
    load(Checkpoint::Reader &in) override;
    /** The rows so far. */
    const StatisticsTable &
    rows() const
    {
      return table;
    }

    /** The table as one string (TableHandler's boost serialization). */
    template <class Archive>
    void
    serialize(Archive &ar);

  private:
    void
    add_row(const Energies &e);

    const SimulatorAccess &access;
    const EnergyBalance                     &balance;
    const std::vector<const Postprocessor *> selected;
    StatisticsTable                          table;
  };
} // namespace WheelRail

#endif
