// move200_bound: machining time of the seeded 200-move program (bench/move200.hpp) by ncsim
// against lower bounds from an independent time-optimal path parameterisation (TOPP) without a
// jerk limit (docs/benchmarks.md "The 200-move table").
//
// Purpose: the table of issue 12: ncsim's `time` (audit::machining_time: the cycle loop of
// `ncsim time`, T = 1 ms) with TRAPEZ and STEP slopes, exact stops, VELOJUMP corners and
// tolerance balls of 0.01 mm, next to what the physics allows:
//  - sum(L / F): no block can be faster than its feed (every feed is below the axes' and the
//    arcs' velocity limits), whatever the accelerations;
//  - TOPP, exact stops: v = 0 at every block end;
//  - TOPP, VELOJUMP corners: v at a knee at most the VELOJUMP link velocity (000 l.108);
//  - TOPP, ideal blends: at a knee of turning angle theta the path may leave the program
//    inside the ball of r = 0.01 mm; the circular fillet tangent to both sides at distance r
//    from the corner (the largest curvature radius a tangent blend inside the ball can have:
//    R = r tan(alpha / 2), alpha = pi - theta the inner angle) caps the velocity at the fillet's
//    apex (per-axis centripetal limit with the best tangential acceleration). The shorter path
//    through the fillet (2 r - R theta, < 0.02 mm a corner) is not credited: < 0.1 s in all.
// Method (TOPP): the path is sampled every ds (both ends of every block included; a knee is
// two samples at distance 0); u = v^2 obeys, per axis i, |x'_i| v <= V_i and
// |x''_i u + x'_i u' / 2| <= A_i, and v <= F. The maximum velocity curve is found per sample
// (bisection on u where the curvature constrains it); a forward pass u_(k+1) = u_k + 2 ds a_hi(u_k)
// and a backward pass u_k = u_(k+1) + 2 ds d_hi(u_(k+1)), both capped by that curve; the time
// is sum 2 ds / (v_k + v_(k+1)) (exact for constant acceleration). The accelerations are taken
// where the velocity is lower (the budget left by the centripetal part is larger there), so the
// discretisation errs on the fast side; printed for two ds to show convergence.
// Usage: move200_bound [--write PATH.nc]  (writes the program in ISG syntax, F in mm/min).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "audit/time.hpp"
#include "bench/move200.hpp"
#include "core/tolerance.hpp"
#include "ipo/interpolator.hpp"
#include "planner/corner.hpp"
#include "planner/path.hpp"

