#include "conveyor/world.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::conveyor {
namespace {

// ncsim's conveyor ids (docs/diagnostics.md "conveyor/"); the manual's are P-ERR-440xx.
constexpr const char* kQueueFull = "NC9001";
constexpr const char* kTooFast = "NC9005";
constexpr const char* kEncoderBelt = "NC9006";

const machines::AxisParams& conveyor_axis(const machines::Machine& m) {
  const machines::AxisParams* a = m.conveyor_axis();
  if (a == nullptr || !a->conveyor) {
    throw std::invalid_argument(
        "P-AXIS-00708: machine '" + m.name +
        "' has no conveyor axis (conv_sync.is_master = 1); conveyor tracking needs one");
  }
  return *a;
}

std::uint8_t index_of(const machines::Machine& m, const machines::AxisParams& a) {
  return static_cast<std::uint8_t>(&a - m.axes.data());
}

bool encoder_mode(const machines::AxisParams& a, const scenario::Scenario* s) {
  const bool encoder =
      s != nullptr && s->conveyor && s->conveyor->mode == scenario::ConveyorMode::encoder;
  if (encoder && !a.encoder_only) {
    throw std::invalid_argument(
        "P-AXIS-00015: the scenario moves the belt (mode = \"encoder\"), but conveyor axis " +
        a.name + " is not a pure encoder axis (kenngr.achs_mode without ACHSMODE_COUNTER " +
        "0x00100000; seed 004 §5: an externally driven conveyor is an encoder axis)");
  }
  if (!encoder && a.encoder_only) {
    throw std::invalid_argument(
        "P-AXIS-00015: conveyor axis " + a.name +
        " is a pure encoder axis (ACHSMODE_COUNTER): the program cannot drive it; give the "
        "scenario [conveyor] mode = \"encoder\" and the belt's velocity");
  }
  return encoder;
}

bool edge_rising(const machines::AxisParams& a) {
  if (a.measure_edge.empty() || a.measure_edge == "POS") return true;
  if (a.measure_edge == "NEG") return false;
  throw std::invalid_argument("P-AXIS-00518: kenngr.measure.edge of axis " + a.name + " is '" +
                              a.measure_edge + "', not POS or NEG");
}

}  // namespace

MeasuringMethod measuring_method(std::string_view s) {
  if (s.empty() || s == "DRIVE_TYPE_DEFAULT" || s == "DRIVE") return MeasuringMethod::drive;
  if (s == "PLC" || s == "PLC_FIRST_EVENT" || s == "PLC_TIMESTAMP")
    return MeasuringMethod::plc_trigger;
  if (s == "PLC_EXT_LATCH_CONTROL") return MeasuringMethod::plc_queue;
  throw std::invalid_argument("P-AXIS-00516: kenngr.measure.signal '" + std::string(s) +
                              "' is no measuring method of conveyor tracking (seed 004 §4.3: "
                              "DRIVE_TYPE_DEFAULT, DRIVE, PLC, PLC_FIRST_EVENT, PLC_TIMESTAMP, "
                              "PLC_EXT_LATCH_CONTROL)");
}

