// golden/golden_file: the golden text format, written by bless and read by check
// (golden.hpp; the format is specified in docs/golden.md).
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <istream>
#include <ostream>
#include <sstream>
#include <string_view>

#include "core/number_text.hpp"
#include "golden/golden.hpp"
#include "golden/text.hpp"

namespace ncsim::golden {
namespace {

constexpr int kFormatVersion = 1;

using text::parse_double;
using text::parse_u64;
using text::trim;
using text::words;

void write_row(std::ostream& out, const Row& row, bool block_end, std::uint64_t cycle_us) {
  std::string s;
  s += block_end ? "b " : "s ";
  s += time_text(row.cycle, cycle_us);
  s += ' ';
  s += std::to_string(row.line);
  for (const double v : row.values) {
    s += ' ';
    s += core::micro_text(v);  // rounded to 1e-6 of its unit
  }
  s += '\n';
  out << s;
}

}  // namespace

Settings settings_for(std::uint64_t cycle_us, const std::optional<Settings>& kept) {
  if (kept) return *kept;
  Settings s;
  if (cycle_us > 0) {
    const double n = std::round(kSampleSeconds * 1e6 / static_cast<double>(cycle_us));
    s.sample_cycles = n < 1.0 ? 1 : static_cast<std::uint64_t>(n);
  }
  return s;
}

Summary write_golden(RunCsv& csv, const Outcome& outcome, const Settings& settings,
                     std::ostream& out) {
  const std::uint64_t n = settings.sample_cycles == 0 ? 1 : settings.sample_cycles;
  out << "# ncsim golden trajectory (docs/golden.md): written by `ncsim golden bless`, compared\n"
         "# by `ncsim golden check`. Rows: kind t[s] line columns; s = a sample every "
      << n
      << " cycles,\n"
         "# b = the last cycle of a block (the line changes after it); values rounded to 1e-6.\n";
  out << "golden " << kFormatVersion << '\n';
  // The file name only: a golden does not depend on where the run was started.
  const std::string program = std::filesystem::path(csv.program()).filename().string();
  out << "program " << (program.empty() ? "-" : program) << '\n';
  out << "machine " << (csv.machine().empty() ? "-" : csv.machine()) << '\n';
  out << "cycle_us " << csv.cycle_us() << '\n';
  out << "sample_cycles " << n << '\n';
  out << "tolerance_cycles " << settings.tolerance_cycles << '\n';
  out << "columns";
  for (const std::string& c : csv.columns())
    out << ' ' << c;
  out << "\ntolerance";
  for (const std::string& c : csv.columns())
    out << ' ' << c << '=' << core::fixed_text(settings.tolerance_for(c));
  out << '\n';

  Summary sum;
  Row prev;
  Row row;
  bool have = false;
  while (csv.next(row)) {
    if (have) {
      const bool block_end = row.line != prev.line;
      if (block_end || prev.cycle % n == 0) {
        write_row(out, prev, block_end, csv.cycle_us());
        ++sum.rows;
        if (block_end) ++sum.blocks;
      }
    }
    std::swap(prev, row);
    have = true;
  }
  if (have) {
    write_row(out, prev, true, csv.cycle_us());
    ++sum.rows;
    ++sum.blocks;
    sum.cycles = prev.cycle;
  }
  out << "end t=" << time_text(sum.cycles, csv.cycle_us()) << " cycles=" << sum.cycles
      << " status=" << outcome.status;
  if (outcome.error) out << " error=" << outcome.error->id << " line=" << outcome.error->line;
  out << '\n';
  if (outcome.error && !outcome.error->text.empty()) out << "# " << outcome.error->text << '\n';
  return sum;
}

GoldenReader::GoldenReader(std::istream& in) : in_(in) {
  std::string line;
  // The file line of each head record (0: not given yet); every record once.
  constexpr std::array<std::string_view, 8> kKeys = {
      "golden",        "program",          "machine", "cycle_us",
      "sample_cycles", "tolerance_cycles", "columns", "tolerance"};
  std::array<std::size_t, kKeys.size()> given{};
  const auto need_at = [](std::size_t file_line, bool ok, const std::string& what) {
    if (!ok) throw FormatError(file_line, what);
  };
  const auto need = [&](bool ok, const std::string& what) { need_at(file_line_, ok, what); };
  const auto all_given = [&]() {
    return std::all_of(given.begin(), given.end(), [](std::size_t l) { return l > 0; });
  };
  while (!all_given()) {
    if (!read_record(line)) {
      // A file without any record is named as such, at a line that exists (not 0).
      const bool nothing =
          std::none_of(given.begin(), given.end(), [](std::size_t l) { return l > 0; });
      need_at(std::max<std::size_t>(file_line_, 1), false,
              nothing ? "the file is empty (no records): a golden starts with 'golden 1' "
                        "(docs/golden.md)"
                      : "the head ends before all of golden, program, machine, cycle_us, "
                        "sample_cycles, tolerance_cycles, columns, tolerance");
    }
    const std::vector<std::string_view> w = words(line);
    const std::string_view key = w.front();
    const auto one = [&]() {
      need(w.size() == 2, "'" + std::string(key) + "' takes one value");
      return w[1];
    };
    const auto k =
        static_cast<std::size_t>(std::find(kKeys.begin(), kKeys.end(), key) - kKeys.begin());
    need(k < kKeys.size(), "unknown head record '" + std::string(key) + "'");
    need(given[k] == 0,
         "'" + std::string(key) + "' given twice (first on line " + std::to_string(given[k]) + ")");
    given[k] = file_line_;
    if (key == "golden") {
      std::uint64_t v = 0;
      need(
          parse_u64(one(), v) && v == kFormatVersion,
          "unknown golden format (this ncsim reads format " + std::to_string(kFormatVersion) + ")");
    } else if (key == "program") {
      head_.program = std::string(one());
    } else if (key == "machine") {
      head_.machine = std::string(one());
    } else if (key == "cycle_us") {
      need(parse_u64(one(), head_.cycle_us), "cycle_us: expected microseconds");
    } else if (key == "sample_cycles") {
      need(parse_u64(one(), head_.settings.sample_cycles) && head_.settings.sample_cycles > 0,
           "sample_cycles: expected a whole number >= 1");
    } else if (key == "tolerance_cycles") {
      need(parse_u64(one(), head_.settings.tolerance_cycles),
           "tolerance_cycles: expected a whole number");
    } else if (key == "columns") {
      for (std::size_t i = 1; i < w.size(); ++i)
        head_.columns.emplace_back(w[i]);
    } else {  // tolerance
      for (std::size_t i = 1; i < w.size(); ++i) {
        const std::size_t eq = w[i].find('=');
        double v = 0.0;
        need(eq != std::string_view::npos && parse_double(w[i].substr(eq + 1), v) && v >= 0.0,
             "tolerance: expected NAME=value (value >= 0)");
        head_.settings.axis_tolerance.emplace_back(std::string(w[i].substr(0, eq)), v);
      }
    }
  }
  // Checks across records: at the line of the record that holds the value.
  for (const std::string& c : head_.columns) {
    bool found = false;
    for (const auto& [name, v] : head_.settings.axis_tolerance)
      found = found || name == c;
    need_at(given[7], found, "tolerance: no value for column " + c);
  }
  need_at(given[3], head_.cycle_us > 0 || head_.columns.empty(), "cycle_us: must be > 0");
}

bool GoldenReader::read_record(std::string& line) {
  while (std::getline(in_, line)) {
    ++file_line_;
    const std::string_view s = trim(line);
    if (s.empty() || s.front() == '#') continue;
    return true;
  }
  return false;
}

bool GoldenReader::next(GoldenRow& out) {
  if (done_) return false;
  std::string line;
  if (!read_record(line)) throw FormatError(file_line_, "the file ends without an 'end' record");
  const std::vector<std::string_view> w = words(line);
  out.file_line = file_line_;
  const auto need = [&](bool ok, const std::string& what) {
    if (!ok) throw FormatError(file_line_, what);
  };
  const auto cycles_of = [&](std::string_view t) {
    double s = 0.0;
    need(parse_double(t, s) && s >= 0.0, "bad time '" + std::string(t) + "'");
    const double us = std::round(s * 1e6);
    const auto k = static_cast<std::uint64_t>(us) / head_.cycle_us;
    need(static_cast<std::uint64_t>(us) == k * head_.cycle_us,
         "time " + std::string(t) + " is not a whole cycle");
    return k;
  };
  if (w.front() == "end") {
    bool have_cycles = false;
    bool have_status = false;
    std::optional<std::uint64_t> t_cycles;
    for (std::size_t i = 1; i < w.size(); ++i) {
      const std::size_t eq = w[i].find('=');
      need(eq != std::string_view::npos, "end: expected key=value");
      const std::string_view key = w[i].substr(0, eq);
      const std::string_view value = w[i].substr(eq + 1);
      std::uint64_t v = 0;
      if (key == "t") {
        t_cycles = head_.cycle_us > 0 ? cycles_of(value) : 0;
      } else if (key == "cycles") {
        need(parse_u64(value, end_.cycle), "end: cycles must be a whole number");
        have_cycles = true;
      } else if (key == "status") {
        need(parse_u64(value, v) && v < 256, "end: status must be an exit status");
        end_.status = static_cast<int>(v);
        have_status = true;
      } else if (key == "error") {
        if (!end_.error) end_.error = RunError{};
        end_.error->id = std::string(value);
      } else if (key == "line") {
        if (!end_.error) end_.error = RunError{};
        need(parse_u64(value, end_.error->line), "end: line must be a whole number");
      } else {
        need(false, "end: unknown key '" + std::string(key) + "'");
      }
    }
    need(have_cycles && have_status, "end: needs cycles= and status=");
    need(!t_cycles || *t_cycles == end_.cycle, "end: t and cycles disagree");
    end_.file_line = file_line_;
    // Only comments may follow.
    std::string rest;
    need(!read_record(rest), "a record after 'end'");
    done_ = true;
    return false;
  }
  need(w.front() == "s" || w.front() == "b",
       "expected a row (s or b) or the end record, found '" + std::string(w.front()) + "'");
  need(w.size() == 3 + head_.columns.size(),
       "a row holds kind, t, line and " + std::to_string(head_.columns.size()) + " values");
  out.block_end = w.front() == "b";
  out.row.cycle = cycles_of(w[1]);
  need(!any_row_ || out.row.cycle > last_cycle_, "rows out of order (times must increase)");
  last_cycle_ = out.row.cycle;
  any_row_ = true;
  need(parse_u64(w[2], out.row.line), "bad line number");
  out.row.values.resize(head_.columns.size());
  for (std::size_t i = 0; i < head_.columns.size(); ++i)
    need(parse_double(w[3 + i], out.row.values[i]), "bad value '" + std::string(w[3 + i]) + "'");
  return true;
}

}  // namespace ncsim::golden
