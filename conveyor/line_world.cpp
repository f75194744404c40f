#include "conveyor/line_world.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "core/number_text.hpp"

namespace ncsim::conveyor {
namespace {

// ncsim's conveyor ids (docs/diagnostics.md "conveyor/"), as conveyor/world raises them.
constexpr const char* kQueueFull = "NC9001";
constexpr const char* kRearEdge = "NC9007";

}  // namespace

const char* fate_name(Fate f) noexcept {
  switch (f) {
    case Fate::free:
      return "on belt";
    case Fate::held:
      return "held";
    case Fate::taken:
      return "taken";
    case Fate::missed:
      return "missed";
  }
  return "?";
}

StationSpec station_of(const machines::Machine& m, std::uint8_t number, double sensor_at) {
  const machines::AxisParams* a = m.conveyor_axis();
  if (a == nullptr || !a->conveyor)
    throw std::invalid_argument("P-AXIS-00708: machine '" + m.name +
                                "' has no conveyor axis (conv_sync.is_master = 1)");
  StationSpec s;
  s.channel = number;
  s.sensor_at = sensor_at;
  s.axis = static_cast<std::uint8_t>(a - m.axes.data());
  s.axis_name = a->name;
  s.method = measuring_method(a->measure_signal);
  s.probe_input = a->measure_input;
  if (a->measure_edge == "NEG") {
    s.default_rising = false;
  } else if (!a->measure_edge.empty() && a->measure_edge != "POS") {
    throw std::invalid_argument("P-AXIS-00518: kenngr.measure.edge of axis " + a->name + " is '" +
                                a->measure_edge + "', not POS or NEG");
  }
  s.sensor_x = m.channel.conveyor ? m.channel.conveyor->t0_shift.x() : 0.0;
  return s;
}

// One channel's station: its probe, its measured values, its Port.
class LineWorld::StationPort final : public Port {
 public:
  StationPort(LineWorld& line, std::size_t index, StationSpec spec, std::size_t capacity)
      : line_(line), k_(index), spec_(std::move(spec)), capacity_(capacity) {}

  void step(double t) noexcept override { line_.step_once(t); }
  const BeltState& actual() const noexcept override { return line_.world_->actual(); }
  const BeltState& measured() const noexcept override { return line_.world_->measured(); }
  const BeltState& master() const noexcept override { return line_.world_->master(); }
  bool command_velocity(const machines::MoveVelocity& command) noexcept override {
    return line_.world_->command_velocity(command);
  }
  void set_reduced_filter(bool on) noexcept override { line_.world_->set_reduced_filter(on); }
  bool set_axis_params(const machines::ConveyorAxisParams& params) noexcept override {
    return line_.world_->set_axis_params(params);
  }
  const std::optional<PortError>& error() const noexcept override {
    return error_ ? error_ : line_.world_->error();
  }
  const LatchInfo& last_latch() const noexcept override { return last_; }

  void arm_probe(const machines::ProbeArm& c) noexcept override;
  std::optional<double> take_latch() noexcept override;

  // The piece's front edge passed this station's sensor at t with the real position `real`.
  void sense(Piece& p, double t, double real) noexcept;
  // Hands out the oldest queued value whose workpiece is still free (method 3).
  void present() noexcept;
  void drop(std::uint64_t workpiece) noexcept {
    std::erase_if(queue_, [&](const LatchInfo& l) { return l.workpiece == workpiece; });
  }
  bool queued_free() const noexcept {
    return std::any_of(queue_.begin(), queue_.end(), [&](const LatchInfo& l) {
      const Piece* p = line_.find_const(l.workpiece);
      return p != nullptr && p->fate == Fate::free;
    });
  }
  bool pending() const noexcept { return !pending_.empty(); }
  // Armed while nothing can reach the sensor any more (the last workpiece taken upstream, or
  // missed): NC9003 now, not a wait until ncsim's time limit.
  void check_reachable() noexcept;
  const StationSpec& spec() const noexcept { return spec_; }
  std::uint64_t taken = 0;

