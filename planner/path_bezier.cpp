// planner/path: quintic Bezier blends with a numerical arc-length parametrisation.
// B(t) = sum_k C(5,k) (1-t)^(5-k) t^k P_k, t in [0, 1]. Arc length s(t) = int_0^t |B'|_metric;
// a table holds s at t = k/K (5-point Gauss-Legendre per interval; K = 16 for a blend, 32 for a
// spline piece), s -> t inverts it by Newton steps inside the table interval. Derivatives with
// respect to s (sigma = |B'|):
//   x'   = B1 / sigma
//   x''  = B2 / sigma^2 - B1 sigma' / sigma^3,            sigma'  = (B1.B2) / sigma
//   x''' = B3 / sigma^3 - 3 B2 sigma' / sigma^4 - B1 sigma'' / sigma^4 + 3 B1 sigma'^2 / sigma^5,
//          sigma'' = ((B2.B2) + (B1.B3) - sigma'^2) / sigma   (dots over the metric axes).

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "core/tolerance.hpp"
#include "planner/minimise.hpp"
#include "planner/path.hpp"

namespace ncsim::planner {

namespace {

// 5-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 5> kGlX = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                        0.5384693101056831, 0.9061798459386640};
constexpr std::array<double, 5> kGlW = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                        0.4786286704993665, 0.2369268850561891};

// Two builds of the numeric loops below (blend_bounds, arc_length_table): the baseline
// instruction set and, on x86-64 with g++, AVX2, taken where the CPU has it (4 doubles an
// instruction instead of 2). Both are the same source inlined into each, with only the IEEE
// operations of the baseline build (add, sub, mul, div, sqrt, and, compare and select: correctly
// rounded or exact, the same in every width; AVX2 brings no FMA, and path_bezier.cpp is compiled
// with -ffp-contract=off), so both give the same values to the bit (test: path_test.cpp,
// "... the AVX2 build ..."). allow_wide_loops(false) keeps the baseline build (tests).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define NCSIM_WIDE_LOOPS 1
#endif

std::atomic<bool> g_wide_loops{true};  // allow_wide_loops()

bool has_avx2() noexcept {
#ifdef NCSIM_WIDE_LOOPS
  static const bool avx2 = __builtin_cpu_supports("avx2") != 0;
  return avx2;
#else
  return false;
#endif
}

/// The AVX2 build is taken.
bool wide() noexcept {
  return has_avx2() && g_wide_loops.load(std::memory_order_relaxed);
}

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

/// Control points of B and of its first three t-derivatives (hodographs), per axis:
/// dB = 5 sum b4_k D1_k, d2B = 20 sum b3_k D2_k, d3B = 60 sum b2_k D3_k (forward differences,
/// scaled here once). Only the first n axes are set (and read): zeroing all kMaxAxes cost
/// more than computing the n used (git history of docs/benchmarks.md, issue 12 session 21).
struct Hodographs {
  std::array<AxisVec, 6> c0;
  std::array<AxisVec, 5> c1;
  std::array<AxisVec, 4> c2;
  std::array<AxisVec, 3> c3;
};

Hodographs hodographs(const std::array<AxisVec, 6>& p, std::size_t n) {
  Hodographs h;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < 6; ++k)
      h.c0[k][i] = p[k][i];
    for (std::size_t k = 0; k < 5; ++k)
      h.c1[k][i] = p[k + 1][i] - p[k][i];
    for (std::size_t k = 0; k < 4; ++k)
      h.c2[k][i] = h.c1[k + 1][i] - h.c1[k][i];
    for (std::size_t k = 0; k < 3; ++k)
      h.c3[k][i] = h.c2[k + 1][i] - h.c2[k][i];
    for (std::size_t k = 0; k < 5; ++k)
      h.c1[k][i] *= 5.0;
    for (std::size_t k = 0; k < 4; ++k)
      h.c2[k][i] *= 20.0;
    for (std::size_t k = 0; k < 3; ++k)
      h.c3[k][i] *= 60.0;
  }
  return h;
}

/// B and its first three t-derivatives from the hodographs and the Bernstein values at t,
/// written to the first n axes of d (x: B, d1..d3: dB/dt, d2B/dt2, d3B/dt3; the caller's
/// PathPoint, turned into arc-length derivatives in place by to_arc_length()).
void eval_with(const Hodographs& h, std::size_t n, const std::array<double, 6>& b5,
               const std::array<double, 5>& b4, const std::array<double, 4>& b3,
               const std::array<double, 3>& b2, PathPoint& d) {
  for (std::size_t i = 0; i < n; ++i) {
    double v0 = 0.0, v1 = 0.0, v2 = 0.0, v3 = 0.0;
    for (std::size_t k = 0; k < 6; ++k)
      v0 += b5[k] * h.c0[k][i];
    for (std::size_t k = 0; k < 5; ++k)
      v1 += b4[k] * h.c1[k][i];
    for (std::size_t k = 0; k < 4; ++k)
      v2 += b3[k] * h.c2[k][i];
    for (std::size_t k = 0; k < 3; ++k)
      v3 += b2[k] * h.c3[k][i];
    d.x[i] = v0;
    d.d1[i] = v1;
    d.d2[i] = v2;
    d.d3[i] = v3;
  }
}

