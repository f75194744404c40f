#include "report/html.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>

#include "core/number_text.hpp"
#include "report/assets.hpp"

namespace ncsim::report {

namespace {

/// Shortest round-trip text (times: exact); null for a non-finite value.
void exact(std::string& s, double v) {
  s += core::json_num(v);
}

/// 7 significant digits (display values: a pixel is far coarser); null when not finite.
void value(std::string& s, double v) {
  s += core::json_num(v, 7);
}

template <class F>
void array(std::string& s, const std::vector<double>& v, F&& f) {
  s += '[';
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i > 0) s += ',';
    f(s, v[i]);
  }
  s += ']';
}

void key(std::string& s, const char* k) {
  s += '"';
  s += k;
  s += "\":";
}

void split(std::string& s, const audit::TimeSplit& x) {
  s += "{\"rapid\":";
  exact(s, x.rapid);
  s += ",\"feed\":";
  exact(s, x.feed);
  s += ",\"dwell\":";
  exact(s, x.dwell);
  s += ",\"tech\":";
  exact(s, x.tech);
  s += ",\"exact_stop\":";
  exact(s, x.exact_stop);
  s += ",\"waiting\":";
  exact(s, x.starved);
  s += ",\"held\":";
  exact(s, x.held);
  s += '}';
}

// One axis's audit extremes and limits as a JSON object; `joint` adds the index of a joint
// checked under #TRAFO ON.
void axis_audit(std::string& s, const audit::AxisAudit& a, std::optional<std::size_t> joint) {
  s += "{\"v\":";
  value(s, std::max(a.v_closed, a.v_diff));
  s += ",\"v_limit\":";
  value(s, a.v_limit);
  s += ",\"a\":";
  value(s, std::max(a.a_closed, a.a_diff));
  s += ",\"a_limit\":";
  value(s, a.a_limit);
  s += ",\"j\":";
  value(s, std::max(a.j_closed, a.j_diff));
  s += ",\"j_limit\":";
  value(s, a.j_limit);
  s += ",\"jerk_cycles\":" + std::to_string(a.jerk_cycles);
  if (joint) s += ",\"index\":" + std::to_string(*joint);
  s += '}';
}

// The run's names, outcome and the axes with their soft limits.
void head(std::string& s, const ReportData& d) {
  key(s, "program");
  s += json_quote(d.program);
  s += ',';
  key(s, "machine");
  s += json_quote(d.machine);
  s += ',';
  key(s, "cycle_s");
  exact(s, d.t_cycle);
  s += ',';
  key(s, "outcome");
  s += json_quote(d.outcome);
  s += ',';
  key(s, "stop");
  s += json_quote(d.stop);
  s += ',';
  key(s, "error");
  s += json_quote(d.error);
  s += ',';
  key(s, "axes");
  s += '[';
  for (std::size_t i = 0; i < d.axes.size(); ++i)
    s += (i > 0 ? "," : "") + json_quote(d.axes[i]);
  s += "],";
  key(s, "soft_limits");
  s += '[';
  for (std::size_t i = 0; i < d.soft_limits.size(); ++i) {
    s += i > 0 ? ",[" : "[";
    value(s, d.soft_limits[i][0]);
    s += ',';
    value(s, d.soft_limits[i][1]);
    s += ']';
  }
  s += "],";
}

// The conveyor's workspace (null without one).
void workspace(std::string& s, const ReportData& d) {
  key(s, "workspace");
  if (!d.workspace) {
    s += "null,";
    return;
  }
  const WorkspaceView& w = *d.workspace;
  s += "{\"lower\":[";
  for (int k = 0; k < 3; ++k) {
    if (k > 0) s += ',';
    value(s, w.lower[k]);
  }
  s += "],\"upper\":[";
  for (int k = 0; k < 3; ++k) {
    if (k > 0) s += ',';
    value(s, w.upper[k]);
  }
  s += "],\"pos_limit\":";
  value(s, w.pos_limit);
  s += std::string(",\"along_x\":") + (w.along_x ? "true" : "false") +
       ",\"sign\":" + std::to_string(w.sign) + "},";
}

// The workpieces, the same objects as `ncsim time --json` (audit::append_json); null without.
void workpieces(std::string& s, const ReportData& d) {
  key(s, "workpieces");
  if (!d.workpieces) {
    s += "null,";
    return;
  }
  s += "{\"summary\":";
  audit::append_json(s, *d.workpieces);
  s += ",\"rows\":[";
  for (std::size_t k = 0; k < d.workpiece_rows.size(); ++k) {
    if (k > 0) s += ',';
    audit::append_json(s, d.workpiece_rows[k]);
  }
  s += "]},";
}