 private:
  void raise(const char* id, std::string message) noexcept {
    if (!error_) error_ = PortError{id, std::move(message)};
  }
  LatchInfo latch(const Piece& p, double value, double real) const;

  LineWorld& line_;
  std::size_t k_;
  StationSpec spec_;
  std::size_t capacity_;
  std::optional<ProbeArming> armed_;
  std::deque<LatchInfo> pending_;  // measured, not yet taken by #SYNC IN
  std::deque<LatchInfo> queue_;    // method 3: the PLC's queue (the workpiece still free)
  LatchInfo last_;
  std::optional<PortError> error_;
};

LatchInfo LineWorld::StationPort::latch(const Piece& p, double value, double real) const {
  LatchInfo l;
  l.workpiece = p.workpiece;
  l.position = value;
  l.true_position = real;
  l.sensor_x = spec_.sensor_x;
  if (p.source != nullptr)
    for (const scenario::VeWrite& v : p.source->ve)
      l.ve.emplace_back(v.name, v.value);
  return l;
}

void LineWorld::StationPort::arm_probe(const machines::ProbeArm& c) noexcept {
  const bool rising = c.edge ? *c.edge == machines::ProbeEdge::rising : spec_.default_rising;
  if (auto e = probe_arm_error(c, rising, armed_, spec_.axis, spec_.axis_name, spec_.probe_input)) {
    raise(e->id.c_str(), std::move(e->message));
    return;
  }
  const bool front_rising = line_.conveyor_ ? line_.conveyor_->sensor.front_edge_rising : true;
  if (!line_.camera_ && rising != front_rising) {
    raise(kRearEdge, std::string("not supported: MC_TouchProbe for the ") +
                         (rising ? "rising" : "falling") +
                         " edge, the rear edge of the light barrier, in a line: a channel's "
                         "sensor along the belt gives the front edge (docs/lines.md)");
    return;
  }
  armed_ = ProbeArming{c.axis, c.channel, rising};
  if (spec_.method == MeasuringMethod::plc_queue) present();
  check_reachable();
}

void LineWorld::StationPort::check_reachable() noexcept {
  if (!armed_ || line_.more_for(k_)) return;
  raise(kNoWorkpieceId, "MC_TouchProbe armed on " + spec_.axis_name + " of channel " +
                            std::to_string(spec_.channel) +
                            ", but no workpiece is left to reach its sensor (the line's "
                            "[conveyor] stream is through, none free or held upstream of it): "
                            "the measured value would never come");
}

void LineWorld::StationPort::present() noexcept {
  while (armed_ && !queue_.empty()) {
    LatchInfo l = std::move(queue_.front());
    queue_.pop_front();
    Piece* p = line_.find(l.workpiece);
    if (p == nullptr || p->fate != Fate::free) continue;  // held downstream, or gone
    pending_.push_back(std::move(l));
    armed_.reset();
    line_.hold(*p, k_, line_.t_);
  }
}

void LineWorld::StationPort::sense(Piece& p, double t, double real) noexcept {
  const double measured = line_.world_->measured().p;
  if (spec_.method == MeasuringMethod::plc_queue) {
    queue_.push_back(latch(p, measured, real));  // the PLC reads the measured value
    if (queue_.size() > capacity_) {
      raise(kQueueFull, "the PLC's queue of measured values of channel " +
                            std::to_string(spec_.channel) + " is full (" +
                            std::to_string(capacity_) + ", conveyor.sensor.queue) at workpiece " +
                            std::to_string(p.workpiece));
      queue_.pop_back();
    }
    present();
    return;
  }
  if (!armed_) return;  // not measured here: it passes on
  // Method 1: the drive latches the real position (with the encoder's noise); method 2: the
  // PLC's trigger takes the NC's measured value of this cycle.
  const double value =
      spec_.method == MeasuringMethod::drive
          ? real + (line_.sigma_ > 0.0 ? line_.sigma_ * line_.latch_noise_.next() : 0.0)
          : measured;
  pending_.push_back(latch(p, value, real));
  armed_.reset();
  line_.hold(p, k_, t);
}

std::optional<double> LineWorld::StationPort::take_latch() noexcept {
  if (pending_.empty()) return std::nullopt;
  last_ = std::move(pending_.front());
  pending_.pop_front();
  // The PLC's words with the value: which workpiece, and how far it travelled since it passed
  // this channel's sensor (by the NC's measured value now).
  const double travel = line_.sign_ * (line_.world_->measured().p - last_.position);
  last_.ve.emplace_back(kVeWorkpiece, static_cast<double>(last_.workpiece));
  last_.ve.emplace_back(kVeTravel, travel);
  return last_.position;
}

LineWorld::LineWorld(std::unique_ptr<Port> world, const scenario::Conveyor* conveyor, double sign,
                     std::vector<StationSpec> stations, double belt_end)
    : world_(std::move(world)),
      conveyor_(conveyor != nullptr ? std::optional<scenario::Conveyor>(*conveyor) : std::nullopt),
      sign_(sign),
      belt_end_(belt_end),
      sensor_(conveyor_ ? &*conveyor_ : nullptr, sign),
      latch_noise_((conveyor_ && conveyor_->noise ? conveyor_->noise->seed : 1) ^
                   0x5A5A5A5AFEEDF00DULL) {
  if (conveyor_) {
    camera_ = conveyor_->sensor.kind == scenario::SensorKind::camera;
    sigma_ = conveyor_->noise ? conveyor_->noise->sigma : 0.0;
  }
  const std::size_t capacity = conveyor_ ? conveyor_->sensor.queue : 16;
  for (std::size_t k = 0; k < stations.size(); ++k)
    stations_.push_back(std::make_unique<StationPort>(*this, k, std::move(stations[k]), capacity));
}

LineWorld::~LineWorld() = default;

Port& LineWorld::port(std::size_t k) noexcept {
  return *stations_[k];
}

LineWorld::Piece* LineWorld::find(std::uint64_t workpiece) noexcept {
  for (Piece& p : pieces_)
    if (p.workpiece == workpiece) return &p;
  return nullptr;
}

const LineWorld::Piece* LineWorld::find_const(std::uint64_t workpiece) const noexcept {
  for (const Piece& p : pieces_)
    if (p.workpiece == workpiece) return &p;
  return nullptr;
}

void LineWorld::record(const Piece& p, double t) noexcept {
  if (p.workpiece == 0 || p.workpiece > fates_.size()) return;
  WorkpieceFate& f = fates_[p.workpiece - 1];
  f.fate = p.fate;
  f.channel = p.fate == Fate::held || p.fate == Fate::taken ? stations_[p.holder]->spec().channel
                                                            : std::uint8_t{0};
  f.t = t;
}

void LineWorld::hold(Piece& p, std::size_t k, double t) noexcept {
  p.fate = Fate::held;
  p.holder = k;
  record(p, t);
  for (const auto& s : stations_)  // the PLC assigns it to this channel alone
    s->drop(p.workpiece);
}

void LineWorld::arrive(const Edge& e) noexcept {
  ++arrived_;
  Piece p;
  p.workpiece = e.workpiece;
  p.u_front = sign_ * e.position;
  p.source = e.source;
  try {
    pieces_.push_back(p);
    if (fates_.size() < kMaxFateRecords && e.workpiece == fates_.size() + 1)
      fates_.push_back(WorkpieceFate{e.workpiece, e.t, Fate::free, 0, e.t});
  } catch (...) {
    std::abort();  // out of memory: the belt holds more workpieces than memory
  }
}

void LineWorld::finish(std::uint64_t workpiece, Fate fate, double t) noexcept {
  for (auto it = pieces_.begin(); it != pieces_.end(); ++it) {
    if (it->workpiece != workpiece) continue;
    it->fate = fate;
    record(*it, t);
    if (fate == Fate::missed) ++missed_;
    if (fate == Fate::taken) ++stations_[it->holder]->taken;
    for (const auto& s : stations_)
      s->drop(workpiece);
    pieces_.erase(it);
    return;
  }
}

void LineWorld::sense(double t0, double u0, double t1, double u1) noexcept {
  const auto when = [&](double u) {
    const double f = u1 > u0 ? std::clamp((u - u0) / (u1 - u0), 0.0, 1.0) : 1.0;
    return t0 + f * (t1 - t0);
  };
  std::vector<std::uint64_t> gone;
  for (Piece& p : pieces_) {
    while (p.next < stations_.size() && p.u_front + stations_[p.next]->spec().sensor_at <= u1) {
      const double at = p.u_front + stations_[p.next]->spec().sensor_at;
      if (p.fate == Fate::free) stations_[p.next]->sense(p, when(at), sign_ * at);
      ++p.next;
    }
    if (p.fate == Fate::free && p.u_front + belt_end_ <= u1) {
      p.t_end = when(p.u_front + belt_end_);
      gone.push_back(p.workpiece);
    }
  }
  for (const std::uint64_t w : gone) {
    const Piece* p = find_const(w);
    finish(w, Fate::missed, p != nullptr ? p->t_end : t1);
  }
}

void LineWorld::step_once(double t, bool arrivals) noexcept {
  if (stepped_ && *stepped_ >= t) return;
  stepped_ = t;
  const BeltState s0 = world_->actual();
  const double t0 = t_;
  world_->step(t);
  const BeltState& s1 = world_->actual();
  t_ = t;
  for (const Edge& e : sensor_.cycle(t0, s0, t, s1))
    if (arrivals && e.front && (e.rising || !camera_)) arrive(e);
  sense(t0, sign_ * s0.p, t, sign_ * s1.p);
  for (const auto& s : stations_)
    s->check_reachable();
}

double LineWorld::drain(double t, double dt, double t_max) noexcept {
  while (free_on_belt() > 0 && t + dt <= t_max + 0.5 * dt) {
    t += dt;
    step_once(t, false);
  }
  return t;
}

void LineWorld::let_go(std::size_t k, std::uint64_t workpiece, double t) noexcept {
  Piece* p = find(workpiece);
  if (p == nullptr || p->fate != Fate::held || p->holder != k) return;
  p->fate = Fate::free;
  record(*p, t);
  if (p->u_front + belt_end_ <= sign_ * world_->actual().p) finish(p->workpiece, Fate::missed, t);
}

void LineWorld::done(std::size_t k, std::uint64_t workpiece, double t) noexcept {
  const Piece* p = find(workpiece);
  if (p == nullptr || p->fate != Fate::held || p->holder != k) return;
  finish(p->workpiece, Fate::taken, t);
}

bool LineWorld::more_for(std::size_t k) const noexcept {
  if (sensor_.more_to_come() || stations_[k]->pending() || stations_[k]->queued_free()) return true;
  return std::any_of(pieces_.begin(), pieces_.end(), [&](const Piece& p) {
    return p.next <= k && !(p.fate == Fate::held && p.holder == k);
  });
}

std::uint64_t LineWorld::taken(std::size_t k) const noexcept {
  return stations_[k]->taken;
}

std::uint64_t LineWorld::taken_total() const noexcept {
  std::uint64_t n = 0;
  for (const auto& s : stations_)
    n += s->taken;
  return n;
}

std::uint64_t LineWorld::held() const noexcept {
  return static_cast<std::uint64_t>(std::count_if(
      pieces_.begin(), pieces_.end(), [](const Piece& p) { return p.fate == Fate::held; }));
}

}  // namespace ncsim::conveyor
