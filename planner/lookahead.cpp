// planner/lookahead: the window, its backward and forward passes, and the ramps carried
// through soft joints (see the header; the segment profiles are in lookahead_profile.cpp).

#include "planner/lookahead.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/number_text.hpp"
#include "planner/lookahead_ramps.hpp"

namespace ncsim::planner {

using ramps::as_state_ramp;
using ramps::ramps_distance_model;
using ramps::released_velocity;

namespace {

/// Where `ramp` begun at (v0, a0) has covered `length`: its time and state there.
struct Cut {
  double t = 0.0;  ///< [s]
  double v = 0.0;  ///< [mm/s]
  double a = 0.0;  ///< [mm/s^2]
};
Cut cut_at(double v0, double a0, const jerk::Ramp& ramp, double length) noexcept {
  const jerk::StateRamp sr = as_state_ramp(ramp);
  const double t = jerk::time_at_distance(v0, a0, sr, length);
  const jerk::State at = jerk::state_at(v0, a0, sr, t);
  return Cut{t, at.v, at.a};
}

/// Distance a brake `ramp` begun at (level, 0) covers until its velocity has fallen to v, for
/// v in (ramp.v_end, level) (0 above level, the whole ramp below v_end): the phase that passes
/// v solved in closed form (the cut checks at the joints a brake crosses, without inverting
/// the distance).
double distance_to_velocity(double level, const jerk::Ramp& ramp, double v) noexcept {
  jerk::State st{0.0, level, 0.0};
  if (!(v < level)) return 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    const double jk = ramp.jerk[i];
    const jerk::State end = jerk::advance(st, jk, ramp.duration[i]);
    if (end.v <= v) {
      // v(t) = st.v + st.a t + jk t^2 / 2 falls through v: the first root, in the form that
      // does not cancel (dv = st.v - v > 0, st.a <= 0).
      const double dv = st.v - v;
      const double disc = std::max(0.0, st.a * st.a - 2.0 * jk * dv);
      const double t = 2.0 * dv / (-st.a + std::sqrt(disc));
      return jerk::advance(st, jk, std::min(t, ramp.duration[i])).p;
    }
    st = end;
    st.a = i < 2 ? ramp.a_peak : 0.0;
  }
  return st.p;
}

/// The highest x in [good, bad] with ok(x), ok(good) known true and ok monotone (true below,
/// false above): `bad` itself when it fits, else bisection to 1e-3 relative (the carries'
/// targets and levels: not limits, the cut state is exact for whichever is taken).
template <class Ok>
double highest_fitting(double good, double bad, const Ok& ok) {
  if (ok(bad)) return bad;
  for (int iter = 0; iter < 12 && bad - good > 1e-3 * bad; ++iter) {
    const double mid = 0.5 * (good + bad);
    (ok(mid) ? good : bad) = mid;
  }
  return good;
}

}  // namespace

std::size_t window_size(LookAheadKind kind, std::optional<std::size_t> custom,
                        std::size_t custom_max) {
  switch (kind) {
    case LookAheadKind::low:
      return 30;
    case LookAheadKind::standard:
      return 120;
    case LookAheadKind::high:
      return 190;
    case LookAheadKind::custom:
      break;
  }
  if (!custom || *custom < 10 || *custom > custom_max)
    throw std::invalid_argument("P-CHAN-00650 FCT_LOOK_AHEAD_CUSTOM: window " +
                                (custom ? std::to_string(*custom) : std::string("(none)")) +
                                " outside [10, " + std::to_string(custom_max) + "] (P-CHAN-00653)");
  return *custom;
}

LookAhead::LookAhead(std::size_t capacity, double t_cycle, SoftJoints soft)
    : t_cycle_(t_cycle), soft_(soft) {
  if (capacity < 1)
    throw std::invalid_argument("planner: look-ahead window of " + std::to_string(capacity) +
                                " segments (P-CHAN-00650)");
  if (!(t_cycle > 0.0) || !std::isfinite(t_cycle))
    throw std::invalid_argument("planner: interpolation cycle must be > 0, got " +
                                core::human(t_cycle));
  slots_.resize(capacity);
}

double LookAhead::planned_jerk(const PathLimits& lim) const noexcept {
  return std::isfinite(lim.j_max) ? lim.j_max : std::max(lim.a_max, lim.d_max) / t_cycle_;
}

