#pragma once
// program/barrier_answers: the interpreter's barriers answered from run time (docs/ipo.md
// "Position barriers", "Scenario").
//
// Purpose: the adapter's side of the seam: it pulls the interpreter's commands and answers its
// barriers. Without run-time answers the decode-only state does (next_decode_only). With a
// scenario (answer_from) the V.E. names come from the scenario's VeStore; with `flush` the path
// first stops (a 0 s Dwell) so every block before the barrier has run when it is answered (the
// kernel's synchronous V.E. read). With the channel's set positions (positions_from): after an
// INDP_ASYN motion or G74 the interpreter does not know where the axis is; a block that
// programs the axis again passes a position barrier for it. The path then stops and waits for
// the axis's INDP motion (a #WAIT INDP of those axes, the kernel's implicit synchronisation
// P-CHAN-00451) and the barrier is answered with the set position the channel reports, so the
// block starts where the axis stands, not where the decoder assumed it (docs/homing.md: G74's
// homed axes stand at P-AXIS-00152 when the channel is done).
// Inputs: the interpreter, the channel events as they pass (note()), the scenario's store, the
// channel's set positions (MCS, interpolated order).
// Outputs: commands; the stop before a barrier (a ChannelWait or a 0 s Dwell); the answer.
// Invariants: an axis whose set position equals the decode-time value (within kRelTol relative)
// keeps the decode-time value bit for bit; a difference that cannot be carried into the frame
// (a rotated #CS on X/Y/Z, PCS1, #TRAFO ON) is `not supported` (NC6001), never ignored.

#include <cstdint>
#include <optional>

#include "interp/interpreter.hpp"
#include "ipo/interpolator.hpp"
#include "machines/machine.hpp"
#include "program/cs_frames.hpp"
#include "program/machine_axes.hpp"
#include "program/pending_events.hpp"
#include "program/signals.hpp"
#include "program/source_errors.hpp"
#include "scenario/player.hpp"

namespace ncsim::program {

/// The parts BarrierAnswers reads and writes; all must outlive it.
struct BarrierParts {
  interp::Interpreter& interp;
  const machines::Machine& machine;
  const AxisLayout& layout;
  SourceErrors& errors;
  const CsFrames& frames;
  PendingEvents& events;
};

class BarrierAnswers {
 public:
  explicit BarrierAnswers(const BarrierParts& parts) noexcept : parts_(parts) {}

  /// V.E. names from `store` (null: the decode-only state); `flush`: the path stops before each
  /// such barrier. The program's V.E. writes go into `store` as they are decoded.
  void answer_from(scenario::VeStore* store, bool flush);
  /// Position barriers from the channel's set positions `set_positions` (null: decode-only).
  void positions_from(const planner::AxisVec* set_positions) noexcept {
    positions_ = set_positions;
  }
  /// #WAIT / #SIGNAL READ barriers from the run's signals (null: the decode-only answer).
  void signals_from(SignalPort* signals) noexcept { signals_ = signals; }
  /// The interpreter's next command (next_decode_only() without run-time answers).
  std::optional<interp::Command> next_command();
  /// The program's V.E. assignments decoded so far into the store, before any barrier after
  /// them is answered.
  void store_ve_writes();
  /// Keeps the axes an INDP_ASYN motion or G74 may still move current for a channel event.
  void note(const interp::CommandBody& body) noexcept;
  /// A barrier answered now (false) or after the path stopped (true: `out` holds the stop).
  bool barrier(const interp::Barrier& body, std::uint32_t line, ipo::Item& out);
  /// A #WAIT / #SIGNAL READ barrier: its signal taken now (false) or the path stops at a
  /// SignalWait event until the channel took it (true: `out` holds the stop).
  bool signal_barrier(const interp::Barrier& body, std::uint32_t line, ipo::Item& out);
  /// The barrier left open at the last stop is answered: every block before it ran.
  void answer_open();

 private:
  /// Answers `barrier` of `line`: the decode-only state with the store's V.E. values and, for
  /// the axes waited for (run_time_), the set positions.
  void answer(const interp::Barrier& barrier, std::uint32_t line);
  /// state.position of the run_time_ axes from *positions_, in barrier.frame.
  void answer_positions(const interp::Barrier& barrier, std::uint32_t line,
                        interp::RunState& state);

  BarrierParts parts_;
  scenario::VeStore* store_ = nullptr;
  SignalPort* signals_ = nullptr;
  /// The signal answer of the open barrier, taken already (a #WAIT answered at its pull)
  std::optional<interp::SignalAnswer> signal_;
  bool flush_ = false;
  std::optional<interp::Barrier> open_;          ///< a barrier waiting for the path to stop
  std::uint32_t open_line_ = 0;                  ///< its line
  const planner::AxisVec* positions_ = nullptr;  ///< the channel's set positions; null: none
  interp::AxisMask indp_running_ = 0;  ///< machine axes an INDP_ASYN motion may still move
  interp::AxisMask run_time_ = 0;      ///< axes the open barrier answers from run time
};

}  // namespace ncsim::program