// The decimated time series, their names and units, and the tool path.
void series(std::string& s, const ReportData& d) {
  key(s, "bucket_cycles");
  s += std::to_string(d.bucket_width);
  s += ',';
  key(s, "t");
  array(s, d.time.t, exact);
  s += ',';
  key(s, "s");
  s += '[';
  for (std::size_t k = 0; k < d.time.series.size(); ++k) {
    if (k > 0) s += ',';
    array(s, d.time.series[k], value);
  }
  s += "],";
  key(s, "named");
  s += '[';
  for (std::size_t k = 0; k < d.named.size(); ++k)
    s += (k > 0 ? "," : "") + std::string("{\"name\":") + json_quote(d.named[k].name) +
         ",\"unit\":" + json_quote(d.named[k].unit) + '}';
  s += "],";
  key(s, "path");
  s += "{\"dims\":" + std::to_string(d.path_dims) + ",\"tol_mm\":";
  value(s, d.path_tolerance);
  s += ",\"mcs\":";
  array(s, d.path_mcs, value);
  s += ",\"pcs1\":";
  array(s, d.path_pcs1, value);
  s += "},";
}

// The machining time: the total, the block count and the slowest blocks.
void times(std::string& s, const ReportData& d) {
  key(s, "total");
  s += "{\"cycles\":" + std::to_string(d.time_total.cycles) + ",\"total_s\":";
  exact(s, d.time_total.total);
  s += ",\"distance_mm\":";
  exact(s, d.time_total.distance);
  s += ",\"split\":";
  split(s, d.time_total.split);
  s += "},";
  key(s, "blocks");
  s += std::to_string(d.blocks);
  s += ',';
  key(s, "slowest");
  s += '[';
  for (std::size_t k = 0; k < d.slowest.size(); ++k) {
    const audit::BlockTime& b = d.slowest[k];
    s += (k > 0 ? ",{\"line\":" : "{\"line\":") + std::to_string(b.line) + ",\"time_s\":";
    exact(s, b.time);
    s += ",\"distance_mm\":";
    exact(s, b.distance);
    s += ",\"feed_programmed_mm_min\":";
    exact(s, b.feed_programmed * 60.0);
    s += ",\"feed_reached_mm_min\":";
    exact(s, b.feed_reached * 60.0);
    if (b.feed_cap > 0.0) {  // F above the axes' velocity (docs/planner.md "F capped")
      s += ",\"feed_cap_mm_min\":";
      exact(s, b.feed_cap * 60.0);
    }
    s += ",\"split\":";
    split(s, b.split);
    s += '}';
  }
  s += "],";
}

// The joints under #TRAFO ON, checked apart (as the CLI's audit lists them): those that a
// transformed cycle moved, each with its axis index.
void joints(std::string& s, const audit::Verdict& v) {
  bool first = true;
  for (std::size_t i = 0; i < v.joints.size(); ++i) {
    const audit::AxisAudit& a = v.joints[i];
    if (a.v_closed == 0.0 && a.v_diff == 0.0) continue;
    if (!first) s += ',';
    first = false;
    axis_audit(s, a, i);
  }
}

// The documented steps per kind with the one closest to its formula (as the CLI prints them).
void step_kinds(std::string& s, const audit::Verdict& v, const std::vector<std::string>& axes) {
  bool first_kind = true;
  for (std::size_t k = 0; k < audit::kStepKindNames.size(); ++k) {
    const audit::StepKind& sk = v.step_kinds[k];
    if (sk.count == 0) continue;
    const audit::Step& c = sk.closest;
    s += first_kind ? "{\"kind\":" : ",{\"kind\":";
    first_kind = false;
    s += json_quote(audit::kStepKindNames[k]) +
         ",\"formula\":" + json_quote(audit::kStepKindFormulas[k]) +
         ",\"count\":" + std::to_string(sk.count) + ",\"t\":";
    exact(s, c.t);
    s += ",\"line\":" + std::to_string(c.line) +
         ",\"axis\":" + json_quote(c.axis < axes.size() ? axes[c.axis] : std::to_string(c.axis)) +
         ",\"value\":";
    value(s, c.value);
    s += ",\"bound\":";
    value(s, c.bound);
    s += ",\"v_link\":";
    value(s, c.v_link);
    s += '}';
  }
}