void LookAhead::push(PreparedSegment segment) {
  if (full()) throw std::logic_error("planner: push into a full look-ahead window");
  Slot& slot = at(count_);
  const PathLimits& lim = segment.limits;
  slot.length = segment.path.length();
  slot.cap = lim.v_max;
  slot.joint_cap = std::min(segment.v_end, lim.v_max);
  slot.a = lim.a_max;
  slot.d = lim.d_max;
  slot.j = planned_jerk(lim);
  slot.segment = std::move(segment);
  ++count_;
  backward_from_end();
}

void LookAhead::backward_from_end() {
  // The new last segment ends at the window end: a possible stop.
  std::size_t k = count_ - 1;
  Slot* s = &at(k);
  s->exit_cap = 0.0;
  s->entry_cap = std::min(s->cap, jerk::entry_velocity_for_exit(0.0, s->length, s->d, s->j));
  while (k > 0) {
    const double entry_next = s->entry_cap;
    --k;
    s = &at(k);
    const double exit = std::min(s->joint_cap, entry_next);
    if (exit <= s->exit_cap) break;  // caps only grow; an unchanged one ends the pass
    s->exit_cap = exit;
    // An exit at the cap leaves the entry at the cap: a speed-up from v never ends below v
    // (jerk::reachable_velocity adds a term >= 0 to it), so the kernel is not asked.
    s->entry_cap =
        exit >= s->cap
            ? s->cap
            : std::min(s->cap, jerk::entry_velocity_for_exit(exit, s->length, s->d, s->j));
  }
}

bool LookAhead::feasible_exit(double v_entry, double a_entry, double v_upper, const Slot& s,
                              double& out) const noexcept {
  auto fits = [&](double v_exit) {
    const jerk::Ramp down = jerk::velocity_ramp(v_entry, a_entry, v_exit, s.a, s.d, s.j);
    // The kernel's inverse functions agree with its ramps to rounding, not exactly.
    return jerk::distance(v_entry, a_entry, down) <= s.length * (1.0 + 1e-12) + 1e-15;
  };
  // Speeding up (or cruising) to v_upper <= reach always fits (from a = 0), and so does the
  // slow-down to the exit cap from at most the backward pass's entry cap: the kernel's inverse
  // found it to fit. Not asked again here: the forward distance grows with the square root of
  // the velocity difference, so where that is tiny its rounding missed the length and the
  // bisection below planned a stop (issue 36 item 1, F2; docs/planner.md "Look-ahead").
  if (a_entry == 0.0 && (v_upper >= v_entry || v_entry <= s.entry_cap)) {
    out = v_upper;
    return true;
  }
  if (a_entry > 0.0) {
    // A carried speed-up: no plan ends at a = 0 in less than the release a0 / j, during
    // which v >= v0; above the release's velocity the change's distance grows with v_exit.
    out = v_upper;
    if (v_entry * a_entry / s.j > s.length * (1.0 + 1e-12)) return false;
    if (v_upper >= released_velocity(v_entry, a_entry, s.j)) return fits(v_upper);
  }
  if (fits(v_upper)) {
    out = v_upper;
    return true;
  }
  // The entry cap of this segment shrank after its entry was committed (the distance of a
  // jerk-limited slow-down with a = 0 at both ends is not monotone in the exit velocity:
  // docs/planner.md "Look-ahead"). Slowing further fits: the slow-downs that fit are [0, v_lo].
  double lo = 0.0;
  double hi = v_upper;
  for (int iter = 0; iter < 60; ++iter) {
    const double mid = 0.5 * (lo + hi);
    if (fits(mid))
      lo = mid;
    else
      hi = mid;
  }
  out = lo;
  // From a = 0 the stop fits by the backward pass; a carried acceleration may not be released
  // within the length at all (then the carry itself goes on: pop()).
  return a_entry == 0.0 || fits(lo);
}

