#include <deal.II/base/mpi.h>

#include <wheelrail/base/checkpoint.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace WheelRail
{
  namespace Checkpoint
  {
    void
    write_header(Writer &out, const Header &header)
    {
      out.pod(magic);
      Header fields = header;
      fields.serialize(out);
    }



    Header
    read_header(Reader &in, const std::string &name)
    {
      std::uint64_t first = 0;
      in.pod(first);
      AssertThrow(first == magic,
                  dealii::ExcMessage("'" + name + "' is not a wheelrail checkpoint."));
      Header header;
      header.serialize(in);
      return header;
    }



    std::string
    verify(const std::string &name)
    {
      std::ifstream file(name, std::ios::binary);
      if (!file.good())
        return "no checkpoint file '" + name + "'";
      file.seekg(0, std::ios::end);
      const std::streamoff size = file.tellg();
      file.seekg(0);
      std::uint64_t first = 0;
      if (size >= std::streamoff(sizeof(first)))
        file.read(reinterpret_cast<char *>(&first), sizeof(first));
      if (first == magic_version_1 || first == magic_version_2 || first == magic_version_3 ||
          first == magic_version_4)
        return "the checkpoint file '" + name + "' has an older format (" +
               (first == magic_version_1 ? "no checksum, no parameter record" :
                first == magic_version_2 ? "no contact-patch window means" :
                first == magic_version_3 ? "no friction state" :
                                           "no sampled nodal damping") +
               ") that this wheelrail cannot resume: run the case again from the start";
      if (size < std::streamoff(sizeof(first)) || first != magic)
        return "'" + name + "' is not a wheelrail checkpoint file";
      if (size < std::streamoff(sizeof(first) + trailer_size))
        return "the checkpoint file '" + name + "' is truncated (" + std::to_string(size) +
               " bytes)";
      std::uint64_t trailer[3] = {0, 0, 0};
      file.seekg(size - std::streamoff(trailer_size));
      file.read(reinterpret_cast<char *>(trailer), sizeof(trailer));
      if (!file.good() || trailer[2] != end_marker ||
          trailer[0] != std::uint64_t(size) - trailer_size)
        return "the checkpoint file '" + name + "' is truncated or incomplete (" +
               std::to_string(size) +
               " bytes, no valid end marker): the run that wrote it "
               "stopped while writing, or the file was cut";
      // the CRC-32 of the payload, read in blocks
      file.seekg(0);
      boost::crc_32_type crc;
      std::vector<char>  buffer(1 << 20);
      for (std::uint64_t left = trailer[0]; left > 0;)
        {
          const std::uint64_t n = std::min<std::uint64_t>(left, buffer.size());
          file.read(buffer.data(), n);
          if (!file.good())
            return "cannot read the checkpoint file '" + name + "'";
          crc.process_bytes(buffer.data(), n);
          left -= n;
        }
      if (crc.checksum() != trailer[1])
        return "the checkpoint file '" + name +
               "' is damaged: its CRC-32 checksum does not match its content";
      return "";
    }



    std::map<std::string, std::string>
    parameter_entries(const std::string &short_prm)
    {
      const auto trim = [](const std::string &s) {
        const auto first = s.find_first_not_of(" \t");
        if (first == std::string::npos)
          return std::string();
        return s.substr(first, s.find_last_not_of(" \t") - first + 1);
      };
      std::map<std::string, std::string> entries;
      std::vector<std::string>           path;
      std::istringstream                 lines(short_prm);
      for (std::string line; std::getline(lines, line);)
        {
          line = trim(line);
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(trim(line.substr(11)));
          else if (line == "end")
            {
              if (!path.empty())
                path.pop_back();
            }
          else if (line.rfind("set ", 0) == 0)
            {
              // entry names have no '='; values may have
              const auto  equal = line.find('=');
              std::string key;
              for (const auto &section : path)
                key += section + "/";
              key += trim(line.substr(4, equal - 4));
              entries[key] = equal == std::string::npos ? "" : trim(line.substr(equal + 1));
            }
        }
      return entries;
    }



    namespace
    {
      /** Whether two values of an entry mean the same: equal text, or the
       *  same numbers in a comma-separated list (2.1e11 = 210e9). */
      bool
      same_value(const std::string &a, const std::string &b)
      {
        if (a == b)
          return true;
        const auto split = [](const std::string &s) {
          std::vector<std::string> items;
          std::istringstream       stream(s);
          for (std::string item; std::getline(stream, item, ',');)
            {
              const auto first = item.find_first_not_of(" \t");
              items.push_back(first == std::string::npos ?
                                std::string() :
                                item.substr(first, item.find_last_not_of(" \t") - first + 1));
            }
          return items;
        };
        const auto number = [](const std::string &s, double &x) {
          try
            {
              std::size_t end = 0;
              x               = std::stod(s, &end);
              return end == s.size();
            }
          catch (...)
            {
              return false;
            }
        };
        const auto items_a = split(a), items_b = split(b);
        if (items_a.size() != items_b.size())
          return false;
        for (std::size_t i = 0; i < items_a.size(); ++i)
          {
            double x = 0, y = 0;
            if (items_a[i] != items_b[i] &&
                !(number(items_a[i], x) && number(items_b[i], y) && x == y))
              return false;
          }
        return true;
      }
    } // namespace



    void
    compare_parameters(const std::string           &old_record,
                       const std::string           &new_record,
                       std::vector<Change>         &allowed,
                       std::vector<Change>         &refused,
                       const std::set<std::string> &may_differ)
    {
      const auto            old_entries = parameter_entries(old_record);
      const auto            new_entries = parameter_entries(new_record);
      std::set<std::string> keys;
      for (const auto &e : old_entries)
        keys.insert(e.first);
      for (const auto &e : new_entries)
        keys.insert(e.first);
      const std::string none = "(not declared)";
      for (const auto &key : keys)
        {
          const auto        o = old_entries.find(key), n = new_entries.find(key);
          const std::string old_value = o == old_entries.end() ? none : o->second;
          const std::string new_value = n == new_entries.end() ? none : n->second;
          if (same_value(old_value, new_value))
            continue;
          (may_differ.count(key) ? allowed : refused).push_back({key, old_value, new_value});
        }
    }



    std::string
    rank_file(const std::string &directory, const unsigned int rank)
    {
      return directory + "/rank_" + std::to_string(rank) + ".bin";
    }



    RankHeader
    read_rank_header(const std::string &directory, MPI_Comm comm)
    {
      RankHeader        r;
      const std::string name = rank_file(directory, dealii::Utilities::MPI::this_mpi_process(comm));
      r.error                = verify(name);
      if (r.error.empty())
        {
          std::ifstream file(name, std::ios::binary);
          Reader        in(file, name);
          r.header = read_header(in, name);
        }
      r.ranks_of_0 =
        dealii::Utilities::MPI::broadcast(comm, r.error.empty() ? r.header.ranks : 0u, 0);
      return r;
    }
  } // namespace Checkpoint
} // namespace WheelRail
