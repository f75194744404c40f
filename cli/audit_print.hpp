#pragma once
// cli/audit_print: the audit's verdict as `time --audit` and `run --audit` print it: one line
// per axis (and per joint under #TRAFO), the contour, the documented steps per kind (each with
// --audit-steps), every violation listed, the belt's share, the verdict.

#include <iosfwd>
#include <string>
#include <vector>

#include "audit/audit.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::cli {

/// Prints `v` on `os`: `names` and `units` of the interpolated axes, `interp` for the blocks'
/// files, `each_step` lists every documented step.
void print_audit(const audit::Verdict& v, const std::vector<std::string>& names,
                 const std::vector<std::string>& units, const interp::Interpreter& interp,
                 std::ostream& os, bool each_step);

}  // namespace ncsim::cli
