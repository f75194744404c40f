// planner/chain: concatenated arc length over C2-joined segments.

#include "planner/chain.hpp"

#include <algorithm>
#include <cstdlib>

namespace ncsim::planner {

Chain::Chain(const Segment& first, std::uint32_t line) {
  parts_.emplace_back(first, first.length(), line);  // built in place: one copy of the segment
}

void Chain::append(const Chain& next) {
  if (parts_.size() + next.parts_.size() > kMaxParts) std::abort();  // broken invariant
  const double base = length();
  for (const Part& p : next.parts_)
    parts_.emplace_back(p.segment, base + p.end, p.line);
}

std::uint8_t Chain::axis_count() const noexcept {
  std::uint8_t n = 0;
  for (const Part& p : parts_)
    n = std::max(n, p.segment.axis_count());
  return n;
}

AxisMask Chain::metric() const noexcept {
  AxisMask m = 0;
  for (const Part& p : parts_)
    m |= p.segment.metric();
  return m;
}

std::size_t Chain::locate(double& s) const noexcept {
  if (parts_.empty()) return 0;
  s = std::clamp(s, 0.0, length());
  // First part whose end lies beyond s (the later part at an inner joint).
  const auto it = std::upper_bound(parts_.begin(), parts_.end(), s,
                                   [](double v, const Part& p) { return v < p.end; });
  const std::size_t i = std::min<std::size_t>(it - parts_.begin(), parts_.size() - 1);
  s -= i == 0 ? 0.0 : parts_[i - 1].end;
  return i;
}

PathPoint Chain::at(double s) const noexcept {
  if (parts_.empty()) return {};
  const std::size_t i = locate(s);
  return parts_[i].segment.at(s);
}

AxisVec Chain::point(double s) const noexcept {
  if (parts_.empty()) return {};
  const std::size_t i = locate(s);
  return parts_[i].segment.point(s);
}

std::uint32_t Chain::line_at(double s) const noexcept {
  if (parts_.empty()) return 0;
  return parts_[locate(s)].line;
}

}  // namespace ncsim::planner