bool LookAhead::carry_fits(double v0, double a0, double v_toward, double a, double j, Carry& out,
                           bool with_cut) const noexcept {
  const Slot& front = slots_[head_];
  const jerk::Ramp ramp = jerk::velocity_ramp(v0, a0, v_toward, a, a, j);
  const double total = jerk::distance(v0, a0, ramp);
  if (!(total > front.length)) return false;  // ends inside the slot: no cut
  // The rest of the ramp, on the next slots: velocities below v_toward, accelerations within
  // a and jerks within j (the caller's limits are the smallest of the slots it spans).
  double rest = total - front.length;
  bool ends = false;
  for (std::size_t k = 1; k < count_ && !ends; ++k) {
    const Slot& m = slots_[(head_ + k) % slots_.size()];
    if (v_toward > m.cap || a > m.a || j > m.j) return false;
    if (rest <= m.length) {  // ends here at (v_toward, 0): the window's braking must still fit
      if (v_toward > m.exit_cap &&
          v_toward > jerk::entry_velocity_for_exit(m.exit_cap, m.length - rest, m.d, m.j))
        return false;
      ends = true;
    } else if (m.segment.stop != StopReason::none || m.segment.a_zero_at_end ||
               v_toward > m.joint_cap) {
      return false;
    } else {
      rest -= m.length;
    }
  }
  if (!ends) return false;  // runs beyond what the window knows
  if (!with_cut) return true;
  // The cut at the slot end: the state carried into the next slot.
  const Cut cut = cut_at(v0, a0, ramp, front.length);
  out.v_toward = v_toward;
  out.a = a;
  out.d = a;  // a speed-up: its ramp's a_down plays no part
  out.j = j;
  out.t_cut = cut.t;
  out.v1 = cut.v;
  out.a1 = cut.a;
  return out.a1 > 0.0 && out.v1 <= std::min(front.cap, front.joint_cap);
}

bool LookAhead::best_carry(double v0, double a0, Carry& out) const noexcept {
  const Slot& front = slots_[head_];
  const Slot& next = slots_[(head_ + 1) % slots_.size()];
  // v_toward above the velocity the slot can reach (else the ramp ends inside it), at most
  // the next slot's cap (the velocity after the joint rises to it).
  double a = std::min(front.a, next.a);
  double j = std::min(front.j, next.j);
  const auto lowest_target = [&] {
    return std::max(released_velocity(v0, a0, j),
                    jerk::reachable_velocity(v0, a0, front.length, a, j));
  };
  double hi = next.cap;
  if (a0 > a || !(hi > lowest_target())) return false;
  // The ramp's limits: the smallest of the slots the longest ramp (towards hi) can span.
  const double span = jerk::distance(v0, a0, jerk::velocity_ramp(v0, a0, hi, a, a, j));
  double covered = front.length + next.length;
  for (std::size_t k = 2; k < count_ && covered < span; ++k) {
    const Slot& prev = slots_[(head_ + k - 1) % slots_.size()];
    if (prev.segment.stop != StopReason::none || prev.segment.a_zero_at_end) break;
    const Slot& m = slots_[(head_ + k) % slots_.size()];
    a = std::min(a, m.a);
    j = std::min(j, m.j);
    covered += m.length;
  }
  const double lo = lowest_target();
  if (a0 > a || !(hi > lo)) return false;
  // The checks tighten as v_toward rises: none fits when the lowest does not; else the
  // highest that fits, by bisection to 1e-3 relative (a target, not a limit: the cut state
  // is exact for whichever is taken). The walk over the next slots first, without the cut
  // (its time_at_distance is the costly part); the cut's own check (the velocity at the slot
  // end) then only where it binds.
  Carry c;
  const double lowest = lo + 1e-3 * (hi - lo);
  if (!carry_fits(v0, a0, lowest, a, j, c, false)) return false;
  const auto fits = [&](bool with_cut) {
    return [&, with_cut](double x) { return carry_fits(v0, a0, x, a, j, c, with_cut); };
  };
  const double walk = highest_fitting(lowest, hi, fits(false));
  if (carry_fits(v0, a0, walk, a, j, out, true)) return true;
  if (!carry_fits(v0, a0, lowest, a, j, out, true)) return false;
  return carry_fits(v0, a0, highest_fitting(lowest, walk, fits(true)), a, j, out, true) ||
         carry_fits(v0, a0, lowest, a, j, out, true);
}

