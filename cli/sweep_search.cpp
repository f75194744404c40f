// cli/sweep_search: the belt velocity search of `sweep` and `line sweep` (see the header).

#include "cli/sweep_search.hpp"

#include <charconv>
#include <cmath>
#include <ostream>
#include <string_view>

#include "cli/number_format.hpp"

namespace ncsim::cli {
namespace {

std::optional<double> parse_number(std::string_view s) {
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

std::optional<SweepRange> parse_sweep_range(const std::string& text, double tolerance,
                                            unsigned grid, const char* who, std::ostream& err) {
  const auto colon = text.find(':');
  const std::optional<double> lo = colon == std::string::npos
                                       ? std::nullopt
                                       : parse_number(std::string_view(text).substr(0, colon));
  const std::optional<double> hi = colon == std::string::npos
                                       ? std::nullopt
                                       : parse_number(std::string_view(text).substr(colon + 1));
  if (!lo || !hi || *lo < 0.0 || !(*lo < *hi)) {
    err << "ncsim: error: " << who << ": --belt-velocity '" << text
        << "' must be LO:HI in mm/s with 0 <= LO < HI [" << kSweepRangeId << "]\n";
    return std::nullopt;
  }
  if (!(tolerance >= kSweepToleranceMin) || !std::isfinite(tolerance)) {
    err << "ncsim: error: " << who << ": --tolerance " << human(tolerance)
        << " mm/s must be a number >= " << human(kSweepToleranceMin) << " mm/s ["
        << kSweepToleranceId << "]\n";
    return std::nullopt;
  }
  return SweepRange{*lo, *hi, tolerance, std::max(1u, grid)};
}

SweepBounds sweep_search(const SweepRange& range, const SweepRound& round) {
  SweepBounds b;
  // Round 0: both ends (the caller also learns there whether the run can be swept at all).
  const std::optional<std::vector<bool>> ends = round(0, {range.lo, range.hi});
  if (!ends) {
    b.stopped = true;
    return b;
  }
  if (!(*ends)[0]) {
    b.none = true;
    return b;
  }
  b.best = range.lo;
  b.fail = range.hi;
  if ((*ends)[1]) {
    b.best = range.hi;
    b.fail = std::numeric_limits<double>::infinity();
  }
  for (unsigned r = 1; std::isfinite(b.fail) && b.fail - b.best > range.tolerance; ++r) {
    std::vector<double> vs;
    for (unsigned i = 1; i <= range.grid; ++i) {
      const double v = b.best + (b.fail - b.best) * i / (range.grid + 1);
      if (v > b.best && v < b.fail && (vs.empty() || v > vs.back())) vs.push_back(v);
    }
    // No double lies between the two any more (huge velocities): the interval cannot shrink,
    // so the search ends rather than trying the same candidates again (issue 34 item 6).
    if (vs.empty()) break;
    const std::optional<std::vector<bool>> passed = round(r, vs);
    if (!passed) {
      b.stopped = true;
      return b;
    }
    // The lowest failure bounds the interval; the highest pass below it is the new best.
    std::size_t k = vs.size();
    for (std::size_t i = 0; i < vs.size() && k == vs.size(); ++i)
      if (!(*passed)[i]) k = i;
    if (k < vs.size()) b.fail = vs[k];
    if (k > 0) b.best = vs[k - 1];
  }
  return b;
}

}  // namespace ncsim::cli
