#pragma once
// tracking/test_port: a test-double conveyor::Port for the channel's conveyor tests (tests only).
// A belt at constant velocity v (changeable between steps: the position integrates it), no
// noise, no dead time: actual = measured = master; latches are pushed by the test; steps are
// counted; an error can be set.

#include <deque>
#include <optional>

#include "conveyor/port.hpp"

namespace ncsim::tracking::test {

/// A belt at constant velocity; latches pushed by the test; no noise, no dead time.
class FakePort final : public ncsim::conveyor::Port {
 public:
  explicit FakePort(double v) : v_(v) {}
  void step(double t) noexcept override {
    if (v_change_at_ && steps_ + 1 == *v_change_at_) v_ = v_new_;
    if (v_change2_at_ && steps_ + 1 == *v_change2_at_) v_ = v_new2_;
    p_ += v_ * (t - t_);
    t_ = t;
    state_ = ncsim::conveyor::BeltState{p_, v_ - v_lag_, a_report_};
    ++steps_;
    if (latch_at_ && steps_ == *latch_at_) latches_.push_back(p_);
  }
  const ncsim::conveyor::BeltState& actual() const noexcept override { return state_; }
  const ncsim::conveyor::BeltState& measured() const noexcept override { return state_; }
  const ncsim::conveyor::BeltState& master() const noexcept override { return state_; }
  bool command_velocity(const ncsim::interp::MoveVelocity&) noexcept override { return false; }
  void arm_probe(const ncsim::interp::ProbeArm&) noexcept override {}
  std::optional<double> take_latch() noexcept override {
    if (latches_.empty()) return std::nullopt;
    const double l = latches_.front();
    latches_.pop_front();
    return l;
  }
  void set_reduced_filter(bool) noexcept override {}
  bool set_axis_params(const ncsim::machines::ConveyorAxisParams& params) noexcept override {
    if (!takes_params_) return false;
    params_ = params;
    params_at_ = steps_;
    return true;
  }
  const std::optional<ncsim::conveyor::PortError>& error() const noexcept override {
    return error_;
  }

  std::deque<double> latches_;
  std::optional<ncsim::conveyor::PortError> error_;
  double v_ = 0.0;
  double p_ = 0.0;  ///< belt position [mm]
  double t_ = 0.0;  ///< time of the last step [s]
  long steps_ = 0;
  std::optional<long> latch_at_;      ///< at this step the belt's position is latched
  std::optional<long> v_change_at_;   ///< from this step on the belt moves at v_new_
  double v_new_ = 0.0;                ///< [mm/s]
  std::optional<long> v_change2_at_;  ///< from this step on the belt moves at v_new2_
  double v_new2_ = 0.0;               ///< [mm/s]
  /// The master's velocity reports the position's slope less this [mm/s]: a filtered velocity
  /// behind its delay-compensated position while the belt accelerates (seed 004 §2.1.5).
  double v_lag_ = 0.0;
  /// The master's reported acceleration [mm/s^2] (the position integrates v_ alone).
  double a_report_ = 0.0;
  ncsim::conveyor::BeltState state_;
  std::optional<ncsim::machines::ConveyorAxisParams> params_;  ///< the last set_axis_params()
  long params_at_ = -1;                                        ///< steps_ when it came
  bool takes_params_ = true;  ///< false: a world without #MACHINE DATA (Port's default)
};

}  // namespace ncsim::tracking::test
