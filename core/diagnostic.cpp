#include "core/diagnostic.hpp"

namespace ncsim::core {

std::string_view to_string(Severity severity) {
  switch (severity) {
    case Severity::error:
      return "error";
    case Severity::warning:
      return "warning";
    case Severity::note:
      return "note";
  }
  return "error";
}

std::string format(const Diagnostic& d, std::string_view source_line) {
  std::string out;
  if (!d.file.empty()) {
    out += d.file;
    out += ':';
    if (d.loc.line > 0) {
      out += std::to_string(d.loc.line) + ':' + std::to_string(d.loc.column) + ':';
    }
    out += ' ';
  }
  out += to_string(d.severity);
  out += ": ";
  out += d.message;
  if (!d.id.empty()) out += " [" + d.id + "]";
  out += '\n';
  if (d.loc.line > 0 && !source_line.empty()) {
    out += source_line;
    out += '\n';
    // Keep tabs so the caret lines up with the source line in a terminal.
    const std::size_t caret_col = d.loc.column > 0 ? d.loc.column - 1 : 0;
    for (std::size_t i = 0; i < caret_col; ++i) {
      out += (i < source_line.size() && source_line[i] == '\t') ? '\t' : ' ';
    }
    out += "^\n";
  }
  return out;
}

std::string format(const Diagnostic& d, const SourceFile& file) {
  if (d.file == file.name()) return format(d, file.line_text(d.loc.line));
  return format(d);
}

void DiagnosticList::add(Diagnostic diagnostic) {
  if (diagnostic.severity == Severity::error) ++errors_;
  items_.push_back(std::move(diagnostic));
}

}  // namespace ncsim::core
