// planner/chain: concatenated arc length over C2-joined segments.

#include "planner/chain.hpp"

#include <algorithm>
#include <cstdlib>

namespace ncsim::planner {

Chain::Chain(Segment first, std::uint32_t line) {
  ends_.push_back(first.length());
  parts_.push_back(std::move(first));
  lines_.push_back(line);
}

void Chain::append(const Chain& next) {
  if (parts_.size() + next.parts_.size() > kMaxParts) std::abort();  // broken invariant
  const double base = length();
  for (std::size_t i = 0; i < next.parts_.size(); ++i) {
    parts_.push_back(next.parts_[i]);
    ends_.push_back(base + next.ends_[i]);
    lines_.push_back(next.lines_[i]);
  }
}

std::uint8_t Chain::axis_count() const noexcept {
  std::uint8_t n = 0;
  for (const Segment& p : parts_)
    n = std::max(n, p.axis_count());
  return n;
}

AxisMask Chain::metric() const noexcept {
  AxisMask m = 0;
  for (const Segment& p : parts_)
    m |= p.metric();
  return m;
}

std::size_t Chain::locate(double& s) const noexcept {
  if (parts_.empty()) return 0;
  s = std::clamp(s, 0.0, length());
  // First part whose end lies beyond s (the later part at an inner joint).
  const auto it = std::upper_bound(ends_.begin(), ends_.end(), s);
  const std::size_t i = std::min<std::size_t>(it - ends_.begin(), parts_.size() - 1);
  s -= i == 0 ? 0.0 : ends_[i - 1];
  return i;
}

PathPoint Chain::at(double s) const noexcept {
  if (parts_.empty()) return {};
  const std::size_t i = locate(s);
  return parts_[i].at(s);
}

AxisVec Chain::point(double s) const noexcept {
  if (parts_.empty()) return {};
  const std::size_t i = locate(s);
  return parts_[i].point(s);
}

std::uint32_t Chain::line_at(double s) const noexcept {
  if (parts_.empty()) return 0;
  return lines_[locate(s)];
}

}  // namespace ncsim::planner
