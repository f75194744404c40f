#include "machines/list_file.hpp"

#include <cctype>
#include <cstdio>
#include <string_view>

#include "machines/param_table.hpp"

namespace ncsim::machines {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

bool is_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '[' ||
         c == ']';
}

bool is_value_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '+' ||
         c == '-';
}

// A byte as it may be shown in a message: printable ASCII as is, anything else as \xNN.
std::string shown_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7F) return std::string(1, c);
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02X", u);
  return buf;
}

// Text as it may be shown in a message, every byte through shown_char.
std::string shown_text(std::string_view text) {
  std::string out;
  for (const char c : text)
    out += shown_char(c);
  return out;
}

// "key (ID)" for a key of either list, "'key'" when the key is unknown.
std::string key_ref(const ListEntry& entry) {
  const ParamSpec* spec = find_param(ListKind::axis, entry.pattern);
  if (spec == nullptr) spec = find_param(ListKind::channel, entry.pattern);
  if (spec == nullptr) return "'" + entry.key + "'";
  return entry.key + " (" + std::string(spec->id) + ")";
}

core::Diagnostic syntax_error(const core::SourceFile& file, std::uint32_t line, std::size_t col,
                              std::string message) {
  return core::Diagnostic{core::Severity::error, file.name(),
                          core::SourceLoc{line, static_cast<std::uint32_t>(col + 1)}, "NC3001",
                          std::move(message)};
}

// Splits "trafo[0].param[4]" into pattern and indices; false on a malformed index.
bool split_key(std::string_view key, std::string& pattern, std::vector<int>& indices) {
  pattern.clear();
  indices.clear();
  std::size_t i = 0;
  while (i < key.size()) {
    const char c = key[i];
    if (c == ']') return false;
    if (c != '[') {
      pattern += c;
      ++i;
      continue;
    }
    const std::size_t close = key.find(']', i);
    if (close == std::string_view::npos || close == i + 1 || close - i > 6) return false;
    int index = 0;
    for (std::size_t k = i + 1; k < close; ++k) {
      if (std::isdigit(static_cast<unsigned char>(key[k])) == 0) return false;
      index = index * 10 + (key[k] - '0');
    }
    indices.push_back(index);
    pattern += "[]";
    i = close + 1;
  }
  return !pattern.empty() && pattern.front() != '.' && pattern.back() != '.';
}
// Parses one non-comment line starting at `pos`; false (with a diagnostic) when malformed.
bool parse_line(const core::SourceFile& file, std::uint32_t line, std::string_view text,
                std::size_t pos, ListEntry& entry, std::vector<core::Diagnostic>& diagnostics) {
  const std::size_t key_start = pos;
  while (pos < text.size() && !is_blank(text[pos]) && text[pos] != '#')
    ++pos;
  const std::string_view key = text.substr(key_start, pos - key_start);
  for (std::size_t k = 0; k < key.size(); ++k) {
    if (!is_key_char(key[k])) {
      diagnostics.push_back(syntax_error(file, line, key_start + k,
                                         "unexpected character '" + shown_char(key[k]) +
                                             "' in key '" + shown_text(key) +
                                             "'; keys are letters, digits, '_', '.' and [index]"));
      return false;
    }
  }
  if (!split_key(key, entry.pattern, entry.indices)) {
    diagnostics.push_back(syntax_error(
        file, line, key_start,
        "malformed key '" + std::string(key) + "'; expected name.name or name[index]"));
    return false;
  }
  entry.key = std::string(key);
  entry.key_loc = core::SourceLoc{line, static_cast<std::uint32_t>(key_start + 1)};

  while (pos < text.size() && is_blank(text[pos]))
    ++pos;
  if (pos == text.size() || text[pos] == '#' || text[pos] == '(') {
    diagnostics.push_back(
        syntax_error(file, line, pos, "missing value after key " + key_ref(entry)));
    return false;
  }
  entry.value_loc = core::SourceLoc{line, static_cast<std::uint32_t>(pos + 1)};
  if (text[pos] == '"') {
    const std::size_t close = text.find('"', pos + 1);
    if (close == std::string_view::npos) {
      diagnostics.push_back(
          syntax_error(file, line, pos, "unterminated string value of " + key_ref(entry)));
      return false;
    }
    entry.value = std::string(text.substr(pos + 1, close - pos - 1));
    pos = close + 1;
  } else {
    // value := word ( '|' word )*, blanks allowed around '|'
    for (;;) {
      const std::size_t word_start = pos;
      while (pos < text.size() && is_value_char(text[pos]))
        ++pos;
      if (pos == word_start) {
        diagnostics.push_back(syntax_error(
            file, line, pos,
            pos < text.size() ? "unexpected character '" + shown_char(text[pos]) +
                                    "' in the value of " + key_ref(entry)
                              : "missing flag after '|' in the value of " + key_ref(entry)));
        return false;
      }
      entry.value += text.substr(word_start, pos - word_start);
      std::size_t look = pos;
      while (look < text.size() && is_blank(text[look]))
        ++look;
      if (look < text.size() && text[look] == '|') {
        entry.value += '|';
        pos = look + 1;
        while (pos < text.size() && is_blank(text[pos]))
          ++pos;
        continue;
      }
      break;
    }
  }
  while (pos < text.size() && is_blank(text[pos]))
    ++pos;
  if (pos < text.size() && text[pos] != '#' && text[pos] != '(') {
    diagnostics.push_back(syntax_error(file, line, pos,
                                       "unexpected text after the value of " + key_ref(entry) +
                                           "; a comment after a value starts with '#' or '('"));
    return false;
  }
  return true;
}

}  // namespace

ListParse parse_list(const core::SourceFile& file) {
  ListParse out;
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  for (std::uint32_t line = 1; line <= file.line_count(); ++line) {
    const std::string_view text = file.line_text(line);
    std::size_t pos = 0;
    // Decision (docs/machines.md): a UTF-8 byte order mark, as editors on Windows write it, is
    // accepted at the start of a list and named in a note; anywhere else it is a stray byte.
    if (line == 1 && text.substr(0, kBom.size()) == kBom) {
      out.diagnostics.push_back(
          core::Diagnostic{core::Severity::note, file.name(), core::SourceLoc{1, 1}, "NC3021",
                           "UTF-8 byte order mark (EF BB BF) at the start of the list ignored"});
      pos = kBom.size();
    }
    while (pos < text.size() && is_blank(text[pos]))
      ++pos;
    if (pos == text.size() || text[pos] == '#') continue;
    ListEntry entry;
    if (parse_line(file, line, text, pos, entry, out.diagnostics)) {
      out.entries.push_back(std::move(entry));
    } else if (!entry.key.empty()) {
      out.rejected.push_back(std::move(entry));
    }
  }
  return out;
}

}  // namespace ncsim::machines
