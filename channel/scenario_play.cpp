// channel/scenario_play: the scenario played in the channel loop (see the header).

#include "channel/scenario_play.hpp"

#include <stdexcept>
#include <utility>
#include <variant>

#include "core/number_text.hpp"

namespace ncsim::channel {

void ScenarioPlay::block_started(std::uint32_t line) noexcept {
  if (aborted_) return;  // the program is aborted (its blocks only brake)
  player_->block_started(line);
  for (const scenario::Action& a : player_->fire_lines()) {
    if (failed_) break;
    failed_ = act(a);
  }
}

std::optional<std::pair<const char*, std::string>> ScenarioPlay::act(
    const scenario::Action& a) noexcept {
  if (std::holds_alternative<scenario::VeWrite>(a)) return std::nullopt;  // in player_->ve()
  // MCV_SetReducedFilter: step() hands player_->reduced_filter() to the Port every cycle.
  if (std::holds_alternative<scenario::ReducedFilter>(a)) return std::nullopt;
  if (const auto* h = std::get_if<scenario::FeedHold>(&a)) {
    ipo_.path_override().set_feed_hold(h->on);
    return std::nullopt;
  }
  if (const auto* o = std::get_if<scenario::PathOverride>(&a)) {
    const double max = ipo::max_override(ipo_.path_override().override_type());
    if (o->fraction <= max) {
      try {
        ipo_.path_override().set_override(o->fraction);
        return std::nullopt;
      } catch (const std::invalid_argument&) {
      }
    }
    return std::pair{kOverrideRangeId,
                     "scenario path override " + core::human(o->fraction * 100.0) + " % above " +
                         core::human(max * 100.0) +
                         " %, the largest of the channel's override type (NCSIM-CHAN-630)"};
  }
  return indp_.set_override(std::get<scenario::AxisOverride>(a), axes_);
}

bool ScenarioPlay::step(bool tracking, conveyor::Port* port, ipo::Status& status,
                        std::optional<RunTimeError>& error) noexcept {
  if (player_ == nullptr) return true;
  if (stopped_) {
    status = ipo::Status::finished;
    return false;
  }
  const ipo::Cycle& last = ipo_.cycle();
  const std::uint64_t k = last.index;
  const double t = static_cast<double>(k) * ipo_.t_cycle();
  for (const scenario::Action& a : player_->step(k, t)) {
    if (auto e = act(a)) {
      ipo::Cycle at = last;
      at.t = t;
      raise(error, e->first, std::move(e->second), at, -1);
      status = ipo::Status::error;
      return false;
    }
  }
  // MCV_SetReducedFilter from the PLC side (docs/conveyor.md "Filters").
  // And the channel's feed hold while it tracks the conveyor (docs/conveyor.md F-4:
  // P-AXIS-00624/00625 "in the case of feedhold").
  if (port != nullptr)
    port->set_reduced_filter(player_->reduced_filter() ||
                             (ipo_.path_override().feed_hold() && tracking));
  if (const auto reason = player_->stop()) {
    stopped_ = *reason;
    status = ipo::Status::finished;
    return false;
  }
  return true;
}

bool ScenarioPlay::check(const ipo::Cycle& c, bool hold_waits,
                         std::optional<RunTimeError>& error) noexcept {
  if (failed_) {
    raise(error, failed_->first, std::move(failed_->second), c, -1);
    return false;
  }
  // No endless hold, unless the workspace hold waits for the belt (NC9081).
  if (player_ == nullptr || !c.held || player_->more_to_come() || hold_waits) return true;
  raise(error, kHeldForeverId,
        ipo_.path_override().feed_hold()
            ? "the path stands by feed hold and no later scenario event releases "
              "it: the run would never end"
            : "the path stands at override 0 and no later scenario event raises "
              "it: the run would never end",
        c, -1);
  return false;
}

}  // namespace ncsim::channel
