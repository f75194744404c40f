#pragma once
// golden/: golden trajectories of NC programs (issue 15, docs/golden.md).
//
// Purpose: keep, per program, a small text record of what `ncsim run` does with it, and tell
// exactly where a later run departs from it. A golden holds the run's trajectory thinned to a
// sample row every `sample_cycles` cycles plus the last cycle of every block (each change of
// the `line` column), and the run's end: its cycle count, exit status and, for a run that stops
// with an error, the error's id and line.
//
// Inputs: the CSV of `ncsim run` (docs/ipo.md "The commands"), streamed row by row (RunCsv),
// and the run's Outcome (exit status, error). Outputs: `write_golden` (bless) writes the
// golden text; `compare` (check) returns the deviations from a golden file.
//
// Invariants:
// - Memory is bounded by one row per stream, whatever the length of the run or the golden
//   (the golden is read through two independent streams, one per cursor).
// - The golden text is a pure function of the run: the same run gives the same bytes (times
//   are printed from whole cycles in microseconds, positions rounded to 1e-6 of their unit).
// - Positions are compared at equal cycles (never across a shifted block end); block ends are
//   compared as a sequence of (line, cycle), each end allowed to move by `tolerance_cycles`.
// - Nothing here writes a golden file: the CLI's `bless` is the only writer.

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ncsim::golden {

/// One cycle of a run: a row of the run CSV, or a row of a golden.
struct Row {
  std::uint64_t cycle = 0;     ///< cycle index k; the row's time is k T (end of the cycle)
  std::uint64_t line = 0;      ///< source line of the active block
  std::vector<double> values;  ///< one per column after `line` [mm | deg]
};

/// How a golden is made and compared. Stored in the golden's head; a re-bless keeps it.
struct Settings {
  std::uint64_t sample_cycles = 50;    ///< a sample row every this many cycles (0.05 s at 1 ms)
  std::uint64_t tolerance_cycles = 1;  ///< a block end or the run's end may move this far
  double tolerance = 1e-4;             ///< position tolerance per axis [mm | deg] (ISG unit 0.1 um)
  std::vector<std::pair<std::string, double>> axis_tolerance;  ///< per column [mm | deg]
  /// The tolerance of column `name` [mm | deg].
  double tolerance_for(const std::string& name) const;
};

/// The default sample interval [s]; sample_cycles = round(kSampleSeconds / T), at least 1.
inline constexpr double kSampleSeconds = 0.05;

/// A run-time or program error that ended a run (a diagnostic `file:line:col: error: ... [ID]`).
struct RunError {
  std::string id;          ///< "NC6001", "20008"; "-" when the text names none
  std::uint64_t line = 0;  ///< source line; 0 when the error has no position
  std::string text;        ///< the diagnostic's first line, for people (not compared)
  bool operator==(const RunError& o) const { return id == o.id && line == o.line; }
};

/// How a run ended.
struct Outcome {
  int status = 0;                 ///< exit status of `ncsim run`: 0 ok, 1 error, 3 audit
  std::optional<RunError> error;  ///< the error that stopped it (status 1)
};

/// The error named by a diagnostic's text (`file:line:col: error: text [ID]`, or any line
/// ending in `[ID]`); nothing when `text` holds no error line.
std::optional<RunError> parse_error(const std::string& text);

/// Streams the CSV written by `ncsim run`: comment lines (`# program: ...`, `# machine: ...`,
/// `# cycle: T s`), the header `t,line,<columns>`, one row per cycle, and an optional closing
/// `# error: ...`. An empty stream is a run that wrote nothing (no head, no rows).
class RunCsv {
 public:
  /// Reads the head up to the column header; throws std::runtime_error (naming the CSV line)
  /// when it is not the run CSV's.
  explicit RunCsv(std::istream& in);
  const std::string& program() const { return program_; }
  const std::string& machine() const { return machine_; }
  std::uint64_t cycle_us() const { return cycle_us_; }  ///< interpolation cycle T [us]
  const std::vector<std::string>& columns() const { return columns_; }
  /// The next row into `row`; false at the end. Throws std::runtime_error on a malformed row,
  /// a time that is not a whole cycle, or cycles out of order.
  bool next(Row& row);
  /// The text after `# error: ` that closed the file; empty if none (complete after next()
  /// returned false).
  const std::string& error_text() const { return error_text_; }

 private:
  bool read_line(std::string& line);

  std::istream& in_;
  std::string program_;
  std::string machine_;
  double cycle_s_ = 0.0;
  std::uint64_t cycle_us_ = 0;
  std::vector<std::string> columns_;
  std::string error_text_;
  std::uint64_t csv_line_ = 0;
  std::uint64_t last_cycle_ = 0;
  bool any_row_ = false;
  std::string buf_;
};

/// What a golden file's head states.
struct Head {
  std::string program;               ///< program file name
  std::string machine;               ///< machine name ("-" for a run that wrote nothing)
  std::uint64_t cycle_us = 0;        ///< interpolation cycle [us]
  std::vector<std::string> columns;  ///< column names after `line` (the axes)
  Settings settings;
};

/// How a golden ends: the run's last cycle, exit status and error.
struct End {
  std::uint64_t cycle = 0;  ///< cycles run (the last row's cycle)
  int status = 0;
  std::optional<RunError> error;
  std::size_t file_line = 0;  ///< line of the `end` record in the golden file
};

/// A malformed golden file: the file line and what is wrong (NC8006).
class FormatError : public std::runtime_error {
 public:
  FormatError(std::size_t file_line, const std::string& what)
      : std::runtime_error(what), file_line_(file_line) {}
  std::size_t file_line() const { return file_line_; }

 private:
  std::size_t file_line_;
};

/// A golden row with its kind and place in the file.
struct GoldenRow {
  Row row;
  bool block_end = false;     ///< `b`: the last cycle of a block; `s`: a sample
  std::size_t file_line = 0;  ///< line in the golden file
};

/// Streams a golden file: the head at construction, then the rows, then the end record.
class GoldenReader {
 public:
  /// Reads the head; throws FormatError.
  explicit GoldenReader(std::istream& in);
  const Head& head() const { return head_; }
  /// The next row; false at the `end` record, which end() then holds. Throws FormatError.
  bool next(GoldenRow& row);
  const End& end() const { return end_; }

 private:
  bool read_record(std::string& line);

  std::istream& in_;
  Head head_;
  End end_;
  std::size_t file_line_ = 0;
  std::uint64_t last_cycle_ = 0;
  bool any_row_ = false;
  bool done_ = false;
};

/// What was written: rows and the run's length.
struct Summary {
  std::uint64_t rows = 0;    ///< rows in the golden
  std::uint64_t blocks = 0;  ///< block-end rows among them
  std::uint64_t cycles = 0;  ///< cycles run
};

/// Settings for a run with cycle T: the defaults with sample_cycles from kSampleSeconds, or
/// `kept` (a previous golden's) unchanged.
Settings settings_for(std::uint64_t cycle_us, const std::optional<Settings>& kept);

/// Writes the golden of the run in `csv` ending with `outcome` (bless). Throws
/// std::runtime_error from the CSV.
Summary write_golden(RunCsv& csv, const Outcome& outcome, const Settings& settings,
                     std::ostream& out);

/// A difference between a run and its golden.
struct Deviation {
  enum class Kind {
    head,      ///< machine, cycle or columns differ (NC8004)
    position,  ///< an axis outside its tolerance at a golden row (NC8001)
    block,     ///< the block sequence or a block end's cycle (NC8002)
    end,       ///< the run's length, exit status or error (NC8003)
  };
  Kind kind = Kind::position;
  std::uint64_t cycle = 0;    ///< when [cycles]; time = cycle * T
  std::uint64_t line = 0;     ///< program line (the golden's)
  std::string axis;           ///< position: the column
  double size = 0.0;          ///< position: |run - golden| [mm | deg]; block, end: [cycles]
  double tolerance = 0.0;     ///< same unit as size
  std::size_t file_line = 0;  ///< golden file line; 0 for the head
  std::string what;           ///< the whole statement for people
};

/// The diagnostic id of a deviation kind ("NC8001" ...).
const char* id_of(Deviation::Kind kind);

/// The result of a comparison.
struct Comparison {
  static constexpr std::size_t kListed = 8;  ///< deviations kept (the earliest)
  std::vector<Deviation> deviations;         ///< the earliest deviations, by cycle
  std::uint64_t count = 0;                   ///< all deviations (position rows count each)
  std::uint64_t rows = 0;                    ///< golden rows compared
  std::uint64_t cycles = 0;                  ///< cycles the run had
  std::uint64_t cycle_us = 0;                ///< the golden's cycle [us]
  bool ok() const { return count == 0; }
};

/// Compares the run in `csv`, ended with `outcome`, with the golden read through two streams
/// over the same golden text (`positions` drives the row comparison, `blocks` the block-end
/// sequence). Throws FormatError (golden) or std::runtime_error (CSV).
Comparison compare(RunCsv& csv, const Outcome& outcome, std::istream& positions,
                   std::istream& blocks);

/// Seconds text of k cycles of `cycle_us`: exact decimal ("12.345").
std::string time_text(std::uint64_t cycles, std::uint64_t cycle_us);

}  // namespace ncsim::golden
