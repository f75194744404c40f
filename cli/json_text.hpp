#pragma once
// cli/json_text: a JSON string literal for the commands' --json outputs.
// Invariants: control characters as \u00XX, '"' and '\' escaped; other bytes as they are.

#include <array>
#include <cstdio>
#include <ostream>
#include <string>

namespace ncsim::cli {

inline void json_string(std::ostream& os, const std::string& s) {
  os << '"';
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      os << '\\' << c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      std::array<char, 8> buf{};
      std::snprintf(buf.data(), buf.size(), "\\u%04x", c);
      os << buf.data();
    } else {
      os << c;
    }
  }
  os << '"';
}

}  // namespace ncsim::cli