World::World(const machines::Machine& m, const scenario::Scenario* s, double t_cycle)
    : axis_(&conveyor_axis(m)),
      axis_index_(index_of(m, *axis_)),
      t_cycle_(t_cycle > 0.0 && std::isfinite(t_cycle)
                   ? t_cycle
                   : throw std::invalid_argument("conveyor: cycle time " +
                                                 core::number_text(t_cycle) + " s is not > 0")),
      encoder_(encoder_mode(*axis_, s)),
      method_(measuring_method(axis_->measure_signal)),
      probe_input_(axis_->measure_input),
      default_rising_(edge_rising(*axis_)),
      conveyor_(s != nullptr ? s->conveyor : std::nullopt),
      belt_(encoder_
                ? Belt::encoder(conveyor_->velocity, conveyor_->profile, conveyor_->fluctuation)
                : Belt::spindle(conveyor_ ? conveyor_->fluctuation : std::nullopt)),
      sensor_(
          conveyor_ ? &*conveyor_ : nullptr,
          m.channel.conveyor && m.channel.conveyor->direction == machines::MoveDirection::negative_x
              ? -1.0
              : 1.0),
      filter_(*axis_->conveyor, t_cycle_),
      noise_(conveyor_ && conveyor_->noise ? conveyor_->noise->seed : 1),
      latch_noise_((conveyor_ && conveyor_->noise ? conveyor_->noise->seed : 1) ^
                   0xA5A5A5A5DEADBEEFULL),
      delayed_belt_(belt_) {
  if (m.channel.conveyor && m.channel.conveyor->direction == machines::MoveDirection::negative_x)
    sign_ = -1.0;
  delay_time_ = axis_->conveyor->delay_time;
  if (conveyor_) {
    dead_time_ = conveyor_->dead_time;
    sigma_ = conveyor_->noise ? conveyor_->noise->sigma : 0.0;
    queue_capacity_ = conveyor_->sensor.queue;
    camera_ = conveyor_->sensor.kind == scenario::SensorKind::camera;
  }
  sensor_x_ = conveyor_ && conveyor_->sensor.position ? *conveyor_->sensor.position
              : m.channel.conveyor                    ? m.channel.conveyor->t0_shift.x()
                                                      : 0.0;
  measured_ = delayed(-dead_time_);
  measured_.a = 0.0;
  filter_.reset(measured_.p, measured_.v);
  const BeltState& f = filter_.state();
  master_ = BeltState{f.p + f.v * delay_time_, f.v, f.a};
}

BeltState World::delayed(double tq) noexcept {
  // Commands reach the delayed belt at their own time, then it moves on to tq.
  while (!commands_.empty() && commands_.front().t <= tq) {
    delayed_belt_.advance(commands_.front().t);
    delayed_belt_.command(commands_.front().v, commands_.front().dynamics);
    commands_.pop_front();
  }
  if (tq <= 0.0) return delayed_belt_.base(tq);  // before the start: the base motion
  return delayed_belt_.advance(tq);
}

void World::raise(const char* id, std::string message) noexcept {
  if (!error_) error_ = PortError{id, std::move(message)};
}

LatchInfo World::latch(const Edge& e, double value) const {
  LatchInfo l;
  l.workpiece = e.workpiece;
  l.position = value;
  l.true_position = e.position;
  l.sensor_x = sensor_x_;
  if (e.source != nullptr) {
    for (const scenario::VeWrite& v : e.source->ve)
      l.ve.emplace_back(v.name, v.value);
  }
  return l;
}

void World::present_from_queue() noexcept {
  if (!armed_ || plc_queue_.empty()) return;
  pending_.push_back(std::move(plc_queue_.front()));
  plc_queue_.pop_front();
  armed_.reset();
}

void World::step(double t) noexcept {
  if (!(t > t_)) return;
  const double t_prev = t_;
  const BeltState s_prev = belt_.state();
  const BeltState& s = belt_.advance(t);
  // The encoder: the real belt a dead time ago, plus noise; velocity and acceleration as the
  // NC forms them, by differences over the cycle (current_v_master, current_a_master).
  const double dt = t - t_prev;
  const double p = delayed(t - dead_time_).p + (sigma_ > 0.0 ? sigma_ * noise_.next() : 0.0);
  const double v = (p - measured_.p) / dt;
  measured_ = BeltState{p, v, (v - measured_.v) / dt};
  const BeltState& f = filter_.push(p, v);
  // Delay-time compensation (P-AXIS-00626): the filtered position fed forward at the filtered
  // velocity, which it assumes constant (seed 004 §2.1.5).
  master_ = BeltState{f.p + f.v * delay_time_, f.v, f.a};
  t_ = t;

  for (const Edge& e : sensor_.cycle(t_prev, s_prev, t, s)) {
    if (method_ == MeasuringMethod::plc_queue) {
      if (e.rising != default_rising_) continue;
      plc_queue_.push_back(latch(e, p));  // the PLC reads the measured value in its cycle
      if (plc_queue_.size() > queue_capacity_) {
        raise(kQueueFull,
              "the PLC's queue of measured values is full (" + std::to_string(queue_capacity_) +
                  ", scenario conveyor.sensor.queue) at workpiece " + std::to_string(e.workpiece) +
                  ": workpieces reach the sensor faster than they are machined");
        plc_queue_.pop_back();
      }
      present_from_queue();
      continue;
    }
    if (armed_ && e.rising == armed_->rising) {
      // Method 1: the drive latches the real position at the edge (its own encoder, no bus
      // delay) with the encoder's noise; method 2: the PLC's trigger takes the NC's measured
      // value of this cycle.
      const double value = method_ == MeasuringMethod::drive
                               ? e.position + (sigma_ > 0.0 ? sigma_ * latch_noise_.next() : 0.0)
                               : p;
      pending_.push_back(latch(e, value));
      if (pending_.size() > queue_capacity_) pending_.pop_front();  // the oldest untaken
      armed_.reset();
    } else if (!armed_ && e.front && (e.rising || !camera_)) {
      ++missed_;  // one per workpiece: a camera's pulse counts at its rising edge
    }
  }
}