/// The brakes brake_carry() tries, one per slot m (1 <= m <= kMaxBrakeJoints) they end in:
/// the brake ends at the end of slot m, at its exit cap w (with a = 0, where the backward
/// pass's caps hold), crossing joints 0 .. m-1 (joint k ends slot k) below bounds[k], each
/// within that joint's cap and the next slot's. The plan with a = 0 at every joint brakes from
/// exit cap to exit cap over each of these slots; after slot m both go on from (w, 0), so their
/// times over slots 0 .. m compare the two. extend() takes the next slot in; find_level() finds the
/// brake's level for the slots taken.
class LookAhead::BrakeSpan {
 public:
  /// From (v0, 0) at the front slot's start; `exit_zero`: its exit with a = 0 at joint 0.
  BrakeSpan(const LookAhead& window, double v0, double exit_zero) noexcept
      : window_(window),
        front_(window.slots_[window.head_]),
        v0_(v0),
        z_(exit_zero),
        a_(front_.a),
        d_(front_.d),
        j_(front_.j) {}

  /// Takes slot m + 1 in; false where no brake ends there or beyond (the tries end).
  bool extend() noexcept;
  /// The highest level whose brake to w() ends at slot m's end, begins in the front slot and
  /// passes every joint it crosses within its bound; none where no level fits.
  std::optional<double> find_level() const noexcept;
  /// The brake from `level` (a = 0) to w() under the span's limits.
  jerk::Ramp brake(double level) const noexcept {
    return jerk::velocity_ramp(level, 0.0, w_, a_, d_, j_);
  }
  /// The brake's part in the front slot [mm] (after the ramp up from v0 to `level`), or 0
  /// where the level does not fit there.
  double part_here(double level, const jerk::Ramp& brake) const noexcept;

  std::size_t m() const noexcept { return m_; }
  double w() const noexcept { return w_; }  ///< velocity the brake ends at [mm/s]
  double bound(std::size_t k) const noexcept { return bounds_[k]; }  ///< at joint k [mm/s]
  double a() const noexcept { return a_; }  ///< the ramp's limits: the smallest of the slots
  double d() const noexcept { return d_; }
  double j() const noexcept { return j_; }
  /// The plan with a = 0 at the joints: its time over slots 1 .. m [s].
  double t_zero() const noexcept { return t_zero_; }

 private:
  const Slot& slot(std::size_t k) const noexcept {
    return window_.slots_[(window_.head_ + k) % window_.slots_.size()];
  }
  bool fits_here(double level) const noexcept { return part_here(level, brake(level)) > 0.0; }
  bool cuts_fit(double level) const noexcept;

  const LookAhead& window_;
  const Slot& front_;
  double v0_ = 0.0;
  std::size_t m_ = 0;
  std::array<double, kMaxBrakeJoints> bounds_{};
  double z_ = 0.0;        ///< the plan with a = 0 at the joints: velocity at the last one
  double w_ = 0.0;        ///< exit cap of slot m [mm/s]
  double a_, d_, j_;      ///< the ramp's limits over slots 0 .. m
  double t_zero_ = 0.0;   ///< the plan with a = 0 at the joints over slots 1 .. m [s]
  double covered_ = 0.0;  ///< the brake's distance after joint 0 [mm]
};

bool LookAhead::BrakeSpan::extend() noexcept {
  const std::size_t m = m_ + 1;
  if (m > kMaxBrakeJoints || m >= window_.count_) return false;
  const Slot& prev = slot(m - 1);
  const Slot& sm = slot(m);
  if (m > 1 && (prev.segment.stop != StopReason::none || prev.segment.a_zero_at_end)) return false;
  bounds_[m - 1] = std::min(prev.joint_cap, sm.cap);
  // A joint whose caps bind the plan with a = 0 there is not passed faster braking: the
  // brake ends at it (as at joint 0: brake_carry()).
  if (m > 1 && !(z_ < bounds_[m - 1])) return false;
  const double w = std::min(sm.exit_cap, sm.cap);
  // Only where the plan with a = 0 at the joints brakes over each slot crossed, and a plan
  // ending at a = 0 at a joint (the override's, up to z: PlannedSegment::v_exit_zero)
  // leaves slot m its brake to w. The backward pass's exit cap can lie above the entry
  // velocity for w (that velocity of a short jerk-limited brake is not monotone in the
  // exit: "Look-ahead"; the slot's pop then brakes to a lower exit): no carry there.
  if (!(w < z_) || z_ > jerk::entry_velocity_for_exit(w, sm.length, sm.d, sm.j)) return false;
  const jerk::Ramp zero = jerk::velocity_ramp(z_, 0.0, w, sm.a, sm.d, sm.j);
  t_zero_ +=
      zero.time() + (w > 0.0 ? std::max(0.0, sm.length - jerk::distance(z_, 0.0, zero)) / w : 0.0);
  z_ = w;
  a_ = std::min(a_, sm.a);
  d_ = std::min(d_, sm.d);
  j_ = std::min(j_, sm.j);
  covered_ += sm.length;
  m_ = m;
  w_ = w;
  return true;
}

