#pragma once
// runner/run: one assembled run of a program on the channel loop (design.md §5).
//
// Purpose: the wiring every command that runs the channel shares: Interpreter -> ProgramSource
// (config.refuse_soft_limits, answer_barriers_from the scenario's player, answer_positions_from
// the channel) -> channel_config -> Audit -> Channel -> scenario Player -> conveyor Port.
// Inputs: a Loaded (runner/load.hpp) and the RunSpec's audit and position answers; the caller's
// sinks (CSV, report recorder), which see every cycle after the audit. Outputs: the channel
// stepped cycle by cycle, then an Ending (failed or not, the error text, the stop reason) and
// the audit's verdict; the caller prints. Invariants: built in two steps (construct, then
// start(sinks)) so that a caller can size its sinks from config() before the channel exists;
// the objects keep their addresses (the channel and the source point into each other).

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "audit/time.hpp"
#include "audit/workpiece_cycles.hpp"
#include "channel/channel.hpp"
#include "interp/interpreter.hpp"
#include "program/program_source.hpp"
#include "program/signals.hpp"
#include "runner/load.hpp"
#include "scenario/player.hpp"

namespace ncsim::runner {

/// How a run ended, once its last step() returned something other than running (or the caller
/// stopped early).
struct Ending {
  bool failed = false;     ///< a run-time error, or a program error that ended the source
  std::string error_text;  ///< the error, positioned (file:line:col, the block), "" when none
  std::string stop;        ///< why it ended: "error", the [stop] reason, "endless", "program end"
  /// The line the program runs endlessly from, when that ended it (no [stop]: docs/interp.md
  /// "Endless programs")
  std::optional<std::uint32_t> endless_from;
};

class Run {
 public:
  /// The interpreter, the program source, the channel configuration and the audit of `loaded`.
  /// `hub`: the line's signal exchange, this run its channel `channel` (docs/lines.md); null:
  /// the run keeps its own for one channel (number 1), steps it and ends a wait that can never
  /// be answered (NC6401).
  Run(std::unique_ptr<Loaded> loaded, const RunSpec& spec, program::SignalHub* hub = nullptr,
      std::uint8_t channel = 1);
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;
  ~Run();

  /// Builds the channel; `sinks` (none null) see every joint and cycle after the audit.
  void start(std::vector<ipo::Sink*> sinks = {});
  /// One cycle; while running, the audit sees the joints under #TRAFO ON. A run that ends
  /// tells the signal exchange (it sends nothing more).
  ipo::Status step();
  /// Steps to the end, `on_cycle` (may be empty) after every running cycle; the last status.
  ipo::Status run(const std::function<void(const channel::Channel&)>& on_cycle = {});
  /// How the run ended after the step that returned `last`.
  Ending ending(ipo::Status last) const;

  /// After start(): step() counts the machining time of every running cycle (`time`; the
  /// same cycles as `run`), `on_block` (may be empty) sees each block's record as it closes.
  void count_time(std::function<void(const audit::BlockTime&)> on_block = {});
  /// Closes the time count: cycles, total, distance and split (count_time() first).
  audit::TimeResult time_result();
  /// The channel tracks a conveyor (a conveyor world and its sync part): time per workpiece.
  bool tracks_conveyor() const noexcept;
  /// After start(), on a run that tracks_conveyor(): step() counts the time per workpiece,
  /// `on_row` sees every row as it ends.
  void count_workpieces(std::function<void(const audit::WorkpieceCycle&)> on_row);
  /// Closes the workpiece count (nullopt when none was counted).
  std::optional<audit::WorkpieceSummary> workpiece_summary();

  const Loaded& loaded() const noexcept { return *in_; }
  const interp::Interpreter& interpreter() const noexcept { return interp_; }
  const program::ProgramSource& source() const noexcept { return src_; }
  /// The channel configuration until start() moves it into the channel.
  const channel::ChannelConfig& config() const noexcept { return config_; }
  channel::Channel& channel() noexcept { return *channel_; }
  const channel::Channel& channel() const noexcept { return *channel_; }
  /// The audit (null without RunSpec::audit).
  const audit::Audit* audit() const noexcept { return audit_.get(); }
  /// The channel plays the scenario (it has events or [stop]).
  bool plays() const noexcept { return player_ != nullptr; }
  /// The scenario's player after start() (null when the channel plays none): a line writes
  /// its PLC's V.E. values into its store (docs/lines.md).
  scenario::Player* player() noexcept { return player_.get(); }

 private:
  class Fanout;
  std::unique_ptr<Loaded> in_;
  std::unique_ptr<program::SignalHub> own_hub_;  ///< a run alone: its own signal exchange
  std::unique_ptr<program::SignalPort> signals_;
  std::uint64_t cycles_ = 0;  ///< cycles stepped (the own hub's cycle count)
  bool ended_ = false;        ///< the signal exchange was told the run ended
  interp::Interpreter interp_;
  program::ProgramSource src_;
  channel::ChannelConfig config_;
  bool answer_positions_ = true;
  std::unique_ptr<audit::Audit> audit_;
  std::unique_ptr<scenario::Player> player_;
  std::unique_ptr<Fanout> fanout_;
  std::unique_ptr<channel::Channel> channel_;
  std::optional<audit::TimeCounter> time_;
  std::optional<audit::WorkpieceCycles> workpieces_;
};

}  // namespace ncsim::runner
