#pragma once
// jerk/trusted: entry points of the kernel's fastest searches (and the two-peak change's
// applicability) for a caller that has already checked its inputs exactly as they do
// (axes::plan_position: limits valid, start, p1 and v1 finite, |v1| <= V), so each plan checks
// them once instead of once per candidate (issue 11, session 25: 2.9 checks per time-optimal
// plan, ~60 instructions).
// Inputs and outputs: those of fastest_move, two_peak_move and reversal_move (jerk.hpp), whose
// answers these are for valid inputs. Invalid inputs are a broken contract (not detected).
// Internal to jerk/ and axes/ (not part of jerk.hpp). Nothing allocates or throws.

#include "jerk/jerk.hpp"

namespace ncsim::jerk::detail {

/// fastest_move without its input check.
Status fastest_move_trusted(const State& start, double p1, double v1, const Limits& limits,
                            Move& out) noexcept;

/// two_peak_move without its input check.
Status two_peak_move_trusted(const State& start, double p1, double v1, const Limits& limits,
                             TwoPeak& out) noexcept;

/// Whether two_peak_move's shape applies at all (a distance, the arrival not behind, a start
/// acceleration pointing the way of the change, within the limits it must keep): its early
/// exits alone, so a caller skips the candidate and its bound where it cannot exist (issue 11,
/// session 25: 56 % of the bench's plans). Without input check.
bool two_peak_applies(const State& start, double p1, double v1, const Limits& limits) noexcept;

/// reversal_move without its input check.
Status reversal_move_trusted(const State& start, double p1, double v1, const Limits& limits,
                             Reversal& out) noexcept;

/// Whether dip_crossing_move's shape applies at all (its early exits: v1 != 0, a start moving
/// against v1 and braking within A- and V, one that can still reach v = 0 within what v1 and the
/// limits allow): no level or root evaluated. Without input check.
bool dip_crossing_applies(const State& start, double v1, const Limits& limits) noexcept;

/// dip_crossing_move without its input check; also not_supported where the family's fastest
/// member (no dip: its time falls with the dip's acceleration) is not faster than `t_max` [s],
/// decided from that member alone.
Status dip_crossing_move_trusted(const State& start, double p1, double v1, const Limits& limits,
                                 double t_max, DipCrossing& out) noexcept;

}  // namespace ncsim::jerk::detail