void eval(const std::array<AxisVec, 6>& p, std::size_t n, double t, PathPoint& d) {
  eval_with(hodographs(p, n), n, basis<5>(t), basis<4>(t), basis<3>(t), basis<2>(t), d);
}

/// eval() at an end of the curve (t = 0 or t = 1), where every Bernstein value is 0 but one,
/// which is exactly 1: B and its derivatives are the first (last) control point of each
/// hodograph. The same differences as hodographs() and the same sums as eval_with() (from 0.0,
/// every other term +-0), so the same values to the bit; the joints of every blend ask here.
void eval_end(const std::array<AxisVec, 6>& p, std::size_t n, bool at_end, PathPoint& d) {
  for (std::size_t i = 0; i < n; ++i) {
    const double e0 = p[1][i] - p[0][i];
    const double e1 = p[2][i] - p[1][i];
    const double e2 = p[3][i] - p[2][i];
    const double e3 = p[4][i] - p[3][i];
    const double e4 = p[5][i] - p[4][i];
    const double f0 = e1 - e0;
    const double f1 = e2 - e1;
    const double f2 = e3 - e2;
    const double f3 = e4 - e3;
    if (!at_end) {
      d.x[i] = 0.0 + p[0][i];
      d.d1[i] = 0.0 + e0 * 5.0;
      d.d2[i] = 0.0 + f0 * 20.0;
      d.d3[i] = 0.0 + (f1 - f0) * 60.0;
    } else {
      d.x[i] = 0.0 + p[5][i];
      d.d1[i] = 0.0 + e4 * 5.0;
      d.d2[i] = 0.0 + f3 * 20.0;
      d.d3[i] = 0.0 + (f3 - f2) * 60.0;
    }
  }
}

/// Degree-8 Bernstein values at the 5 K Gauss nodes of a K-interval arc-length table (|B'|^2
/// is a degree-8 polynomial), by degree index first (b8[j][node]): the table's loop runs over
/// the nodes innermost.
template <int K>
struct GaussNodes {
  static constexpr std::size_t kNodes = static_cast<std::size_t>(K) * 5;
  std::array<std::array<double, kNodes>, 9> b8{};
  GaussNodes() {
    constexpr double dt = 1.0 / K;
    for (int k = 0; k < K; ++k)
      for (std::size_t g = 0; g < 5; ++g) {
        const auto b = basis<8>((k + 0.5) * dt + 0.5 * dt * kGlX[g]);
        for (std::size_t j = 0; j < 9; ++j)
          b8[j][static_cast<std::size_t>(k) * 5 + g] = b[j];
      }
  }
};

/// Bernstein values at fixed parameters, computed once: the arc-length tables' Gauss nodes and
/// the bound samples (the same t for every curve, so no basis is recomputed per curve).
struct Tables {
  static constexpr int kSamples = 64;  ///< bound samples: t = k / 64, k = 0..64
  GaussNodes<geom::BezierGeom::kTable> gauss_spline;
  GaussNodes<geom::BezierGeom::kBlendTable> gauss_blend;
  std::array<std::array<double, 6>, kSamples + 1> s5{};
  std::array<std::array<double, 5>, kSamples + 1> s4{};
  std::array<std::array<double, 4>, kSamples + 1> s3{};
  std::array<std::array<double, 3>, kSamples + 1> s2{};
  /// The same values by degree index first (u4[m][k] = s4[k][m]), padded to a multiple of 4
  /// with the last sample repeated: the blend bound loop runs over k innermost (blend_bounds),
  /// in lanes of 4.
  static constexpr std::size_t kPadded = kSamples + 4;
  std::array<std::array<double, kPadded>, 5> u4{};
  std::array<std::array<double, kPadded>, 4> u3{};
  std::array<std::array<double, kPadded>, 3> u2{};
  // The same for the spline pieces' kSplineBoundSamples (degrees 4, 3, 2 only).
  std::array<std::array<double, 5>, kSplineBoundSamples + 1> f4{};
  std::array<std::array<double, 4>, kSplineBoundSamples + 1> f3{};
  std::array<std::array<double, 3>, kSplineBoundSamples + 1> f2{};
  Tables() {
    for (int k = 0; k <= kSamples; ++k) {
      const double t = static_cast<double>(k) / kSamples;
      const auto u = static_cast<std::size_t>(k);
      s5[u] = basis<5>(t);
      s4[u] = basis<4>(t);
      s3[u] = basis<3>(t);
      s2[u] = basis<2>(t);
    }
    for (std::size_t k = 0; k < kPadded; ++k) {
      const std::size_t from = std::min<std::size_t>(k, kSamples);
      for (std::size_t m = 0; m < 5; ++m)
        u4[m][k] = s4[from][m];
      for (std::size_t m = 0; m < 4; ++m)
        u3[m][k] = s3[from][m];
      for (std::size_t m = 0; m < 3; ++m)
        u2[m][k] = s2[from][m];
    }
    for (std::size_t k = 0; k <= kSplineBoundSamples; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(kSplineBoundSamples);
      f4[k] = basis<4>(t);
      f3[k] = basis<3>(t);
      f2[k] = basis<2>(t);
    }
  }
};

