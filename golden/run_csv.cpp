// golden/run_csv: the run CSV reader, error texts and time texts (golden.hpp).
#include <charconv>
#include <cmath>
#include <istream>
#include <string_view>

#include "golden/golden.hpp"
#include "golden/text.hpp"

namespace ncsim::golden {
namespace {

/// A cycle [us] or a time [cycles] of the CSV this close to a whole number is that number.
constexpr double kWholeNumber = 1e-6;

using text::parse_double;
using text::parse_u64;
using text::trim;

[[noreturn]] void fail(std::uint64_t line, const std::string& what) {
  throw std::runtime_error("run CSV line " + std::to_string(line) + ": " + what);
}

}  // namespace

double Settings::tolerance_for(const std::string& name) const {
  for (const auto& [axis, tol] : axis_tolerance)
    if (axis == name) return tol;
  return tolerance;
}

std::optional<RunError> parse_error(const std::string& text) {
  // The first line that ends in "[ID]" (the diagnostic line; the source echo follows it).
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string_view line = trim(std::string_view(text).substr(start, end - start));
    const std::size_t marker = line.find(": error: ");
    if (marker != std::string_view::npos) {
      RunError e;
      e.text = std::string(line);
      e.id = "-";
      if (!line.empty() && line.back() == ']') {
        const std::size_t open = line.rfind('[');
        if (open != std::string_view::npos && open + 2 < line.size())
          e.id = std::string(line.substr(open + 1, line.size() - open - 2));
      }
      // "file:line:col" before the marker; a bare "ncsim" (no position) leaves line 0.
      const std::string_view where = line.substr(0, marker);
      const std::size_t c2 = where.rfind(':');
      if (c2 != std::string_view::npos && c2 > 0) {
        const std::size_t c1 = where.rfind(':', c2 - 1);
        std::uint64_t n = 0;
        std::uint64_t col = 0;
        if (c1 != std::string_view::npos && parse_u64(where.substr(c1 + 1, c2 - c1 - 1), n) &&
            parse_u64(where.substr(c2 + 1), col)) {
          e.line = n;
        } else if (parse_u64(where.substr(c2 + 1), n)) {
          e.line = n;  // "file:line" without a column
        }
      }
      return e;
    }
    start = end + 1;
  }
  return std::nullopt;
}

std::string time_text(std::uint64_t cycles, std::uint64_t cycle_us) {
  const std::uint64_t us = cycles * cycle_us;
  std::string s = std::to_string(us / 1000000);
  std::uint64_t frac = us % 1000000;
  if (frac != 0) {
    std::string digits = std::to_string(frac);
    digits.insert(0, 6 - digits.size(), '0');
    while (digits.back() == '0')
      digits.pop_back();
    s += '.' + digits;
  }
  return s;
}

RunCsv::RunCsv(std::istream& in) : in_(in) {
  std::string line;
  bool any = false;
  while (read_line(line)) {
    any = true;
    const std::string_view s = trim(line);
    if (s.empty()) continue;
    if (s.front() == '#') {
      const std::string_view body = trim(s.substr(1));
      const auto value = [&](std::string_view key) -> std::optional<std::string_view> {
        if (body.substr(0, key.size()) != key) return std::nullopt;
        return trim(body.substr(key.size()));
      };
      if (auto v = value("program:")) {
        program_ = std::string(*v);
      } else if (auto m = value("machine:")) {
        machine_ = std::string(*m);
      } else if (auto c = value("cycle:")) {
        std::string_view text = *c;
        if (text.size() > 2 && text.substr(text.size() - 2) == " s")
          text = trim(text.substr(0, text.size() - 2));
        if (!parse_double(text, cycle_s_) || cycle_s_ <= 0.0)
          fail(csv_line_, "bad cycle '" + std::string(*c) + "'");
        const double us = cycle_s_ * 1e6;
        cycle_us_ = static_cast<std::uint64_t>(std::llround(us));
        if (cycle_us_ == 0 || std::abs(us - static_cast<double>(cycle_us_)) > kWholeNumber)
          fail(csv_line_, "the cycle " + std::string(*c) + " is not a whole microsecond");
      }
      continue;
    }
    // The column header.
    if (s.substr(0, 7) != "t,line,") fail(csv_line_, "expected the header 't,line,...'");
    if (cycle_us_ == 0) fail(csv_line_, "no '# cycle:' before the header");
    std::string_view rest = s.substr(7);
    while (!rest.empty()) {
      const std::size_t comma = rest.find(',');
      columns_.emplace_back(trim(rest.substr(0, comma)));
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
    return;
  }
  if (any) fail(csv_line_, "no column header");
}

bool RunCsv::read_line(std::string& line) {
  if (!std::getline(in_, line)) return false;
  ++csv_line_;
  return true;
}

bool RunCsv::next(Row& row) {
  if (columns_.empty()) return false;
  while (read_line(buf_)) {
    const std::string_view s = trim(buf_);
    if (s.empty()) continue;
    if (s.front() == '#') {
      const std::string_view body = trim(s.substr(1));
      if (body.substr(0, 6) == "error:") error_text_ = std::string(trim(body.substr(6)));
      continue;
    }
    std::string_view rest = s;
    const auto field = [&]() -> std::string_view {
      const std::size_t comma = rest.find(',');
      const std::string_view f = rest.substr(0, comma);
      rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
      return f;
    };
    double t = 0.0;
    if (!parse_double(field(), t) || t < 0.0) fail(csv_line_, "bad time");
    const double k = t * 1e6 / static_cast<double>(cycle_us_);
    row.cycle = static_cast<std::uint64_t>(std::llround(k));
    if (std::abs(k - static_cast<double>(row.cycle)) > kWholeNumber)
      fail(csv_line_, "time " + std::string(s.substr(0, s.find(','))) + " is not a whole cycle");
    if (any_row_ && row.cycle <= last_cycle_) fail(csv_line_, "cycles out of order");
    last_cycle_ = row.cycle;
    any_row_ = true;
    if (!parse_u64(field(), row.line)) fail(csv_line_, "bad line number");
    row.values.resize(columns_.size());
    for (double& v : row.values) {
      if (!parse_double(field(), v)) fail(csv_line_, "bad or missing value");
    }
    if (!rest.empty()) fail(csv_line_, "more values than columns");
    return true;
  }
  return false;
}

}  // namespace ncsim::golden
