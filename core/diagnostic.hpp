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

/// `file:line:col: error: message [id]`, then the source line and a caret under the column
/// when `source_line` is given. Ends with a newline.
std::string format(const Diagnostic& diagnostic, std::string_view source_line = {});

/// Formats a diagnostic, taking the source line from `file` when it matches.
std::string format(const Diagnostic& diagnostic, const SourceFile& file);

/// A list of diagnostics with the counts a command needs for its exit status.
class DiagnosticList {
 public:
  void add(Diagnostic diagnostic);
  const std::vector<Diagnostic>& items() const { return items_; }
  std::size_t error_count() const { return errors_; }
  bool has_errors() const { return errors_ > 0; }

 private:
  std::vector<Diagnostic> items_;
  std::size_t errors_ = 0;
};

}  // namespace ncsim::core
