#pragma once
// ipo/program_source: the interpreter's command stream as an ipo::Source, and the machine's
// axis lists as the interpolator's Config.
//
// Purpose: the first end-to-end seam interp -> planner -> ipo (`ncsim time`, `ncsim run`).
// Inputs: an interp::Interpreter (pulled lazily), the machine it decodes for.
// Outputs: ipo::Item values (planner::Move / ipo::Dwell) in program order; Config with one
// AxisLimits and one ExactStop per interpolated axis (docs/ipo.md "From program to cycles").
// Method: Motion (rapid, linear, arc) in MCS becomes a Move in the interpolated-axis order; G04
// a Dwell; Tech, Message, ProgramStop (M00/M01 do not stop in time/run: no operator), Flush,
// WaitIndp, #CS selections and the switching-off forms of #TRAFO / #CAXTRACK pass; End ends
// the stream. Barriers are answered from the decode-only state (next_decode_only): run-time
// answers come with the channel loop. Every other command is a program error
// `not supported: <what>` (NC6001) at its line: nothing is skipped silently.
// Errors end the stream like End does, and error() holds the diagnostic: the blocks decoded
// before the faulty one run to their end and the path stops there, then the caller reports
// the error (the channel stops at the faulty block; docs/ipo.md). Memory: one Command.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "interp/interpreter.hpp"
#include "ipo/interpolator.hpp"
#include "machines/machine.hpp"

namespace ncsim::ipo {

/// Id of the adapter's `not supported: ...` program errors.
inline constexpr const char* kNotSupportedId = "NC6001";

/// Machine indices of the axes the path interpolator drives, in machine order: linear and
/// rotary axes; spindles, encoder-only axes and the conveyor axis are not interpolated.
std::vector<std::uint8_t> interpolated_axes(const machines::Machine& machine);

/// The interpolator Config of `machine` (docs/ipo.md "Machine limits"): per interpolated axis
/// v_max P-AXIS-00212, v_reference = v_max (no ISG key), v_rapid P-AXIS-00209,
/// A+ = min(P-AXIS-00001, P-AXIS-00008), A- = min(P-AXIS-00002, P-AXIS-00008),
/// J = Dynamics::jerk_feed(), C0 NCSIM-AXIS-020; ExactStop window P-AXIS-00236, settling
/// P-AXIS-00532 (0 when not monitored); window P-CHAN-00650 look-ahead blocks; cycle `t_cycle`
/// [s] (the channel list has no cycle key in ncsim yet: the CLI's default is 1 ms).
Config machine_config(const machines::Machine& machine, double t_cycle);

class ProgramSource final : public Source {
 public:
  /// `interp` and `machine` must outlive the source. Throws std::invalid_argument when the
  /// machine has no interpolated axis.
  ProgramSource(interp::Interpreter& interp, const machines::Machine& machine);

  /// The next Move or Dwell; false at End or at a program error (error() then holds it).
  bool next(Item& out) override;

  /// The error that ended the stream: the interpreter's, or the adapter's NC6001. Check it
  /// after the interpolator finished: a stream that ends with an error is not a program end.
  const core::Diagnostic* error() const { return error_ ? &*error_ : nullptr; }

 private:
  struct Stop {};  ///< thrown by fail() to leave the visit; caught in next()
  bool pull(Item& out);
  [[noreturn]] void fail(std::uint32_t line, const std::string& what);
  planner::Move to_move(const interp::Motion& m, std::uint32_t line);

  interp::Interpreter& interp_;
  const machines::Machine& machine_;
  std::vector<std::uint8_t> axes_;  ///< interpolated machine indices
  std::vector<int> slot_;           ///< machine index -> interpolated index, -1: not interpolated
  planner::AxisMask path_axes_ = 0;
  std::optional<core::Diagnostic> error_;
  std::uint32_t line_ = 0;
  std::uint16_t file_ = 0;  ///< Command::file of the last command
};

}  // namespace ncsim::ipo
