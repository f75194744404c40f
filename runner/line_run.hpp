#pragma once
// runner/line_run: a production line run (issue 37 step 1, docs/lines.md): several channels
// in one run, stepped in the same interpolation cycle, sharing one conveyor world and one
// signal exchange (#SIGNAL / #WAIT).
//
// Purpose: what `ncsim line` runs. Inputs: a LineSpec (the line file, --cycle-us, --max-time,
// the audit). Method: the line file is validated (scenario/line_file); each channel is loaded
// by runner::load like `time PROG --machine DIR --scenario FILE` and becomes a runner::Run (one
// more call of the runner per channel, not a copy of its wiring) on the line's SignalHub with
// its channel number; the interpreters learn the line's channel numbers (250008). Every
// channel must run at the same cycle (NCSIM-CHAN-610 or cycle_us / --cycle-us; NC7105 at the
// channel's `machine` otherwise). The line's `[conveyor]` is built once, against the first
// channel (by number) whose machine has a conveyor axis, and each such channel attaches a
// conveyor::SharedPort to its own station of the line's conveyor::LineWorld (its sensor at
// `sensor_at`, its probe; stepped once per cycle; the line steps it when no channel did).
// Per cycle (step()): the hub's cycle starts, every running channel steps in number order,
// the world is stepped to the cycle's end, the hub marks the waits that can never be answered
// (the channel fails such a wait in its next cycle, NC6401), each channel's time waiting for
// a signal is counted, and what each channel did with its workpiece goes to the belt (let go
// before a catch-up, finished at #SYNC OUT after one), which keeps every workpiece's fate.
// Outputs: per channel its Run (ending, time result), end time, waiting time; the line's end.
// Invariants: deterministic (fixed channel order, one cycle of signal transport whatever the
// order); the objects keep their addresses (the runs point into the hub and the world).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "conveyor/line_world.hpp"
#include "conveyor/port.hpp"
#include "conveyor/shared_port.hpp"
#include "program/signals.hpp"
#include "runner/run.hpp"
#include "runner/spec.hpp"
#include "scenario/line_file.hpp"
#include "tracking/sync_phase.hpp"

namespace ncsim::runner {

/// What to run: the line file and the options of `ncsim line`.
struct LineSpec {
  std::filesystem::path file;             ///< the line file (TOML)
  std::optional<std::uint64_t> cycle_us;  ///< --cycle-us over the line's cycle_us
  std::optional<double> max_time;         ///< --max-time S for every channel
  bool audit = false;                     ///< every channel's setpoints audited
  /// `line sweep`, a study: [mm/s] replaces every channel's #SYNC IN CONV_VEL (RunSpec::conv_vel)
  std::optional<double> conv_vel;
  /// `line sweep`: the line's [conveyor] changed before the belt is built (may be empty)
  std::function<void(scenario::Conveyor&)> adjust_conveyor;
  /// `line sweep`: the belt wrapped once it is built (may be empty; RunSpec::wrap)
  WrapPort wrap;
  /// Changes the validated line file before its channels load (a study's varied belt,
  /// docs/study.md; may be empty).
  std::function<void(scenario::LineFile&)> adjust;
};

/// One channel's figures after the run.
struct LineChannelTime {
  double t_end = 0.0;      ///< [s] the end of its last cycle
  double t_waiting = 0.0;  ///< [s] cycles it stood at a #WAIT / #WAIT SYN not answered
};

class LineRun;

/// The outcome of load_line_run (like LoadResult).
struct LineLoadResult {
  std::unique_ptr<LineRun> line;  ///< null when the line cannot start
  Exit exit = Exit::ok;
  std::string messages;  ///< what the command prints on stderr (each line ends in '\n')
  bool ok() const noexcept { return line != nullptr; }
};

/// Loads the line file and every channel (their programs syntax-checked, machines, scenarios).
LineLoadResult load_line_run(const LineSpec& spec);

/// Every channel of the line checked without motion (`ncsim line check`): syntax and the
/// decode-only semantics with the line's channel numbers; the diagnostics in `out` (positioned,
/// with their source lines), the exit category.
Exit check_line(const LineSpec& spec, std::string& out);

class LineRun {
 public:
  LineRun(const LineRun&) = delete;
  LineRun& operator=(const LineRun&) = delete;
  ~LineRun();

  const scenario::LineFile& file() const noexcept { return file_; }
  std::size_t size() const noexcept { return runs_.size(); }
  Run& channel(std::size_t k) noexcept { return *runs_[k]; }
  const Run& channel(std::size_t k) const noexcept { return *runs_[k]; }
  const scenario::LineChannel& channel_spec(std::size_t k) const noexcept { return order_[k]; }
  double t_cycle() const noexcept { return t_cycle_; }

  /// Starts every channel; `sinks[k]` (may be shorter) are channel k's sinks.
  void start(const std::vector<std::vector<ipo::Sink*>>& sinks = {});
  /// One cycle of the line; false once every channel ended.
  bool step();
  /// Steps to the end, `after_cycle` (may be empty) after every cycle (the last one too), then
  /// runs the belt on until every free workpiece has left it.
  void run(const std::function<void()>& after_cycle = {});
  /// [s] the end of the last cycle stepped.
  double t() const noexcept { return static_cast<double>(cycle_) * t_cycle_; }
  /// Channel k stood at a #WAIT / #WAIT SYN not answered in the last cycle.
  bool waiting(std::size_t k) const noexcept { return waiting_[k] != 0; }
  /// The real belt at the end of the last cycle (null: the line has no conveyor world).
  const conveyor::BeltState* belt_state() const noexcept;
  /// Channel k's last status (running until it ended).
  ipo::Status status(std::size_t k) const noexcept { return status_[k]; }
  const LineChannelTime& time(std::size_t k) const noexcept { return times_[k]; }
  /// [s] the end of the line: the last channel's end.
  double t_end() const noexcept;
  /// The belt and its workpieces (null: the line has no conveyor world).
  const conveyor::LineWorld* belt() const noexcept { return belt_.get(); }
  /// Channel k's station on the belt (nullopt: its machine has no conveyor axis).
  std::optional<std::size_t> station(std::size_t k) const noexcept { return watch_[k].station; }

 private:
  friend LineLoadResult load_line_run(const LineSpec& spec);
  LineRun() = default;

  scenario::LineFile file_;
  std::vector<scenario::LineChannel> order_;  ///< the channels by number
  double t_cycle_ = 0.001;
  std::unique_ptr<program::SignalHub> hub_;
  // What a channel does with the workpiece it measured (docs/lines.md "Workpieces along the
  // belt"): let it go before a catch-up, or finish it after one.
  struct Watch {
    std::optional<std::size_t> station;  ///< its station on the belt
    std::uint64_t workpiece = 0;         ///< the workpiece its last #SYNC IN took
    bool open = false;                   ///< that workpiece is not let go nor finished
    bool caught = false;                 ///< a catch-up on it began
    double more = -1.0;                  ///< the LINE_MORE value last written
  };
  void watch(std::size_t k, double t) noexcept;
  void write_more(std::size_t k);

  std::unique_ptr<conveyor::LineWorld> belt_;  ///< the belt and its stations (null: none)
  std::vector<Watch> watch_;
  std::vector<std::unique_ptr<Run>> runs_;
  std::vector<ipo::Status> status_;
  std::vector<LineChannelTime> times_;
  std::vector<std::uint8_t> waiting_;  ///< per channel: waiting() in the last cycle
  std::uint64_t cycle_ = 0;
};

}  // namespace ncsim::runner
