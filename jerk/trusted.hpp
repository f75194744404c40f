#pragma once
// jerk/trusted: entry points of the kernel's fastest searches for a caller that has already
// checked its inputs exactly as they do (axes::plan_position: limits valid, start, p1 and v1
// finite, |v1| <= V), so each plan checks them once instead of once per candidate (issue 11,
// session 25: 2.9 checks per time-optimal plan, ~60 instructions).
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

/// reversal_move without its input check.
Status reversal_move_trusted(const State& start, double p1, double v1, const Limits& limits,
                             Reversal& out) noexcept;

}  // namespace ncsim::jerk::detail