const Tables& tables() {
  static const Tables t;
  return t;
}

/// The bounds of a whole blend on the 65 tabled parameters: the arithmetic of the general loop
/// in Segment::bezier_bounds (the same operations in the same order per sample, so the same
/// values), with the samples innermost so that the compiler can vectorise; the padding sample
/// repeats the last one (maxima unchanged). An axis outside `moving` (constant on the curve:
/// every hodograph value 0) is skipped: its terms would add +0 to the sums and its bounds are
/// 0, the values the loops would compute. The sums start at their first term instead of at 0.0
/// (0.0 + x is x, except that it turns -0 into +0): a sum differs from the general loop's at
/// most in the sign of a zero, and no sign of a zero reaches a bound (every bound is the
/// maximum of |values|, the zeros meet no division, and x + (+-0) is x for x != 0), so the
/// bounds are the same to the bit. Inlined into a build for the baseline instruction set and,
/// on x86-64 with g++, one for AVX2 (blend_bounds below).
[[gnu::always_inline]] inline DerivativeBounds blend_bounds_body(const Hodographs& h, std::size_t n,
                                                                 AxisMask metric, AxisMask moving) {
  constexpr std::size_t kN = Tables::kPadded;
  const Tables& tab = tables();
  std::array<std::array<double, kN>, kMaxAxes> v1;  // first n rows set
  std::array<std::array<double, kN>, kMaxAxes> v2;
  std::array<std::array<double, kN>, kMaxAxes> v3;
  std::array<double, kN> b11, b12, b22, b13;  // set by the first metric axis (or zeroed below)
  bool sums_set = false;
  // Planar CAM: two moving axes, both metric. Both axes and the sums in one loop over the
  // samples, so each Bernstein value is loaded once for both: the same operations in the same
  // order as the loop below (first axis, then the second added to the sums), the same values.
  std::array<std::size_t, 2> two{};
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (has(moving, i)) {
      if (count < 2) two[count] = i;
      ++count;
    }
  if (count == 2 && has(metric, two[0]) && has(metric, two[1])) {
    const std::size_t i = two[0];
    const std::size_t o = two[1];
    std::array<double, kN>& x1 = v1[i];
    std::array<double, kN>& x2 = v2[i];
    std::array<double, kN>& x3 = v3[i];
    std::array<double, kN>& y1 = v1[o];
    std::array<double, kN>& y2 = v2[o];
    std::array<double, kN>& y3 = v3[o];
    const std::array<double, 5> e1 = {h.c1[0][i], h.c1[1][i], h.c1[2][i], h.c1[3][i], h.c1[4][i]};
    const std::array<double, 4> e2 = {h.c2[0][i], h.c2[1][i], h.c2[2][i], h.c2[3][i]};
    const std::array<double, 3> e3 = {h.c3[0][i], h.c3[1][i], h.c3[2][i]};
    const std::array<double, 5> f1 = {h.c1[0][o], h.c1[1][o], h.c1[2][o], h.c1[3][o], h.c1[4][o]};
    const std::array<double, 4> f2 = {h.c2[0][o], h.c2[1][o], h.c2[2][o], h.c2[3][o]};
    const std::array<double, 3> f3 = {h.c3[0][o], h.c3[1][o], h.c3[2][o]};
    for (std::size_t k = 0; k < kN; ++k) {
      const double u40 = tab.u4[0][k], u41 = tab.u4[1][k], u42 = tab.u4[2][k];
      const double u43 = tab.u4[3][k], u44 = tab.u4[4][k];
      const double u30 = tab.u3[0][k], u31 = tab.u3[1][k], u32 = tab.u3[2][k];
      const double u33 = tab.u3[3][k];
      const double u20 = tab.u2[0][k], u21 = tab.u2[1][k], u22 = tab.u2[2][k];
      const double a1 = u40 * e1[0] + u41 * e1[1] + u42 * e1[2] + u43 * e1[3] + u44 * e1[4];
      const double a2 = u30 * e2[0] + u31 * e2[1] + u32 * e2[2] + u33 * e2[3];
      const double a3 = u20 * e3[0] + u21 * e3[1] + u22 * e3[2];
      const double d1 = u40 * f1[0] + u41 * f1[1] + u42 * f1[2] + u43 * f1[3] + u44 * f1[4];
      const double d2 = u30 * f2[0] + u31 * f2[1] + u32 * f2[2] + u33 * f2[3];
      const double d3 = u20 * f3[0] + u21 * f3[1] + u22 * f3[2];
      x1[k] = a1;
      x2[k] = a2;
      x3[k] = a3;
      y1[k] = d1;
      y2[k] = d2;
      y3[k] = d3;
      double s11 = a1 * a1;
      double s12 = a1 * a2;
      double s22 = a2 * a2;
      double s13 = a1 * a3;
      s11 += d1 * d1;
      s12 += d1 * d2;
      s22 += d2 * d2;
      s13 += d1 * d3;
      b11[k] = s11;
      b12[k] = s12;
      b22[k] = s22;
      b13[k] = s13;
    }
    sums_set = true;
  }
  const bool planar = sums_set;  // the loop below is done already
  for (std::size_t i = 0; i < n && !planar; ++i) {
    if (!has(moving, i)) continue;
    std::array<double, kN>& a1 = v1[i];
    std::array<double, kN>& a2 = v2[i];
    std::array<double, kN>& a3 = v3[i];
    // Each value summed over m in order (the general loop's order), in registers.
    const std::array<double, 5> e1 = {h.c1[0][i], h.c1[1][i], h.c1[2][i], h.c1[3][i], h.c1[4][i]};
    const std::array<double, 4> e2 = {h.c2[0][i], h.c2[1][i], h.c2[2][i], h.c2[3][i]};
    const std::array<double, 3> e3 = {h.c3[0][i], h.c3[1][i], h.c3[2][i]};
    for (std::size_t k = 0; k < kN; ++k) {
      a1[k] = tab.u4[0][k] * e1[0] + tab.u4[1][k] * e1[1] + tab.u4[2][k] * e1[2] +
              tab.u4[3][k] * e1[3] + tab.u4[4][k] * e1[4];
      a2[k] =
          tab.u3[0][k] * e2[0] + tab.u3[1][k] * e2[1] + tab.u3[2][k] * e2[2] + tab.u3[3][k] * e2[3];
      a3[k] = tab.u2[0][k] * e3[0] + tab.u2[1][k] * e3[1] + tab.u2[2][k] * e3[2];
    }
    if (!has(metric, i)) continue;
    if (!sums_set) {
      for (std::size_t k = 0; k < kN; ++k) {
        b11[k] = a1[k] * a1[k];
        b12[k] = a1[k] * a2[k];
        b22[k] = a2[k] * a2[k];
        b13[k] = a1[k] * a3[k];
      }
      sums_set = true;
      continue;
    }
    for (std::size_t k = 0; k < kN; ++k) {
      b11[k] += a1[k] * a1[k];
      b12[k] += a1[k] * a2[k];
      b22[k] += a2[k] * a2[k];
      b13[k] += a1[k] * a3[k];
    }
  }
  if (!sums_set) {  // no metric axis moves: every sample has |B'| = 0
    b11.fill(0.0);
    b12.fill(0.0);
    b22.fill(0.0);
    b13.fill(0.0);
  }
  // Per sample: 1 / sg and the factors of the second and third derivatives (the general loop's
  // i2, i3, c1, c2, c3); a sample with sg = 0 contributes nothing (all its factors 0). Without
  // a branch, so that the loops vectorise (sqrt without errno: CMakeLists.txt): a dead sample
  // is computed with sg = 1 (b12 = b22 = b13 = 0 there: finite) and its factors multiplied by
  // 0; a live one by 1, exactly its values. Three loops: one with the selects alone keeps the
  // compiler from turning them back into branches.
  std::array<double, kN> sg, live;  // every entry written below (no zeroing)
  for (std::size_t k = 0; k < kN; ++k)
    sg[k] = std::sqrt(b11[k]);
  for (std::size_t k = 0; k < kN; ++k) {
    live[k] = sg[k] > 0.0 ? 1.0 : 0.0;
    sg[k] = sg[k] > 0.0 ? sg[k] : 1.0;
  }
  std::array<double, kN> inv, i2, i3, c1, c2, c3;
  for (std::size_t k = 0; k < kN; ++k) {
    const double iv = 1.0 / sg[k];
    const double sg1 = b12[k] * iv;
    const double sg2 = (b22[k] + b13[k] - sg1 * sg1) * iv;
    const double q2 = iv * iv;
    const double q3 = q2 * iv;
    const double q4 = q3 * iv;
    const double m = live[k];
    inv[k] = iv * m;
    i2[k] = q2 * m;
    i3[k] = q3 * m;
    c1[k] = sg1 * q3 * m;
    c2[k] = 3.0 * sg1 * q4 * m;
    c3[k] = (3.0 * sg1 * sg1 * q4 * iv - sg2 * q4) * m;
  }
  // The maxima over the samples: the |values| in one loop, then running maxima in lanes of
  // kLanes samples (a GNU vector type), then over the lanes. Per lane the select
  // `x > m ? x : m` is what std::max(m, x) is, also for a NaN x (m stays), and the maximum of
  // numbers >= 0 does not depend on the order they are taken in, so this is the largest of the
  // same |values| as a scalar loop gives. With std::max in one loop the compiler left it scalar
  // (25 instructions a sample, a third of the blend's bounds; session dense3).
  constexpr std::size_t kLanes = 4;
  using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
  static_assert(kN % kLanes == 0);
  DerivativeBounds b;                 // zero: the bounds of the constant axes
  std::array<double, kN> x1, x2, x3;  // every entry written below
  for (std::size_t i = 0; i < n; ++i) {
    if (!has(moving, i)) continue;
    const std::array<double, kN>& a1 = v1[i];
    const std::array<double, kN>& a2 = v2[i];
    const std::array<double, kN>& a3 = v3[i];
    for (std::size_t q = 0; q < kN; ++q) {
      x1[q] = std::abs(a1[q] * inv[q]);
      x2[q] = std::abs(a2[q] * i2[q] - a1[q] * c1[q]);
      x3[q] = std::abs(a3[q] * i3[q] - a2[q] * c2[q] + a1[q] * c3[q]);
    }
    Lanes m1{}, m2{}, m3{};
    for (std::size_t k = 0; k < kN; k += kLanes) {
      Lanes y1, y2, y3;
      std::memcpy(&y1, &x1[k], sizeof y1);
      std::memcpy(&y2, &x2[k], sizeof y2);
      std::memcpy(&y3, &x3[k], sizeof y3);
      m1 = y1 > m1 ? y1 : m1;
      m2 = y2 > m2 ? y2 : m2;
      m3 = y3 > m3 ? y3 : m3;
    }
    for (std::size_t l = 0; l < kLanes; ++l) {
      b.d1[i] = std::max(b.d1[i], m1[l]);
      b.d2[i] = std::max(b.d2[i], m2[l]);
      b.d3[i] = std::max(b.d3[i], m3[l]);
    }
  }
  return b;
}

