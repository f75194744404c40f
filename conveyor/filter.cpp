#include "conveyor/filter.hpp"

#include <cmath>
#include <numbers>
#include <numeric>

namespace ncsim::conveyor {

std::vector<double> sinc_taps(std::size_t n) {
  std::vector<double> h(n, 1.0);
  if (n <= 1) return h;
  const double mid = 0.5 * static_cast<double>(n - 1);
  for (std::size_t k = 0; k < n; ++k) {
    // sinc(2 fc (k - mid) T) with fc = 1 / (n T): the main lobe spans the n taps.
    const double x = 2.0 * (static_cast<double>(k) - mid) / static_cast<double>(n);
    h[k] = x == 0.0 ? 1.0 : std::sin(std::numbers::pi * x) / (std::numbers::pi * x);
  }
  const double sum = std::accumulate(h.begin(), h.end(), 0.0);
  for (double& v : h)
    v /= sum;
  return h;
}

std::vector<double> average_taps(std::size_t n) {
  return std::vector<double>(n, n == 0 ? 1.0 : 1.0 / static_cast<double>(n));
}

Fir::Fir(std::vector<double> taps) : taps_(std::move(taps)) {
  if (taps_.empty()) taps_ = {1.0};
  ring_.assign(taps_.size(), 0.0);
}

void Fir::fill(double x) noexcept {
  std::fill(ring_.begin(), ring_.end(), x);
}

double Fir::push(double x) noexcept {
  const std::size_t n = ring_.size();
  head_ = head_ + 1 == n ? 0 : head_ + 1;
  ring_[head_] = x;
  double y = 0.0;
  std::size_t i = head_;  // newest first
  for (std::size_t k = 0; k < n; ++k) {
    y += taps_[k] * ring_[i];
    i = i == 0 ? n - 1 : i - 1;
  }
  return y;
}

double Fir::delay_samples() const noexcept {
  return 0.5 * static_cast<double>(taps_.size() - 1);
}

namespace {
std::vector<double> taps_of(int type, int order) {
  const auto n = static_cast<std::size_t>(order < 1 ? 1 : order);
  return type == 1 ? average_taps(n) : sinc_taps(n);
}
}  // namespace

ActualValueFilter::ActualValueFilter(const machines::ConveyorAxisParams& p, double t_cycle)
    : enabled_(p.enable_filter),
      t_cycle_(t_cycle),
      position_(taps_of(p.type_pos_filter, p.order_pos_filter)),
      normal_(sinc_taps(static_cast<std::size_t>(std::max(1, p.order_v_filter)))),
      dyn_(sinc_taps(static_cast<std::size_t>(std::max(1, p.order_v_filter_dyn)))),
      post_(average_taps(static_cast<std::size_t>(std::max(1, p.order_post_v_filter)))) {}

void ActualValueFilter::reset(double p, double v) noexcept {
  // A ramp through the position filter: history p - k v T, so that a constant velocity comes
  // out delayed by the filter's delay and without a start-up transient.
  position_.fill(p);
  if (enabled_) {
    const double n = 2.0 * position_.delay_samples() + 1.0;
    for (int k = static_cast<int>(n) - 1; k >= 0; --k)
      position_.push(p - static_cast<double>(k) * v * t_cycle_);
  }
  normal_.fill(v);
  dyn_.fill(v);
  post_.fill(v);
  v_prev_ = v;
  out_ = BeltState{enabled_ ? p - v * position_delay() : p, v, 0.0};
}

const BeltState& ActualValueFilter::push(double p, double v) noexcept {
  double pf = p;
  double vf = v;
  const double vn = normal_.push(v);
  const double vr = post_.push(dyn_.push(v));
  if (enabled_) {
    pf = position_.push(p);
    vf = reduced_ ? vr : vn;
  }
  out_ = BeltState{pf, vf, (vf - v_prev_) / t_cycle_};
  v_prev_ = vf;
  return out_;
}

double ActualValueFilter::position_delay() const noexcept {
  return enabled_ ? position_.delay_samples() * t_cycle_ : 0.0;
}

}  // namespace ncsim::conveyor
