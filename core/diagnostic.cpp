#include "core/diagnostic.hpp"

#include <algorithm>
#include <vector>

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

namespace {

/// Bytes of the valid UTF-8 sequence starting at `text[i]` (>= 2), or 0.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto b = static_cast<unsigned char>(text[i]);
  std::size_t n = 0;
  if (b >= 0xC2 && b <= 0xDF) {
    n = 2;
  } else if (b >= 0xE0 && b <= 0xEF) {
    n = 3;
  } else if (b >= 0xF0 && b <= 0xF4) {
    n = 4;
  } else {
    return 0;
  }
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return 0;
  }
  const auto b1 = static_cast<unsigned char>(text[i + 1]);
  if ((b == 0xE0 && b1 < 0xA0) || (b == 0xED && b1 > 0x9F) || (b == 0xF0 && b1 < 0x90) ||
      (b == 0xF4 && b1 > 0x8F)) {
    return 0;  // overlong, surrogate or beyond U+10FFFF
  }
  return n;
}

void append_hex(std::string& out, unsigned char b) {
  constexpr char kHex[] = "0123456789ABCDEF";
  out += "\\x";
  out += kHex[b >> 4];
  out += kHex[b & 15];
}

/// Appends text[i..] of one character in printable form; returns the bytes consumed and sets
/// `width` to the terminal columns it takes (a tab counts as itself).
std::size_t append_printable(std::string& out, std::string_view text, std::size_t i,
                             std::size_t& width) {
  const auto b = static_cast<unsigned char>(text[i]);
  if (b >= 0x80) {
    if (const std::size_t n = utf8_length(text, i); n > 0) {
      out.append(text.substr(i, n));
      width = 1;
      return n;
    }
    append_hex(out, b);
    width = 4;
    return 1;
  }
  if ((b < 0x20 && b != '\t') || b == 0x7F) {
    append_hex(out, b);
    width = 4;
    return 1;
  }
  out += static_cast<char>(b);
  width = 1;
  return 1;
}

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  std::size_t width = 0;
  for (std::size_t i = 0; i < text.size();)
    i += append_printable(out, text, i, width);
  return out;
}

std::string format(const Diagnostic& d, std::string_view source_line) {
  std::string out;
  if (!d.file.empty()) {
    out += printable(d.file);
    out += ':';
    if (d.loc.line > 0) {
      out += std::to_string(d.loc.line) + ':' + std::to_string(d.loc.column) + ':';
    }
    out += ' ';
  }
  out += to_string(d.severity);
  out += ": ";
  out += printable(d.message);
  if (!d.id.empty()) out += " [" + d.id + "]";
  out += '\n';
  if (d.loc.line > 0 && !source_line.empty()) {
    const std::size_t col = d.loc.column > 0 ? d.loc.column - 1 : 0;
    // A window of kEchoWidth bytes around the column of a long line.
    std::size_t from = 0;
    std::size_t to = source_line.size();
    if (source_line.size() > kEchoWidth) {
      from = col > kEchoWidth / 2 ? col - kEchoWidth / 2 : 0;
      from = std::min(from, source_line.size() - kEchoWidth);
      to = from + kEchoWidth;
      // Do not start inside a UTF-8 sequence.
      while (from > 0 && (static_cast<unsigned char>(source_line[from]) & 0xC0) == 0x80)
        --from;
    }
    std::string caret;
    if (from > 0) {
      out += "...";
      caret += "   ";
    }
    std::size_t width = 0;
    for (std::size_t i = from; i < to;) {
      const std::size_t n = append_printable(out, source_line, i, width);
      // Keep tabs so the caret lines up with the source line in a terminal.
      if (i < col) caret += source_line[i] == '\t' ? std::string("\t") : std::string(width, ' ');
      i += n;
    }
    if (to < source_line.size()) out += "...";
    out += '\n';
    if (col >= to) caret.append(col - to + (to < source_line.size() ? 3 : 0), ' ');
    out += caret;
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
  if (items_.size() >= limit_) {
    ++dropped_;
    return;
  }
  items_.push_back(std::move(diagnostic));
}

void DiagnosticList::sort_by_position() {
  std::stable_sort(items_.begin(), items_.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return a.loc.line != b.loc.line ? a.loc.line < b.loc.line : a.loc.column < b.loc.column;
  });
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace ncsim::core
