#pragma once
// runner/line: one headless run of a program for `ncsim sweep` / `ncsim tune-delay` and the
// accuracy benchmark: the pass of `time --audit`, with the world adjusted before it is built
// (RunSpec::adjust, wrap, conv_vel) and the channel shown to the caller after every cycle.

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "channel/channel.hpp"
#include "runner/spec.hpp"

namespace ncsim::runner {

struct LineOutcome {
  Exit status = Exit::ok;  ///< ok, program_errors (error), usage (load), audit
  std::string id;          ///< the error's id (run-time or program error), "" when none
  std::string error;       ///< the error's first line, or the audit's first violation
  double t_end = 0.0;      ///< [s] end of the last cycle
  std::uint64_t audit_violations = 0;
};

class Run;

/// The id of the error that ended `run` (its run-time error's, else its program source's or
/// interpreter's), "" when none.
std::string error_id(const Run& run);

/// Loads `spec` (the load's diagnostics on `err`) and runs it to its end, `on_cycle` (may be
/// empty) after every running cycle.
LineOutcome run_line(const RunSpec& spec,
                     const std::function<void(const channel::Channel&)>& on_cycle,
                     std::ostream& err);

/// The lines (main program) whose `#MACHINE DATA` sets parameter `id` ("P-AXIS-00626"), from a
/// decode-only pass of at most `max_commands` commands; empty when the program does not load.
std::vector<std::uint32_t> machine_data_lines(const ProgramSpec& program, std::string_view id,
                                              std::size_t max_commands = 100000);

}  // namespace ncsim::runner
