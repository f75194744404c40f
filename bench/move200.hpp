#pragma once
// bench/move200: the seeded 200-move line/arc program of issue 12 (docs/benchmarks.md
// "200-move program"), shared by ipo_bench and move200_bound.
//
// Purpose: one deterministic program of sharp corners: moves k % 3 == 2 are arcs (R 5-30 mm,
// sweep 29-178 degrees, either direction, starting at the current point), the others lines of
// 5-50 mm in random directions (corners of every angle up to reversals); feeds 20-50 mm/s;
// XY plane, TRAPEZ slope (callers set slope, transition and contour per variant).
// Inputs: none (seed 200, std::mt19937_64, uniform_real_distribution as below).
// Outputs: 200 planner::Moves, lines 1..200, each starting where the previous ends.
// Invariants: deterministic for a given standard library (libstdc++ here).

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "planner/move.hpp"

namespace ncsim::bench {

/// The 200 moves (TRAPEZ, G08 continuous path, no contouring).
inline std::vector<planner::Move> move200() {
  std::mt19937_64 rng(200);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<planner::Move> moves;
  planner::AxisVec p{};
  for (int k = 0; k < 200; ++k) {
    planner::Move m;
    m.start = p;
    m.end = p;
    m.feed = 20.0 + 30.0 * u(rng);
    m.slope = planner::SlopeType::trapez;
    m.line = static_cast<std::uint32_t>(k + 1);
    if (k % 3 == 2) {
      const double r = 5.0 + 25.0 * u(rng);
      const double phi = 2.0 * std::numbers::pi * u(rng);
      const double sweep = (0.5 + 2.6 * u(rng)) * (u(rng) < 0.5 ? 1 : -1);
      m.arc =
          planner::Arc{0, 1, p[0] - r * std::cos(phi), p[1] - r * std::sin(phi), sweep < 0, false};
      m.end[0] = m.arc->centre_1 + r * std::cos(phi + sweep);
      m.end[1] = m.arc->centre_2 + r * std::sin(phi + sweep);
    } else {
      const double len = 5.0 + 45.0 * u(rng);
      const double dir = 2.0 * std::numbers::pi * u(rng);
      m.end[0] += len * std::cos(dir);
      m.end[1] += len * std::sin(dir);
    }
    moves.push_back(m);
    p = m.end;
  }
  return moves;
}

}  // namespace ncsim::bench