bool World::command_velocity(const machines::MoveVelocity& c) noexcept {
  if (encoder_) {
    raise(kEncoderBelt, "MC_MoveVelocity on conveyor axis " + axis_->name +
                            ": the scenario moves this belt ([conveyor] mode = \"encoder\", "
                            "ACHSMODE_COUNTER); the program cannot drive it");
    return false;
  }
  if (c.axis != axis_index_) {
    raise(kNotConveyorId, "MC_MoveVelocity reached the conveyor world for machine axis " +
                              std::to_string(c.axis) + ", not the conveyor axis " + axis_->name);
    return false;
  }
  const machines::Dynamics& d = axis_->dynamics;
  if (c.velocity > d.v_max) {
    raise(kTooFast, "MC_MoveVelocity Velocity " + core::number_text(c.velocity * 1000.0) +
                        " um/s (" + core::number_text(c.velocity) +
                        " mm/s) is above conveyor axis " + axis_->name + "'s P-AXIS-00212 vb_max " +
                        core::number_text(d.v_max) + " mm/s");
    return false;
  }
  double v = c.velocity;
  if (c.direction == machines::VelocityDirection::negative ||
      (c.direction == machines::VelocityDirection::current && belt_.state().v < 0.0))
    v = -v;
  // 0 (or less): the axis list's value (PROG-208363915); never beyond P-AXIS-00008.
  VelocityDynamics dyn;
  dyn.acceleration = std::min(c.acceleration > 0.0 ? c.acceleration : d.acc_feed, d.acc_max);
  dyn.deceleration = std::min(c.deceleration > 0.0 ? c.deceleration : d.dec_feed, d.acc_max);
  dyn.jerk = c.jerk > 0.0 ? c.jerk : d.jerk_feed();
  belt_.command(v, dyn);
  commands_.push_back(Command{belt_.time(), v, dyn});
  return true;
}

void World::arm_probe(const machines::ProbeArm& c) noexcept {
  const bool rising = c.edge ? *c.edge == machines::ProbeEdge::rising : default_rising_;
  if (auto e = probe_arm_error(c, rising, armed_, axis_index_, axis_->name, probe_input_)) {
    raise(e->id.c_str(), std::move(e->message));
    return;
  }
  armed_ = ProbeArming{c.axis, c.channel, rising};
  if (method_ == MeasuringMethod::plc_queue) present_from_queue();
  if (armed_ && !sensor_.more_to_come()) {
    raise(kNoWorkpieceId, "MC_TouchProbe armed on " + axis_->name +
                              ", but no workpiece is left to reach the sensor (scenario "
                              "[conveyor] workpiece / workpieces): the measured value would "
                              "never come");
  }
}

bool World::set_axis_params(const machines::ConveyorAxisParams& params) noexcept {
  try {
    ActualValueFilter f(params, t_cycle_);
    f.set_reduced(filter_.reduced());
    f.reset(measured_.p, measured_.v);
    filter_ = std::move(f);
  } catch (const std::bad_alloc&) {
    return false;  // the orders are <= 1000 (machines/): a few kB
  }
  delay_time_ = params.delay_time;
  return true;
}

std::optional<double> World::take_latch() noexcept {
  if (pending_.empty()) return std::nullopt;
  last_ = std::move(pending_.front());
  pending_.pop_front();
  return last_.position;
}

std::unique_ptr<Port> make_port(const machines::Machine& machine,
                                const scenario::Scenario* scenario, double t_cycle) {
  return std::make_unique<World>(machine, scenario, t_cycle);
}

}  // namespace ncsim::conveyor
