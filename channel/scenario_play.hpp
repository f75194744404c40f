#pragma once
// channel/scenario_play: the scenario played in the channel loop, before each cycle
// (docs/scenario.md "When events fire", docs/ipo.md "The channel loop").
//
// Purpose: Player::step(k, t) with k the cycle's index and t its start time; its V.E. writes are
// in the store the ProgramSource answers barriers from; a [stop] condition met ends the run
// before the cycle (Status::finished, stop_reason()); path override and feed hold go to
// PathOverride::set_override / set_feed_hold (an override above the type's largest is
// run-time error NC6102); an axis override goes to the INDP axes (002 2.2; NC6105). Every block
// that starts inside a cycle (the interpolator's BlockObserver) goes to Player::block_started
// and its `line` events fire at once: they belong to the cycle in which the block starts.
// Inputs: the Player (null: none), the interpolator and the INDP axes it acts on.
// Outputs: the actions applied, the stop reason, an action's error raised mid-cycle and a path
// held forever (NC6301) as run-time errors (check()).
// Invariants: noexcept; no allocation per cycle beyond the Player's own.

#include <optional>
#include <string>
#include <utility>

#include "channel/axis_stage.hpp"
#include "channel/channel_types.hpp"
#include "channel/indp_stage.hpp"
#include "conveyor/port.hpp"
#include "ipo/interpolator.hpp"
#include "scenario/player.hpp"

namespace ncsim::channel {

class ScenarioPlay {
 public:
  /// `ipo`, `indp` and `axes` must outlive the part (the channel's own parts).
  ScenarioPlay(ipo::PathInterpolator& ipo, IndpStage& indp, const AxisStage& axes) noexcept
      : ipo_(ipo), indp_(indp), axes_(axes) {}
  ScenarioPlay(const ScenarioPlay&) = delete;
  ScenarioPlay& operator=(const ScenarioPlay&) = delete;

  /// Plays `player`'s scenario from the next cycle on; null: none.
  void attach(scenario::Player* player) noexcept {
    player_ = player;
    ipo_.observe_blocks(player != nullptr ? &blocks_ : nullptr);
  }
  scenario::Player* player() const noexcept { return player_; }
  /// The scenario's cycle before the interpolator's (none without a player); false when the
  /// run ends before it: `status` finished (a [stop] condition) or error (raised into `error`).
  /// `tracking`: the channel tracks the conveyor (its feed hold reduces the filters of `port`,
  /// null: none).
  bool step(bool tracking, conveyor::Port* port, ipo::Status& status,
            std::optional<RunTimeError>& error) noexcept;
  /// After the interpolator's step, at its cycle `c`: an action's run-time error raised by a
  /// block start inside the cycle, or NC6301 when the path stands by feed hold or override 0
  /// and no later scenario event releases it (unless `hold_waits`: the workspace hold waits for
  /// the belt, NC9081). False: raised into `error`.
  bool check(const ipo::Cycle& c, bool hold_waits, std::optional<RunTimeError>& error) noexcept;
  /// The [stop] condition that ended the run, if one did.
  const std::optional<scenario::StopReason>& stop_reason() const noexcept { return stopped_; }
  /// The program is aborted (after an error while synchronised): its blocks only brake.
  void abort_program() noexcept { aborted_ = true; }

 private:
  /// Passes the interpolator's block starts to the player.
  class BlockRelay final : public ipo::BlockObserver {
   public:
    explicit BlockRelay(ScenarioPlay& play) : play_(play) {}
    void on_block_started(std::uint32_t line, std::uint16_t file) noexcept override {
      play_.block_started(file == 0 ? line : 0);  // scenario lines are the main program's
    }

   private:
    ScenarioPlay& play_;
  };
  /// A block starts inside the cycle being computed: the player counts it and fires its
  /// `line` events now; an action's run-time error waits in failed_ for the cycle's end.
  void block_started(std::uint32_t line) noexcept;
  /// Applies one scenario action; the run-time error (id, text) it raises, if any.
  std::optional<std::pair<const char*, std::string>> act(const scenario::Action& a) noexcept;

  ipo::PathInterpolator& ipo_;
  IndpStage& indp_;
  const AxisStage& axes_;
  scenario::Player* player_ = nullptr;
  std::optional<scenario::StopReason> stopped_;
  std::optional<std::pair<const char*, std::string>> failed_;  ///< an action's error, mid-cycle
  bool aborted_ = false;
  BlockRelay blocks_{*this};
};

}  // namespace ncsim::channel
