// planner/path: quintic Bezier blends with a numerical arc-length parametrisation.
// B(t) = sum_k C(5,k) (1-t)^(5-k) t^k P_k, t in [0, 1]. Arc length s(t) = int_0^t |B'|_metric;
// a table holds s at t = k/32 (5-point Gauss-Legendre per interval), s -> t inverts it by
// Newton steps inside the table interval. Derivatives with respect to s (sigma = |B'|):
//   x'   = B1 / sigma
//   x''  = B2 / sigma^2 - B1 sigma' / sigma^3,            sigma'  = (B1.B2) / sigma
//   x''' = B3 / sigma^3 - 3 B2 sigma' / sigma^4 - B1 sigma'' / sigma^4 + 3 B1 sigma'^2 / sigma^5,
//          sigma'' = ((B2.B2) + (B1.B3) - sigma'^2) / sigma   (dots over the metric axes).

#include <algorithm>
#include <cmath>

#include "planner/path.hpp"

namespace ncsim::planner {

namespace {

bool has(AxisMask mask, std::size_t i) {
  return ((mask >> i) & 1U) != 0;
}

// 5-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 5> kGlX = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                        0.5384693101056831, 0.9061798459386640};
constexpr std::array<double, 5> kGlW = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                        0.4786286704993665, 0.2369268850561891};

/// Bernstein basis of degree M (M + 1 values) at t.
template <int M>
std::array<double, M + 1> basis(double t) {
  std::array<double, M + 1> b{};
  const double u = 1.0 - t;
  std::array<double, M + 1> tp{};
  std::array<double, M + 1> up{};
  tp[0] = up[0] = 1.0;
  for (int k = 1; k <= M; ++k) {
    tp[k] = tp[k - 1] * t;
    up[k] = up[k - 1] * u;
  }
  double binom = 1.0;
  for (int i = 0; i <= M; ++i) {
    b[i] = binom * tp[i] * up[M - i];
    binom = binom * (M - i) / (i + 1);
  }
  return b;
}

struct Derivs {
  AxisVec b0{}, b1{}, b2{}, b3{};
};

/// B and its first three t-derivatives with one basis evaluation shared by every axis:
/// dB = 5 sum b4_i D1_i, d2B = 20 sum b3_i D2_i, d3B = 60 sum b2_i D3_i (forward differences Dk).
Derivs eval(const std::array<AxisVec, 6>& p, std::size_t n, double t) {
  const auto b5 = basis<5>(t);
  const auto b4 = basis<4>(t);
  const auto b3 = basis<3>(t);
  const auto b2 = basis<2>(t);
  Derivs d;
  for (std::size_t i = 0; i < n; ++i) {
    std::array<double, 6> c = {p[0][i], p[1][i], p[2][i], p[3][i], p[4][i], p[5][i]};
    double v0 = 0.0;
    for (int k = 0; k <= 5; ++k)
      v0 += b5[k] * c[k];
    for (int k = 0; k < 5; ++k)
      c[k] = c[k + 1] - c[k];
    double v1 = 0.0;
    for (int k = 0; k <= 4; ++k)
      v1 += b4[k] * c[k];
    for (int k = 0; k < 4; ++k)
      c[k] = c[k + 1] - c[k];
    double v2 = 0.0;
    for (int k = 0; k <= 3; ++k)
      v2 += b3[k] * c[k];
    for (int k = 0; k < 3; ++k)
      c[k] = c[k + 1] - c[k];
    double v3 = 0.0;
    for (int k = 0; k <= 2; ++k)
      v3 += b2[k] * c[k];
    d.b0[i] = v0;
    d.b1[i] = 5.0 * v1;
    d.b2[i] = 20.0 * v2;
    d.b3[i] = 60.0 * v3;
  }
  return d;
}

double speed(const std::array<AxisVec, 6>& p, std::size_t n, AxisMask metric, double t) {
  const auto b4 = basis<4>(t);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!has(metric, i)) continue;
    double v = 0.0;
    for (int k = 0; k < 5; ++k)
      v += b4[k] * (p[k + 1][i] - p[k][i]);
    v *= 5.0;
    sum += v * v;
  }
  return std::sqrt(sum);
}

double integrate_speed(const std::array<AxisVec, 6>& p, std::size_t n, AxisMask metric, double a,
                       double b) {
  const double h = 0.5 * (b - a);
  const double m = 0.5 * (a + b);
  double sum = 0.0;
  for (std::size_t k = 0; k < kGlX.size(); ++k)
    sum += kGlW[k] * speed(p, n, metric, m + h * kGlX[k]);
  return h * sum;
}

}  // namespace

