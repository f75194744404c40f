// program/program_static: #CAXTRACK and the static processing unit (x_virtual) at the adapter
// (issue 14; docs/caxtrack.md, docs/conveyor.md "Static processing unit").
//
// Every path Move leaves the adapter through emit_path(): under #CAXTRACK ON the tracker
// (tracking/caxtrack.hpp) sets the tracking axis's values and may put a C-only turn block, after
// a 0 s Dwell that stops the path, before it; while a static unit (P-CHAN-00364 = 1) is
// synchronised, every block gets the belt feed (tracking/x_virtual.hpp) and the static unit's
// errors NC9100..NC9102 are raised at the block's line. The results are queued and handed out
// before the next command (pull()); --- static-blend: a part that ends in a tolerance ball waits
// for the next path part (xv_held_), so that both feeds can be raised for the ball; --- static-c1:
// every joint of two parts without a ball is checked against the planner's link (xv_last_).

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <variant>

#include "program/program_source.hpp"

namespace ncsim::ipo {

namespace {

/// Largest tangent change at a joint of the static unit's contour [deg] (004 l.441: C2).
constexpr double kXvCornerMax = 1.0;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

void ProgramSource::caxtrack(const interp::CaxTrack& c, std::uint32_t line) {
  if (!c.on) {
    if (c.angpos_given)
      fail(line, "#CAXTRACK OFF [ANGPOS=...] (the axis stays where tracking left it)");
    if (cax_ && cax_->tracker) {
      c_hold_ = cax_->tracker->current();
      c_hold_slot_ = cax_->slot;
    }
    cax_.reset();
    return;
  }
  if (!c.unsupported.empty()) fail(line, "#CAXTRACK ON " + c.unsupported);
  if (c.rotmode != 0.0 && c.rotmode != 1.0)
    fail(line, "#CAXTRACK ON ROTMODE=" + number(c.rotmode) + " (ncsim runs ROTMODE 0 and 1)");
  int index = -1;  // machine index of the tracking axis
  if (c.axis) {
    index = *c.axis;
  } else if (machine_.channel.tracking_axis_number) {
    if (const machines::AxisParams* a =
            machine_.find_axis_number(*machine_.channel.tracking_axis_number))
      index = static_cast<int>(a - machine_.axes.data());
  }
  if (index < 0)
    fail_with(line, "NC9103",
              "#CAXTRACK ON: no tracking axis (neither AX= nor P-CHAN-00095 "
              "log_number_tracking_axis names one)");
  const std::string& name = machine_.axes[static_cast<std::size_t>(index)].name;
  for (const int main_axis : xyz_)
    if (main_axis == index)
      fail_with(line, "120626",
                "#CAXTRACK ON: the tracking axis " + name +
                    " is a main axis; it must be an additional axis (P-CHAN-00095)");
  const int slot = slot_[static_cast<std::size_t>(index)];
  if (slot < 0 || xyz_[0] < 0 || xyz_[1] < 0 || slot_[static_cast<std::size_t>(xyz_[0])] < 0 ||
      slot_[static_cast<std::size_t>(xyz_[1])] < 0)
    fail(line, "#CAXTRACK ON without interpolated X, Y and tracking axis " + name);
  std::optional<double> now;  // a second ON goes on from where the axis is
  if (cax_ && cax_->tracker && cax_->slot == slot) now = cax_->tracker->current();
  cax_ = CaxState{CaxTrackParams{c.anglimit, c.offset, static_cast<int>(c.rotmode)}, slot, {}};
  if (now) {
    c_hold_ = now;
    c_hold_slot_ = slot;
  }
}

void ProgramSource::static_sync(const interp::CommandBody& body) {
  const auto& conv = machine_.channel.conveyor;
  if (!conv || !conv->x_virtual || xyz_[0] < 0 || slot_[static_cast<std::size_t>(xyz_[0])] < 0)
    return;
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
    const Config config = machine_config(machine_, t_cycle_);
    xv_limits_ = config.axes;
    xv_channel_ = config.channel;
    for (const std::uint8_t a : axes_)
      xv_names_.push_back(machine_.axes[a].name);
  }
  xv_ = XVirtualParams{slot_[static_cast<std::size_t>(xyz_[0])],
                       conv->direction == machines::MoveDirection::positive_x ? 1.0 : -1.0,
                       kXvPlanFactor * in->conv_vel, path_axes_};
  xv_tangent_.reset();
  xv_last_.reset();
}

void ProgramSource::xv_release() {
  if (!xv_held_) return;
  queue_.push_back(std::move(*xv_held_));
  xv_held_.reset();
}

void ProgramSource::static_stop(std::uint32_t line, const char* what) {
  if (xv_)
    fail_with(line, kXvStopId,
              std::string("x_virtual: ") + what +
                  " would stop the path on the moving belt; a static unit cannot stop while "
                  "synchronised (004 l.438-440)");
}

void ProgramSource::emit_path(planner::Move mv) {
  std::vector<planner::Move> moves;
  if (cax_) {
    const auto c = static_cast<std::size_t>(cax_->slot);
    if (!cax_->tracker) {
      const double c_now = c_hold_ && c_hold_slot_ == cax_->slot ? *c_hold_ : mv.start[c];
      const int x = slot_[static_cast<std::size_t>(xyz_[0])];
      const int y = slot_[static_cast<std::size_t>(xyz_[1])];
      cax_->tracker.emplace(cax_->params, x, y, cax_->slot, c_now);
      c_hold_.reset();
    }
    CaxOutcome o = cax_->tracker->track(mv);
    if (!o.error.empty()) fail_in(mv.file, mv.line, kNotSupportedId, "not supported: " + o.error);
    if (o.turned) {
      if (xv_)
        fail_in(mv.file, mv.line, kXvStopId,
                "x_virtual: the tangent turns by " + number(o.joint_turn) +
                    " deg > ANGLIMIT here: #CAXTRACK would stop the path on the moving belt to "
                    "turn the axis (004 l.441-443: the contour must be C2)");
      Dwell stop{0.0, mv.line, 0};  // the path stops before the turn block
      stop.file = mv.file;
      queue_.push_back(stop);
    }
    moves = std::move(o.moves);
  } else {
    if (c_hold_) {  // after #CAXTRACK OFF the axis stands where tracking left it
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
    moves.push_back(std::move(mv));
  }
  for (planner::Move& m : moves) {
    if (!xv_) {
      queue_.push_back(std::move(m));
      continue;
    }
    if (m.arc && (m.arc_plane || m.arc->axis_1 != xv_->x ||
                  static_cast<int>(m.arc->axis_2) != slot_[static_cast<std::size_t>(xyz_[1])]))
      fail_in(m.file, m.line, kNotSupportedId,
              "not supported: G02/G03 outside the XY plane (G17) under x_virtual");
    if (m.exact_stop || m.transition == planner::Transition::stop_at_end)
      fail_in(m.file, m.line, kXvStopId,
              "x_virtual: an exact stop would stop the path on the moving belt (004 l.438-440)");
    const auto t = move_tangents(m, xv_->x, slot_[static_cast<std::size_t>(xyz_[1])]);
    if (t && xv_tangent_) {
      const double turn = std::fabs(unwrap_near(t->first, *xv_tangent_) - *xv_tangent_);
      if (turn > kXvCornerMax)
        fail_in(m.file, m.line, kXvStopId,
                "x_virtual: the contour turns by " + number(turn) +
                    " deg at this block's start; the path would slow down on the moving belt "
                    "(004 l.441: the contour must be C2, e.g. a spline)");
    }
    XvOutcome o = belt_feed(m, *xv_, xv_limits_, xv_names_);
    if (o.error) fail_in(m.file, m.line, o.error->id, o.error->message);
    for (std::size_t k = 0; k < o.moves.size(); ++k) {
      planner::Move& part = o.moves[k];
      if (xv_held_) {  // --- static-blend: the ball after the held part, raised feeds
        if (auto e = blend_belt_feed(*xv_held_, part, *xv_, xv_limits_, xv_names_))
          fail_in(xv_held_->file, xv_held_->line, e->id, e->message);
        xv_last_ = *xv_held_;  // where the planner puts no ball, its joint is checked below
        xv_release();
      }
      // --- static-c1: a joint without a ball (C1, a knee below 1 deg, C's tangent jumping)
      // must let the path pass at the belt's velocity (inner joints of a split block are C2).
      if (xv_last_)
        if (auto e = joint_belt_check(*xv_last_, part, *xv_, xv_limits_, xv_channel_, xv_names_))
          fail_in(xv_last_->file, xv_last_->line, e->id, e->message);
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
}

}  // namespace ncsim::ipo