namespace {

using namespace ncsim;

constexpr double kV = 100.0;    // [mm/s]
constexpr double kA = 1000.0;   // [mm/s^2]
constexpr double kJ = 1e5;      // [mm/s^3]
constexpr double kT = 0.001;    // [s]
constexpr double kBall = 0.01;  // [mm]
constexpr int kAxes = 2;        // the program lies in XY
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Sample {
  double d1[kAxes];
  double d2[kAxes];
  double u_max;
};

/// Feasible path acceleration interval at u on a sample; lo > hi when none.
void accel_interval(const Sample& p, double u, double& lo, double& hi) {
  lo = -kInf;
  hi = kInf;
  for (int i = 0; i < kAxes; ++i) {
    if (std::abs(p.d1[i]) > kTiny) {
      const double b1 = (-kA - p.d2[i] * u) / p.d1[i];
      const double b2 = (kA - p.d2[i] * u) / p.d1[i];
      lo = std::max(lo, std::min(b1, b2));
      hi = std::min(hi, std::max(b1, b2));
    } else if (std::abs(p.d2[i]) * u > kA) {
      lo = 1.0;
      hi = -1.0;
    }
  }
}

/// Largest u <= u_hi at which some path acceleration keeps every axis within A.
double feasible_u(const Sample& p, double u_hi) {
  double lo = 0.0;
  double hi = 0.0;
  accel_interval(p, u_hi, lo, hi);
  if (lo <= hi) return u_hi;
  double a = 0.0;
  double b = u_hi;
  for (int it = 0; it < 80; ++it) {
    const double m = 0.5 * (a + b);
    accel_interval(p, m, lo, hi);
    (lo <= hi ? a : b) = m;
  }
  return a;
}

enum class Corners { exact_stop, velojump, ideal_blend };

Sample sample_at(const planner::PathPoint& pt, double feed) {
  Sample s{};
  double u = feed * feed;
  for (int i = 0; i < kAxes; ++i) {
    s.d1[i] = pt.d1[i];
    s.d2[i] = pt.d2[i];
    if (std::abs(pt.d1[i]) > 0.0)
      u = std::min(u, (kV / std::abs(pt.d1[i])) * (kV / std::abs(pt.d1[i])));
  }
  s.u_max = feasible_u(s, u);
  return s;
}

/// Velocity cap [mm/s] at the apex of the ideal fillet of a knee from tangent t_in to t_out.
double fillet_cap(const planner::AxisVec& t_in, const planner::AxisVec& t_out, double feed) {
  const double theta = planner::tangent_angle(t_in, t_out, kAxes, 0b11);
  const double alpha = std::numbers::pi - theta;
  if (alpha <= kRelTol) return 0.0;  // reversal: no tangent blend fits
  const double radius = kBall * std::tan(alpha / 2.0);
  // Apex: tangent along t_in + t_out, normal towards the inside (t_out - t_in).
  Sample s{};
  double tn = 0.0;
  double nn = 0.0;
  for (int i = 0; i < kAxes; ++i) {
    tn += (t_in[i] + t_out[i]) * (t_in[i] + t_out[i]);
    nn += (t_out[i] - t_in[i]) * (t_out[i] - t_in[i]);
  }
  tn = std::sqrt(tn);
  nn = std::sqrt(nn);
  double u = feed * feed;
  for (int i = 0; i < kAxes; ++i) {
    s.d1[i] = (t_in[i] + t_out[i]) / tn;
    s.d2[i] = nn > 0.0 ? (t_out[i] - t_in[i]) / nn / radius : 0.0;
    if (std::abs(s.d1[i]) > 0.0)
      u = std::min(u, (kV / std::abs(s.d1[i])) * (kV / std::abs(s.d1[i])));
  }
  return std::sqrt(feasible_u(s, u));
}

/// TOPP time [s] of the program with samples every ds [mm] and the given corner rule.
double topp(const std::vector<planner::Move>& moves, double ds, Corners corners) {
  std::vector<Sample> pts;
  std::vector<double> gap;  // distance from sample k to k+1 [mm]
  std::vector<planner::Segment> segs;
  for (const planner::Move& m : moves)
    segs.push_back(planner::Segment::from_move(m));
  for (std::size_t b = 0; b < segs.size(); ++b) {
    const planner::Segment& seg = segs[b];
    const double len = seg.length();
    const int n = std::max(1, static_cast<int>(std::ceil(len / ds)));
    if (b > 0) gap.push_back(0.0);  // the knee: two samples at one point
    for (int k = 0; k <= n; ++k) {
      pts.push_back(sample_at(seg.at(len * k / n), moves[b].feed));
      if (k < n) gap.push_back(len / n);
    }
    const std::size_t last = pts.size() - 1;
    if (b + 1 == segs.size()) {
      pts[last].u_max = 0.0;
      continue;
    }
    const planner::PathPoint in = seg.at(len);
    const planner::PathPoint out = segs[b + 1].at(0.0);
    const double angle = planner::tangent_angle(in.d1, out.d1, kAxes, 0b11);
    double cap = kInf;
    if (corners == Corners::exact_stop) {
      cap = 0.0;
    } else if (angle > planner::kTangentTolerance) {
      if (corners == Corners::velojump) {
        double c = kInf;
        for (int i = 0; i < kAxes; ++i) {
          const double step = std::abs(out.d1[i] - in.d1[i]);
          if (step > 0.0) c = std::min(c, kA * kT / step);  // C0 = 1, A+ = |A-|
        }
        cap = c;
      } else {
        cap = fillet_cap(in.d1, out.d1, std::min(moves[b].feed, moves[b + 1].feed));
      }
    }
    pts[last].u_max = std::min(pts[last].u_max, cap * cap);
  }
  // Knee caps onto the second sample of each knee (the first of the next block).
  for (std::size_t k = 0; k + 1 < pts.size(); ++k)
    if (gap[k] == 0.0) pts[k + 1].u_max = std::min(pts[k + 1].u_max, pts[k].u_max);
  pts[0].u_max = 0.0;
  std::vector<double> u(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k)
    u[k] = pts[k].u_max;
  u[0] = 0.0;
  double lo = 0.0;
  double hi = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
    accel_interval(pts[k], u[k], lo, hi);
    u[k + 1] = std::min(u[k + 1], u[k] + 2.0 * gap[k] * std::max(hi, 0.0));
  }
  for (std::size_t k = pts.size() - 1; k > 0; --k) {
    accel_interval(pts[k], u[k], lo, hi);
    u[k - 1] = std::min(u[k - 1], u[k] + 2.0 * gap[k - 1] * std::max(-lo, 0.0));
  }
  double t = 0.0;
  for (std::size_t k = 0; k + 1 < pts.size(); ++k)
    if (gap[k] > 0.0) t += 2.0 * gap[k] / (std::sqrt(u[k]) + std::sqrt(u[k + 1]));
  return t;
}

