#pragma once
// cli/line_report: what `ncsim line time|run` prints (docs/lines.md "ncsim line"): the line's
// end, per channel its end, waiting time, utilisation, stop and the workpieces it took; the
// belt's counts (arrived, taken per channel, missed, on the belt) with the workpieces per
// minute; then every workpiece's fate. As text, or one JSON object (`--json`).
// Inputs: a LineRun after its last step. Outputs: text on `out`. Invariants: reruns give the
// same bytes; the counts satisfy arrived = taken + missed + on the belt.

#include <iosfwd>

#include "runner/line_run.hpp"

namespace ncsim::cli {

/// The line's times and workpieces as text.
void print_line_text(const runner::LineRun& line, std::ostream& out);
/// The same as one JSON object (and a newline).
void print_line_json(const runner::LineRun& line, std::ostream& out);

}  // namespace ncsim::cli
