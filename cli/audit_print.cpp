#include "cli/audit_print.hpp"

#include <algorithm>
#include <ostream>
#include <sstream>

#include "cli/number_format.hpp"
#include "runner/texts.hpp"

namespace ncsim::cli {

using runner::block_where;

// The audit verdict, one line per axis, then the documented steps and every violation listed.
void print_audit(const audit::Verdict& v, const std::vector<std::string>& names,
                 const std::vector<std::string>& units, const interp::Interpreter& interp,
                 std::ostream& os, bool each_step) {
  for (std::size_t i = 0; i < v.axes.size(); ++i) {
    const audit::AxisAudit& a = v.axes[i];
    const std::string& u = i < units.size() ? units[i] : std::string("mm");
    os << "audit: " << names[i] << " |v| " << human(std::max(a.v_closed, a.v_diff)) << " / "
       << human(a.v_limit) << ' ' << u << "/s, |a| " << human(std::max(a.a_closed, a.a_diff))
       << " / " << human(a.a_limit) << ' ' << u << "/s^2, |j| ";
    if (a.jerk_cycles == 0) {  // STEP slope throughout: the jerk is not limited, not audited
      os << "not limited (acceleration-limited slope)\n";
      continue;
    }
    os << human(std::max(a.j_closed, a.j_diff)) << " / " << human(a.j_limit) << ' ' << u
       << "/s^3\n";
  }
  // Under #TRAFO ON the joints (the machine axes) are checked apart.
  for (std::size_t i = 0; i < v.joints.size(); ++i) {
    const audit::AxisAudit& a = v.joints[i];
    if (a.v_closed == 0.0 && a.v_diff == 0.0) continue;  // no transformed cycle moved it
    os << "audit: " << (i < names.size() ? names[i] : std::to_string(i)) << " under #TRAFO |v| "
       << human(std::max(a.v_closed, a.v_diff)) << " / " << human(a.v_limit) << ", |a| "
       << human(std::max(a.a_closed, a.a_diff)) << " / " << human(a.a_limit) << ", |j| "
       << human(std::max(a.j_closed, a.j_diff)) << " / " << human(a.j_limit) << " (deg | mm, s)\n";
  }
  os << "audit: contour deviation " << human(v.contour_max) << " mm (tolerance "
     << human(v.contour_tolerance) << " mm), " << v.step_count
     << " documented VELOJUMP / TRANSVELMIN / C1 steps within their formulas, " << v.cycles
     << " cycles\n";
  // One documented step: where, which axis, its value against its formula's bound.
  const auto step_text = [&](const audit::Step& s) {
    const bool c1 = s.quantity == audit::Quantity::c1_step;  // an acceleration step
    const char* unit = c1 ? "/s^2" : "/s";
    const std::string& u = s.axis < units.size() ? units[s.axis] : std::string("mm");
    std::ostringstream t;
    t << "t=" << num(s.t) << " s line " << block_where(interp, s.file, s.line) << " axis "
      << (s.axis < names.size() ? names[s.axis] : std::to_string(s.axis))
      << (s.joint ? " under #TRAFO " : " ") << (c1 ? "|da| " : "|dv| ") << human(s.value) << " of "
      << human(s.bound) << ' ' << u << unit << " at the link velocity " << human(s.v_link)
      << " mm/s";
    return t.str();
  };
  // The documented steps listed apart (issue 12): per kind, how many and the closest to its
  // formula's bound (the axis that came closest at that joint); with --audit-steps each one.
  for (std::size_t k = 0; k < audit::kStepKindNames.size(); ++k) {
    const audit::StepKind& sk = v.step_kinds[k];
    if (sk.count == 0) continue;
    os << "audit: " << audit::kStepKindNames[k] << " steps " << sk.count << ", closest to "
       << audit::kStepKindFormulas[k] << ": " << step_text(sk.closest) << '\n';
  }
  if (each_step) {
    for (const audit::Step& s : v.steps)
      os << "audit: step " << audit::kStepKindNames[audit::step_kind(s.quantity)] << ' '
         << step_text(s) << '\n';
    if (v.step_count > v.steps.size())
      os << "audit: ... " << (v.step_count - v.steps.size()) << " more steps\n";
  }
  for (const audit::Violation& x : v.violations) {
    os << "audit: violation t=" << num(x.t) << " s line " << block_where(interp, x.file, x.line)
       << " axis " << (x.axis < names.size() ? names[x.axis] : std::to_string(x.axis)) << ' '
       << audit::quantity_name(x.quantity) << " (" << audit::method_name(x.method) << ") "
       << num(x.value) << " > " << num(x.limit);
    if (x.path >= 0.0)  // the axis moved with the belt (audit/audit.hpp)
      os << " (" << num(x.path) << " without the belt's share)";
    os << '\n';
  }
  if (v.violation_count > v.violations.size()) {
    os << "audit: ... " << (v.violation_count - v.violations.size()) << " more violations\n";
  }
  if (v.belt_count > 0)  // the belt's own dynamics (004 l.454)
    os << "audit: " << v.belt_count
       << " of the violations are the belt's own acceleration or jerk on top of a path within "
          "the axis's limits (004 l.454: \"dynamic overshoots ... caused by fluctuations in "
          "conveyor belt velocity\"; docs/conveyor.md \"The belt's own dynamics\")\n";
  os << "audit: " << (v.ok() ? "ok" : std::to_string(v.violation_count) + " violations") << '\n';
}

}  // namespace ncsim::cli