DerivativeBounds blend_bounds_baseline(const Hodographs& h, std::size_t n, AxisMask metric,
                                       AxisMask moving) {
  return blend_bounds_body(h, n, metric, moving);
}

#ifdef NCSIM_WIDE_LOOPS
/// The same source for AVX2 (above: NCSIM_WIDE_LOOPS).
[[gnu::target("avx2")]] DerivativeBounds blend_bounds_avx2(const Hodographs& h, std::size_t n,
                                                           AxisMask metric, AxisMask moving) {
  return blend_bounds_body(h, n, metric, moving);
}
#endif

DerivativeBounds blend_bounds(const Hodographs& h, std::size_t n, AxisMask metric,
                              AxisMask moving) {
#ifdef NCSIM_WIDE_LOOPS
  if (wide()) return blend_bounds_avx2(h, n, metric, moving);
#endif
  return blend_bounds_baseline(h, n, metric, moving);
}

/// |B'|^2 over the metric axes as a degree-8 Bernstein polynomial: the square of each axis's
/// degree-4 hodograph, B4_a B4_b = C(4,a) C(4,b) / C(8,a+b) B8_(a+b).
std::array<double, 9> squared_speed(const std::array<AxisVec, 6>& p, std::size_t n,
                                    AxisMask metric) {
  constexpr std::array<double, 5> c4 = {1.0, 4.0, 6.0, 4.0, 1.0};
  constexpr std::array<double, 9> c8 = {1.0, 8.0, 28.0, 56.0, 70.0, 56.0, 28.0, 8.0, 1.0};
  std::array<double, 9> beta{};
  for (std::size_t i = 0; i < n; ++i) {
    if (!has(metric, i)) continue;
    std::array<double, 5> d{};
    for (std::size_t k = 0; k < 5; ++k)
      d[k] = 5.0 * (p[k + 1][i] - p[k][i]);
    for (std::size_t a = 0; a < 5; ++a)
      for (std::size_t b = 0; b < 5; ++b)
        beta[a + b] += c4[a] * c4[b] * d[a] * d[b];
  }
  for (std::size_t j = 0; j < 9; ++j)
    beta[j] /= c8[j];
  return beta;
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

/// x', x'', x''' with respect to arc length from the t-derivatives (formulas at the top), in
/// place: p holds B and its t-derivatives on the first n axes (eval, eval_end) and 0 beyond.
void to_arc_length(PathPoint& p, std::size_t n, AxisMask metric) {
  double b11 = 0.0, b12 = 0.0, b22 = 0.0, b13 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!has(metric, i)) continue;
    b11 += p.d1[i] * p.d1[i];
    b12 += p.d1[i] * p.d2[i];
    b22 += p.d2[i] * p.d2[i];
    b13 += p.d1[i] * p.d3[i];
  }
  const double sg = std::sqrt(b11);
  if (sg <= 0.0) {  // no tangent: the position alone
    for (std::size_t i = 0; i < n; ++i)
      p.d1[i] = p.d2[i] = p.d3[i] = 0.0;
    return;
  }
  const double sg1 = b12 / sg;
  const double sg2 = (b22 + b13 - sg1 * sg1) / sg;
  const double s2 = sg * sg;
  const double s3 = s2 * sg;
  const double s4 = s3 * sg;
  const double s5 = s4 * sg;
  for (std::size_t i = 0; i < n; ++i) {
    const double b1 = p.d1[i];
    const double b2 = p.d2[i];
    const double b3 = p.d3[i];
    p.d1[i] = b1 / sg;
    p.d2[i] = b2 / s2 - b1 * sg1 / s3;
    p.d3[i] = b3 / s3 - 3.0 * b2 * sg1 / s4 - b1 * sg2 / s4 + 3.0 * b1 * sg1 * sg1 / s5;
  }
}

