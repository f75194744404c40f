#pragma once
// program/program_source: the interpreter's command stream as an ipo::Source, and the machine's
// axis lists as the interpolator's Config (program/machine_axes).
//
// Purpose: the first end-to-end seam interp -> planner -> ipo (`ncsim time`, `ncsim run`).
// Inputs: an interp::Interpreter (pulled lazily), the machine it decodes for, a SourceConfig.
// Outputs: ipo::Item values (planner::Move / ipo::Dwell / ipo::ChannelWait) in program order and
// the channel events beside them (docs/ipo.md "From program to cycles").
// Method: Motion (rapid, linear, arc) becomes a Move in the interpolated-axis order, in MCS
// (MoveBuilder; under a #CS chain its points go through the chain's frame, CsFrames: an arc
// under a rotation becomes an arc in the rotated plane, planner::ArcPlane); a #SPLINE section
// (SplineBegin / SplinePoint / SplineEnd) goes through planner::SplineBuilder and becomes one
// spline Move per curve piece (SplineSection; never chopped into lines); every path Move leaves
// through PathOutput (#CAXTRACK, the static unit); G04 a Dwell; #FLUSH / #FLUSH WAIT a
// ChannelWait (the path stops at the end of the block before it, the events before it done;
// #FLUSH CONTINUE passes: the next block is always there); Tech, Message, ProgramStop (M00/M01
// do not stop in time/run: no operator), WaitIndp and the switching-off forms of #TRAFO /
// #CAXTRACK pass; #CS selections update the adapter's own #CS stack (the interpreter's rules,
// machines::CsStack); channel events are tagged and queued (PendingEvents); End ends the stream.
// Barriers are answered from the decode-only state, or from run time (BarrierAnswers: the
// scenario's V.E. store, the channel's set positions). Every other command is a program error
// `not supported: <what>` (NC6001) at its line: nothing is skipped silently. Errors end the
// stream like End does, and error() holds the diagnostic: the blocks decoded before the faulty
// one run to their end and the path stops there, then the caller reports the error (the channel
// stops at the faulty block; docs/ipo.md). Memory: one Command.
//
// Parts (each owned by value, constructed with references to the parts it needs; program/):
//   SourceErrors   the program errors, raised by any part              source_errors
//   AxisLayout     interpolated axes and their index maps              machine_axes
//   CsFrames       #CS frames: points and arcs into MCS                cs_frames
//   BeltSplit      the PCS1 velocity split                             belt_split
//   TrafoPath      #KIN ID / #TRAFO, workspace, the joints' belt share trafo_path
//   MoveBuilder    Motion -> Move with its modal state                 move_builder
//   PathOutput     #CAXTRACK, the static unit, the item queue          path_output
//   BallHold       the PCS1 block held for its ball's share            ball_hold
//   SplineSection  #SPLINE sections                                    spline_section
//   PendingEvents  channel events, tags, the INDP_SYN wait             pending_events
//   BarrierAnswers the interpreter's commands, its barriers answered   barrier_answers

#include <cstdint>
#include <optional>

#include "core/diagnostic.hpp"
#include "interp/interpreter.hpp"
#include "ipo/interpolator.hpp"
#include "machines/machine.hpp"
#include "program/ball_hold.hpp"
#include "program/barrier_answers.hpp"
#include "program/belt_split.hpp"
#include "program/channel_event.hpp"
#include "program/cs_frames.hpp"
#include "program/machine_axes.hpp"
#include "program/move_builder.hpp"
#include "program/path_output.hpp"
#include "program/pending_events.hpp"
#include "program/source_errors.hpp"
#include "program/spline_section.hpp"
#include "program/trafo.hpp"
#include "program/trafo_path.hpp"
#include "scenario/player.hpp"

namespace ncsim::program {

/// How a ProgramSource adapts a program: one value.
struct SourceConfig {
  /// The interpolation cycle the run's channel steps with [s] (> 0): the static unit's joint
  /// check (joint_belt_check) asks the planner's link rules at it.
  double t_cycle = kDefaultCycle;
  /// Refuse, before it moves, a block whose programmed target (or arc extent, spline point) in
  /// the MCS without kinematics lies beyond the soft limits, with `check`'s NC4601 at its line
  /// (interp::add_soft_limit_errors), so `time` / `run` and `check` apply one rule (issue 34
  /// item 22). Off: the channel's per-cycle monitor NC5501 / NC5502 alone, as the unit tests of
  /// the monitor need; every CLI run turns it on.
  bool refuse_soft_limits = false;
};

class ProgramSource final : public ipo::Source {
 public:
  /// `interp` and `machine` must outlive the source. Throws std::invalid_argument when the
  /// machine has no interpolated axis or `config.t_cycle` is not > 0.
  ProgramSource(interp::Interpreter& interp, const machines::Machine& machine,
                SourceConfig config = {});

