#pragma once
// ipo/source: the program stream the path interpolator pulls, and whom it tells.
//
// Purpose: the values and interfaces between the interpolator and the program around it.
// Inputs: none (types only).
// Outputs: Item (a planner::Move, a G04 Dwell or a ChannelWait), Source (where the items come
// from), WaitHandler (who decides at a ChannelWait), BlockObserver (told of every block start).
// Invariants: a Source may be endless and may throw (the interpolator turns that into
// Status::error); WaitHandler and BlockObserver never throw (they run inside step()).

#include <cstdint>
#include <functional>
#include <utility>
#include <variant>

#include "planner/move.hpp"

namespace ncsim::program {
struct ChannelEvent;  // program/channel_event.hpp
}

namespace ncsim::ipo {

/// G04: dwell between motions [s] (the path stops before it).
struct Dwell {
  double seconds = 0.0;         ///< programmed dwell time [s], >= 0
  std::uint32_t line = 0;       ///< source line of the G04 block
  std::uint32_t event_tag = 0;  ///< channel events up to this tag fire when the dwell starts
  std::uint16_t file = 0;       ///< source file of `line` (interp::Command::file, 0: main)
  /// A technology function's acknowledgement (Activity::tech), not a G04
  bool tech = false;
  /// `seconds` count from the output of the events of `event_tag` when a motion started with
  /// them (MVS_SNS: the wait at the block's end is what the motion did not cover)
  bool since_output = false;
};

/// A point of the program where the channel takes over (program/channel_event.hpp): the path
/// stops exactly at the end of the block before it (the look-ahead ends there, as at a dwell);
/// the WaitHandler then decides whether the path goes on at once or holds (Activity::channel
/// cycles) until release_wait().
struct ChannelWait {
  std::uint32_t line = 0;  ///< source line of the command that needs the standing path
  std::uint32_t tag = 0;   ///< channel events up to this tag are due at the wait
  /// The wait after a block of INDP_SYN ... INTERRUPTIBLE motions followed by MC_TouchProbe or
  /// #SYNC IN (sync-feed): it need not wait for them (the catch-up takes them over).
  bool interruptible = false;
  std::uint16_t file = 0;  ///< source file of `line` (interp::Command::file, 0: main)
};

/// One item of the program stream.
using Item = std::variant<planner::Move, Dwell, ChannelWait>;

/// Where the interpolator pulls its items from. next() fills `out` and returns true, or
/// returns false at the end of the program. May be endless; may throw (the interpolator
/// turns that into Status::error).
class Source {
 public:
  virtual ~Source() = default;
  virtual bool next(Item& out) = 0;
  /// The oldest channel event whose tag is <= `up_to`, removed from the source; false when
  /// there is none (sources without events: always).
  virtual bool take_event(std::uint32_t up_to, program::ChannelEvent& out) {
    (void)up_to;
    (void)out;
    return false;
  }
};

/// Called by the interpolator when the path has stopped at a ChannelWait (inside step()).
class WaitHandler {
 public:
  virtual ~WaitHandler() = default;
  /// True: the path goes on in the same step(); false: it holds until release_wait().
  virtual bool on_wait(const ChannelWait& wait) noexcept = 0;
};

/// A Source from a callable `bool(Item&)` (the adapter from the interpreter's commands).
class CallbackSource final : public Source {
 public:
  explicit CallbackSource(std::function<bool(Item&)> next) : next_(std::move(next)) {}
  bool next(Item& out) override { return next_(out); }

 private:
  std::function<bool(Item&)> next_;
};

/// Told of every block that starts executing, in execution order, inside the step() of the
/// cycle in which it starts (also when several start in one cycle; docs/ipo.md "Block starts").
class BlockObserver {
 public:
  virtual ~BlockObserver() = default;
  /// A programmed Move (at its first path point) or a G04 dwell (> 0 s) of source line `line`
  /// in source file `file` (interp::Command::file, 0: the main program).
  virtual void on_block_started(std::uint32_t line, std::uint16_t file) noexcept = 0;
};

}  // namespace ncsim::ipo