double LookAhead::BrakeSpan::part_here(double level, const jerk::Ramp& brake) const noexcept {
  // Its part here and its velocity at every joint grow with the level: the fitting levels
  // are [lo, highest].
  const jerk::Ramp up = jerk::velocity_ramp(v0_, 0.0, level, a_, d_, j_);
  const double e = jerk::distance(level, 0.0, brake) - covered_;
  return e > 0.0 && jerk::distance(v0_, 0.0, up) + e <= front_.length * (1.0 + 1e-12) ? e : 0.0;
}

bool LookAhead::BrakeSpan::cuts_fit(double level) const noexcept {
  // Every joint the brake crosses lies inside its ramp (a < 0 there, and a release from the
  // state there ends at or above w); its velocity there is within the joint's bound where
  // the ramp passes the bound before it (distance_to_velocity: no inversion of the
  // distance). The distances are summed in the order through_brake() sums them.
  const jerk::Ramp br = brake(level);
  double s = part_here(level, br);
  if (!(s > 0.0)) return false;
  for (std::size_t k = 0; k < m_; ++k) {
    if (k > 0) s += slot(k).length;
    if (bounds_[k] < level && s < distance_to_velocity(level, br, bounds_[k]) * (1.0 + 1e-12))
      return false;
  }
  return true;
}

std::optional<double> LookAhead::BrakeSpan::find_level() const noexcept {
  // The highest level by the distance alone first (cheap), to 1e-3 relative (a target: the
  // cut state is exact for whichever level is taken), then the cuts' checks. The distance in
  // closed form first (ramps_distance_model: equal to the kernel's distances up to rounding),
  // by bisection on it (1e-3 relative), then the kernel's check.
  const auto here = [this](double v) { return fits_here(v); };
  const auto model_fits = [this](double v) {
    return ramps_distance_model(v0_, v, w_, a_, d_, j_) - covered_ <= front_.length;
  };
  const auto cuts = [this](double v) { return cuts_fit(v); };
  // The brake must begin before the joint (e > 0): from just above the level whose brake
  // to w is as long as the slots after joint 0 (the kernel's inverse; its distance grows
  // with the level).
  const double hi = std::max(front_.cap, std::max(v0_, w_));
  double lo = std::max(v0_, w_);
  if (!fits_here(lo)) {
    const double exact = jerk::entry_velocity_for_exit(w_, covered_, d_, j_);
    lo = std::max(lo, exact + 1e-9 * exact);
    if (!(lo < hi) || !fits_here(lo)) return std::nullopt;
  }
  double level = highest_fitting(lo, hi, model_fits);
  if (!fits_here(level)) level = highest_fitting(lo, level, here);
  if (!cuts_fit(level)) {
    if (!cuts_fit(lo)) return std::nullopt;
    level = highest_fitting(lo, level, cuts);
  }
  return level;
}

