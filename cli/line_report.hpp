#pragma once
// cli/line_report: what `ncsim line time|run` prints (docs/lines.md "ncsim line"): the line's
// end, per channel its end, waiting time, utilisation, stop and the workpieces it took; the
// belt's counts (arrived, taken per channel, missed, on the belt) with the workpieces per
// minute; then every workpiece's fate. As text, or one JSON object (`--json`).
// Inputs: a LineRun after its last step. Outputs: text on `out`. Invariants: reruns give the
// same bytes; the counts satisfy arrived = taken + missed + on the belt.

#include <cstdint>
#include <iosfwd>

#include "runner/line_run.hpp"

namespace ncsim::cli {

/// Channel k's utilisation [%]: (its end - its waiting) / the line's end, to 0.1 %.
double line_utilisation(const runner::LineRun& line, std::size_t k);
/// `n` workpieces per minute over the line's end `t_line` [s] (0 when it is 0).
double line_per_minute(std::uint64_t n, double t_line);

/// The line's times and workpieces as text.
void print_line_text(const runner::LineRun& line, std::ostream& out);
/// The same as one JSON object (and a newline).
void print_line_json(const runner::LineRun& line, std::ostream& out);

}  // namespace ncsim::cli
