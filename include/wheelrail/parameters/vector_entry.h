/**
 * @file parameters/vector_entry.h
 * Parameter entries holding a vector of three real numbers "a, b, c".
 */
#ifndef wheelrail_parameters_vector_entry_h
#define wheelrail_parameters_vector_entry_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/utilities.h>

#include <string>

namespace WheelRail
{
  namespace ParameterEntries
  {
    /** Pattern for a vector of three real numbers "a, b, c". */
    inline dealii::Patterns::List
    vector_pattern()
    {
      return dealii::Patterns::List(dealii::Patterns::Double(), 3, 3, ",");
    }

    /** The value of the vector entry @p name of the current subsection. */
    inline dealii::Tensor<1, 3>
    get_vector(const dealii::ParameterHandler &prm, const std::string &name)
    {
      const auto values = dealii::Utilities::string_to_double(
        dealii::Utilities::split_string_list(prm.get(name), ','));
      dealii::Tensor<1, 3> t;
      for (unsigned int d = 0; d < 3; ++d)
        t[d] = values[d];
      return t;
    }
  } // namespace ParameterEntries
} // namespace WheelRail

#endif
