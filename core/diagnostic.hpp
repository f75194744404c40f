#pragma once
// core/diagnostic: the one error/warning type every stage reports to the user.
//
// A Diagnostic names where (file, line, column), how bad (severity), what (a message saying what
// was expected and what was found) and an id. Ids are the manuals' numbers where a manual gives
// one ("20218", "22262", "P-ERR-70082"); otherwise ncsim's own "NCxxxx" ids listed in
// docs/diagnostics.md. Program errors are returned as Diagnostics; they are never thrown.

#include <string>
#include <string_view>
#include <vector>

#include "core/source_file.hpp"

namespace ncsim::core {

enum class Severity { error, warning, note };

struct Diagnostic {
  Severity severity = Severity::error;
  std::string file;  ///< file name as given by the user; empty for command-line problems
  SourceLoc loc;     ///< 1-based; line 0 when the diagnostic has no position
  std::string id;    ///< manual id ("20218") or ncsim id ("NC1001")
  std::string message;
};

std::string_view to_string(Severity severity);

/// Source text echoed in a diagnostic shows at most this many bytes around the column.
inline constexpr std::size_t kEchoWidth = 160;

/// `file:line:col: error: message [id]`, then the source line and a caret under the column
/// when `source_line` is given. Ends with a newline. Bytes a terminal would act on or cannot
/// show (control characters but tab, DEL, bytes that are not valid UTF-8) print as `\xHH`,
/// in the message and in the echo; an echo longer than kEchoWidth is cut to a window around
/// the column, marked with `...`.
std::string format(const Diagnostic& diagnostic, std::string_view source_line = {});

/// `text` with control characters, DEL and invalid UTF-8 bytes written as `\xHH`.
std::string printable(std::string_view text);

/// Formats a diagnostic, taking the source line from `file` when it matches.
std::string format(const Diagnostic& diagnostic, const SourceFile& file);

/// A list of diagnostics with the counts a command needs for its exit status. It keeps the
/// first `limit` diagnostics and counts the rest (memory stays bounded however broken the
/// input is: a million syntax errors are a million counted, a thousand kept).
class DiagnosticList {
 public:
  static constexpr std::size_t kDefaultLimit = 1000;

  explicit DiagnosticList(std::size_t limit = kDefaultLimit) : limit_(limit) {}
  void add(Diagnostic diagnostic);
  const std::vector<Diagnostic>& items() const { return items_; }
  std::size_t error_count() const { return errors_; }
  bool has_errors() const { return errors_ > 0; }
  /// Diagnostics added beyond the limit: counted (errors in error_count()), not kept.
  std::size_t dropped() const { return dropped_; }
  /// Orders the kept diagnostics by line and column (stable: equal positions keep their order).
  void sort_by_position();

 private:
  std::vector<Diagnostic> items_;
  std::size_t limit_;
  std::size_t errors_ = 0;
  std::size_t dropped_ = 0;
};

/// Edit distance (insertions, deletions, substitutions) between two short names: the measure
/// of the "did you mean" suggestions of the machine and scenario loaders.
std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace ncsim::core
