#pragma once
// core/limits: bounds of time every stage shares, so decode (check, trace) and run time (time,
// run) refuse the same programs and scenarios.
//
// kLongestTime is the longest single time ncsim accepts: a G04 / #TIME dwell, a G93 block time,
// an INDP TIME, a feed motion's time at its programmed feed, a scenario time. One day: no NC
// block sensibly lasts longer, the run stays a bounded number of cycles (86.4e6 at 1 ms,
// 8.64e10 at the shortest cycle of 1 us, far below 2^53, so the cycle counts stay exact in a
// double and convert to an integer without overflow), and a typo such as `G04 100000000000`
// is an error at its line instead of a run that never ends (issue 34 items 1, 19;
// docs/interp.md "The longest time").

namespace ncsim::core {

inline constexpr double kLongestTime = 86'400.0;  // [s] one day

}  // namespace ncsim::core