/// The arc-length table of a K-interval curve from |B'|^2 in Bernstein form: 9 products and a
/// root per Gauss node, whatever the axes. Each node's sum runs over j in order; the nine terms
/// are unrolled inside the node loop, which the compiler vectorises over the nodes with the sums
/// in registers (summing over j outermost through a node array cost 1.7 times the
/// instructions; the same values).
template <int K>
[[gnu::always_inline]] inline void arc_length_table_body(
    const std::array<double, 9>& beta, const GaussNodes<K>& nodes,
    std::array<double, geom::BezierGeom::kTable + 1>& s_at) {
  constexpr double dt = 1.0 / K;
  constexpr std::size_t kNodes = GaussNodes<K>::kNodes;
  std::array<double, kNodes> node_speed;  // every entry written below
  for (std::size_t q = 0; q < kNodes; ++q) {
    double v = 0.0;
    for (std::size_t j = 0; j < 9; ++j)
      v += beta[j] * nodes.b8[j][q];
    node_speed[q] = std::sqrt(std::max(v, 0.0));
  }
  for (std::size_t k = 0; k < static_cast<std::size_t>(K); ++k) {
    double sum = 0.0;
    for (std::size_t q = 0; q < 5; ++q)
      sum += kGlW[q] * node_speed[k * 5 + q];
    s_at[k + 1] = s_at[k] + 0.5 * dt * sum;
  }
}

