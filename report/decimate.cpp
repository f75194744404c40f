#include "report/decimate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/number_text.hpp"

namespace ncsim::report {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

MinMaxDecimator::MinMaxDecimator(std::size_t series, std::size_t max_buckets)
    : series_(series), max_buckets_(max_buckets) {
  if (max_buckets < 2 || max_buckets % 2 != 0)
    throw std::invalid_argument("report decimator: max_buckets must be even and >= 2, got " +
                                std::to_string(max_buckets));
  buckets_.reserve(max_buckets);
  ext_.reserve(max_buckets * series);
}

void MinMaxDecimator::add(double t, std::span<const double> values) {
  if (values.size() != series_)
    throw std::invalid_argument("report decimator: " + std::to_string(values.size()) +
                                " values for " + std::to_string(series_) + " series");
  if (buckets_.empty() || buckets_.back().count >= width_) {
    if (buckets_.size() == max_buckets_) merge_pairs();
    buckets_.push_back(Bucket{t, t, 0});
    ext_.resize(ext_.size() + series_, Extreme{kNaN, kNaN, 0, 0});
  }
  Bucket& b = buckets_.back();
  b.t1 = t;
  ++b.count;
  Extreme* e = ext_.data() + (buckets_.size() - 1) * series_;
  for (std::size_t s = 0; s < series_; ++s) {
    const double v = values[s];
    if (std::isnan(v)) continue;
    if (std::isnan(e[s].min) || v < e[s].min) {
      e[s].min = v;
      e[s].i_min = samples_;
    }
    if (std::isnan(e[s].max) || v > e[s].max) {
      e[s].max = v;
      e[s].i_max = samples_;
    }
  }
  ++samples_;
}

void MinMaxDecimator::merge_pairs() {
  const std::size_t half = buckets_.size() / 2;
  for (std::size_t k = 0; k < half; ++k) {
    const Bucket& a = buckets_[2 * k];
    const Bucket& b = buckets_[2 * k + 1];
    buckets_[k] = Bucket{a.t0, b.t1, a.count + b.count};
    for (std::size_t s = 0; s < series_; ++s) {
      const Extreme ea = ext_[2 * k * series_ + s];
      const Extreme eb = ext_[(2 * k + 1) * series_ + s];
      Extreme m = ea;
      // Ties keep the earlier sample (a comes first).
      if (std::isnan(m.min) || (!std::isnan(eb.min) && eb.min < m.min)) {
        m.min = eb.min;
        m.i_min = eb.i_min;
      }
      if (std::isnan(m.max) || (!std::isnan(eb.max) && eb.max > m.max)) {
        m.max = eb.max;
        m.i_max = eb.i_max;
      }
      ext_[k * series_ + s] = m;
    }
  }
  buckets_.resize(half);
  ext_.resize(half * series_);
  width_ *= 2;
}

Decimated MinMaxDecimator::finish() const {
  Decimated d;
  d.series.resize(series_);
  for (std::size_t k = 0; k < buckets_.size(); ++k) {
    const Bucket& b = buckets_[k];
    const bool two = b.count > 1;
    d.t.push_back(b.t0);
    if (two) d.t.push_back(b.t1);
    for (std::size_t s = 0; s < series_; ++s) {
      const Extreme& e = ext_[k * series_ + s];
      std::vector<double>& out = d.series[s];
      if (!two) {
        out.push_back(e.min);
      } else if (e.i_min <= e.i_max) {
        out.push_back(e.min);
        out.push_back(e.max);
      } else {
        out.push_back(e.max);
        out.push_back(e.min);
      }
    }
  }
  return d;
}

PathThinner::PathThinner(std::size_t dims, std::size_t max_points, double tolerance)
    : dims_(dims), max_points_(max_points), tol_(tolerance) {
  if (dims < 1 || dims > 3 || max_points < 4 || !(tolerance > 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("report path: dims 1..3, max_points >= 4, tolerance > 0; got " +
                                std::to_string(dims) + ", " + std::to_string(max_points) + ", " +
                                core::human(tolerance));
  kept_.reserve(max_points * dims);
}

bool PathThinner::far(const double* a, const double* b) const noexcept {
  for (std::size_t i = 0; i < dims_; ++i)
    if (std::fabs(a[i] - b[i]) >= tol_) return true;
  return false;
}

void PathThinner::add(std::span<const double> p) {
  if (p.size() != dims_)
    throw std::invalid_argument("report path: " + std::to_string(p.size()) + " coordinates for " +
                                std::to_string(dims_));
  for (const double c : p)
    if (!std::isfinite(c)) return;
  last_.assign(p.begin(), p.end());
  if (kept_.empty() || far(p.data(), kept_.data() + kept_.size() - dims_)) {
    kept_.insert(kept_.end(), p.begin(), p.end());
    if (kept_.size() / dims_ >= max_points_) rethin();
  }
}

void PathThinner::rethin() {
  while (kept_.size() / dims_ >= max_points_) {
    tol_ *= 2.0;
    std::size_t n = dims_;  // the first point stays
    for (std::size_t i = dims_; i < kept_.size(); i += dims_) {
      if (far(kept_.data() + i, kept_.data() + n - dims_)) {
        for (std::size_t k = 0; k < dims_; ++k)
          kept_[n + k] = kept_[i + k];
        n += dims_;
      }
    }
    kept_.resize(n);
  }
}

std::vector<double> PathThinner::finish() const {
  std::vector<double> out = kept_;
  if (!last_.empty() && (out.empty() || !std::equal(last_.begin(), last_.end(),
                                                    out.end() - static_cast<long>(dims_))))
    out.insert(out.end(), last_.begin(), last_.end());
  return out;
}

}  // namespace ncsim::report
