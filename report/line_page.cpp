// report/line_page: the line page's data and JSON (see the header).

#include "report/line_page.hpp"

#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/number_text.hpp"
#include "report/html.hpp"

namespace ncsim::report {
namespace {

// `json` with '<', '>' and '&' as \u00XX: outside strings JSON has none of them, inside a
// string the escape reads back to the same character, and no text can close the script
// element (the summary comes from `line time --json`, whose strings escape only '"', '\'
// and control characters).
std::string script_safe(std::string_view json) {
  std::string out;
  out.reserve(json.size());
  for (const char c : json) {
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '>') {
      out += "\\u003e";
    } else if (c == '&') {
      out += "\\u0026";
    } else {
      out += c;
    }
  }
  return out;
}

void numbers(std::string& s, const std::vector<double>& v, int digits) {
  s += '[';
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i > 0) s += ',';
    s += digits > 0 ? core::json_num(v[i], digits) : core::json_num(v[i]);
  }
  s += ']';
}

std::string line_json(const LineReportData& d) {
  std::string s = "{\"kind\":\"line\",\"line\":" + json_quote(d.line) +
                  ",\"description\":" + json_quote(d.description) +
                  ",\"summary\":" + script_safe(d.summary_json) +
                  ",\"belt\":" + (d.belt ? "true" : "false") +
                  ",\"bucket_cycles\":" + std::to_string(d.bucket_width) + ",\"t\":";
  numbers(s, d.time.t, 0);  // times exact, values to 7 digits (as a run page's)
  s += ",\"s\":[";
  for (std::size_t k = 0; k < d.time.series.size(); ++k) {
    if (k > 0) s += ',';
    numbers(s, d.time.series[k], 7);
  }
  s += "],\"runs\":[";
  for (std::size_t k = 0; k < d.channels.size(); ++k) {
    if (k > 0) s += ',';
    s += report_json(d.channels[k]);
  }
  s += "]}";
  return s;
}

}  // namespace

LineRecorder::LineRecorder(std::size_t channels, bool belt)
    : channels_(channels),
      belt_(belt),
      series_(2 + 2 * channels, Recorder::kBuckets),
      row_(2 + 2 * channels, 0.0) {}

void LineRecorder::add(double t, double belt_pos, double belt_v, std::span<const LaneState> lanes) {
  if (lanes.size() != channels_)
    throw std::invalid_argument("LineRecorder::add: " + std::to_string(lanes.size()) +
                                " lanes for " + std::to_string(channels_) + " channels");
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  row_[0] = belt_ ? belt_pos : kNone;
  row_[1] = belt_ ? belt_v : kNone;
  for (std::size_t k = 0; k < channels_; ++k) {
    row_[2 + 2 * k] = lanes[k] == LaneState::running ? 1.0 : 0.0;
    row_[3 + 2 * k] = lanes[k] == LaneState::waiting ? 1.0 : 0.0;
  }
  series_.add(t, row_);
}

LineReportData LineRecorder::finish(std::string line, std::string description,
                                    std::string summary_json,
                                    std::vector<ReportData> channels) const {
  LineReportData d;
  d.line = std::move(line);
  d.description = std::move(description);
  d.summary_json = std::move(summary_json);
  d.belt = belt_;
  d.time = series_.finish();
  d.bucket_width = series_.bucket_width();
  d.channels = std::move(channels);
  return d;
}

void write_line_html(const LineReportData& data, std::ostream& os) {
  write_page(os, "ncsim line report: " + data.line, line_json(data));
}

bool write_line_html_file(const LineReportData& data, core::OutputFile& out, std::string& why) {
  std::ostringstream page;
  write_line_html(data, page);
  return commit_page(page.view(), out, why);
}

}  // namespace ncsim::report