// The first kPageViolations violations.
void violations(std::string& s, const audit::Verdict& v, const std::vector<std::string>& axes) {
  const std::size_t listed = std::min(v.violations.size(), kPageViolations);
  for (std::size_t k = 0; k < listed; ++k) {
    const audit::Violation& x = v.violations[k];
    const std::string axis = x.joint                ? "joint " + std::to_string(x.axis)
                             : x.axis < axes.size() ? axes[x.axis]
                                                    : std::to_string(x.axis);
    s += (k > 0 ? ",{\"t\":" : "{\"t\":");
    exact(s, x.t);
    s += ",\"line\":" + std::to_string(x.line) + ",\"axis\":" + json_quote(axis) +
         ",\"quantity\":" + json_quote(audit::quantity_name(x.quantity)) +
         ",\"method\":" + json_quote(audit::method_name(x.method)) + ",\"value\":";
    value(s, x.value);
    s += ",\"limit\":";
    value(s, x.limit);
    s += '}';
  }
}

// The audit of the same pass: the verdict, the extremes per axis and joint, steps, violations.
void audit(std::string& s, const ReportData& d) {
  const audit::Verdict& v = d.verdict;
  key(s, "audit");
  s += std::string("{\"ok\":") + (v.ok() ? "true" : "false") + ",\"contour_mm\":";
  value(s, v.contour_max);
  s += ",\"contour_tolerance_mm\":";
  value(s, v.contour_tolerance);
  s += ",\"steps\":" + std::to_string(v.step_count) + ",\"cycles\":" + std::to_string(v.cycles) +
       ",\"violation_count\":" + std::to_string(v.violation_count) + ",\"axes\":[";
  for (std::size_t i = 0; i < v.axes.size(); ++i) {
    if (i > 0) s += ',';
    axis_audit(s, v.axes[i], {});
  }
  s += "],\"joints\":[";
  joints(s, v);
  s += "],\"step_kinds\":[";
  step_kinds(s, v, d.axes);
  s += "],\"belt_count\":" + std::to_string(v.belt_count);
  s += ",\"violations\":[";
  violations(s, v, d.axes);
  s += "]}";
}

}  // namespace

std::string report_json(const ReportData& d) {
  std::string s;
  s.reserve(1 << 20);
  s += '{';
  head(s, d);
  workspace(s, d);
  workpieces(s, d);
  series(s, d);
  times(s, d);
  audit(s, d);
  s += '}';
  return s;
}

namespace {

std::string html_text(std::string_view s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Installed before any other script: every error, rejection and console.error is counted and
// marked on #ncsim-status (the headless test and a person both see it).
constexpr const char* kErrorCapture = R"(window.__ncsimErrors = [];
(function () {
  function note(m) {
    window.__ncsimErrors.push(String(m));
    var s = document.getElementById('ncsim-status');
    if (s) { s.dataset.errors = String(window.__ncsimErrors.length); s.dataset.state = 'error';
             s.textContent = 'page error: ' + window.__ncsimErrors.join('; '); }
  }
  window.addEventListener('error', function (e) { note(e.message || 'resource failed to load'); }, true);
  window.addEventListener('unhandledrejection', function (e) { note(e.reason); });
  var ce = console.error;
  console.error = function () { note(Array.prototype.join.call(arguments, ' ')); return ce.apply(console, arguments); };
})();
)";

}  // namespace

std::string json_quote(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || c == '<' || c == '>' || c == '&') {
      std::array<char, 8> buf{};
      std::snprintf(buf.data(), buf.size(), "\\u%04x", u);
      out += buf.data();
    } else {
      out += c;
    }
  }
  out += '"';
  return out;
}

void write_html(const ReportData& data, std::ostream& os) {
  write_page(os, "ncsim report: " + data.program, report_json(data));
}

void write_page(std::ostream& os, std::string_view title, std::string_view json) {
  os << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
     << "<meta name=\"generator\" content=\"ncsim report, uPlot " << uplot_version() << "\">\n"
     << "<title>" << html_text(title) << "</title>\n"
     << "<script>\n"
     << kErrorCapture << "</script>\n<style>\n"
     << uplot_css() << "\n</style>\n<style>\n"
     << page_css() << "</style>\n</head>\n<body>\n"
     << "<div id=\"ncsim-status\" data-state=\"loading\" data-charts=\"0\" data-drawn=\"0\" "
        "data-empty=\"0\" data-errors=\"0\">loading</div>\n"
     << "<main id=\"report\"></main>\n"
     << "<script type=\"application/json\" id=\"ncsim-data\">" << json << "</script>\n"
     << "<script>\n"
     << uplot_js() << "\n</script>\n<script>\n"
     << page_js() << "</script>\n</body>\n</html>\n";
}

bool write_html_file(const ReportData& data, core::OutputFile& out, std::string& why) {
  std::ostringstream page;
  write_html(data, page);
  return commit_page(page.view(), out, why);
}

bool commit_page(std::string_view page, core::OutputFile& out, std::string& why) {
  out.write(page);  // a write error is commit()'s reason
  if (!out.commit(why)) {
    why = "the report: " + why + " [NC8100]";
    return false;
  }
  return true;
}

}  // namespace ncsim::report
