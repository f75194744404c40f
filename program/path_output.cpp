#include "program/path_output.hpp"

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <variant>

#include "core/number_text.hpp"

namespace ncsim::program {

namespace {

/// Largest tangent change at a joint of the static unit's contour [deg] (004 l.441: C2).
constexpr double kXvCornerMax = 1.0;

}  // namespace

void PathOutput::caxtrack(const interp::CaxTrack& c, std::uint32_t line) {
  if (!c.on) {
    if (c.angpos_given)
      errors_.not_supported(line,
                            "#CAXTRACK OFF [ANGPOS=...] (the axis stays where tracking left it)");
    if (cax_ && cax_->tracker) {
      c_hold_ = cax_->tracker->current();
      c_hold_slot_ = cax_->slot;
    }
    cax_.reset();
    return;
  }
  if (!c.unsupported.empty()) errors_.not_supported(line, "#CAXTRACK ON " + c.unsupported);
  if (c.rotmode != 0.0 && c.rotmode != 1.0)
    errors_.not_supported(
        line, "#CAXTRACK ON ROTMODE=" + core::human(c.rotmode) + " (ncsim runs ROTMODE 0 and 1)");
  int index = -1;  // machine index of the tracking axis
  if (c.axis) {
    index = *c.axis;
  } else if (machine_.channel.tracking_axis_number) {
    if (const machines::AxisParams* a =
            machine_.find_axis_number(*machine_.channel.tracking_axis_number))
      index = static_cast<int>(a - machine_.axes.data());
  }
  if (index < 0)
    errors_.raise(line, "NC9103",
                  "#CAXTRACK ON: no tracking axis (neither AX= nor P-CHAN-00095 "
                  "log_number_tracking_axis names one)");
  const std::string& name = machine_.axes[static_cast<std::size_t>(index)].name;
  for (const int main_axis : layout_.xyz)
    if (main_axis == index)
      errors_.raise(line, "120626",
                    "#CAXTRACK ON: the tracking axis " + name +
                        " is a main axis; it must be an additional axis (P-CHAN-00095)");
  const int slot = layout_.slot[static_cast<std::size_t>(index)];
  if (slot < 0 || layout_.xyz_slot(0) < 0 || layout_.xyz_slot(1) < 0)
    errors_.not_supported(line, "#CAXTRACK ON without interpolated X, Y and tracking axis " + name);
  std::optional<double> now;  // a second ON goes on from where the axis is
  if (cax_ && cax_->tracker && cax_->slot == slot) now = cax_->tracker->current();
  cax_ = CaxState{
      tracking::CaxTrackParams{c.anglimit, c.offset, static_cast<int>(c.rotmode)}, slot, {}};
  if (now) {
    c_hold_ = now;
    c_hold_slot_ = slot;
  }
}

void PathOutput::on_command(const interp::CommandBody& body) {
  const auto& conv = machine_.channel.conveyor;
  if (!conv || !conv->x_virtual || layout_.xyz_slot(0) < 0) return;
  if (std::holds_alternative<interp::SyncOut>(body)) {
    xv_.reset();
    xv_last_.reset();
    return;
  }
  const auto* in = std::get_if<interp::SyncIn>(&body);
  if (in == nullptr) return;
  if (xv_limits_.empty()) {
    // The planner's limits at the run's cycle (it enters only the joints' link velocity,
    // joint_belt_check: the C1 rule's sqrt(j T / |dx''|)).
    const ipo::Config config = machine_config(machine_, t_cycle_);
    xv_limits_ = config.axes;
    xv_channel_ = config.channel;
    for (const std::uint8_t a : layout_.axes)
      xv_names_.push_back(machine_.axes[a].name);
  }
  xv_ = tracking::XVirtualParams{
      layout_.xyz_slot(0), conv->direction == machines::MoveDirection::positive_x ? 1.0 : -1.0,
      tracking::kXvPlanFactor * in->conv_vel, layout_.path_axes};
  xv_tangent_.reset();
  xv_last_.reset();
}

void PathOutput::queue_held() {
  if (!xv_held_) return;
  queue_.push_back(std::move(*xv_held_));
  xv_held_.reset();
}

void PathOutput::check_stop(std::uint32_t line, const char* what) const {
  if (xv_)
    errors_.raise(line, tracking::kXvStopId,
                  std::string("x_virtual: ") + what +
                      " would stop the path on the moving belt; a static unit cannot stop while "
                      "synchronised (004 l.438-440)");
}

void PathOutput::emit(planner::Move mv) {
  if (!cax_) {  // no vector of Moves: one Move goes on (an allocation per block saved)
    hold_c(mv);
    pass_static(mv);
    return;
  }
  for (planner::Move& m : track(std::move(mv)))
    pass_static(m);
}

bool PathOutput::pop(ipo::Item& out) {
  if (queue_.empty()) return false;
  out = std::move(queue_.front());
  queue_.pop_front();
  return true;
}

planner::Move PathOutput::release_part() {
  xv_last_ = *xv_held_;
  planner::Move out = std::move(*xv_held_);
  xv_held_.reset();
  return out;
}

std::vector<planner::Move> PathOutput::track(planner::Move mv) {
  const auto c = static_cast<std::size_t>(cax_->slot);
  if (!cax_->tracker) {
    const double c_now = c_hold_ && c_hold_slot_ == cax_->slot ? *c_hold_ : mv.start[c];
    const int x = layout_.xyz_slot(0);
    const int y = layout_.xyz_slot(1);
    cax_->tracker.emplace(cax_->params, x, y, cax_->slot, c_now);
    c_hold_.reset();
  }
  tracking::CaxOutcome o = cax_->tracker->track(mv);
  if (!o.error.empty())
    errors_.raise_in(mv.file, mv.line, kNotSupportedId, "not supported: " + o.error);
  if (o.turned) {
    if (xv_)
      errors_.raise_in(mv.file, mv.line, tracking::kXvStopId,
                       "x_virtual: the tangent turns by " + core::human(o.joint_turn) +
                           " deg > ANGLIMIT here: #CAXTRACK would stop the path on the moving belt "
                           "to turn the axis (004 l.441-443: the contour must be C2)");
    ipo::Dwell stop{0.0, mv.line, 0};  // the path stops before the turn block
    stop.file = mv.file;
    queue_.push_back(stop);
  }
  return std::move(o.moves);
}

void PathOutput::hold_c(planner::Move& mv) {
  if (!c_hold_) return;  // after #CAXTRACK OFF the axis stands where tracking left it
  const auto c = static_cast<std::size_t>(c_hold_slot_);
  const bool moves_c = mv.end[c] != mv.start[c];
  if (!moves_c) mv.end[c] = *c_hold_;
  if (mv.spline && !moves_c) {
    auto ctl = std::make_shared<planner::SplineControl>(*mv.spline);
    ctl->c1[c] = ctl->c2[c] = *c_hold_;
    mv.spline = std::move(ctl);
  }
  mv.start[c] = *c_hold_;
  if (moves_c) c_hold_.reset();
}

void PathOutput::pass_static(planner::Move& m) {
  if (!xv_) {
    queue_.push_back(std::move(m));
    return;
  }
  if (m.arc && (m.arc_plane || m.arc->axis_1 != xv_->x ||
                static_cast<int>(m.arc->axis_2) != layout_.xyz_slot(1)))
    errors_.raise_in(m.file, m.line, kNotSupportedId,
                     "not supported: G02/G03 outside the XY plane (G17) under x_virtual");
  if (m.exact_stop || m.transition == planner::Transition::stop_at_end)
    errors_.raise_in(
        m.file, m.line, tracking::kXvStopId,
        "x_virtual: an exact stop would stop the path on the moving belt (004 l.438-440)");
  const auto t = tracking::move_tangents(m, xv_->x, layout_.xyz_slot(1));
  if (t && xv_tangent_) {
    const double turn = std::fabs(tracking::unwrap_near(t->first, *xv_tangent_) - *xv_tangent_);
    if (turn > kXvCornerMax)
      errors_.raise_in(
          m.file, m.line, tracking::kXvStopId,
          "x_virtual: the contour turns by " + core::human(turn) +
              " deg at this block's start; the path would slow down on the moving belt "
              "(004 l.441: the contour must be C2, e.g. a spline)");
  }
  tracking::XvOutcome o = tracking::belt_feed(m, *xv_, xv_limits_, xv_names_);
  if (o.error) errors_.raise_in(m.file, m.line, o.error->id, o.error->message);
  for (std::size_t k = 0; k < o.moves.size(); ++k) {
    planner::Move& part = o.moves[k];
    if (xv_held_) {  // the ball after the held part, raised feeds
      if (auto e = tracking::blend_belt_feed(*xv_held_, part, *xv_, xv_limits_, xv_names_))
        errors_.raise_in(xv_held_->file, xv_held_->line, e->id, e->message);
      xv_last_ = *xv_held_;  // where the planner puts no ball, its joint is checked below
      queue_held();
    }
    // A joint without a ball (C1, a knee below 1 deg, C's tangent jumping)
    // must let the path pass at the belt's velocity (inner joints of a split block are C2).
    if (xv_last_)
      if (auto e =
              tracking::joint_belt_check(*xv_last_, part, *xv_, xv_limits_, xv_channel_, xv_names_))
        errors_.raise_in(xv_last_->file, xv_last_->line, e->id, e->message);
    xv_last_.reset();
    // Inner joints of a split block are tangent (no ball); its last part waits for the next.
    if (k + 1 == o.moves.size() && part.contour != planner::Contour::none) {
      xv_held_ = std::move(part);
    } else {
      xv_last_ = part;
      queue_.push_back(std::move(part));
    }
  }
  // A block blended into the next (G61 / G261) leaves a smooth joint: no corner check there.
  xv_tangent_.reset();
  if (t && m.contour == planner::Contour::none) xv_tangent_ = t->second;
}

}  // namespace ncsim::program
