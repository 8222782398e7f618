#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/parameters/parameter_file.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace WheelRail
{
  namespace ParameterFile
  {
    using namespace dealii;

    namespace
    {
      /** Include depth beyond which a chain of includes is refused. */
      constexpr unsigned int max_include_depth = 32;

      /**
       * The line as deal.II's parser sees its start: without the comment
       * (from an unescaped '#') and the surrounding white space.
       */
      std::string
      statement(const std::string &line)
      {
        std::string::size_type hash = 0;
        while ((hash = line.find('#', hash)) != std::string::npos && hash > 0 &&
               line[hash - 1] == '\\')
          ++hash;
        return Utilities::trim(line.substr(0, hash));
      }

      /** The target of an "include FILE" statement, or "" if none. */
      std::string
      include_target(const std::string &statement)
      {
        for (const char *keyword : {"include", "INCLUDE"})
          {
            const std::string k(keyword);
            if (statement.size() > k.size() && statement.compare(0, k.size(), k) == 0 &&
                std::isspace(static_cast<unsigned char>(statement[k.size()])))
              return Utilities::trim(statement.substr(k.size()));
          }
        return "";
      }

      std::string
      where(const std::string &file, const unsigned int line)
      {
        return "Line <" + std::to_string(line) + "> of file <" + file + ">: ";
      }
    } // namespace



    ExpandedText::ExpandedText(const std::string &filename)
      : top(filename)
    {
      std::vector<std::string> chain;
      read(filename, chain, 0);
      bool               sets_something = false;
      std::istringstream lines(expanded);
      for (std::string line; std::getline(lines, line) && !sets_something;)
        {
          const std::string s = statement(line);
          sets_something      = s.compare(0, 4, "set ") == 0 || s.compare(0, 4, "SET ") == 0;
        }
      AssertThrow(sets_something,
                  ExcMessage("The parameter file '" + filename +
                             "' sets no parameter (it is empty or holds only comments and "
                             "subsections); write the entries that differ from the defaults, "
                             "e.g. starting from a copy of prm/default.prm."));
    }



    void
    ExpandedText::read(const std::string        &filename,
                       std::vector<std::string> &chain,
                       const unsigned int        depth)
    {
      const std::string           who = chain.empty() ? "The parameter file '" + filename + "'" :
                                                        "The included file '" + filename + "'";
      std::error_code             ec;
      const std::filesystem::path path(filename);
      const std::filesystem::file_status status = std::filesystem::status(path, ec);
      AssertThrow(std::filesystem::exists(status),
                  ExcMessage(who + " does not exist" +
                             (chain.empty() ? std::string(".") :
                                              std::string(" (a relative include is read from the "
                                                          "directory of the file that includes "
                                                          "it)."))));
      AssertThrow(!std::filesystem::is_directory(status),
                  ExcMessage(who + " is a directory, not a parameter file."));
      AssertThrow(std::filesystem::is_regular_file(status),
                  ExcMessage(who + " is not a regular file."));
      std::ifstream in(filename, std::ios::binary);
      AssertThrow(in.good(), ExcMessage(who + " cannot be opened (no read permission?)."));

      const std::string canonical = std::filesystem::weakly_canonical(path, ec).string();
      chain.push_back(canonical);
      const std::filesystem::path directory = path.parent_path();

      int          open_subsections = 0;
      unsigned int number           = 0;
      bool         continued        = false; // the previous line ended in '\'
      for (std::string line; std::getline(in, line);)
        {
          ++number;
          if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
            line.erase(0, 3);
          if (!line.empty() && line.back() == '\r')
            line.pop_back();
          AssertThrow(line.find('\0') == std::string::npos,
                      ExcMessage(where(filename, number) +
                                 "a NUL byte: this is not a text parameter file."));

          const std::string s       = statement(line);
          const bool        is_cont = continued;
          const std::string trimmed = Utilities::trim(line);
          continued                 = !trimmed.empty() && trimmed.back() == '\\';
          const std::string target  = is_cont ? std::string() : include_target(s);
          if (target.empty())
            {
              if (!is_cont)
                {
                  if (s.compare(0, 11, "subsection ") == 0 || s.compare(0, 11, "SUBSECTION ") == 0)
                    ++open_subsections;
                  else if (s == "end" || s == "END")
                    {
                      AssertThrow(open_subsections > 0,
                                  ExcMessage(where(filename, number) +
                                             "'end' without a subsection to close."));
                      --open_subsections;
                    }
                }
              expanded += line;
              expanded += '\n';
              origin.emplace_back(filename, number);
              continue;
            }

          const std::filesystem::path t(target);
          const std::string           resolved =
            (t.is_absolute() || directory.empty()) ? target : (directory / t).string();
          const std::string resolved_canonical =
            std::filesystem::weakly_canonical(resolved, ec).string();
          for (unsigned int i = 0; i < chain.size(); ++i)
            if (chain[i] == resolved_canonical)
              {
                std::string cycle;
                for (unsigned int j = i; j < chain.size(); ++j)
                  cycle += std::filesystem::path(chain[j]).filename().string() + " -> ";
                AssertThrow(false,
                            ExcMessage(where(filename, number) + "'include " + target +
                                       "' closes a cycle of includes (" + cycle +
                                       std::filesystem::path(resolved).filename().string() +
                                       "): a file must not include itself."));
              }
          AssertThrow(depth + 1 < max_include_depth,
                      ExcMessage(where(filename, number) + "more than " +
                                 std::to_string(max_include_depth) + " nested includes."));
          try
            {
              read(resolved, chain, depth + 1);
            }
          catch (const ExceptionBase &e)
            {
              // a message without a place is about the included file as a
              // whole: it gets the place of the include line
              std::ostringstream info;
              e.print_info(info);
              const std::string text = Utilities::trim(info.str());
              AssertThrow(false,
                          ExcMessage(text.compare(0, 6, "Line <") == 0 ?
                                       text :
                                       where(filename, number) + "'include " + target +
                                         "': " + text));
            }
        }
      AssertThrow(open_subsections == 0,
                  ExcMessage(who + " leaves " + std::to_string(open_subsections) +
                             " subsection(s) without 'end'."));
      chain.pop_back();
    }



    std::string
    ExpandedText::locate(const std::string &message) const
    {
      const std::string key = "Line <";
      std::string       result;
      std::size_t       pos = 0;
      for (std::size_t hit; (hit = message.find(key, pos)) != std::string::npos;)
        {
          const std::size_t number_end = message.find('>', hit + key.size());
          const std::string file_key   = "> of file <" + top;
          if (number_end == std::string::npos ||
              message.compare(number_end, file_key.size(), file_key) != 0)
            {
              result += message.substr(pos, hit + key.size() - pos);
              pos = hit + key.size();
              continue;
            }
          unsigned int n = 0;
          try
            {
              n = Utilities::string_to_int(
                message.substr(hit + key.size(), number_end - hit - key.size()));
            }
          catch (...)
            {}
          result += message.substr(pos, hit - pos);
          if (n >= 1 && n <= origin.size())
            result +=
              "Line <" + std::to_string(origin[n - 1].second) + "> of file <" + origin[n - 1].first;
          else
            result += message.substr(hit, number_end + file_key.size() - hit);
          pos = number_end + file_key.size();
        }
      return result + message.substr(pos);
    }



    void
    parse(ParameterHandler &prm, const std::string &filename)
    {
      const ExpandedText file(filename);
      std::istringstream text(file.text());
      try
        {
          prm.parse_input(text, filename);
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          AssertThrow(false, ExcMessage(file.locate(info.str())));
        }
    }
  } // namespace ParameterFile
} // namespace WheelRail
