#pragma once
// cli/sweep_search: the search both `ncsim sweep` (one program) and `ncsim line sweep` (a
// production line) run over the belt velocity (docs/conveyor.md "The line's limits offline",
// docs/lines.md "ncsim line sweep").
//
// Purpose: the highest velocity in [LO, HI] at which a candidate passes, to a tolerance.
// Inputs: the range and tolerance as the user gave them (checked here: NC9120, NC9121), the
// candidates per round K, the threads; a round function that evaluates the velocities of one
// round (in parallel with evaluate_all()), prints their verdicts and says which passed.
// Method: round 0 runs LO and HI; then each round runs K candidates evenly inside the interval
// [highest passing, lowest failing] and keeps the highest pass below the lowest failure, until
// the interval is <= the tolerance (or no double lies inside it any more). The sequence of
// candidates depends on LO, HI, K and the tolerance only, never on the threads' timing, so the
// output is the same on any machine. It assumes that what passes at a velocity passes at every
// lower one (a failure below a pass bounds the interval all the same).
// Outputs: the highest passing velocity and the lowest failing one (+inf when HI passes).
// Invariants: deterministic; candidates of a round are evaluated independently.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace ncsim::cli {

/// NC9120: --belt-velocity is not LO:HI with 0 <= LO < HI (both finite numbers, mm/s).
inline constexpr const char* kSweepRangeId = "NC9120";
/// NC9121: --tolerance is not a number >= kSweepToleranceMin.
inline constexpr const char* kSweepToleranceId = "NC9121";
/// Smallest --tolerance [mm/s]: 1 um/s (docs/conveyor.md "The line's limits offline"); 1e-300
/// never ended, the same candidate again and again (issue 34 item 6).
inline constexpr double kSweepToleranceMin = 0.001;

/// The searched interval and how it is searched.
struct SweepRange {
  double lo = 0.0;         ///< [mm/s] LO
  double hi = 0.0;         ///< [mm/s] HI
  double tolerance = 1.0;  ///< [mm/s] the result's resolution
  unsigned grid = 3;       ///< candidates per round after round 0
};

/// `text` ("LO:HI") and `tolerance` checked into a range; nullopt (the reason with its id on
/// `err`, prefixed `who`: "sweep", "line sweep") when either is not valid.
std::optional<SweepRange> parse_sweep_range(const std::string& text, double tolerance,
                                            unsigned grid, const char* who, std::ostream& err);

/// Evaluates the velocities of one round, prints their verdicts and returns whether each passed
/// (same order); nullopt stops the search (round 0: the run cannot be swept at all).
using SweepRound =
    std::function<std::optional<std::vector<bool>>(unsigned round, const std::vector<double>& vs)>;

/// The outcome of sweep_search.
struct SweepBounds {
  bool stopped = false;  ///< a round returned nullopt
  bool none = false;     ///< LO fails: no velocity of the range passes
  double best = 0.0;     ///< [mm/s] the highest passing velocity
  double fail = std::numeric_limits<double>::infinity();  ///< [mm/s] the lowest failing one
};

/// The search (see the header's "Method").
SweepBounds sweep_search(const SweepRange& range, const SweepRound& round);

/// `evaluate(v)` for every v of `vs`, at most `jobs` at a time (0: the cores); results in the
/// order of `vs` whatever the threads' timing.
template <class Result, class Evaluate>
std::vector<Result> evaluate_all(const std::vector<double>& vs, unsigned jobs,
                                 const Evaluate& evaluate) {
  std::vector<Result> out(vs.size());
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < vs.size(); i = next++)
      out[i] = evaluate(vs[i]);
  };
  if (jobs == 0) jobs = std::max(1u, std::thread::hardware_concurrency());
  const unsigned n = std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(vs.size())));
  std::vector<std::thread> threads;
  for (unsigned k = 1; k < n; ++k)
    threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads)
    t.join();
  return out;
}

}  // namespace ncsim::cli
