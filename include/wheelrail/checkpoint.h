/**
 * @file checkpoint.h
 * Binary checkpoint streams: each rank writes the state it owns (vectors,
 * contact and friction state, axle, statistics) in a fixed order and reads
 * it back in the same order. Only trivially copyable values and vectors of
 * them go in raw; a restart needs the same executable and rank count (the
 * header records them and read_header() checks).
 */
#ifndef wheelrail_checkpoint_h
#define wheelrail_checkpoint_h

#include <deal.II/base/exceptions.h>

#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace WheelRail
{
  namespace Checkpoint
  {
    /** Appends values to a binary stream. */
    class Writer
    {
    public:
      explicit Writer(std::ostream &out)
        : out(out)
      {}

      template <typename T>
      void
      pod(const T &value)
      {
        static_assert(std::is_trivially_copyable_v<T>, "raw values only");
        out.write(reinterpret_cast<const char *>(&value), sizeof(T));
      }

      template <typename T>
      void
      vector(const std::vector<T> &values)
      {
        static_assert(std::is_trivially_copyable_v<T>, "raw values only");
        pod<std::uint64_t>(values.size());
        out.write(reinterpret_cast<const char *>(values.data()), values.size() * sizeof(T));
      }

      void
      string(const std::string &s)
      {
        pod<std::uint64_t>(s.size());
        out.write(s.data(), s.size());
      }

      /** Raw array of @p n values (e.g. the owned part of a vector). */
      void
      array(const double *values, const std::uint64_t n)
      {
        pod(n);
        out.write(reinterpret_cast<const char *>(values), n * sizeof(double));
      }

      bool
      good() const
      {
        return out.good();
      }

    private:
      std::ostream &out;
    };

    /** Reads values in the order a Writer wrote them. */
    class Reader
    {
    public:
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

    private:
      void
      check() const
      {
        AssertThrow(in.good(),
                    dealii::ExcMessage("The checkpoint " + name + " ends early (truncated?)."));
      }

      std::istream &    in;
      const std::string name;
    };
  } // namespace Checkpoint
} // namespace WheelRail

#endif
