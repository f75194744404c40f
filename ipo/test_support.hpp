#pragma once
// ipo/test_support: sources, limits and seeded random programs for the ipo tests.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "ipo/interpolator.hpp"
#include "planner/spline.hpp"
#include "planner/test_support.hpp"

namespace ncsim::ipo::test {

/// Items from a list.
class ListSource final : public Source {
 public:
  explicit ListSource(std::vector<Item> items) : items_(std::move(items)) {}
  bool next(Item& out) override {
    if (next_ >= items_.size()) return false;
    out = items_[next_++];
    return true;
  }

 private:
  std::vector<Item> items_;
  std::size_t next_ = 0;
};

using planner::test::axis;
using planner::test::vec;

inline planner::Move line(const AxisVec& a, const AxisVec& b, double feed, std::uint32_t ln) {
  planner::Move m;
  m.start = a;
  m.end = b;
  m.feed = feed;
  m.slope = planner::SlopeType::trapez;
  m.line = ln;
  return m;
}

/// Parameters of a seeded random program.
struct RandomProgram {
  int moves = 60;
  bool blends = true;    ///< some blocks end with G261 PATH_DEV
  bool dist = false;     ///< with `blends`: G261 #CONTOUR MODE DIST PRE_DIST / POST_DIST instead
  bool stops = true;     ///< some G09 / G60 / G04 / G00
  bool helices = true;   ///< arcs move Z too
  bool splines = false;  ///< some #SPLINE sections (Akima or B-spline, 4-8 points) between moves
};

/// A #SPLINE section of 4-8 points from `pos` (a random walk of 0.5-10 mm steps in XY, some
/// in Z), Akima or B-spline, one source line per point from `ln`: its pieces as Moves.
inline void random_spline(std::mt19937_64& rng, AxisVec& pos, std::uint32_t& ln,
                          std::vector<Item>& items) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const planner::SplineType type =
      u(rng) < 0.5 ? planner::SplineType::akima : planner::SplineType::bspline;
  planner::Move modal;
  modal.slope = u(rng) < 0.9 ? planner::SlopeType::trapez : planner::SlopeType::step;
  planner::SplineBuilder builder(type, modal.axis_count, modal.path_axes);
  const double feed = 5.0 + 95.0 * u(rng);
  const auto emit = [&](std::span<const planner::SplinePiece> pieces) {
    for (const planner::SplinePiece& piece : pieces)
      items.emplace_back(planner::spline_move(piece, modal));
  };
  emit(builder.push(planner::SplineVertex{pos, ln, feed}));
  const int points = 4 + static_cast<int>(rng() % 5);
  double heading = 2.0 * std::numbers::pi * u(rng);
  for (int k = 1; k < points; ++k) {
    heading += (u(rng) - 0.5) * 2.0;
    const double step = 0.5 + 9.5 * u(rng);
    pos[0] += step * std::cos(heading);
    pos[1] += step * std::sin(heading);
    if (u(rng) < 0.2) pos[2] += step * (u(rng) - 0.5);
    emit(builder.push(planner::SplineVertex{pos, ++ln, feed}));
  }
  emit(builder.finish());
  ++ln;
}

/// Seeded random lines, arcs and helices (and events), one source line per item from 1.
inline std::vector<Item> random_program(std::mt19937_64& rng, const RandomProgram& p) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Item> items;
  AxisVec pos{};
  std::uint32_t ln = 1;
  for (int k = 0; k < p.moves; ++k) {
    planner::Move m;
    m.start = pos;
    m.end = pos;
    m.feed = 5.0 + 95.0 * u(rng);
    m.slope = u(rng) < 0.9 ? planner::SlopeType::trapez : planner::SlopeType::step;
    m.line = ln++;
    const double kind = u(rng);
    if (kind < 0.35) {
      const double r = 0.5 + 30.0 * u(rng);
      const double phi = 2.0 * std::numbers::pi * u(rng);
      const double sweep = (0.2 + 3.0 * u(rng)) * (u(rng) < 0.5 ? 1.0 : -1.0);
      m.arc = planner::Arc{
          0, 1, pos[0] - r * std::cos(phi), pos[1] - r * std::sin(phi), sweep < 0.0, false};
      m.end[0] = m.arc->centre_1 + r * std::cos(phi + sweep);
      m.end[1] = m.arc->centre_2 + r * std::sin(phi + sweep);
      if (p.helices && u(rng) < 0.3) m.end[2] += 5.0 * (u(rng) - 0.5);
    } else {
      const double len = kind < 0.5 ? 0.05 + 0.5 * u(rng) : 1.0 + 60.0 * u(rng);
      const double dir = 2.0 * std::numbers::pi * u(rng);
      m.end[0] += len * std::cos(dir);
      m.end[1] += len * std::sin(dir);
      if (u(rng) < 0.2) m.end[2] += len * (u(rng) - 0.5);
    }
    // A spline section follows some blocks; contouring never meets a spline (120255).
    const bool spline_next = p.splines && u(rng) < 0.1;
    if (p.blends && !spline_next && u(rng) < 0.5) {
      if (p.dist) {
        m.contour = planner::Contour::distance;
        m.pre_dist = 0.005 + 0.5 * u(rng);  // the range of PATH_DEV below
        m.post_dist = 0.005 + 0.5 * u(rng);
      } else {
        m.contour = planner::Contour::tolerance;
        m.path_dev = 0.005 + 0.5 * u(rng);
      }
    }
    if (p.stops) {
      const double e = u(rng);
      if (e < 0.05)
        m.transition = planner::Transition::stop_at_end;
      else if (e < 0.1)
        m.exact_stop = true;
      else if (e < 0.15 && !m.arc)
        m.rapid = true;
    }
    items.emplace_back(m);
    pos = m.end;
    if (p.stops && u(rng) < 0.04) items.emplace_back(Dwell{0.0005 + 0.02 * u(rng), ln++});
    if (spline_next) random_spline(rng, pos, ln, items);
  }
  return items;
}

/// Random axis limits (3 axes).
inline std::vector<planner::AxisLimits> random_limits(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<planner::AxisLimits> axes;
  for (int i = 0; i < 3; ++i) {
    planner::AxisLimits ax = axis(20.0 + 180.0 * u(rng), 200.0 + 5000.0 * u(rng),
                                  2e3 + 2e5 * u(rng), 0.2 + 1.8 * u(rng));
    ax.v_rapid = ax.v_max * (0.5 + 0.5 * u(rng));
    ax.d_max = ax.a_max * (0.5 + u(rng));
    axes.push_back(ax);
  }
  return axes;
}

/// A random interpolator configuration: random_limits, a cycle of 0.25 ms x 1..cycle_steps,
/// an exact-stop window of 0.01 mm with `settle` [s] on each axis, a look-ahead window of
/// 10..129 entries.
inline Config random_config(std::mt19937_64& rng, std::uint64_t cycle_steps, double settle) {
  Config cfg;
  cfg.axes = random_limits(rng);
  cfg.channel.t_cycle = 0.00025 * static_cast<double>(1 + rng() % cycle_steps);
  cfg.exact_stop = {ExactStop{0.01, settle}, ExactStop{0.01, settle}, ExactStop{0.01, settle}};
  cfg.window = 10 + rng() % 120;
  return cfg;
}

}  // namespace ncsim::ipo::test
