// planner/spline: Akima and clamped cubic B-spline pieces from streamed points (spline.hpp).

#include "planner/spline.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/tolerance.hpp"
#include "planner/minimise.hpp"

namespace ncsim::planner {

namespace {

AxisVec axpy(const AxisVec& x, double a, const AxisVec& y, std::size_t n) {
  AxisVec r = x;
  for (std::size_t i = 0; i < n; ++i)
    r[i] += a * y[i];
  return r;
}

}  // namespace

Move spline_move(const SplinePiece& piece, const Move& modal) {
  Move move = modal;
  move.axis_count = piece.curve.axis_count();
  move.start = piece.control[0];
  move.end = piece.control[3];
  move.arc.reset();
  move.spline =
      std::make_shared<const SplineControl>(SplineControl{piece.control[1], piece.control[2]});
  move.rapid = false;
  move.block_time.reset();
  move.feed = piece.feed;
  move.line = piece.line;
  return move;
}

SplineBuilder::SplineBuilder(SplineType type, std::uint8_t axis_count, AxisMask path_axes)
    : type_(type), n_(axis_count), path_axes_(path_axes) {
  if (axis_count == 0 || axis_count > kMaxAxes)
    throw std::invalid_argument("planner: spline axis_count " + std::to_string(axis_count) +
                                " outside 1.." + std::to_string(kMaxAxes));
}

double SplineBuilder::chord_length(std::uint64_t k) const noexcept {
  const AxisVec& a = vertex(k).point;
  const AxisVec& b = vertex(k + 1).point;
  AxisVec d{};
  for (std::size_t i = 0; i < n_; ++i)
    d[i] = b[i] - a[i];
  const AxisMask metric = effective_metric(n_, path_axes_, d);
  double sum = 0.0;
  for (std::size_t i = 0; i < n_; ++i)
    if (((metric >> i) & 1U) != 0) sum += d[i] * d[i];
  return std::sqrt(sum);
}

AxisVec SplineBuilder::chord(std::int64_t k) const noexcept {
  const auto chords = static_cast<std::int64_t>(count_) - 1;
  if (chords == 1) k = 0;  // one chord: every direction is that chord (a straight piece)
  if (k < 0) {             // Akima's extrapolation: m_(-1) = 2 m_0 - m_1, m_(-2) = 2 m_(-1) - m_0
    const AxisVec a = chord(k + 1);
    const AxisVec b = chord(k + 2);
    AxisVec r{};
    for (std::size_t i = 0; i < n_; ++i)
      r[i] = 2.0 * a[i] - b[i];
    return r;
  }
  if (finished_ && k >= chords) {  // the mirror at the end
    const AxisVec a = chord(k - 1);
    const AxisVec b = chord(k - 2);
    AxisVec r{};
    for (std::size_t i = 0; i < n_; ++i)
      r[i] = 2.0 * a[i] - b[i];
    return r;
  }
  const auto uk = static_cast<std::uint64_t>(k);
  const double h = chord_length(uk);
  AxisVec r{};
  for (std::size_t i = 0; i < n_; ++i)
    r[i] = (vertex(uk + 1).point[i] - vertex(uk).point[i]) / h;
  return r;
}

AxisVec SplineBuilder::akima_tangent(std::int64_t i) const noexcept {
  const AxisVec m1 = chord(i - 2);
  const AxisVec m2 = chord(i - 1);
  const AxisVec m3 = chord(i);
  const AxisVec m4 = chord(i + 1);
  double w1 = 0.0;  // |m4 - m3|: weight of m2
  double w2 = 0.0;  // |m2 - m1|: weight of m3
  for (std::size_t a = 0; a < n_; ++a) {
    w1 += (m4[a] - m3[a]) * (m4[a] - m3[a]);
    w2 += (m2[a] - m1[a]) * (m2[a] - m1[a]);
  }
  w1 = std::sqrt(w1);
  w2 = std::sqrt(w2);
  AxisVec t{};
  const double sum = w1 + w2;
  for (std::size_t a = 0; a < n_; ++a)
    t[a] = sum > kTiny ? (w1 * m2[a] + w2 * m3[a]) / sum : 0.5 * (m2[a] + m3[a]);
  return t;
}

SplinePiece SplineBuilder::akima_piece(std::uint64_t k) const noexcept {
  const auto ik = static_cast<std::int64_t>(k);
  const double h = chord_length(k);
  const AxisVec& p0 = vertex(k).point;
  const AxisVec& p1 = vertex(k + 1).point;
  // Cubic Hermite in u in [0, h] as a cubic Bezier: inner points at +-h t / 3.
  const std::array<AxisVec, 4> c = {p0, axpy(p0, h / 3.0, akima_tangent(ik), n_),
                                    axpy(p1, -h / 3.0, akima_tangent(ik + 1), n_), p1};
  const SplineVertex& src = vertex(k + 1);
  return {Segment::cubic(n_, polygon_metric(n_, path_axes_, c), c), src.line, src.feed, c};
}

double SplineBuilder::knot(std::int64_t k) const noexcept {
  // Clamped uniform: t_k = clamp(k - 3, 0, n - 3); n is known only when finished (callers
  // ask for unclamped high knots only when the points are there).
  const double t = static_cast<double>(std::max<std::int64_t>(k - 3, 0));
  if (!finished_) return t;
  return std::min(t, static_cast<double>(count_) - 3.0);
}

SplinePiece SplineBuilder::bspline_piece(std::uint64_t k) noexcept {
  // De Boor span j = k + 3 (t_j = k <= u < k + 1 = t_(j+1)), control points k .. k + 3. Bezier
  // point m is the blossom at (3 - m) times t_j and m times t_(j+1).
  const auto j = static_cast<std::int64_t>(k) + 3;
  const double lo = knot(j);
  const double hi = knot(j + 1);
  std::array<AxisVec, 4> c{};
  for (int m = 0; m <= 3; ++m) {
    std::array<AxisVec, 4> d{};
    for (std::size_t i = 0; i < 4; ++i)
      d[i] = vertex(k + i).point;
    for (int r = 1; r <= 3; ++r) {
      const double arg = r <= 3 - m ? lo : hi;
      for (int i = 3; i >= r; --i) {
        const std::int64_t g = j - 3 + i;
        const double t0 = knot(g);
        const double t1 = knot(g + 4 - r);
        const double alpha = (arg - t0) / (t1 - t0);
        for (std::size_t a = 0; a < n_; ++a)
          d[i][a] = (1.0 - alpha) * d[i - 1][a] + alpha * d[i][a];
      }
    }
    c[m] = d[3];
  }
  if (k > 0) c[0] = last_end_;  // bit-equal joints (the blossoms agree up to rounding)
  last_end_ = c[3];
  const bool last = finished_ && k + 4 == count_;
  const SplineVertex& src = vertex(last ? count_ - 1 : k + 2);
  return {Segment::cubic(n_, polygon_metric(n_, path_axes_, c), c), src.line, src.feed, c};
}

void SplineBuilder::emit(std::uint64_t k) {
  out_[out_n_] = type_ == SplineType::akima ? akima_piece(k) : bspline_piece(k);
  ++out_n_;
  ++emitted_;
}

std::span<const SplinePiece> SplineBuilder::push(const SplineVertex& v) {
  out_n_ = 0;
  if (count_ > 0) {
    const AxisVec& last = vertex(count_ - 1).point;
    bool same = true;
    for (std::size_t i = 0; i < n_; ++i)
      same = same && std::abs(v.point[i] - last[i]) <= kSamePoint;
    if (same) return {};
  }
  ring_[count_ % kWindow] = v;
  ++count_;
  // Akima piece k needs points k - 2 .. k + 3; B-spline span k needs the knot t_(k+6)
  // unclamped, i.e. points up to k + 5.
  const std::uint64_t lead = type_ == SplineType::akima ? 4 : 6;
  if (count_ >= lead) emit(count_ - lead);
  return {out_.data(), out_n_};
}

std::span<const SplinePiece> SplineBuilder::finish() {
  out_n_ = 0;
  finished_ = true;
  if (type_ == SplineType::bspline && count_ > 1 && count_ < 4)
    throw std::invalid_argument("planner: a B-spline needs at least 4 control points, got " +
                                std::to_string(count_) + " (NC4401)");
  const std::uint64_t pieces =
      count_ < 2 ? 0 : (type_ == SplineType::akima ? count_ - 1 : count_ - 3);
  while (emitted_ < pieces)
    emit(emitted_);
  count_ = 0;
  emitted_ = 0;
  finished_ = false;
  return {out_.data(), out_n_};
}

std::vector<SplinePiece> split_near_cusp(const SplinePiece& piece, AxisMask path_axes) {
  constexpr int kSamples = 1024;
  constexpr int kHalvings = 30;  // the innermost parts are 2^-30 of a sample interval wide
  const std::size_t n = piece.curve.axis_count();
  const std::array<AxisVec, 4>& c = piece.control;
  constexpr double kMinPart = 1e-3;   // [mm] no cut nearer the near-cusp than 1 um
  const auto point = [&](double t) {  // B(t)
    const double s = 1.0 - t;
    AxisVec p{};
    for (std::size_t i = 0; i < n; ++i)
      p[i] = s * s * s * c[0][i] + 3.0 * s * s * t * c[1][i] + 3.0 * s * t * t * c[2][i] +
             t * t * t * c[3][i];
    return p;
  };
  const auto distance = [&](const AxisVec& a, const AxisVec& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (((path_axes >> i) & 1u) != 0) sum += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum);
  };
  const auto speed2 = [&](double t) {  // (|B'(t)| / 3)^2 over the path axes
    const double s = 1.0 - t;
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (((path_axes >> i) & 1u) == 0) continue;
      const double d = s * s * (c[1][i] - c[0][i]) + 2.0 * s * t * (c[2][i] - c[1][i]) +
                       t * t * (c[3][i] - c[2][i]);
      sum += d * d;
    }
    return sum;
  };
  std::array<double, kSamples + 1> v{};
  double v_max = 0.0;
  for (int k = 0; k <= kSamples; ++k) {
    v[k] = std::sqrt(speed2(static_cast<double>(k) / kSamples));
    v_max = std::max(v_max, v[k]);
  }
  // A run of samples below kCuspExtent of the largest speed, widened by a sample, whose
  // slowest sample is below kCuspSpeed holds a near-cusp: its speed minimum t_m (golden-section
  // search) and cuts at halving distances towards it from both ends of the run, so each part's
  // bounds come from its end nearest the near-cusp and the path slows down only as much as the
  // curvature there asks.
  const double low = kCuspExtent * v_max;
  std::vector<double> cuts;  // increasing parameters in (0, 1)
  for (int k = 0; k <= kSamples; ++k) {
    if (!(v[k] < low)) continue;
    int last = k;
    double slowest = v[k];
    while (last < kSamples && v[last + 1] < low)
      slowest = std::min(slowest, v[++last]);
    if (!(slowest < kCuspSpeed * v_max)) {
      k = last;
      continue;
    }
    const double t_lo = static_cast<double>(std::max(0, k - 1)) / kSamples;
    const double t_hi = static_cast<double>(std::min(kSamples, last + 1)) / kSamples;
    k = last + 1;
    const double t_m = golden_section_minimum(speed2, t_lo, t_hi, 100);
    // Halving stops 1 um from the near-cusp: smaller parts lose their digits (control points
    // within a few ulp of 500 mm), and the innermost part's curvature is the near-cusp's.
    const AxisVec p_m = point(t_m);
    const auto far = [&](double t) { return distance(point(t), p_m) >= kMinPart; };
    const auto add_cut = [&](double t) {
      if (t > 0.0 && t < 1.0 && (cuts.empty() || t > cuts.back())) cuts.push_back(t);
    };
    for (int j = 0; j <= kHalvings && far(t_m - (t_m - t_lo) * std::ldexp(1.0, -j)); ++j)
      add_cut(t_m - (t_m - t_lo) * std::ldexp(1.0, -j));
    int j_right = 0;  // the innermost cut right of t_m still 1 um away
    while (j_right < kHalvings && far(t_m + (t_hi - t_m) * std::ldexp(1.0, -(j_right + 1))))
      ++j_right;
    for (int j = j_right; j >= 0; --j)
      add_cut(t_m + (t_hi - t_m) * std::ldexp(1.0, -j));
  }
  std::vector<SplinePiece> out;
  if (cuts.empty()) return out;
  // de Casteljau: the control points of the part [0, t] of `p`, and of [t, 1].
  const auto split = [n](const std::array<AxisVec, 4>& p, double t) {
    std::array<AxisVec, 4> left{}, right{};
    for (std::size_t i = 0; i < n; ++i) {
      const double a = p[0][i] + t * (p[1][i] - p[0][i]);
      const double b = p[1][i] + t * (p[2][i] - p[1][i]);
      const double d = p[2][i] + t * (p[3][i] - p[2][i]);
      const double ab = a + t * (b - a);
      const double bd = b + t * (d - b);
      const double m = ab + t * (bd - ab);
      left[0][i] = p[0][i];
      left[1][i] = a;
      left[2][i] = ab;
      left[3][i] = m;
      right[0][i] = m;
      right[1][i] = bd;
      right[2][i] = d;
      right[3][i] = p[3][i];
    }
    return std::pair{left, right};
  };
  const auto add = [&](const std::array<AxisVec, 4>& p) {
    const auto axes = static_cast<std::uint8_t>(n);
    out.push_back(
        {Segment::cubic(axes, polygon_metric(axes, path_axes, p), p), piece.line, piece.feed, p});
  };
  out.reserve(cuts.size() + 1);
  std::array<AxisVec, 4> rest = c;
  double t_rest = 0.0;  // where `rest` starts on the piece
  for (const double t : cuts) {
    const auto [left, right] = split(rest, (t - t_rest) / (1.0 - t_rest));
    add(left);  // a part ends where the next starts, bit for bit (the same point m)
    rest = right;
    t_rest = t;
  }
  add(rest);
  return out;
}

}  // namespace ncsim::planner
