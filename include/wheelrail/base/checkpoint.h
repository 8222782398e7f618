/**
 * @file checkpoint.h
 * Binary checkpoint streams: each rank writes the state it owns (vectors,
 * contact and friction state, axle, statistics) in a fixed order and reads
 * it back in the same order. Only trivially copyable values and vectors of
 * them go in raw; a restart needs the same executable and rank count.
 *
 * A rank file is: the magic number, the Header (rank count, mesh size,
 * step, time, time step and every parameter with its value), the state,
 * and a trailer (the number of bytes before it, their CRC-32, an end
 * marker). verify() checks the trailer before anything is read, so that a
 * damaged, truncated or older file stops a resumed run naming the file;
 * compare_parameters() says which entries differ from the run that wrote
 * the checkpoint, and which of them may (EntryFlag::resumable).
 */
#ifndef wheelrail_checkpoint_h
#define wheelrail_checkpoint_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>

#include <boost/crc.hpp>

#include <cstdint>
#include <fstream>
#include <istream>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

namespace WheelRail
{
  namespace Checkpoint
  {
    /** First 8 bytes of a rank file of the current format ("whlrchp5"). */
    constexpr std::uint64_t magic = 0x77686c7263687035ull;
    /** ... of the formats before: without the checksum and parameter
     *  record ("whlrchp1"); without the contact patch's window means
     *  ("whlrchp2"); without the friction state of the contact nodes
     *  ("whlrchp3"); without the sampled dissipation of the nodal damping
     *  ("whlrchp4"). */
    constexpr std::uint64_t magic_version_1 = 0x77686c7263687031ull;
    constexpr std::uint64_t magic_version_2 = 0x77686c7263687032ull;
    constexpr std::uint64_t magic_version_3 = 0x77686c7263687033ull;
    constexpr std::uint64_t magic_version_4 = 0x77686c7263687034ull;
    /** Last 8 bytes of a complete rank file ("whlrend2"). */
    constexpr std::uint64_t end_marker = 0x77686c72656e6432ull;
    /** Bytes of the trailer: payload size, CRC-32 (as 8 bytes), end marker. */
    constexpr std::uint64_t trailer_size = 24;

    /** Appends values to a binary stream and keeps the CRC-32 of all
     *  bytes written; finish() appends the trailer.
     *
     *  Writer and Reader have the same member functions (pod, vector,
     *  string, array), so that an object's checkpoint is one
     *  `template <class Archive> void serialize(Archive &ar)` that lists
     *  its fields once, for both directions; `Archive::is_loading` tells
     *  it which one runs (e.g. to rebuild derived data after reading). */
    class Writer
    {
    public:
      static constexpr bool is_loading = false;

      explicit Writer(std::ostream &out)
        : out(out)
      {}

      template <typename T>
      void
      pod(const T &value)
      {
        static_assert(std::is_trivially_copyable_v<T>, "raw values only");
        write(reinterpret_cast<const char *>(&value), sizeof(T));
      }

      template <typename T>
      void
      vector(const std::vector<T> &values)
      {
        static_assert(std::is_trivially_copyable_v<T>, "raw values only");
        pod<std::uint64_t>(values.size());
        write(reinterpret_cast<const char *>(values.data()), values.size() * sizeof(T));
      }

      void
      string(const std::string &s)
      {
        pod<std::uint64_t>(s.size());
        write(s.data(), s.size());
      }

      /** Raw array of @p n values (e.g. the owned part of a vector). */
      void
      array(const double *values, const std::uint64_t n)
      {
        pod(n);
        write(reinterpret_cast<const char *>(values), n * sizeof(double));
      }

      /** Append the trailer (size and CRC-32 of everything written so
       *  far, end marker); nothing may be written after it. */
      void
      finish()
      {
        const std::uint64_t trailer[3] = {bytes, crc.checksum(), end_marker};
        out.write(reinterpret_cast<const char *>(trailer), sizeof(trailer));
      }

      bool
      good() const
      {
        return out.good();
      }

    private:
      void
      write(const char *data, const std::uint64_t n)
      {
        out.write(data, n);
        crc.process_bytes(data, n);
        bytes += n;
      }

      std::ostream      &out;
      boost::crc_32_type crc;
      std::uint64_t      bytes = 0;
    };

    /** Reads values in the order a Writer wrote them. */
    class Reader
    {
    public:
      static constexpr bool is_loading = true;

      Reader(std::istream &in, const std::string &name)
        : in(in)
        , name(name)
      {}

      template <typename T>
      void
      pod(T &value)
      {
        static_assert(std::is_trivially_copyable_v<T>, "raw values only");
        in.read(reinterpret_cast<char *>(&value), sizeof(T));
        check();
      }

