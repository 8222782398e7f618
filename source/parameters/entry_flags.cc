/**
 * @file parameters/entry_flags.cc
 * The marks of the parameter entries and the lists derived from them.
 */

#include <deal.II/base/parameter_handler.h>

#include <wheelrail/parameters/entry_flags.h>
#include <wheelrail/parameters/parameters.h>

#include <map>

namespace WheelRail
{
  namespace
  {
    /** Every mark made, by the entry's path. */
    std::map<std::string, unsigned int> &
    marks()
    {
      static std::map<std::string, unsigned int> flags;
      return flags;
    }
  } // namespace



  EntryFlags::EntryFlags(std::string section)
    : section(std::move(section))
  {}



  const EntryFlags &
  EntryFlags::mark(const std::string &name, const EntryFlag flag) const
  {
    unsigned int bits = static_cast<unsigned int>(flag);
    if (flag == EntryFlag::resumable)
      bits |= static_cast<unsigned int>(EntryFlag::static_start_free);
    marks()[section + "/" + name] |= bits;
    return *this;
  }



  std::set<std::string>
  EntryFlags::marked(const EntryFlag flag)
  {
    std::set<std::string> paths;
    for (const auto &[path, bits] : marks())
      if (bits & static_cast<unsigned int>(flag))
        paths.insert(path);
    return paths;
  }



  const std::set<std::string> &
  EntryFlags::entries(const EntryFlag flag)
  {
    static const bool declared = [] {
      dealii::ParameterHandler prm;
      Parameters::declare_parameters(prm);
      return true;
    }();
    (void)declared;
    static const std::set<std::string> resumable         = marked(EntryFlag::resumable);
    static const std::set<std::string> static_start_free = marked(EntryFlag::static_start_free);
    return flag == EntryFlag::resumable ? resumable : static_start_free;
  }
} // namespace WheelRail
