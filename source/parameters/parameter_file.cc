#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <wheelrail/parameters/parameter_file.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <new>
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

      /**
       * @p statement without @p keyword ("set ", "subsection ", in lower or
       * in upper case), or "" if it does not start with it.
       */
      std::string
      after_keyword(const std::string &statement, std::string keyword)
      {
        for (int upper = 0; upper < 2; ++upper)
          {
            if (statement.compare(0, keyword.size(), keyword) == 0)
              return Utilities::trim(statement.substr(keyword.size()));
            std::transform(keyword.begin(), keyword.end(), keyword.begin(), [](char c) {
              return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
            });
          }
        return "";
      }

      /** The target of an "include FILE" statement, or "" if none. */
      std::string
      include_target(const std::string &statement)
      {
        return after_keyword(statement, "include ");
      }

      std::string
      where(const std::string &file, const unsigned int line)
      {
        return "Line <" + std::to_string(line) + "> of file <" + file + ">: ";
      }

      /**
       * Reads the next line of @p in into @p line, without its end: a line
       * ends at LF, CR LF or a lone CR (files saved on Windows or old Macs).
       * Returns false at the end of the input with nothing read. Stores at
       * most max_line_length characters: @p too_long is set for a longer
       * line, and the rest of it is left unread. A failed read throws (the
       * file buffer reports it as std::ios_base::failure).
       */
      bool
      next_line(std::streambuf &in, std::string &line, bool &too_long)
      {
        using traits = std::char_traits<char>;
        line.clear();
        too_long = false;
        for (traits::int_type c = in.sbumpc();; c = in.sbumpc())
          {
            if (traits::eq_int_type(c, traits::eof()))
              return !line.empty();
            const char ch = traits::to_char_type(c);
            if (ch == '\n')
              return true;
            if (ch == '\r')
              {
                if (traits::eq_int_type(in.sgetc(), traits::to_int_type('\n')))
                  in.sbumpc();
                return true;
              }
            if (line.size() == max_line_length)
              {
                too_long = true;
                return true;
              }
            line += ch;
          }
      }

      /**
       * Checks that @p path names a readable regular file; @p who names it
       * in the messages.
       */
      void
      check_file(const std::filesystem::path &path, const std::string &who, const bool included)
      {
        std::error_code                    ec;
        const std::filesystem::file_status status = std::filesystem::status(path, ec);
        AssertThrow(ec != std::errc::too_many_symbolic_link_levels,
                    ExcMessage(who + " is a symbolic link that leads back to itself (a link to "
                                     "itself or a cycle of links), not a file."));
        if (status.type() == std::filesystem::file_type::not_found)
          {
            std::error_code link_ec;
            AssertThrow(!std::filesystem::is_symlink(
                          std::filesystem::symlink_status(path, link_ec)),
                        ExcMessage(who + " is a symbolic link to '" +
                                   std::filesystem::read_symlink(path, link_ec).string() +
                                   "', which does not exist."));
            AssertThrow(false,
                        ExcMessage(who + " does not exist" +
                                   (included ? std::string(" (a relative include is read from the "
                                                           "directory of the file that includes "
                                                           "it).") :
                                               std::string("."))));
          }
        AssertThrow(std::filesystem::status_known(status) &&
                      status.type() != std::filesystem::file_type::unknown,
                    ExcMessage(who + " cannot be reached: " + ec.message() + "."));
        AssertThrow(!std::filesystem::is_directory(status),
                    ExcMessage(who + " is a directory, not a parameter file."));
        AssertThrow(std::filesystem::is_regular_file(status),
                    ExcMessage(who + " is not a regular file."));
      }



      /**
       * Checks statement @p s (the line @p number of @p filename, comments
       * removed, continued lines joined): subsections open and close in
       * order (@p sections holds the open ones), and no entry is set twice
       * to different values (@p entries: the entries set so far, by full
       * name, with value and line).
       */
      void
      check_statement(const std::string                                           &s,
                      const std::string                                           &filename,
                      const unsigned int                                           number,
                      std::vector<std::string>                                    &sections,
                      std::map<std::string, std::pair<std::string, unsigned int>> &entries)
      {
        const std::string section = after_keyword(s, "subsection ");
        if (!section.empty())
          {
            sections.push_back(section);
            return;
          }
        if (s == "end" || s == "END")
          {
            AssertThrow(!sections.empty(),
                        ExcMessage(where(filename, number) +
                                   "'end' without a subsection to close."));
            sections.pop_back();
            return;
          }
        const std::string assignment = after_keyword(s, "set ");
        const std::size_t equals     = assignment.find('=');
        if (equals == std::string::npos)
          return; // deal.II's parser names what is wrong
        std::string name;
        for (const std::string &open : sections)
          name += open + "/";
        name += Utilities::trim(assignment.substr(0, equals));
        const std::string value      = Utilities::trim(assignment.substr(equals + 1));
        const auto [previous, first] = entries.emplace(name, std::make_pair(value, number));
        AssertThrow(first || previous->second.first == value,
                    ExcMessage(where(filename, number) + "'" + name + "' is set to '" + value +
                               "' here and to '" + previous->second.first + "' on line " +
                               std::to_string(previous->second.second) +
                               " of the same file: set each entry once in a file (a file may "
                               "override what a file it includes sets)."));
      }



      /**
       * Reads line @p number + 1 of @p filename from @p in into @p line as
       * next_line() does and counts it in @p number; returns false at the
       * end of the file. A failed read, a line longer than max_line_length
       * and a NUL byte are errors. The UTF-8 byte-order mark of the first
       * line is removed and a tab becomes a space (deal.II's parser reads it
       * as one too).
       */
      bool
      read_line(std::streambuf    &in,
                const std::string &filename,
                unsigned int      &number,
                std::string       &line)
      {
        bool too_long = false;
        try
          {
            if (!next_line(in, line, too_long))
              return false;
          }
        catch (const std::exception &e)
          {
            AssertThrow(false,
                        ExcMessage(where(filename, number + 1) + "reading the file failed (" +
                                   e.what() + ")."));
          }
        ++number;
        AssertThrow(!too_long,
                    ExcMessage(where(filename, number) + "the line is longer than " +
                               std::to_string(max_line_length) +
                               " characters, the most a parameter file's line may hold."));
        if (number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
          line.erase(0, 3);
        AssertThrow(line.find('\0') == std::string::npos,
                    ExcMessage(where(filename, number) +
                               "a NUL byte: this is not a text parameter file."));
        std::replace(line.begin(), line.end(), '\t', ' ');
        return true;
      }



      /**
       * The statements of one file as its lines come: a line ending in a
       * backslash joined with the next, and each complete statement checked by
       * check_statement() against the subsections open and the entries set
       * in this file.
       */
      class Statements
      {
      public:
        explicit Statements(const std::string &filename)
          : filename(filename)
        {}

        /** Whether a statement is continued from an earlier line. */
        bool
        continued() const
        {
          return joined_from > 0;
        }

        /** Adds line @p number, @p trimmed of white space; @p continues: it
         *  ends in a backslash, which is left out. */
        void
        add(const std::string &trimmed, const bool continues, const unsigned int number)
        {
          if (!continued())
            joined_from = number;
          joined += continues ? trimmed.substr(0, trimmed.size() - 1) : trimmed;
          if (!continues)
            {
              check_statement(statement(joined), filename, joined_from, sections, entries);
              joined.clear();
              joined_from = 0;
            }
        }

        /** At the end of the file (@p who names it): no statement
         *  continued past it, no subsection left open. */
        void
        finish(const std::string &who) const
        {
          AssertThrow(joined_from == 0,
                      ExcMessage(where(filename, joined_from) +
                                 "the statement is continued with '\\' past the end of the file."));
          AssertThrow(sections.empty(),
                      ExcMessage(who + " leaves " + std::to_string(sections.size()) +
                                 " subsection(s) without 'end'."));
        }

      private:
        const std::string       &filename;
        std::vector<std::string> sections; ///< the subsections open in this file
        /** The entries this file sets: full name -> value and line. */
        std::map<std::string, std::pair<std::string, unsigned int>> entries;
        std::string  joined;          ///< a statement continued over lines
        unsigned int joined_from = 0; ///< its first line
      };
    } // namespace



    std::string
    printable(const std::string &text)
    {
      static const char *const hex    = "0123456789abcdef";
      const auto               escape = [&](const unsigned char c) {
        return std::string("\\x") + hex[c >> 4] + hex[c & 15];
      };
      const auto continuation = [&](const std::size_t i, const unsigned char lo, unsigned char hi) {
        return i < text.size() && static_cast<unsigned char>(text[i]) >= lo &&
               static_cast<unsigned char>(text[i]) <= hi;
      };
      std::string result;
      for (std::size_t i = 0; i < text.size();)
        {
          const unsigned char c = text[i];
          if (c == '\t' || c == '\n' || (c >= 0x20 && c < 0x7f))
            {
              result += text[i++];
              continue;
            }
          // a well-formed UTF-8 character other than a C1 control (U+0080
          // to U+009F) is kept; anything else is escaped byte by byte
          std::size_t length = 0;
          if (c == 0xc2)
            length = continuation(i + 1, 0xa0, 0xbf) ? 2 : 0;
          else if (c >= 0xc3 && c <= 0xdf)
            length = continuation(i + 1, 0x80, 0xbf) ? 2 : 0;
          else if (c >= 0xe0 && c <= 0xef)
            length = continuation(i + 1, c == 0xe0 ? 0xa0 : 0x80, c == 0xed ? 0x9f : 0xbf) &&
                         continuation(i + 2, 0x80, 0xbf) ?
                       3 :
                       0;
          else if (c >= 0xf0 && c <= 0xf4)
            length = continuation(i + 1, c == 0xf0 ? 0x90 : 0x80, c == 0xf4 ? 0x8f : 0xbf) &&
                         continuation(i + 2, 0x80, 0xbf) && continuation(i + 3, 0x80, 0xbf) ?
                       4 :
                       0;
          if (length > 0)
            {
              result += text.substr(i, length);
              i += length;
            }
          else if (c == 0xc2 && continuation(i + 1, 0x80, 0x9f))
            {
              result += escape(c) + escape(text[i + 1]);
              i += 2;
            }
          else
            result += escape(text[i++]);
        }
      return result;
    }



    ExpandedText::ExpandedText(const std::string &filename)
      : top(filename)
    {
      std::vector<std::string> chain;
      read(filename, chain, 0);
      bool               sets_something = false;
      std::istringstream lines(expanded);
      for (std::string line; std::getline(lines, line) && !sets_something;)
        sets_something = !after_keyword(statement(line), "set ").empty();
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
      const std::filesystem::path path(filename);
      check_file(path, who, !chain.empty());
      std::ifstream in(filename, std::ios::binary);
      AssertThrow(in.is_open(), ExcMessage(who + " cannot be opened (no read permission?)."));

      std::error_code   ec;
      const std::string canonical = std::filesystem::weakly_canonical(path, ec).string();
      chain.push_back(canonical);

      Statements   statements(filename);
      unsigned int number = 0;
      for (std::string line; read_line(*in.rdbuf(), filename, number, line);)
        {
          const bool        is_cont   = statements.continued();
          const std::string trimmed   = Utilities::trim(line);
          const bool        continues = !trimmed.empty() && trimmed.back() == '\\';
          const std::string target =
            is_cont || continues ? std::string() : include_target(statement(line));
          if (target.empty())
            {
              statements.add(trimmed, continues, number);
              keep(line, filename, number);
            }
          else
            include(target, filename, number, chain, depth);
        }
      statements.finish(who);
      chain.pop_back();
    }



    void
    ExpandedText::keep(const std::string &line, const std::string &filename, unsigned int number)
    {
      try
        {
          expanded += line;
          expanded += '\n';
          origin.emplace_back(filename, number);
        }
      catch (const std::bad_alloc &)
        {
          AssertThrow(false,
                      ExcMessage(where(filename, number) +
                                 "out of memory for the parameter files' text."));
        }
    }



    void
    ExpandedText::include(const std::string        &target,
                          const std::string        &filename,
                          const unsigned int        number,
                          std::vector<std::string> &chain,
                          const unsigned int        depth)
    {
      const std::filesystem::path directory = std::filesystem::path(filename).parent_path();
      const std::filesystem::path t(target);
      const std::string           resolved =
        (t.is_absolute() || directory.empty()) ? target : (directory / t).string();
      std::error_code   ec;
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
                                   where(filename, number) + "'include " + target + "': " + text));
        }
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



    std::string
    ExpandedText::directory_of(const std::string &section, const std::string &entry) const
    {
      std::string              file = top;
      std::string              path; // the open subsections, "A/B"
      std::vector<std::string> sections;
      std::istringstream       lines(expanded);
      unsigned int             index = 0;
      for (std::string line; std::getline(lines, line); ++index)
        {
          const std::string s       = statement(line);
          const std::string opened  = after_keyword(s, "subsection ");
          const std::string setting = after_keyword(s, "set ");
          if (!opened.empty() || ((s == "end" || s == "END") && !sections.empty()))
            {
              if (!opened.empty())
                sections.push_back(opened);
              else
                sections.pop_back();
              path.clear();
              for (const std::string &name : sections)
                path += (path.empty() ? "" : "/") + name;
            }
          else if (!setting.empty() && setting.find('=') != std::string::npos &&
                   Utilities::trim(setting.substr(0, setting.find('='))) == entry &&
                   path == section)
            file = origin[index].first;
        }
      return std::filesystem::path(file).parent_path().string();
    }



    ExpandedText
    parse(ParameterHandler &prm, const std::string &filename)
    {
      ExpandedText       file(filename);
      std::istringstream text(file.text());
      try
        {
          prm.parse_input(text, filename);
        }
      catch (const ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          std::string message = file.locate(info.str());
          // deal.II 9.4's message on an unknown subsection leaves out the
          // '>' that closes the file name
          const std::string unknown = ": There is no such subsection";
          const auto        at      = message.find(unknown);
          const auto        open    = message.rfind("of file <", at);
          if (at != std::string::npos && open != std::string::npos && message.find('>', open) > at)
            message.insert(at, ">");
          AssertThrow(false, ExcMessage(message));
        }
      return file;
    }
  } // namespace ParameterFile
} // namespace WheelRail