Segment Segment::bezier(std::uint8_t axis_count, AxisMask metric, const std::array<AxisVec, 6>& p) {
  Segment seg;
  seg.n_ = axis_count;
  AxisMask all = 0;
  for (std::size_t i = 0; i < axis_count; ++i)
    all |= AxisMask{1} << i;
  seg.metric_ = metric & all;  // the caller passes the metric of the blended segments
  BezierGeom g;
  g.p = p;
  constexpr double dt = 1.0 / BezierGeom::kTable;
  for (int k = 0; k < BezierGeom::kTable; ++k)
    g.s_at[k + 1] = g.s_at[k] + integrate_speed(p, axis_count, seg.metric_, k * dt, (k + 1) * dt);
  seg.s_hi_ = g.s_at[BezierGeom::kTable];
  seg.geom_ = g;
  return seg;
}

double Segment::bezier_t(const BezierGeom& g, double s) const noexcept {
  constexpr double dt = 1.0 / BezierGeom::kTable;
  const auto it = std::upper_bound(g.s_at.begin(), g.s_at.end(), s);
  const int k = std::clamp(static_cast<int>(it - g.s_at.begin()) - 1, 0, BezierGeom::kTable - 1);
  const double t_k = k * dt;
  const double s_k = g.s_at[k];
  const double span = g.s_at[k + 1] - s_k;
  double t = span > 0.0 ? t_k + dt * std::clamp((s - s_k) / span, 0.0, 1.0) : t_k;
  for (int iter = 0; iter < 6; ++iter) {
    const double sp = speed(g.p, n_, metric_, t);
    if (sp <= 0.0) break;
    const double f = integrate_speed(g.p, n_, metric_, t_k, t) - (s - s_k);
    const double step = f / sp;
    t = std::clamp(t - step, t_k, t_k + dt);
    if (std::abs(step) < 1e-15) break;
  }
  return t;
}

PathPoint Segment::bezier_at_t(const BezierGeom& g, double t) const noexcept {
  const Derivs d = eval(g.p, n_, t);
  double b11 = 0.0, b12 = 0.0, b22 = 0.0, b13 = 0.0;
  for (std::size_t i = 0; i < n_; ++i) {
    if (!has(metric_, i)) continue;
    b11 += d.b1[i] * d.b1[i];
    b12 += d.b1[i] * d.b2[i];
    b22 += d.b2[i] * d.b2[i];
    b13 += d.b1[i] * d.b3[i];
  }
  PathPoint p;
  p.x = d.b0;
  const double sg = std::sqrt(b11);
  if (sg <= 0.0) return p;
  const double sg1 = b12 / sg;
  const double sg2 = (b22 + b13 - sg1 * sg1) / sg;
  const double s2 = sg * sg;
  const double s3 = s2 * sg;
  const double s4 = s3 * sg;
  const double s5 = s4 * sg;
  for (std::size_t i = 0; i < n_; ++i) {
    p.d1[i] = d.b1[i] / sg;
    p.d2[i] = d.b2[i] / s2 - d.b1[i] * sg1 / s3;
    p.d3[i] = d.b3[i] / s3 - 3.0 * d.b2[i] * sg1 / s4 - d.b1[i] * sg2 / s4 +
              3.0 * d.b1[i] * sg1 * sg1 / s5;
  }
  return p;
}

PathPoint Segment::bezier_at(const BezierGeom& g, double s) const noexcept {
  return bezier_at_t(g, bezier_t(g, s));
}

DerivativeBounds Segment::bezier_bounds() const noexcept {
  // Uniform in the curve parameter t over the window (no arc-length inversion per sample).
  constexpr int kSamples = 64;
  constexpr double kMargin = 1.01;
  const BezierGeom& g = std::get<BezierGeom>(geom_);
  const double t0 = bezier_t(g, s_lo_);
  const double t1 = bezier_t(g, s_hi_);
  DerivativeBounds b;
  for (int k = 0; k <= kSamples; ++k) {
    const PathPoint p = bezier_at_t(g, t0 + (t1 - t0) * k / kSamples);
    for (std::size_t i = 0; i < n_; ++i) {
      b.d1[i] = std::max(b.d1[i], std::abs(p.d1[i]));
      b.d2[i] = std::max(b.d2[i], std::abs(p.d2[i]));
      b.d3[i] = std::max(b.d3[i], std::abs(p.d3[i]));
    }
  }
  for (std::size_t i = 0; i < n_; ++i) {
    b.d1[i] = has(metric_, i) ? std::min(1.0, b.d1[i] * kMargin) : b.d1[i] * kMargin;
    b.d2[i] *= kMargin;
    b.d3[i] *= kMargin;
  }
  return b;
}

}  // namespace ncsim::planner
