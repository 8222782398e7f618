/**
 * @file parameters/parameter_file.h
 * Reading a parameter file: the file and the files it includes, checked
 * and expanded into one text for deal.II's ParameterHandler, with the origin
 * of every line so that parser messages name the file and line the user
 * wrote.
 */
#ifndef wheelrail_parameters_parameter_file_h
#define wheelrail_parameters_parameter_file_h

#include <deal.II/base/parameter_handler.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace WheelRail
{
  namespace ParameterFile
  {
    /** The longest line a parameter file may hold, in bytes (64 KiB). */
    constexpr std::size_t max_line_length = 65536;

    /**
     * @p text with terminal control characters (C0 but tab and newline,
     * DEL, C1 and bytes that are no UTF-8) written as \xNN, so that echoing
     * what a user wrote cannot drive the terminal.
     */
    std::string
    printable(const std::string &text);

    /**
     * A parameter file with its includes expanded in place.
     *
     * Rules (README, "Parameter files"): an `include FILE` line is replaced
     * by FILE's lines; a relative FILE is read relative to the directory of
     * the file that includes it (never the working directory); a file that
     * includes itself directly or through others, a directory, a missing or
     * unreadable file, a symbolic link loop, an unbalanced subsection/end in
     * one file, a case file without any entry, a line longer than
     * max_line_length, a read that fails, a line continued with '\' past the
     * end of its file and an entry set twice in one file to different values
     * (a file may override an entry of a file it includes) are errors. A UTF-8
     * byte-order mark is removed; a line ends at LF, CR LF or a lone CR; a
     * tab separates words as a space does.
     */
    class ExpandedText
    {
    public:
      /** Reads @p filename and everything it includes. */
      explicit ExpandedText(const std::string &filename);

      /** The expanded text, one line per line of the files read. */
      const std::string &
      text() const
      {
        return expanded;
      }

      /**
       * The directory of the file whose line sets @p entry in subsection
       * @p section ("Geometry/Profiles"), the last such line winning; the
       * directory of the file read where no line sets it. A file name
       * given by an entry is read relative to it, as an include is.
       */
      std::string
      directory_of(const std::string &section, const std::string &entry) const;

      /**
       * @p message with every "Line <N> of file <TOP" of the expanded text
       * replaced by the file and line that line came from.
       */
      std::string
      locate(const std::string &message) const;

    private:
      /**
       * Reads @p filename (an include @p depth levels down; @p chain: the
       * files that include it, as canonical paths) line by line: each
       * statement is checked and kept, each include line is replaced by
       * the included file's lines.
       */
      void
      read(const std::string &filename, std::vector<std::string> &chain, unsigned int depth);

      /** Appends @p line, line @p number of @p filename, to the expanded
       *  text and its origin; running out of memory is an error. */
      void
      keep(const std::string &line, const std::string &filename, unsigned int number);

      /**
       * Reads the file @p target of "include TARGET" on line @p number of
       * @p filename (relative to its directory) in its place; a cycle of
       * includes and more than max_include_depth nested ones are errors.
       * A message of the included file without a line gets this line.
       */
      void
      include(const std::string        &target,
              const std::string        &filename,
              unsigned int              number,
              std::vector<std::string> &chain,
              unsigned int              depth);

      std::string                                       top;
      std::string                                       expanded;
      std::vector<std::pair<std::string, unsigned int>> origin; // of each expanded line
    };

    /**
     * Reads @p filename with its includes into @p prm; a parser error is
     * rethrown with the file and line it comes from.
     */
    ExpandedText
    parse(dealii::ParameterHandler &prm, const std::string &filename);
  } // namespace ParameterFile
} // namespace WheelRail

#endif