class Moves final : public ipo::Source {
 public:
  explicit Moves(std::vector<planner::Move> m) : m_(std::move(m)) {}
  bool next(ipo::Item& out) override {
    if (k_ >= m_.size()) return false;
    out = m_[k_++];
    return true;
  }

 private:
  std::vector<planner::Move> m_;
  std::size_t k_ = 0;
};

double ncsim_time(std::vector<planner::Move> moves, planner::SlopeType slope, Corners corners) {
  for (planner::Move& m : moves) {
    m.slope = slope;
    if (corners == Corners::exact_stop) m.transition = planner::Transition::stop_at_end;
    if (corners == Corners::ideal_blend) {
      m.contour = planner::Contour::tolerance;
      m.path_dev = kBall;
    }
  }
  ipo::Config cfg;
  planner::AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = kV;
  ax.a_max = ax.d_max = kA;
  ax.j_max = kJ;
  ax.c0 = 1.0;
  cfg.axes = {ax, ax, ax};
  cfg.channel.t_cycle = kT;
  cfg.window = 120;
  Moves src(std::move(moves));
  return audit::machining_time(cfg, src).total;
}

void write_program(const std::vector<planner::Move>& moves, const char* path) {
  std::FILE* f = std::fopen(path, "w");
  if (f == nullptr) {
    std::fprintf(stderr, "move200_bound: cannot write %s\n", path);
    return;
  }
  std::fprintf(f,
               "; move200: the seeded 200-move line/arc program of issue 12 (bench/move200.hpp,\n"
               "; written by bench/move200_bound --write). Axes V 100 mm/s, A 1000 mm/s^2,\n"
               "; J 1e5 mm/s^3 (docs/benchmarks.md \"The 200-move table\").\n"
               "%%move200\nN1 G17 G90 G71 G94 G08\nN2 G00 X0 Y0 Z0\n");
  for (const planner::Move& m : moves) {
    if (m.arc)
      std::fprintf(f, "N%u G0%d X%.6f Y%.6f I%.6f J%.6f F%.3f\n", 10 * m.line + 10,
                   m.arc->clockwise ? 2 : 3, m.end[0], m.end[1], m.arc->centre_1 - m.start[0],
                   m.arc->centre_2 - m.start[1], m.feed * 60.0);
    else
      std::fprintf(f, "N%u G01 X%.6f Y%.6f F%.3f\n", 10 * m.line + 10, m.end[0], m.end[1],
                   m.feed * 60.0);
  }
  std::fprintf(f, "M30\n");
  std::fclose(f);
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<planner::Move> moves = bench::move200();
  if (argc == 3 && std::strcmp(argv[1], "--write") == 0) write_program(moves, argv[2]);
  double length = 0.0;
  double lf = 0.0;
  for (const planner::Move& m : moves) {
    const double l = planner::Segment::from_move(m).length();
    length += l;
    lf += l / m.feed;
  }
  std::printf("program: %zu moves, %.3f mm, sum(L/F) = %.3f s\n", moves.size(), length, lf);
  const struct {
    const char* name;
    Corners c;
  } rows[] = {{"exact stop", Corners::exact_stop},
              {"VELOJUMP (C0 = 1)", Corners::velojump},
              {"tolerance ball 0.01 mm", Corners::ideal_blend}};
  for (const auto& r : rows) {
    const double trapez = ncsim_time(moves, planner::SlopeType::trapez, r.c);
    const double step = ncsim_time(moves, planner::SlopeType::step, r.c);
    const double b1 = topp(moves, 0.02, r.c);
    const double b2 = topp(moves, 0.005, r.c);
    std::printf(
        "%-24s ncsim TRAPEZ %8.3f s  STEP %8.3f s  TOPP(no jerk) ds 0.02: %8.3f s  "
        "ds 0.005: %8.3f s\n",
        r.name, trapez, step, b1, b2);
  }
  return 0;
}