      template <typename T>
      void
      vector(std::vector<T> &values)
      {
        std::uint64_t n = 0;
        pod(n);
        AssertThrow(n < (std::uint64_t(1) << 40),
                    dealii::ExcMessage("The checkpoint " + name + " is corrupt."));
        values.resize(n);
        in.read(reinterpret_cast<char *>(values.data()), n * sizeof(T));
        check();
      }

      void
      string(std::string &s)
      {
        std::uint64_t n = 0;
        pod(n);
        AssertThrow(n < (std::uint64_t(1) << 40),
                    dealii::ExcMessage("The checkpoint " + name + " is corrupt."));
        s.resize(n);
        in.read(s.data(), n);
        check();
      }

      /** An array written by Writer::array() into @p values of size @p n. */
      void
      array(double *values, const std::uint64_t n)
      {
        std::uint64_t stored = 0;
        pod(stored);
        AssertThrow(stored == n,
                    dealii::ExcMessage("The checkpoint " + name +
                                       " does not fit this run (vector of " +
                                       std::to_string(stored) + " entries, expected " +
                                       std::to_string(n) + "): another mesh or rank count?"));
        in.read(reinterpret_cast<char *>(values), n * sizeof(double));
        check();
      }

      /** The file read, for messages. */
      const std::string &
      file_name() const
      {
        return name;
      }

    private:
      void
      check() const
      {
        AssertThrow(in.good(),
                    dealii::ExcMessage("The checkpoint " + name + " ends early (truncated?)."));
      }

      std::istream     &in;
      const std::string name;
    };

    /** What a rank file records before the state. */
    struct Header
    {
      unsigned int                     ranks     = 0;
      dealii::types::global_cell_index cells     = 0;
      dealii::types::global_dof_index  dofs      = 0;
      unsigned long                    step      = 0;
      double                           time      = 0;
      double                           time_step = 0;
      /** Every parameter as ParameterHandler::ShortPRM prints it. */
      std::string parameters;

      /** The fields after the magic number, for Writer and Reader. */
      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar.pod(ranks);
        ar.pod(cells);
        ar.pod(dofs);
        ar.pod(step);
        ar.pod(time);
        ar.pod(time_step);
        ar.string(parameters);
      }
    };

    /** Write the magic number and @p header. */
    void
    write_header(Writer &out, const Header &header);

    /** Write the rank file @p name: @p header, what @p body(Writer &)
     *  writes, the magic number and the trailer. Returns whether the file
     *  is good after the flush (false: disk full or no permission). */
    template <class Body>
    bool
    write_rank_file(const std::string &name, const Header &header, Body &&body)
    {
      std::ofstream file(name, std::ios::binary);
      Writer        out(file);
      write_header(out, header);
      body(out);
      out.pod(magic);
      out.finish();
      file.flush();
      return file.good();
    }

    /** Read what write_header() wrote (the magic number is checked). */
    Header
    read_header(Reader &in, const std::string &name);

    /** Check the rank file @p name before it is read: it exists, has the
     *  current format, is complete and its CRC-32 matches. Returns an
     *  empty string, or the reason naming the file. */
    std::string
    verify(const std::string &name);

    /** The entries of ParameterHandler::ShortPRM text as
     *  "Section/Subsection/Entry" -> value. */
    std::map<std::string, std::string>
    parameter_entries(const std::string &short_prm);

    /** One entry whose value differs. */
    struct Change
    {
      std::string entry, old_value, new_value;
    };

    /** Differences between the parameter records @p old_record and
     *  @p new_record (ShortPRM text): @p allowed gets those listed in
     *  @p may_differ, @p refused all others (an entry present in only one
     *  of them has the value "(not declared)" in the other). */
    void
    compare_parameters(const std::string           &old_record,
                       const std::string           &new_record,
                       std::vector<Change>         &allowed,
                       std::vector<Change>         &refused,
                       const std::set<std::string> &may_differ);

    /** The file of rank @p rank in the state directory @p directory. */
    std::string
    rank_file(const std::string &directory, const unsigned int rank);

    /** What read_rank_header() found. */
    struct RankHeader
    {
      Header       header;         ///< of this rank's file (if no error)
      std::string  error;          ///< why this rank's file cannot be read, naming it
      unsigned int ranks_of_0 = 0; ///< rank count in rank 0's file, 0 if unreadable
    };

    /** verify() this rank's file in @p directory and read its header; the
     *  rank count that rank 0's file gives (a state written by another
     *  rank count is refused for that before anything else). */
    RankHeader
    read_rank_header(const std::string &directory, MPI_Comm comm);
  } // namespace Checkpoint
} // namespace WheelRail

#endif