#ifdef NCSIM_WIDE_LOOPS
template <int K>
[[gnu::target("avx2")]] void arc_length_table_avx2(
    const std::array<double, 9>& beta, const GaussNodes<K>& nodes,
    std::array<double, geom::BezierGeom::kTable + 1>& s_at) {
  arc_length_table_body(beta, nodes, s_at);
}
#endif

template <int K>
void arc_length_table(const std::array<double, 9>& beta, const GaussNodes<K>& nodes,
                      std::array<double, geom::BezierGeom::kTable + 1>& s_at) {
#ifdef NCSIM_WIDE_LOOPS
  if (wide()) return arc_length_table_avx2(beta, nodes, s_at);
#endif
  arc_length_table_body(beta, nodes, s_at);
}

}  // namespace

Segment Segment::bezier(std::uint8_t axis_count, AxisMask metric, const std::array<AxisVec, 6>& p) {
  return bezier_with(axis_count, metric, p, BezierGeom::kBlendTable);
}

Segment Segment::bezier_uneven(std::uint8_t axis_count, AxisMask metric,
                               const std::array<AxisVec, 6>& p) {
  Segment seg = bezier_with(axis_count, metric, p, BezierGeom::kTable);
  seg.fine_ = true;
  return seg;
}

Segment Segment::bezier_with(std::uint8_t axis_count, AxisMask metric,
                             const std::array<AxisVec, 6>& p, int intervals) {
  Segment seg;
  seg.n_ = axis_count;
  AxisMask all = 0;
  for (std::size_t i = 0; i < axis_count; ++i)
    all |= AxisMask{1} << i;
  seg.metric_ = metric & all;  // the caller passes the metric of the blended segments
  BezierGeom& g = seg.geom_.emplace<BezierGeom>();  // built in place, not copied in
  g.p = p;
  for (std::size_t i = 0; i < axis_count; ++i)
    for (std::size_t k = 1; k < 6; ++k)
      if (p[k][i] != p[0][i]) g.moving |= AxisMask{1} << i;
  const Tables& tab = tables();
  const std::array<double, 9> beta = squared_speed(p, axis_count, seg.metric_);
  if (intervals == BezierGeom::kBlendTable) {
    g.intervals = BezierGeom::kBlendTable;
    arc_length_table(beta, tab.gauss_blend, g.s_at);
  } else {
    g.intervals = BezierGeom::kTable;
    arc_length_table(beta, tab.gauss_spline, g.s_at);
  }
  seg.s_hi_ = g.s_at[g.intervals];
  return seg;
}

