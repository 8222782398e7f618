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

#include <string>
#include <utility>
#include <vector>

namespace WheelRail
{
  namespace ParameterFile
  {
    /**
     * A parameter file with its includes expanded in place.
     *
     * Rules (README, "Parameter files"): an `include FILE` line is replaced
     * by FILE's lines; a relative FILE is read relative to the directory of
     * the file that includes it (never the working directory); a file that
     * includes itself directly or through others, a directory, a missing or
     * unreadable file, an unbalanced subsection/end in one file and a case
     * file without any entry are errors. A UTF-8 byte-order mark and
     * carriage returns at line ends (files saved on Windows) are removed.
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
       * @p message with every "Line <N> of file <TOP" of the expanded text
       * replaced by the file and line that line came from.
       */
      std::string
      locate(const std::string &message) const;

    private:
      void
      read(const std::string &filename, std::vector<std::string> &chain, unsigned int depth);

      std::string                                       top;
      std::string                                       expanded;
      std::vector<std::pair<std::string, unsigned int>> origin; // of each expanded line
    };

    /**
     * Reads @p filename with its includes into @p prm; a parser error is
     * rethrown with the file and line it comes from.
     */
    void
    parse(dealii::ParameterHandler &prm, const std::string &filename);
  } // namespace ParameterFile
} // namespace WheelRail

#endif
