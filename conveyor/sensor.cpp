#include "conveyor/sensor.hpp"

#include <algorithm>
#include <limits>

namespace ncsim::conveyor {

Sensor::Sensor(const scenario::Conveyor* conveyor, double sign) : conveyor_(conveyor), sign_(sign) {
  if (conveyor_ == nullptr) return;
  camera_ = conveyor_->sensor.kind == scenario::SensorKind::camera;
  front_rising_ = conveyor_->sensor.front_edge_rising;
  for (std::size_t i = 0; i < conveyor_->workpieces.size(); ++i)
    (conveyor_->workpieces[i].travel ? travel_list_ : time_list_).push_back(i);
  if (conveyor_->series) {
    series_item_ = conveyor_->series->first;
    const auto& series = *conveyor_->series;
    series_next_ = series.first.travel ? *series.first.travel : series.first.t.value_or(0.0);
    scatter_ = SplitMix64(series.seed);
  }
}

double Sensor::series_at() const {
  const auto& s = *conveyor_->series;
  if (s.scatter > 0.0) return series_next_;
  const double first = s.first.travel ? *s.first.travel : *s.first.t;
  return first + static_cast<double>(next_series_) * s.pitch;
}

std::optional<Sensor::Pending> Sensor::next_by_travel() const {
  std::optional<Pending> best;
  if (next_travel_ < travel_list_.size()) {
    const scenario::Workpiece& w = conveyor_->workpieces[travel_list_[next_travel_]];
    best = Pending{w.travel, std::nullopt, &w};
  }
  if (conveyor_ != nullptr && conveyor_->series && conveyor_->series->first.travel &&
      next_series_ < conveyor_->series->count) {
    const auto& s = *conveyor_->series;
    const double travel = series_at();
    if (!best || travel < *best->travel) best = Pending{travel, std::nullopt, &s.first};
  }
  return best;
}

std::optional<Sensor::Pending> Sensor::next_by_time() const {
  std::optional<Pending> best;
  if (next_time_ < time_list_.size()) {
    const scenario::Workpiece& w = conveyor_->workpieces[time_list_[next_time_]];
    best = Pending{std::nullopt, w.t, &w};
  }
  if (conveyor_ != nullptr && conveyor_->series && conveyor_->series->first.t &&
      next_series_ < conveyor_->series->count) {
    const auto& s = *conveyor_->series;
    const double t = series_at();
    if (!best || t < *best->t) best = Pending{std::nullopt, t, &s.first};
  }
  return best;
}

void Sensor::consume(const Pending& p) {
  const bool from_series = conveyor_->series && p.source == &conveyor_->series->first;
  if (from_series) {
    ++next_series_;
    const auto& s = *conveyor_->series;
    if (s.scatter > 0.0) series_next_ += s.pitch + s.scatter * scatter_.uniform();
  } else if (p.travel) {
    ++next_travel_;
  } else {
    ++next_time_;
  }
}

bool Sensor::more_to_come() const noexcept {
  if (conveyor_ == nullptr) return false;
  return !in_beam_.empty() || next_travel_ < travel_list_.size() ||
         next_time_ < time_list_.size() ||
         (conveyor_->series && next_series_ < conveyor_->series->count);
}

void Sensor::emit(bool front, double t, double position, std::uint64_t workpiece,
                  const scenario::Workpiece* source) {
  if (camera_) {
    if (!front) return;
    edges_.push_back(Edge{true, true, t, position, workpiece, source});
    edges_.push_back(Edge{false, true, t, position, workpiece, source});
    return;
  }
  const bool rising = front ? front_rising_ : !front_rising_;
  edges_.push_back(Edge{rising, front, t, position, workpiece, source});
}

const std::vector<Edge>& Sensor::cycle(double t0, const BeltState& s0, double t1,
                                       const BeltState& s1) {
  edges_.clear();
  if (conveyor_ == nullptr || !(t1 > t0)) return edges_;
  const double dt = t1 - t0;
  const double u0 = sign_ * s0.p;  // travel in the conveying direction
  const double u1 = sign_ * s1.p;
  // The axis position at fraction f of the cycle (cubic Hermite on p and v).
  const auto position_at = [&](double f) {
    const double f2 = f * f, f3 = f2 * f;
    return (2 * f3 - 3 * f2 + 1) * s0.p + (f3 - 2 * f2 + f) * dt * s0.v +
           (-2 * f3 + 3 * f2) * s1.p + (f3 - f2) * dt * s1.v;
  };
  const auto travel_fraction = [&](double u) { return u1 > u0 ? (u - u0) / (u1 - u0) : 1.0; };
  for (;;) {
    // The earliest of: the next front edge by travel, by time, a rear edge in the beam.
    constexpr double kNone = std::numeric_limits<double>::infinity();
    double f_best = kNone;
    int kind = -1;  // 0 travel front, 1 time front, 2 rear
    std::size_t rear_index = 0;
    const auto by_travel = next_by_travel();
    if (by_travel && *by_travel->travel > u0 && *by_travel->travel <= u1) {
      f_best = travel_fraction(*by_travel->travel);
      kind = 0;
    }
    const auto by_time = next_by_time();
    if (by_time && *by_time->t <= t1) {
      const double f = std::max(0.0, (*by_time->t - t0) / dt);
      if (f < f_best) {
        f_best = f;
        kind = 1;
      }
    }
    for (std::size_t i = 0; i < in_beam_.size(); ++i) {
      if (in_beam_[i].travel > u0 && in_beam_[i].travel <= u1) {
        const double f = travel_fraction(in_beam_[i].travel);
        if (f < f_best) {
          f_best = f;
          kind = 2;
          rear_index = i;
        }
      }
    }
    if (kind < 0) break;
    const double t = t0 + f_best * dt;
    if (kind == 2) {
      const Rear r = in_beam_[rear_index];
      in_beam_.erase(in_beam_.begin() + static_cast<std::ptrdiff_t>(rear_index));
      if (in_beam_.empty()) emit(false, t, sign_ * r.travel, r.workpiece, r.source);
      continue;
    }
    const Pending p = kind == 0 ? *by_travel : *by_time;
    consume(p);
    const double position = kind == 0 ? sign_ * *p.travel : position_at(f_best);
    const std::uint64_t id = ++arrived_;
    const bool beam_was_clear = in_beam_.empty();
    if (!camera_) in_beam_.push_back(Rear{sign_ * position + p.source->length, id, p.source});
    if (camera_ || beam_was_clear) emit(true, t, position, id, p.source);
  }
  return edges_;
}

}  // namespace ncsim::conveyor
