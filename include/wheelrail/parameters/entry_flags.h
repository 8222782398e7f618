/**
 * @file parameters/entry_flags.h
 * What a parameter entry allows, marked beside its declaration: whether a
 * resumed run may change it, and whether the static start of the wheelset
 * does not depend on it. The lists that the resume and the static start's
 * reuse check against are derived from these marks.
 */
#ifndef wheelrail_parameters_entry_flags_h
#define wheelrail_parameters_entry_flags_h

#include <set>
#include <string>

namespace WheelRail
{
  /** A property of a parameter entry. */
  enum class EntryFlag : unsigned
  {
    /** A resumed run may change it: it changes what is written, where the
     *  run stops and the verdict thresholds, not the state that is
     *  integrated (nor its recorded history). */
    resumable = 1u << 0,
    /** The static start of the wheelset (Wheelset/Static start state)
     *  does not depend on it: what acts only once the wheel rolls
     *  (friction, creepage and torque control, run-up damping, initial
     *  velocities) and what is only recorded. Every resumable entry is
     *  also static-start free. */
    static_start_free = 1u << 1
  };

  /**
   * The marks of one subsection's entries, made in its declare_parameters()
   * right after each entry is declared:
   *
   *   prm.enter_subsection("Output");
   *   const EntryFlags flags("Output");
   *   prm.declare_entry("VTU interval", ...);
   *   flags.mark("VTU interval", EntryFlag::resumable);
   */
  class EntryFlags
  {
  public:
    /** The subsection's path from the top, "/"-separated
     *  ("Geometry/Wheel"). */
    explicit EntryFlags(std::string section);

    /** Mark entry @p name of this subsection with @p flag. */
    const EntryFlags &
    mark(const std::string &name, EntryFlag flag) const;

    /**
     * The paths ("Output/VTU interval") of every entry marked with @p flag,
     * sorted: the parameters' declarations (Parameters::declare_parameters)
     * run once into a handler of their own to collect them.
     */
    static const std::set<std::string> &
    entries(EntryFlag flag);

    /** The paths marked with @p flag by the declarations that have run so
     *  far (entries() before its first call completes, e.g. within the
     *  declarations themselves). */
    static std::set<std::string>
    marked(EntryFlag flag);

  private:
    const std::string section;
  };
} // namespace WheelRail

#endif
