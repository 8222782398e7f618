/**
 * @file parameters/vector_function.cc
 * Vector-valued expressions of the parameter file (muparser through
 * deal.II's FunctionParser): user constants, their checks, and the parsed
 * function.
 */

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/parameters/parameters.h>

#include <cctype>
#include <cmath>
#include <map>
#include <string>

namespace WheelRail
{
  namespace
  {
    /**
     * A user constant's name must be an identifier that is neither a
     * variable of the expression nor a name muparser (or deal.II's
     * FunctionParser) already gives a meaning: such a name would shadow it
     * or make the expression fail to parse.
     */
    void
    check_constant_name(const std::string &name,
                        const std::string &variables,
                        const std::string &entry)
    {
      bool identifier =
        !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
      for (const char ch : name)
        identifier = identifier && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_');
      AssertThrow(identifier,
                  ExcMessage(entry + " constants: '" + name +
                             "' is not a name (letters, digits and '_', not starting with a "
                             "digit)."));
      for (const auto &v : Utilities::split_string_list(variables))
        AssertThrow(name != v,
                    ExcMessage(entry + " constants: '" + name +
                               "' is a variable of the expression (" + variables +
                               ") and cannot be a constant."));
      static const char *reserved[] = {"_pi",   "_e",        "sin",   "cos",   "tan",  "asin",
                                       "acos",  "atan",      "sinh",  "cosh",  "tanh", "asinh",
                                       "acosh", "atanh",     "log2",  "log10", "log",  "ln",
                                       "exp",   "sqrt",      "sign",  "rint",  "abs",  "min",
                                       "max",   "sum",       "avg",   "if",    "int",  "ceil",
                                       "cot",   "csc",       "floor", "sec",   "pow",  "erfc",
                                       "rand",  "rand_seed", "atan2", "fmod"};
      for (const char *r : reserved)
        AssertThrow(name != r,
                    ExcMessage(entry + " constants: '" + name +
                               "' is a built-in function or constant of the expression parser."));
    }
  } // namespace



  std::unique_ptr<FunctionParser<3>>
  make_vector_function(const std::string &expression,
                       const std::string &constants_text,
                       const std::string &variables,
                       const std::string &entry)
  {
    std::map<std::string, double> constants = {{"pi", M_PI}};
    for (const auto &c : Utilities::split_string_list(constants_text))
      {
        const auto kv = Utilities::split_string_list(c, '=');
        AssertThrow(kv.size() == 2,
                    ExcMessage(entry + " constants: cannot read '" + c + "' as name=value."));
        const std::string &name = kv[0];
        check_constant_name(name, variables, entry);
        AssertThrow(constants.count(name) == 0,
                    ExcMessage(entry + " constants: '" + name +
                               (name == "pi" ?
                                  "' is built in (pi = 3.14159...) and cannot be redefined." :
                                  "' is defined twice.")));
        double value = 0;
        try
          {
            value = Utilities::string_to_double(kv[1]);
          }
        catch (...)
          {
            AssertThrow(false, ExcMessage(entry + " constants: '" + kv[1] + "' is not a number."));
          }
        AssertThrow(std::isfinite(value),
                    ExcMessage(entry + " constants: " + name + " = " + kv[1] + " is not finite."));
        constants[name] = value;
      }
    const auto components = Utilities::split_string_list(expression, ';');
    AssertThrow(components.size() == 3,
                ExcMessage(entry + " = '" + expression +
                           "' must have three expressions separated by ';'."));
    auto              function = std::make_unique<FunctionParser<3>>(3);
    const std::string known    = "(variables " + variables + "; constants pi" +
                              (constants_text.empty() ? std::string() : ", " + constants_text) +
                              ")";
    // deal.II's parser reads the expressions at their first evaluation
    Vector<double> at_origin(3);
    try
      {
        function->initialize(variables,
                             components,
                             constants,
                             variables.find('t') != std::string::npos);
        for (unsigned int d = 0; d < 3; ++d)
          at_origin[d] = function->value(Point<3>(), d);
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false,
                    ExcMessage(entry + " = '" + expression + "' cannot be evaluated " + known +
                               "."));
      }
    for (unsigned int d = 0; d < 3; ++d)
      AssertThrow(std::isfinite(at_origin[d]),
                  ExcMessage(entry + " = '" + expression + "' is not finite at the origin" +
                             (variables.find('t') != std::string::npos ? " at t = 0" : "") +
                             " (component " + std::to_string(d + 1) + ": " +
                             (std::isnan(at_origin[d]) ? "NaN" :
                              at_origin[d] > 0         ? "+inf" :
                                                         "-inf") +
                             ") " + known +
                             ": give an expression that is finite wherever it is used."));
    return function;
  }
} // namespace WheelRail
