#include "conveyor/belt.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncsim::conveyor {

Belt Belt::encoder(double v0, const std::vector<scenario::BeltChange>& profile,
                   std::optional<scenario::BeltFluctuation> fluctuation) {
  Belt b;
  b.encoder_ = true;
  b.fluctuation_ = fluctuation;
  b.pieces_.push_back(Piece{0.0, 0.0, v0, 0.0});
  const auto close_at = [&](double t) {  // the travel and velocity of the last piece at t
    const Piece& last = b.pieces_.back();
    const double dt = t - last.t0;
    return std::pair{last.p0 + dt * (last.v0 + 0.5 * last.a * dt), last.v0 + last.a * dt};
  };
  for (const scenario::BeltChange& c : profile) {
    const auto [p, vc] = close_at(c.t);
    if (c.ramp > 0.0) {
      b.pieces_.push_back(Piece{c.t, p, vc, (c.velocity - vc) / c.ramp});
      const auto [p_end, v_end] = close_at(c.t + c.ramp);
      (void)v_end;  // exactly c.velocity up to rounding: use the target itself
      b.pieces_.push_back(Piece{c.t + c.ramp, p_end, c.velocity, 0.0});
    } else {
      b.pieces_.push_back(Piece{c.t, p, c.velocity, 0.0});  // a step
    }
  }
  b.state_ = b.base(0.0);
  b.cursor_ = 0;
  if (b.fluctuation_)
    b.state_.a +=
        b.state_.v * b.fluctuation_->amplitude * 2.0 * std::numbers::pi * b.fluctuation_->frequency;
  return b;
}

Belt Belt::spindle(std::optional<scenario::BeltFluctuation> fluctuation) {
  Belt b;
  b.encoder_ = false;
  b.fluctuation_ = fluctuation;
  return b;
}

BeltState Belt::ramp_state(double t) const noexcept {
  double tau = t - t_cmd_;
  jerk::State s = cmd_start_;
  for (std::size_t i = 0; i < 3 && tau > 0.0; ++i) {
    const double dt = std::min(tau, ramp_.duration[i]);
    s = jerk::advance(s, ramp_.jerk[i], dt);
    tau -= dt;
  }
  if (tau > 0.0) {  // cruise at the target after the ramp (its exact value, not a rounding)
    s.v = ramp_.v_end;
    s.a = 0.0;
    s = jerk::advance(s, 0.0, tau);
  }
  return BeltState{s.p, s.v, s.a};
}

BeltState Belt::base(double t) noexcept {
  if (!encoder_) {
    if (t < t_cmd_) {  // before the command in force: rest (only t < 0 asks this)
      return BeltState{cmd_start_.p + cmd_start_.v * (t - t_cmd_), cmd_start_.v, 0.0};
    }
    return ramp_state(t);
  }
  if (t < 0.0) return BeltState{pieces_[0].v0 * t, pieces_[0].v0, 0.0};
  while (cursor_ + 1 < pieces_.size() && t >= pieces_[cursor_ + 1].t0)
    ++cursor_;
  const Piece& p = pieces_[cursor_];
  const double dt = t - p.t0;
  return BeltState{p.p0 + dt * (p.v0 + 0.5 * p.a * dt), p.v0 + p.a * dt, p.a};
}

const BeltState& Belt::advance(double t) noexcept {
  if (t <= t_) return state_;
  if (!fluctuation_) {
    state_ = base(t);
    t_ = t;
    return state_;
  }
  const double w = 2.0 * std::numbers::pi * fluctuation_->frequency;
  const double amp = fluctuation_->amplitude;
  // Simpson over [t_, t] of v_base(tau) sin(w tau), 4 sub-intervals; base() is a cursor, so
  // the sub-points are asked in increasing order and t itself last.
  const double h = (t - t_) / 4.0;
  double sum = 0.0;
  BeltState b;
  for (int k = 0; k <= 4; ++k) {
    const double tk = k == 4 ? t : t_ + h * k;
    b = base(tk);
    sum += b.v * std::sin(w * tk) * (k == 0 || k == 4 ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0));
  }
  fluct_travel_ += amp * sum * h / 3.0;
  const double sn = std::sin(w * t);
  const double cs = std::cos(w * t);
  b.a = b.a * (1.0 + amp * sn) + b.v * amp * w * cs;
  b.v = b.v * (1.0 + amp * sn);
  b.p += fluct_travel_;
  t_ = t;
  state_ = b;
  return state_;
}

void Belt::command(double v, const VelocityDynamics& d) noexcept {
  if (encoder_) return;
  const BeltState now = ramp_state(t_);  // the base state (without fluctuation) now
  double up = d.acceleration;
  double down = d.deceleration;
  if (now.v <= 0.0 && v <= 0.0 && !(now.v == 0.0 && v == 0.0)) {
    std::swap(up, down);  // moving backwards: positive acceleration slows down
  } else if ((now.v > 0.0 && v < 0.0) || (now.v < 0.0 && v > 0.0)) {
    up = down = std::min(d.acceleration, d.deceleration);  // a reversal (docs/conveyor.md)
  }
  cmd_start_ = jerk::State{now.p, now.v, now.a};
  t_cmd_ = t_;
  ramp_ = jerk::velocity_ramp(now.v, now.a, v, up, down, d.jerk);
}

}  // namespace ncsim::conveyor