bool LookAhead::brake_carry(double v0, PlannedSegment& out, Carry& carry) const noexcept {
  const double exit_zero = out.v_exit;
  const Slot& front = slots_[head_];
  // Nothing to gain where the joint's caps bind the plan with a = 0 there.
  if (!(exit_zero < std::min(front.joint_cap, slots_[(head_ + 1) % slots_.size()].cap)))
    return false;
  struct Best {
    Cut cut;
    double level = 0.0, w = 0.0, e = 0.0, a = 0.0, d = 0.0, j = 0.0, gain = 0.0;
    std::size_t m = 0;
  } best;
  double t_front = -1.0;  // the front slot's time with a = 0 at joint 0 (when first needed)
  BrakeSpan span(*this, v0, exit_zero);
  while (span.extend()) {
    const std::optional<double> level = span.find_level();
    if (!level) continue;
    // The state committed at joint 0, checked on the cut itself.
    const jerk::Ramp brake = span.brake(*level);
    const double e = span.part_here(*level, brake);
    const Cut cut = cut_at(*level, 0.0, brake, e);
    if (!(e > 0.0 && cut.a < 0.0 && cut.v <= span.bound(0) &&
          cut.v - 0.5 * cut.a * cut.a / span.j() >= span.w()))
      continue;
    if (!(cut.v > exit_zero)) continue;  // joint 0 no faster than with a = 0 there
    PlannedSegment tried = out;
    tried.shape = ProfileShape::carry_down;
    tried.v_exit = cut.v;
    tried.a_exit = cut.a;
    tried.v_brake = span.w();
    tried.t_brake = cut.t;
    tried.level = *level;
    tried.ramp_a = span.a();
    tried.ramp_d = span.d();
    tried.ramp_j = span.j();
    if (t_front < 0.0) t_front = profile(out).time();
    const double gain = t_front + span.t_zero() - (profile(tried).time() + (brake.time() - cut.t));
    if (gain > best.gain)
      best = Best{cut, *level, span.w(), e, span.a(), span.d(), span.j(), gain, span.m()};
  }
  if (best.m == 0) return false;
  out.shape = ProfileShape::carry_down;
  out.v_exit_zero = exit_zero;
  out.v_exit = best.cut.v;
  out.a_exit = best.cut.a;
  out.v_brake = best.w;
  out.t_brake = best.cut.t;
  out.level = best.level;
  carry.v_toward = best.w;
  carry.level = best.level;
  carry.t_cut = best.cut.t;
  carry.s_cut = best.e;
  carry.joints = best.m - 1;
  carry.a = best.a;
  carry.d = best.d;
  carry.j = best.j;
  set_ramp_limits(out, carry);
  return true;
}

double LookAhead::start_at(double v) noexcept {  // a path that starts moving (sync-feed)
  v_committed_ = std::clamp(v, 0.0, front_entry_cap());
  a_committed_ = 0.0;
  return v_committed_;
}

PlannedSegment LookAhead::pop() {
  if (empty()) throw std::logic_error("planner: pop from an empty look-ahead window");
  Slot& s = at(0);
  PlannedSegment out;
  out.v_entry = v_committed_;
  out.a_entry = a_committed_;
  out.a_max = s.a;
  out.d_max = s.d;
  out.j_max = s.j;
  if (a_committed_ < 0.0 && carry_.joints > 0)
    through_brake(out);
  else if (a_committed_ < 0.0)
    end_brake(out);
  else
    plan_front(out);
  v_committed_ = out.v_exit;
  a_committed_ = out.a_exit;
  if (split_) {
    split_ = false;
    return out;
  }
  head_ = (head_ + 1) % slots_.size();
  --count_;
  return out;
}

void LookAhead::end_brake(PlannedSegment& out) noexcept {
  // The rest of a carried brake: it ends at (v_toward, 0) at this slot's end (its check
  // when it was committed), a cruise takes up what rounding leaves.
  out.shape = ProfileShape::brake_end;
  out.v_toward = carry_.v_toward;
  out.level = carry_.level;
  out.t_cut = carry_.t_cut;
  out.v_exit = carry_.v_toward;
  out.v_exit_zero = out.v_exit;
  set_ramp_limits(out, carry_);
  out.segment = std::move(at(0).segment);
}

void LookAhead::through_brake(PlannedSegment& out) noexcept {
  // A carried brake that crosses this slot's end joint too: its part up to the next cut (the
  // distances summed as brake_carry() checked them, so the cut is the one checked).
  const Slot& s = at(0);
  const jerk::Ramp brake =
      jerk::velocity_ramp(carry_.level, 0.0, carry_.v_toward, carry_.a, carry_.d, carry_.j);
  carry_.s_cut += s.length;
  const Cut cut = cut_at(carry_.level, 0.0, brake, carry_.s_cut);
  out.shape = ProfileShape::brake_through;
  out.v_toward = carry_.v_toward;
  out.level = carry_.level;
  out.t_cut = carry_.t_cut;
  out.t_brake = cut.t;
  out.v_exit = cut.v;
  out.a_exit = cut.a;
  out.v_exit_zero = s.exit_cap;
  set_ramp_limits(out, carry_);
  carry_.t_cut = cut.t;
  --carry_.joints;
  out.segment = std::move(at(0).segment);
}