  /// The next Move, Dwell or ChannelWait; false at End or at a program error (error() then
  /// holds it).
  bool next(ipo::Item& out) override;
  /// The oldest channel event with tag <= up_to (program/channel_event.hpp).
  bool take_event(std::uint32_t up_to, ChannelEvent& out) override {
    return events_.take(up_to, out);
  }

  /// The error that ended the stream: the interpreter's, or the adapter's NC6001. Check it
  /// after the interpolator finished: a stream that ends with an error is not a program end.
  const core::Diagnostic* error() const { return errors_.error(); }
  /// The line the program runs endlessly from, when the stream ended there
  /// (interp::Options::end_when_endless); empty otherwise.
  std::optional<std::uint32_t> ended_endless() const noexcept { return ended_endless_; }

  /// Barriers that want V.E. values are answered from `store` (must outlive the source; null:
  /// the decode-only state again). `flush`: the path stops before each such barrier (a 0 s
  /// Dwell is handed out first), so a value written while the blocks before it ran reaches it.
  /// The program's own V.E. assignments are written into `store` as they are decoded
  /// (docs/scenario.md "The program's V.E. writes").
  void answer_barriers_from(scenario::VeStore* store, bool flush) {
    answers_.answer_from(store, flush);
  }
  /// Position barriers are answered from `set_positions`: the channel's set positions after
  /// its last cycle (Channel::axes().command, interpolated order; must outlive the source;
  /// null: the decode-only state). A barrier that asks for an axis an INDP_ASYN motion may
  /// still move (the interpreter asks for such an axis only when the block programs it again)
  /// first stops the path and waits for that motion (a `#WAIT INDP` of those axes: P-CHAN-00451's
  /// implicit synchronisation); the answer then gives those axes where they stand
  /// (docs/ipo.md "Position barriers").
  void answer_positions_from(const planner::AxisVec* set_positions) noexcept {
    answers_.positions_from(set_positions);
  }
  /// #SIGNAL is sent and #WAIT / #SIGNAL READ answered through `signals` (the run's signal
  /// exchange, must outlive the source; docs/lines.md). Null (the default): a #SIGNAL is
  /// NC6001 and a #WAIT gets the decode-only answer.
  void exchange_signals(SignalPort* signals) noexcept {
    signals_ = signals;
    answers_.signals_from(signals);
  }

 private:
  /// What a step of pull() did: handed out an item, go on with the next command, the stream
  /// ended, or nothing (release_held: the command goes on its way).
  enum class Pulled : std::uint8_t { item, again, end, none };
  bool pull(ipo::Item& out);
  /// The next command: the one held back, else the interpreter's (its V.E. writes to the
  /// store).
  std::optional<interp::Command> take_command();
  /// A command that emits nothing and does not stop the path (a held block stays held).
  bool rides_along(const interp::Command& cmd) const noexcept;
  /// Hands out the static unit's held part or the PCS1 block held for its ball when `cmd` does
  /// not continue its path (`cmd` is then held back for the next pull).
  Pulled release_held(std::optional<interp::Command>& cmd, ipo::Item& out);
  /// A channel event (or the catch-up / departure motion after #SYNC IN / OUT): queued with
  /// its tag; the path stops where it needs to.
  Pulled route_event(interp::Command& cmd, ipo::Item& out);
  /// Every other command: motion, dwell, flush, barrier, frames, splines, end.
  Pulled run_command(interp::Command& cmd, ipo::Item& out);
  /// A Motion's Move out: after the held block (BallHold), held itself or into PathOutput.
  void motion(const interp::Motion& body, std::uint32_t line);

  interp::Interpreter& interp_;
  const machines::Machine& machine_;
  SourceConfig config_;  ///< checked before the parts are built
  SourceErrors errors_;
  std::optional<std::uint32_t> ended_endless_;
  AxisLayout layout_;
  CsFrames frames_;
  BeltSplit belt_;
  TrafoPath trafo_;
  MoveBuilder moves_;
  PathOutput output_;
  BallHold ball_;
  SplineSection spline_;
  PendingEvents events_;
  BarrierAnswers answers_;
  /// The command held back: after a block's INDP_SYN commands, or after a held block.
  std::optional<interp::Command> held_;
  bool out_queued_ = false;        ///< pull() handed out a queued item (it carries its own file)
  bool sync_motion_ = false;       ///< the next Motion is a catch-up / departure
  bool end_reached_ = false;       ///< End came after a final ChannelWait
  SignalPort* signals_ = nullptr;  ///< the run's signal exchange (null: none)
};

}  // namespace ncsim::program