Segment Segment::cubic(std::uint8_t axis_count, AxisMask metric, const std::array<AxisVec, 4>& c) {
  // Degree elevation 3 -> 4 -> 5 (exact): Q_k = (k / (m + 1)) P_(k-1) + (1 - k / (m + 1)) P_k.
  std::array<AxisVec, 5> q{};
  std::array<AxisVec, 6> p{};
  for (std::size_t i = 0; i < axis_count; ++i) {
    q[0][i] = c[0][i];
    for (int k = 1; k <= 3; ++k)
      q[k][i] = (k / 4.0) * c[k - 1][i] + (1.0 - k / 4.0) * c[k][i];
    q[4][i] = c[3][i];
    p[0][i] = q[0][i];
    for (int k = 1; k <= 4; ++k)
      p[k][i] = (k / 5.0) * q[k - 1][i] + (1.0 - k / 5.0) * q[k][i];
    p[5][i] = q[4][i];
  }
  Segment seg = bezier_with(axis_count, metric, p, BezierGeom::kTable);
  seg.spline_ = true;
  return seg;
}

double Segment::bezier_t(const BezierGeom& g, double s) const noexcept {
  const int intervals = g.intervals;
  const double dt = 1.0 / intervals;
  if (s <= 0.0) return 0.0;
  if (s >= g.s_at[g.intervals]) return 1.0;
  const auto end = g.s_at.begin() + intervals + 1;
  const auto it = std::upper_bound(g.s_at.begin(), end, s);
  const int k = std::clamp(static_cast<int>(it - g.s_at.begin()) - 1, 0, intervals - 1);
  const double t_k = k * dt;
  const double s_k = g.s_at[k];
  const double span = g.s_at[k + 1] - s_k;
  double t = span > 0.0 ? t_k + dt * std::clamp((s - s_k) / span, 0.0, 1.0) : t_k;
  // A constant metric axis adds exactly +0 to the squared speed: leaving it out is the same sum.
  const AxisMask metric = metric_ & g.moving;
  for (int iter = 0; iter < 6; ++iter) {
    const double sp = speed(g.p, n_, metric, t);
    if (sp <= 0.0) break;
    const double f = integrate_speed(g.p, n_, metric, t_k, t) - (s - s_k);
    const double step = f / sp;
    t = std::clamp(t - step, t_k, t_k + dt);
    if (std::abs(step) < kParameterWidth) break;
  }
  return t;
}

PathPoint Segment::bezier_at_t(const BezierGeom& g, double t) const noexcept {
  PathPoint p;  // one result built in place (the axes from n_ on stay 0)
  if (t == 0.0 || t == 1.0)
    eval_end(g.p, n_, t == 1.0, p);
  else
    eval(g.p, n_, t, p);
  to_arc_length(p, n_, metric_);
  return p;
}

PathPoint Segment::bezier_at(const BezierGeom& g, double s) const noexcept {
  return bezier_at_t(g, bezier_t(g, s));
}

