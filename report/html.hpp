#pragma once
// report/html: the self-contained HTML page of a run report (docs/report.md).
//
// Purpose: one file that opens offline in a browser: uPlot's script and style (inlined from
// the npm package at build time, report/assets.hpp), the page's own script and style, and the
// run's data as one JSON object.
// Inputs: ReportData (report/recorder.hpp). Outputs: the page on a stream.
// Invariants: byte-identical output for identical data (numbers by core/number_text: times
// shortest round-trip, values 7 significant digits); no external reference (no URL is
// loaded); strings are escaped so no data can close the script element.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <string_view>

#include "core/output_file.hpp"
#include "report/recorder.hpp"

namespace ncsim::report {

/// Violations embedded in the page at most (the verdict's count covers all).
inline constexpr std::size_t kPageViolations = 200;

/// The page data of one run as one JSON object (docs/report.md "Data contract").
std::string report_json(const ReportData& data);

/// The page shell around `json` (an object whose strings are json_quote()d, or otherwise free
/// of '<'): uPlot, page.css and page.js inlined; page.js draws a run page, or a line page
/// when the object has `"kind":"line"` (report/line_page.hpp).
void write_page(std::ostream& os, std::string_view title, std::string_view json);

/// Writes the page of `data` to `os`.
void write_html(const ReportData& data, std::ostream& os);

/// Writes the page to `out` (opened before the run, core/output_file) and commits it: renamed
/// into place when complete; false with the reason in `why` (NC8100; the temporary file
/// removed, the target untouched) on a write error.
bool write_html_file(const ReportData& data, core::OutputFile& out, std::string& why);
/// The same for a page already written to `page` (the run page, the line page).
bool commit_page(std::string_view page, core::OutputFile& out, std::string& why);

/// `s` as a JSON string literal, with '<', '>' and '&' escaped (safe inside <script>).
std::string json_quote(std::string_view s);

}  // namespace ncsim::report
