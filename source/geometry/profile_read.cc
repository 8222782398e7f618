/**
 * @file geometry/profile_read.cc
 * SplineProfile::read(): the profile file's format. Plain text or CSV, two
 * numbers y z [mm] a line, separated by spaces, tabs, commas or semicolons;
 * lines starting with '#' or '%' are comments (CONTACT's .prr/.prw files start
 * their comment lines with '%'); blank lines are skipped; one header line of
 * words ("y,z", "Y [mm] Z [mm]") is allowed as the first line that is not a
 * comment. Numbers are read with std::from_chars (no locale): a decimal comma
 * is refused with its own message rather than read as a separator.
 */
#include <wheelrail/geometry/profile.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace WheelRail
{
  namespace Geometry
  {
    namespace
    {
      using internal::throw_profile_error;

      /** The pieces of `text` between the characters of `separators`. */
      std::vector<std::string>
      split(const std::string &text, const char *separators)
      {
        std::vector<std::string> tokens;
        std::size_t              begin = text.find_first_not_of(separators);
        while (begin != std::string::npos)
          {
            const std::size_t end = text.find_first_of(separators, begin);
            tokens.push_back(text.substr(begin, end - begin));
            begin = text.find_first_not_of(separators, end);
          }
        return tokens;
      }

      /** Whether `token` is digits, a comma and digits (with an optional sign). */
      bool
      is_decimal_comma(const std::string &token)
      {
        const std::size_t start = (!token.empty() && (token[0] == '-' || token[0] == '+'));
        const std::size_t comma = token.find(',');
        if (comma == std::string::npos || comma == start || comma + 1 == token.size())
          return false;
        for (std::size_t i = start; i < token.size(); ++i)
          if (i != comma && !std::isdigit(static_cast<unsigned char>(token[i])))
            return false;
        return true;
      }

      /** `token` as a number, or false where it is not one entirely. */
      bool
      parse_number(const std::string &token, double &value)
      {
        const char *begin = token.data(), *end = token.data() + token.size();
        if (begin != end && *begin == '+')
          ++begin;
        const auto result = std::from_chars(begin, end, value);
        return result.ec == std::errc() && result.ptr == end;
      }

      /** Where a profile file is read from, for the messages. */
      struct FileContext
      {
        const std::string &file, &parameter;
      };

      /**
       * The fields of one data line; throws for a decimal comma. The line's
       * separators are white space and ';', and ',' where no field has a
       * decimal comma.
       */
      std::vector<std::string>
      fields(const std::string &text, const FileContext &c, const unsigned int line)
      {
        const auto coarse = split(text, " \t;");
        if (coarse.size() >= 2)
          for (const auto &token : coarse)
            if (is_decimal_comma(token))
              throw_profile_error(c.file,
                                  line,
                                  "'" + token +
                                    "' has a decimal comma: write numbers with a decimal "
                                    "point (the columns may be separated by commas)",
                                  c.parameter);
        return split(text, " \t;,");
      }

      /** The point of one data line [m]; `header` is whether a header may come. */
      bool
      parse_line(const std::string                   &text,
                 const FileContext                   &c,
                 const unsigned int                   line,
                 const bool                           header_allowed,
                 std::vector<internal::ProfilePoint> &points)
      {
        const auto          tokens = fields(text, c, line);
        std::vector<double> numbers;
        std::string         word;
        for (const auto &token : tokens)
          {
            double value;
            if (parse_number(token, value))
              numbers.push_back(value);
            else if (word.empty())
              word = token;
          }
        if (numbers.empty() && header_allowed)
          return false; // the header line
        if (!word.empty())
          throw_profile_error(c.file,
                              line,
                              "'" + word + "' is not a number" +
                                (numbers.empty() ? " (a header of words is allowed only as the "
                                                   "first line that is not a comment)" :
                                                   ""),
                              c.parameter);
        if (numbers.size() != 2)
          throw_profile_error(c.file,
                              line,
                              std::to_string(numbers.size()) +
                                (numbers.size() == 1 ? " number" : " numbers") +
                                " where two (y z in mm) are expected",
                              c.parameter);
        if (!std::isfinite(numbers[0]) || !std::isfinite(numbers[1]))
          throw_profile_error(c.file, line, "'" + text + "' is not finite", c.parameter);
        points.push_back({numbers[0] * 1e-3, numbers[1] * 1e-3, line});
        return true;
      }

      /** Throws unless @p path names a readable regular file (named
       *  c.file in the messages). */
      void
      check_file(const std::string &path, const FileContext &c)
      {
        namespace fs = std::filesystem;
        std::error_code error;
        if (path.empty())
          throw_profile_error("(no file)", 0, "no profile file given", c.parameter);
        if (fs::is_directory(path, error))
          throw_profile_error(c.file, 0, "is a directory, not a profile file", c.parameter);
        if (!fs::exists(path, error))
          throw_profile_error(c.file, 0, "no such file", c.parameter);
      }
    } // namespace



    std::shared_ptr<SplineProfile>
    SplineProfile::read(const std::string &filename, const ProfileReadOptions &options)
    {
      const std::string &shown = options.name.empty() ? filename : options.name;
      const FileContext  c{shown, options.parameter};
      check_file(filename, c);
      std::ifstream in(filename);
      if (!in)
        throw_profile_error(shown, 0, "cannot be opened for reading", options.parameter);

      std::vector<internal::ProfilePoint> points;
      std::string                         text;
      bool                                content_seen = false;
      for (unsigned int line = 1; std::getline(in, text); ++line)
        {
          const std::size_t begin = text.find_first_not_of(" \t\r\v\f");
          if (begin == std::string::npos || text[begin] == '#' || text[begin] == '%')
            continue;
          text = text.substr(begin, text.find_last_not_of(" \t\r\v\f") + 1 - begin);
          parse_line(text, c, line, !content_seen, points);
          content_seen = true;
        }
      if (in.bad())
        throw_profile_error(shown, 0, "could not be read to its end", options.parameter);
      if (points.empty())
        throw_profile_error(shown,
                            0,
                            "contains no points (two columns y z in mm)",
                            options.parameter);
      return build(std::move(points), options, shown);
    }
  } // namespace Geometry
} // namespace WheelRail