DerivativeBounds Segment::bezier_bounds() const noexcept {
  // Uniform in the curve parameter t over the window (no arc-length inversion per sample); a
  // whole curve (every blend and spline piece) uses the precomputed Bernstein tables.
  // Spline pieces: the speed of a cubic between uneven points varies much more than a blend's,
  // and 65 samples missed curvature peaks by up to 16 % (docs/planner.md "Geometry").
  const bool fine = spline_ || fine_;
  const std::size_t samples = fine ? kSplineBoundSamples : Tables::kSamples;
  constexpr double kMargin = 1.01;
  const BezierGeom& g = std::get<BezierGeom>(geom_);
  const bool whole = s_lo_ <= 0.0 && s_hi_ >= g.s_at[g.intervals];
  const bool table = whole;
  const double t0 = whole ? 0.0 : bezier_t(g, s_lo_);
  const double t1 = whole ? 1.0 : bezier_t(g, s_hi_);
  const Hodographs h = hodographs(g.p, n_);
  const Tables& tab = tables();
  DerivativeBounds b;
  if (table && !fine) {
    b = blend_bounds(h, n_, metric_, g.moving);
  } else {
    // The formulas of to_arc_length(), inlined without the position and without
    // building PathPoints (this loop is most of the cost of a tolerance ball).
    std::array<double, kMaxAxes> v1;  // first n_ entries set per sample
    std::array<double, kMaxAxes> v2;
    std::array<double, kMaxAxes> v3;
    // One sample from its Bernstein values: the bounds take its |x'|, |x''|, |x'''| per axis;
    // returns the speed |dB/dt| there.
    const auto sample = [&](const std::array<double, 5>& b4, const std::array<double, 4>& b3,
                            const std::array<double, 3>& b2) {
      double b11 = 0.0, b12 = 0.0, b22 = 0.0, b13 = 0.0;
      for (std::size_t i = 0; i < n_; ++i) {
        double a1 = 0.0, a2 = 0.0, a3 = 0.0;
        for (std::size_t m = 0; m < 5; ++m)
          a1 += b4[m] * h.c1[m][i];
        for (std::size_t m = 0; m < 4; ++m)
          a2 += b3[m] * h.c2[m][i];
        for (std::size_t m = 0; m < 3; ++m)
          a3 += b2[m] * h.c3[m][i];
        v1[i] = a1;
        v2[i] = a2;
        v3[i] = a3;
        if (has(metric_, i)) {
          b11 += a1 * a1;
          b12 += a1 * a2;
          b22 += a2 * a2;
          b13 += a1 * a3;
        }
      }
      const double sg = std::sqrt(b11);
      if (sg <= 0.0) return sg;
      const double inv = 1.0 / sg;
      const double sg1 = b12 * inv;
      const double sg2 = (b22 + b13 - sg1 * sg1) * inv;
      const double i2 = inv * inv;
      const double i3 = i2 * inv;
      const double i4 = i3 * inv;
      const double c1 = sg1 * i3;        // x'' = B2 / sg^2 - B1 c1
      const double c2 = 3.0 * sg1 * i4;  // x''' = B3 / sg^3 - B2 c2 + B1 c3
      const double c3 = 3.0 * sg1 * sg1 * i4 * inv - sg2 * i4;
      for (std::size_t i = 0; i < n_; ++i) {
        b.d1[i] = std::max(b.d1[i], std::abs(v1[i] * inv));
        b.d2[i] = std::max(b.d2[i], std::abs(v2[i] * i2 - v1[i] * c1));
        b.d3[i] = std::max(b.d3[i], std::abs(v3[i] * i3 - v2[i] * c2 + v1[i] * c3));
      }
      return sg;
    };
    const auto sample_at = [&](double t) { return sample(basis<4>(t), basis<3>(t), basis<2>(t)); };
    std::array<double, kSplineBoundSamples + 1> speed{};
    double speed_max = 0.0;
    for (std::size_t k = 0; k <= samples; ++k) {
      const double t = t0 + (t1 - t0) * static_cast<double>(k) / static_cast<double>(samples);
      speed[k] = !table ? sample_at(t)
                 : fine ? sample(tab.f4[k], tab.f3[k], tab.f2[k])
                        : sample(tab.s4[k], tab.s3[k], tab.s2[k]);
      speed_max = std::max(speed_max, speed[k]);
    }
    // Near-cusps (issue 34 item 12): where the curve folds back on itself its speed nearly
    // vanishes and |x''| = |B''_perp| / |B'|^2 peaks in a width far below the sample spacing
    // (27,773 mm/s^2 were planned against 3000). Around every local minimum of the sampled
    // speed below kCuspSpeed of the largest, the speed's minimum is found by golden-section
    // search and the bounds take samples at it and at halving distances from it (every scale
    // down to the double's resolution). Curves without such a minimum keep their bounds.
    constexpr double kCuspSpeed = 0.05;
    const double dt = (t1 - t0) / static_cast<double>(samples);
    const auto speed2 = [&](double t) {  // |B'(t)|^2 over the metric axes
      const std::array<double, 5> b4 = basis<4>(t);
      double sum = 0.0;
      for (std::size_t i = 0; i < n_; ++i) {
        if (!has(metric_, i)) continue;
        double a1 = 0.0;
        for (std::size_t m = 0; m < 5; ++m)
          a1 += b4[m] * h.c1[m][i];
        sum += a1 * a1;
      }
      return sum;
    };
    for (std::size_t k = 0; k <= samples; ++k) {
      const bool low = speed[k] < kCuspSpeed * speed_max;
      const bool local =
          (k == 0 || speed[k] <= speed[k - 1]) && (k == samples || speed[k] <= speed[k + 1]);
      if (!low || !local) continue;
      const double tk = t0 + dt * static_cast<double>(k);
      const double tm =
          golden_section_minimum(speed2, std::max(t0, tk - dt), std::min(t1, tk + dt), 80);
      sample_at(tm);
      for (double d = dt; d > 1e-16; d *= 0.5) {
        if (tm - d >= t0) sample_at(tm - d);
        if (tm + d <= t1) sample_at(tm + d);
      }
    }
  }
  for (std::size_t i = 0; i < n_; ++i) {
    b.d1[i] = has(metric_, i) ? std::min(1.0, b.d1[i] * kMargin) : b.d1[i] * kMargin;
    b.d2[i] *= kMargin;
    b.d3[i] *= kMargin;
  }
  b.curvature = metric_norm(b.d2);  // the per-axis maxima bound |x''| over the metric axes
  b.metric = metric_;
  return b;
}

bool wide_loops_available() noexcept {
  return has_avx2();
}

void allow_wide_loops(bool allowed) noexcept {
  g_wide_loops.store(allowed, std::memory_order_relaxed);
}

}  // namespace ncsim::planner