void LookAhead::set_ramp_limits(PlannedSegment& out, const Carry& c) noexcept {
  out.ramp_a = c.a;
  out.ramp_d = c.d;
  out.ramp_j = c.j;
}

void LookAhead::plan_front(PlannedSegment& out) noexcept {
  Slot& s = at(0);
  const double v0 = out.v_entry;
  const double a0 = out.a_entry;
  const double reach = jerk::reachable_velocity(v0, a0, s.length, s.a, s.j);
  const double upper = std::min({s.exit_cap, reach, s.cap});
  double exit = 0.0;
  const bool plain = feasible_exit(v0, a0, upper, s, exit);
  // A speed-up the length cuts at a soft joint goes on through it (docs/planner.md
  // "Acceleration at joints"); a carried one that cannot be released here goes on too.
  const bool soft = soft_ == SoftJoints::carry && s.segment.stop == StopReason::none &&
                    !s.segment.a_zero_at_end && count_ > 1;
  const bool cut = !plain || (upper == reach && reach < std::min(s.exit_cap, s.cap));
  Carry c;
  bool carried = soft && cut && best_carry(v0, a0, c) && (!plain || c.v1 > exit);
  if (!plain && !carried && a0 > 0.0) {
    // The committed carry's own ramp: it was checked to fit when it was committed.
    const jerk::Ramp ramp =
        jerk::velocity_ramp(v0, a0, carry_.v_toward, carry_.a, carry_.a, carry_.j);
    if (jerk::distance(v0, a0, ramp) > s.length) {
      const Cut k = cut_at(v0, a0, ramp, s.length);
      c = carry_;
      c.t_cut = k.t;
      c.v1 = k.v;
      c.a1 = std::max(k.a, 0.0);
      carried = true;
    }
  }
  if (carried) {
    out.shape = ProfileShape::carry_up;
    out.v_exit = c.v1;
    out.a_exit = c.a1;
    out.v_toward = c.v_toward;
    out.t_cut = c.t_cut;
    set_ramp_limits(out, c);
    carry_ = c;
  } else {
    out.v_exit = exit;
  }
  out.v_exit_zero = out.v_exit;
  out.segment = std::move(s.segment);
  // A brake the next slot goes on with is carried through a soft joint too, where that is
  // faster over both than the plan with a = 0 at the joint.
  if (!carried && soft && plain && a0 == 0.0 && exit == s.exit_cap && brake_carry(v0, out, c))
    carry_ = c;
  else if (!carried && a0 == 0.0 && out.segment.option_count > 0) {
    const PathLimits own = out.segment.limits;
    const double t_single = fastest_option(out);
    split_ = t_single > 0.0 && stage_arc(out, own, t_single);
  }
}

LookAhead::Stage LookAhead::best_stage(const PlannedSegment& out, double t_single) const noexcept {
  const PreparedSegment& seg = out.segment;
  const Slot& s = slots_[head_];
  const double length = seg.path.length();
  const double ve = out.v_entry;
  const double vx = out.v_exit;
  Stage best;
  best.t = t_single * (1.0 - 1e-9);
  const auto consider = [&](std::size_t k, bool head, const jerk::TimeDistance& ramp,
                            double t_rest) {
    if (ramp.t + t_rest < best.t) best = {k, head, ramp.s * (1.0 + 1e-12), ramp.t + t_rest};
  };
  for (std::size_t k = 0; k < seg.option_count; ++k) {
    const PathLimits& o = seg.options[k];
    if (o.v_max > s.cap) continue;
    const double jo = planned_jerk(o);
    if (o.a_max > s.a && o.v_max > ve) {  // a ramp at the start under o, the rest under own
      const jerk::TimeDistance h = jerk::velocity_change(ve, 0.0, o.v_max, o.a_max, jo);
      const double rest = length - h.s * (1.0 + 1e-12);
      // The rest can still brake to its exit cap, and reach the planned exit.
      if (rest > 0.0 && o.v_max <= jerk::entry_velocity_for_exit(s.exit_cap, rest, s.d, s.j) &&
          std::min(s.exit_cap, jerk::reachable_velocity(o.v_max, 0.0, rest, s.a, s.j)) >= vx)
        consider(k, true, h, plain_profile(rest, s.cap, o.v_max, 0.0, vx, s.a, s.d, s.j).time());
    }
    if (o.d_max > s.d && o.v_max > vx) {  // the rest under own, a brake at the end under o
      const jerk::TimeDistance b = jerk::velocity_change(o.v_max, 0.0, vx, o.d_max, jo);
      const double first = length - b.s * (1.0 + 1e-12);
      // The first part reaches o's cap from the entry, or brakes to it.
      if (first > 0.0 && jerk::reachable_velocity(ve, 0.0, first, s.a, s.j) >= o.v_max &&
          ve <= jerk::entry_velocity_for_exit(o.v_max, first, s.d, s.j))
        consider(k, false, b, plain_profile(first, s.cap, ve, 0.0, o.v_max, s.a, s.d, s.j).time());
    }
  }
  return best;
}

