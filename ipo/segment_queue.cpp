// ipo/segment_queue: source, ring of programmed Moves, preparer and window (see the header).

#include "ipo/segment_queue.hpp"

#include <bit>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <utility>

#include "core/limits.hpp"
#include "core/tolerance.hpp"

namespace ncsim::ipo {

namespace {

/// Moves shorter than this carry no path (planner/prepare.cpp drops them with the same rule).
constexpr double kMinLength = kSamePoint;  // [mm]
/// Items pulled in one fill() at most: a source of endless zero-length blocks cannot hang a
/// cycle (the cycle is reported as Activity::starved).
constexpr std::size_t kMaxPulls = 4096;

std::size_t ring_size(std::size_t window) {
  return std::bit_ceil((window + 2) * planner::Chain::kMaxParts + 16);
}

/// The length planner::Segment::line gives a line Move (Segment::from_move), without building
/// the Segment: the same effective metric and the same sum of squares in the same order
/// (Segment::metric_norm), so the same bits.
double line_length(const planner::Move& m) {
  planner::AxisVec delta{};
  for (std::size_t i = 0; i < m.axis_count; ++i)
    delta[i] = m.end[i] - m.start[i];
  const planner::AxisMask metric = planner::effective_metric(m.axis_count, m.path_axes, delta);
  double sum = 0.0;
  for (std::size_t i = 0; i < m.axis_count; ++i)
    if (((metric >> i) & 1U) != 0) sum += delta[i] * delta[i];
  return std::sqrt(sum);
}

/// The length of a Move's path: lines without building their Segment.
double move_length(const planner::Move& m) {
  if (!m.arc && !m.spline) return line_length(m);
  return planner::Segment::from_move(m).length();
}

}  // namespace

SegmentQueue::SegmentQueue(Source& source, std::span<const planner::AxisLimits> axes,
                           const planner::ChannelLimits& channel, std::size_t window,
                           std::optional<planner::JointLimits> joints)
    : source_(source),
      prep_(axes, channel),
      window_(window, channel.t_cycle),
      item_(planner::Move{}) {
  if (axes.empty() || axes.size() > planner::kMaxAxes)
    throw std::invalid_argument("ipo: " + std::to_string(axes.size()) + " axes (1.." +
                                std::to_string(planner::kMaxAxes) + ")");
  if (joints) prep_.set_joints(std::move(*joints));
  ring_.resize(ring_size(window));
  ring_mask_ = ring_.size() - 1;
  ready_.reserve(16);
}

bool SegmentQueue::fill(std::string& message) noexcept {
  try {
    std::size_t pulls = 0;
    while (!window_.full()) {
      if (ready_next_ < ready_.size()) {
        window_.push(std::move(ready_[ready_next_++]));
        continue;
      }
      ready_.clear();
      ready_next_ = 0;
      if (source_done_ || dwell_ || wait_) break;
      if (next_token_ - oldest_ >= ring_.size()) break;  // every ring slot still referenced
      if (pulls++ >= kMaxPulls) break;
      if (!source_.next(item_)) {
        source_done_ = true;
        prep_.finish(ready_);
        continue;
      }
      if (!take(message)) return false;
    }
    return true;
  } catch (const planner::KinematicError& e) {  // the planner carries the ring token
    message = "line " + std::to_string(programmed(e.line()).line) + ": " + e.what();
    return false;
  } catch (const std::exception& e) {
    message = e.what();
    return false;
  } catch (...) {
    message = "ipo: the program source failed";
    return false;
  }
}

bool SegmentQueue::take(std::string& message) {
  if (const Dwell* d = std::get_if<Dwell>(&item_)) {
    if (!(d->seconds >= 0.0) || !(d->seconds <= core::kLongestTime)) {
      message = "G04 dwell time must be 0 .. 86400 s (core::kLongestTime), got " +
                std::to_string(d->seconds) + " s (line " + std::to_string(d->line) + ")";
      return false;
    }
    dwell_ = *d;
    prep_.finish(ready_);  // the path stops before the dwell
    return true;
  }
  if (const ChannelWait* w = std::get_if<ChannelWait>(&item_)) {
    wait_ = *w;
    prep_.finish(ready_);  // the path stops before the wait
    return true;
  }
  planner::Move& m = std::get<planner::Move>(item_);
  // A zero-length line takes no ring slot: the planner drops it (passing on its stop).
  if (!m.arc && move_length(m) < kMinLength) {
    m.line = static_cast<std::uint32_t>(next_token_);
    prep_.push(m, ready_);
    return true;
  }
  ring_[next_token_ & ring_mask_] = m;
  m.line = static_cast<std::uint32_t>(next_token_);  // the planner carries the token
  ++next_token_;
  prep_.push(m, ready_);
  return true;
}

std::uint64_t SegmentQueue::full_token(std::uint32_t token) const noexcept {
  return next_token_ - static_cast<std::uint32_t>(static_cast<std::uint32_t>(next_token_) - token);
}

void SegmentQueue::activate(std::uint32_t token) noexcept {
  oldest_ = full_token(token);
}

void SegmentQueue::report_starts_to(std::uint32_t token, BlockObserver& observer) noexcept {
  // Tokens count the ring's Moves in order; the ring still holds every token from the last
  // reported one on (fill() reuses only slots below oldest_, which is at most the active one).
  const std::uint64_t full = full_token(token);
  for (; reported_ <= full; ++reported_)
    observer.on_block_started(ring_[reported_ & ring_mask_].line,
                              ring_[reported_ & ring_mask_].file);
}

void SegmentQueue::report_part_starts(const planner::Chain& path, double s_from, double s_to,
                                      BlockObserver& observer) noexcept {
  // Part k + 1 starts at the end of part k (Chain::at: an inner joint belongs to the later
  // part); parts of one block (a blend carries its incoming block's token) are reported once.
  for (std::size_t k = 0; k + 1 < path.parts(); ++k) {
    const double e = path.part_end(k);
    if (e > s_from && e <= s_to) report_starts_to(path.part_line(k + 1), observer);
  }
}

std::optional<Dwell> SegmentQueue::take_dwell() noexcept {
  std::optional<Dwell> d = dwell_;
  dwell_.reset();
  return d;
}

std::optional<ChannelWait> SegmentQueue::take_wait() noexcept {
  std::optional<ChannelWait> w = wait_;
  wait_.reset();
  return w;
}

}  // namespace ncsim::ipo
