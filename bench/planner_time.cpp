// Machining time of a seeded 200-move line/arc program (issue 12's reference case): axes
// V = 100 mm/s, A = 1000 mm/s^2, J = 1e5 mm/s^3, feeds 20-50 mm/s, sharp corners, blend
// tolerance 0.01 mm, T = 1 ms. Prints the planned time (sum of the segment profiles) for
// exact stops, VELOJUMP corners and tolerance balls, with TRAPEZ and STEP slopes, against the
// lower bound sum(L / F) (every feed is below what the axes and the arcs' curvature allow,
// so no path can be faster than its programmed feed). Deterministic: seeded, no wall clock.

#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "planner/lookahead.hpp"

namespace {

using namespace ncsim::planner;

std::vector<Move> program(Contour contour, SlopeType slope, bool stops) {
  std::mt19937_64 rng(200);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Move> moves;
  AxisVec p{};
  for (int k = 0; k < 200; ++k) {
    Move m;
    m.start = p;
    m.feed = 20.0 + 30.0 * u(rng);
    m.slope = slope;
    m.contour = contour;
    m.path_dev = 0.01;
    m.transition = stops ? Transition::stop_at_end : Transition::accelerate_at_start;
    m.line = static_cast<std::uint32_t>(k + 1);
    m.end = p;
    if (k % 3 == 2) {
      const double r = 5.0 + 25.0 * u(rng);
      const double phi = 6.283185307179586 * u(rng);
      const double sweep = (0.5 + 2.6 * u(rng)) * (u(rng) < 0.5 ? 1 : -1);
      m.arc = Arc{0, 1, p[0] - r * std::cos(phi), p[1] - r * std::sin(phi), sweep < 0, false};
      m.end[0] = m.arc->centre_1 + r * std::cos(phi + sweep);
      m.end[1] = m.arc->centre_2 + r * std::sin(phi + sweep);
    } else {
      const double len = 5.0 + 45.0 * u(rng);
      const double dir = 6.283185307179586 * u(rng);
      m.end[0] += len * std::cos(dir);
      m.end[1] += len * std::sin(dir);
    }
    moves.push_back(m);
    p = m.end;
  }
  return moves;
}

struct Result {
  double time = 0.0;
  double lower_bound = 0.0;
};

Result plan_time(Contour contour, SlopeType slope, bool stops) {
  AxisLimits ax;
  ax.v_max = ax.v_reference = ax.v_rapid = 100.0;
  ax.a_max = ax.d_max = 1000.0;
  ax.j_max = 1e5;
  const std::array<AxisLimits, 3> axes = {ax, ax, ax};
  const ChannelLimits channel{};
  Preparer prep(axes, channel);
  LookAhead window(window_size(LookAheadKind::standard), channel.t_cycle);
  std::vector<PreparedSegment> ready;
  Result r;
  auto drain = [&](bool all) {
    for (auto& s : ready) {
      while (window.full())
        r.time += profile(window.pop()).time();
      window.push(std::move(s));
    }
    ready.clear();
    while (all && !window.empty())
      r.time += profile(window.pop()).time();
  };
  for (const Move& m : program(contour, slope, stops)) {
    r.lower_bound += Segment::from_move(m).length() / m.feed;
    prep.push(m, ready);
    drain(false);
  }
  prep.finish(ready);
  drain(true);
  return r;
}

}  // namespace

int main() {
  std::printf("| corners | slope | planned time [s] | lower bound sum(L/F) [s] | ratio |\n");
  std::printf("|---|---|---|---|---|\n");
  struct Case {
    const char* name;
    Contour contour;
    bool stops;
  };
  const Case cases[] = {{"exact stop (G09 every block)", Contour::none, true},
                        {"VELOJUMP (G260, C0 = 1)", Contour::none, false},
                        {"tolerance balls (G261, 0.01 mm)", Contour::tolerance, false}};
  for (const Case& c : cases) {
    for (const SlopeType slope : {SlopeType::trapez, SlopeType::step}) {
      const Result r = plan_time(c.contour, slope, c.stops);
      std::printf("| %s | %s | %.2f | %.2f | %.3f |\n", c.name,
                  slope == SlopeType::trapez ? "TRAPEZ" : "STEP", r.time, r.lower_bound,
                  r.time / r.lower_bound);
    }
  }
  return 0;
}