bool LookAhead::stage_arc(PlannedSegment& out, const PathLimits& own, double t_single) noexcept {
  PreparedSegment& seg = out.segment;
  if (seg.path.parts() != 1) return false;
  const Stage stage = best_stage(out, t_single);
  if (stage.option == kArcOptions) return false;
  Slot& s = at(0);
  const PathLimits o = seg.options[stage.option];
  const double length = seg.path.length();
  const double at = stage.head ? stage.cut : length - stage.cut;
  const Segment& part = seg.path.part(0);
  const std::uint32_t line = seg.path.part_line(0);
  PreparedSegment rest = seg;
  rest.path = Chain(part.trimmed(at, length), line);
  seg.path = Chain(part.trimmed(0.0, at), line);
  seg.stop = StopReason::none;  // a C2 joint inside the arc, left at a = 0
  seg.joint = TransitionClass::c2;
  seg.a_zero_at_end = true;
  // The piece under o: the first one (a ramp) or the rest (a brake, with o's cap in its slot).
  const PathLimits& first_limits = stage.head ? o : own;
  seg.limits = first_limits;
  out.a_max = first_limits.a_max;
  out.d_max = first_limits.d_max;
  out.j_max = planned_jerk(first_limits);
  rest.limits = stage.head ? own : o;
  if (!stage.head) {
    s.cap = o.v_max;
    s.a = o.a_max;
    s.d = o.d_max;
    s.j = planned_jerk(o);
  }
  out.v_exit = o.v_max;
  out.v_exit_zero = o.v_max;
  seg.v_end = o.v_max;
  s.segment = std::move(rest);
  s.length = s.segment.path.length();
  s.entry_cap = std::min(s.cap, jerk::entry_velocity_for_exit(s.exit_cap, s.length, s.d, s.j));
  return true;
}

double LookAhead::fastest_option(PlannedSegment& out) const noexcept {
  PreparedSegment& seg = out.segment;
  if (seg.option_count == 0 || out.shape != ProfileShape::plain || out.a_exit != 0.0) return 0.0;
  const double length = seg.path.length();
  const PathLimits own = seg.limits;
  PathLimits best = own;
  double best_a = out.a_max, best_d = out.d_max, best_j = out.j_max;
  double t_best = profile(out).time();
  for (std::size_t k = 0; k < seg.option_count; ++k) {
    const PathLimits& o = seg.options[k];
    if (o.v_max < std::max(out.v_entry, out.v_exit)) continue;
    // profile() reads the cap from the segment and a, d, j from the plan.
    seg.limits = o;
    out.a_max = o.a_max;
    out.d_max = o.d_max;
    out.j_max = planned_jerk(o);
    const SegmentProfile p = profile(out);
    // Its two ramps must fit the length (profile() keeps the lowest level when none does).
    const double used =
        jerk::distance(p.v0, p.a0, p.first) + jerk::distance(p.v_level, 0.0, p.second);
    if (used <= length * (1.0 + 1e-12) + 1e-15 && p.time() < t_best) {
      t_best = p.time();
      best = o;
      best_a = out.a_max;
      best_d = out.d_max;
      best_j = out.j_max;
    }
  }
  seg.limits = best;
  out.a_max = best_a;
  out.d_max = best_d;
  out.j_max = best_j;
  return t_best;
}

}  // namespace ncsim::planner
