// planner/blend: construction documented in blend.hpp.

#include "planner/blend.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "planner/corner.hpp"

namespace ncsim::planner {

namespace {

/// k(angle) minimising the peak curvature of the symmetric line-line blend, sampled at these
/// angles (degrees) by a one-off search over k in 0.05..1 (docs/planner.md "Blend curve").
constexpr std::array<double, 9> kAngleDeg = {0, 30, 60, 90, 120, 135, 150, 165, 175};
constexpr std::array<double, 9> kShape = {0.71, 0.70, 0.67, 0.61, 0.51, 0.43, 0.34, 0.20, 0.08};

constexpr int kRadiusHalvings = 20;
constexpr int kLambdaSteps = 12;
constexpr double kLambdaShrink = 0.75;

/// Distance over the metric axes.
struct Metric {
  std::size_t n = 0;
  AxisMask mask = 0;
  double operator()(const AxisVec& a, const AxisVec& b) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (((mask >> i) & 1U) != 0) sum += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(sum);
  }
};

/// Arc length s in [lo, hi] where the distance from `corner` equals r; the distance falls
/// monotonically from lo (where it is >= r) to the corner end (at hi when `toward_hi`).
/// `tangent` is the segment's tangent at the corner (a line's direction everywhere).
double cut_point(const Segment& seg, const Metric& distance, const AxisVec& corner, double r,
                 double lo, double hi, bool toward_hi, const AxisVec& tangent) {
  if (seg.kind() == SegmentKind::line) {
    // Closed form: the distance grows linearly with the arc length from the corner end.
    const double rate = distance(tangent, AxisVec{});
    if (rate > 0.0) {
      const double s_corner = toward_hi ? hi : lo;  // the corner is at the end of the search
      const double s = toward_hi == (hi > lo) ? s_corner - r / rate : s_corner + r / rate;
      return std::clamp(s, std::min(lo, hi), std::max(lo, hi));
    }
  }
  // Curved: regula falsi with the Illinois modification on f(s) = distance - r, which keeps a
  // sign-changing bracket (so it converges like bisection at worst) and needs about 8 points
  // instead of the 64 of plain bisection.
  auto f = [&](double s) { return distance(seg.point(s), corner) - r; };
  double a = lo;
  double b = hi;
  double fa = f(a);
  double fb = f(b);
  if (fa == 0.0) return a;
  if (fb == 0.0 || (fa > 0.0) == (fb > 0.0)) return toward_hi ? b : a;
  int side = 0;
  for (int iter = 0; iter < 64; ++iter) {
    const double c = (a * fb - b * fa) / (fb - fa);
    const double fc = f(c);
    if (std::abs(fc) <= 1e-14 * r || std::abs(b - a) <= 1e-15 * std::max(std::abs(a), 1.0))
      return c;
    if ((fc > 0.0) == (fa > 0.0)) {
      a = c;
      fa = fc;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      b = c;
      fb = fc;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

double blend_shape(double angle) noexcept {
  const double deg = angle * 180.0 / 3.14159265358979323846;
  if (deg <= kAngleDeg.front()) return kShape.front();
  for (std::size_t i = 1; i < kAngleDeg.size(); ++i) {
    if (deg <= kAngleDeg[i]) {
      const double f = (deg - kAngleDeg[i - 1]) / (kAngleDeg[i] - kAngleDeg[i - 1]);
      return kShape[i - 1] + f * (kShape[i] - kShape[i - 1]);
    }
  }
  return kShape.back();
}

JointEnds joint_ends(const Segment& in, const Segment& out) {
  const std::uint8_t n = std::max(in.axis_count(), out.axis_count());
  JointEnds ends{in.at(in.length()), out.at(0.0), 0.0};
  ends.angle = tangent_angle(ends.in_end.d1, ends.out_start.d1, n, in.metric() | out.metric());
  return ends;
}

std::optional<Blend> make_blend(const Segment& in, const Segment& out, double radius,
                                double max_cut_in, double max_cut_out) {
  return make_blend(in, out, joint_ends(in, out), radius, max_cut_in, max_cut_out);
}

std::optional<Blend> make_blend(const Segment& in, const Segment& out, const JointEnds& ends,
                                double radius, double max_cut_in, double max_cut_out) {
  return make_blend(in, out, ends, CornerDistances{radius, radius, true}, max_cut_in, max_cut_out);
}

std::optional<Blend> make_blend(const Segment& in, const Segment& out, const JointEnds& ends,
                                const CornerDistances& d, double max_cut_in, double max_cut_out) {
  const std::uint8_t n = std::max(in.axis_count(), out.axis_count());
  const AxisMask metric = in.metric() | out.metric();
  const Metric distance{n, metric};
  const double len_in = in.length();
  const double len_out = out.length();
  max_cut_in = std::clamp(max_cut_in, 0.0, len_in);
  max_cut_out = std::clamp(max_cut_out, 0.0, len_out);
  if (!(d.in > 0.0) || !(d.out > 0.0) || max_cut_in <= 0.0 || max_cut_out <= 0.0)
    return std::nullopt;

  const double angle = ends.angle;
  if (angle <= kTangentTolerance || angle > kMaxBlendAngle) return std::nullopt;

  const AxisVec corner = ends.in_end.x;
  const double reach_in = distance(in.point(len_in - max_cut_in), corner);
  const double reach_out = distance(out.point(max_cut_out), corner);
  // DEV: one ball, the nearer half-block point caps both ends; DIST: each end its own.
  double d_in = d.symmetric ? std::min({d.in, reach_in, reach_out}) : std::min(d.in, reach_in);
  double d_out = d.symmetric ? d_in : std::min(d.out, reach_out);
  const double k = blend_shape(angle);

  for (int halving = 0; halving <= kRadiusHalvings && std::max(d_in, d_out) > 1e-9;
       ++halving, d_in *= 0.5, d_out *= 0.5) {
    const double r = std::max(d_in, d_out);
    const double s_in =
        cut_point(in, distance, corner, d_in, len_in - max_cut_in, len_in, true, ends.in_end.d1);
    const double s_out =
        cut_point(out, distance, corner, d_out, max_cut_out, 0.0, true, ends.out_start.d1);
    const PathPoint a = in.at(s_in);
    const PathPoint b = out.at(s_out);
    double lambda_in = 2.5 * k * d_in;
    double lambda_out = 2.5 * k * d_out;
    for (int step = 0; step < kLambdaSteps;
         ++step, lambda_in *= kLambdaShrink, lambda_out *= kLambdaShrink) {
      std::array<AxisVec, 6> p{};
      for (std::size_t i = 0; i < n; ++i) {
        p[0][i] = a.x[i];
        p[1][i] = a.x[i] + lambda_in * a.d1[i] / 5.0;
        p[2][i] = 2.0 * p[1][i] - p[0][i] + lambda_in * lambda_in * a.d2[i] / 20.0;
        p[5][i] = b.x[i];
        p[4][i] = b.x[i] - lambda_out * b.d1[i] / 5.0;
        p[3][i] = 2.0 * p[4][i] - p[5][i] + lambda_out * lambda_out * b.d2[i] / 20.0;
      }
      const double tolerance = r * (1.0 + 1e-9) + 1e-12;
      const bool inside = std::all_of(
          p.begin(), p.end(), [&](const AxisVec& q) { return distance(q, corner) <= tolerance; });
      if (!inside) continue;
      // Ends at different distances: the speed along the curve varies more (bezier_uneven).
      Blend blend{
          d_in == d_out ? Segment::bezier(n, metric, p) : Segment::bezier_uneven(n, metric, p),
          len_in - s_in, s_out, r};
      return blend;
    }
  }
  return std::nullopt;
}

std::optional<CornerDistances> corner_distances(const Move& move) noexcept {
  switch (move.contour) {
    case Contour::none:
      return std::nullopt;
    case Contour::tolerance:
      return CornerDistances{move.path_dev, move.path_dev, true};
    case Contour::distance:
      return CornerDistances{move.pre_dist, move.post_dist, false};
  }
  return std::nullopt;
}

std::optional<Blend> corner_blend(const Move& in_move, const Segment& in, const Segment& out,
                                  const JointEnds& ends, double max_cut_in, double max_cut_out) {
  const std::optional<CornerDistances> d = corner_distances(in_move);
  if (!d) return std::nullopt;
  return make_blend(in, out, ends, *d, max_cut_in, max_cut_out);
}

std::optional<Blend> corner_blend(const Move& in_move, const Segment& in, const Segment& out,
                                  double max_cut_in, double max_cut_out) {
  if (!contoured(in_move)) return std::nullopt;
  return corner_blend(in_move, in, out, joint_ends(in, out), max_cut_in, max_cut_out);
}

}  // namespace ncsim::planner
