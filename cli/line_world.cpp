// cli/line_world: the belt velocity override and the workspace margin (see the header).

#include "cli/line_world.hpp"

#include <cmath>
#include <utility>

namespace ncsim::cli {
namespace {

// Forwards everything to the world, with every commanded Velocity > 0 replaced.
class BeltOverride final : public conveyor::Port {
 public:
  BeltOverride(std::unique_ptr<conveyor::Port> port, double v) : port_(std::move(port)), v_(v) {}
  void step(double t) noexcept override { port_->step(t); }
  const conveyor::BeltState& actual() const noexcept override { return port_->actual(); }
  const conveyor::BeltState& measured() const noexcept override { return port_->measured(); }
  const conveyor::BeltState& master() const noexcept override { return port_->master(); }
  bool command_velocity(const interp::MoveVelocity& command) noexcept override {
    interp::MoveVelocity c = command;
    if (c.velocity > 0.0) c.velocity = v_;
    return port_->command_velocity(c);
  }
  void arm_probe(const interp::ProbeArm& command) noexcept override { port_->arm_probe(command); }
  std::optional<double> take_latch() noexcept override { return port_->take_latch(); }
  void set_reduced_filter(bool on) noexcept override { port_->set_reduced_filter(on); }
  const std::optional<conveyor::PortError>& error() const noexcept override {
    return port_->error();
  }
  bool set_axis_params(const machines::ConveyorAxisParams& params) noexcept override {
    return port_->set_axis_params(params);
  }
  const conveyor::LatchInfo& last_latch() const noexcept override { return port_->last_latch(); }

 private:
  std::unique_ptr<conveyor::Port> port_;
  double v_;
};

}  // namespace

BeltSetting set_belt_velocity(const machines::Machine& machine,
                              std::optional<scenario::Scenario>& scenario, double v) noexcept {
  BeltSetting b;
  b.conveyor = machine.conveyor_axis() != nullptr && machine.channel.conveyor.has_value();
  if (!scenario || !scenario->conveyor ||
      scenario->conveyor->mode != scenario::ConveyorMode::encoder)
    return b;
  b.encoder = true;
  b.encoder_zero = !scale_encoder_belt(*scenario->conveyor, v);
  return b;
}

bool scale_encoder_belt(scenario::Conveyor& c, double v) noexcept {
  if (c.velocity == 0.0) return false;
  const double k = v / std::abs(c.velocity);
  c.velocity *= k;
  for (scenario::BeltChange& change : c.profile)
    change.velocity *= k;
  return true;
}

std::unique_ptr<conveyor::Port> override_belt(std::unique_ptr<conveyor::Port> port, double v) {
  return std::make_unique<BeltOverride>(std::move(port), v);
}

void WorkspaceWatch::configure(const machines::Machine& machine) noexcept {
  if (machine.channel.conveyor) box_ = machine.channel.conveyor->workspace;
}

void WorkspaceWatch::on_cycle(const channel::Channel& channel) noexcept {
  const tracking::ConveyorSync* sync = channel.conveyor_sync();
  if (!box_ || sync == nullptr || !sync->synchronised()) return;
  // The commanded TCP: the axes' setpoints, or under #TRAFO ON the TCP the joints were computed
  // from (Channel::tcp(): the PCS1 point plus the belt offset in MCS, what tracking/trafo_sync
  // checks the workspace's faces with).
  const auto& x = channel.transformed() ? channel.tcp() : channel.setpoints();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < channel.axis_count(); ++i)
    if (const int k = sync->xyz(i); k >= 0) p[k] = x[i].p;
  const Eigen::Vector3d& e = sync->frame().direction();
  constexpr double kCos60 = 0.5;  // tracking/workspace's class of a conveying face
  for (int k = 0; k < 3; ++k) {
    double d = 0.0;
    if (e[k] > kCos60) {
      d = box_->upper[k] - p[k];
    } else if (e[k] < -kCos60) {
      d = p[k] - box_->lower[k];
    } else {
      continue;
    }
    if (!margin_.valid || d < margin_.distance) {
      margin_.valid = true;
      margin_.distance = d;
      margin_.t = channel.cycle().t;
      margin_.line = channel.cycle().line;
    }
  }
}

}  // namespace ncsim::cli
