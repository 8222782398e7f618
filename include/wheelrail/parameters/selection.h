/**
 * @file parameters/selection.h
 * A Patterns::Selection entry read once into an enum class: the names in
 * the enumerators' order, so that names[i] names the i-th enumerator.
 */
#ifndef wheelrail_parameters_selection_h
#define wheelrail_parameters_selection_h

#include <deal.II/base/exceptions.h>

#include <array>
#include <cstddef>
#include <string>

namespace WheelRail
{
  /** The names of the values of @p Enum, in the order of its enumerators. */
  template <typename Enum, std::size_t N>
  struct SelectionNames
  {
    std::array<const char *, N> names;

    /** The enumerator named @p value (a value the entry's pattern let
     *  through). */
    Enum
    parse(const std::string &value) const
    {
      for (std::size_t i = 0; i < N; ++i)
        if (value == names[i])
          return static_cast<Enum>(i);
      AssertThrow(false, dealii::ExcMessage("'" + value + "' is not one of the selection's names."));
      return static_cast<Enum>(0);
    }

    /** The name of @p value. */
    const char *
    operator()(const Enum value) const
    {
      return names[static_cast<std::size_t>(value)];
    }
  };
} // namespace WheelRail

#endif
