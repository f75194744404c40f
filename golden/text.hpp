#pragma once
// golden/text: the text primitives both golden readers use (the run CSV reader, run_csv.cpp,
// and the golden file reader, golden_file.cpp): one definition of what a blank, a word and a
// number are, so that the two formats cannot drift apart.
// Inputs: views of one line. Outputs: trimmed views, words, parsed numbers.
// Invariants: no allocation except words()' vector; numbers must fill the whole field
// (std::from_chars, locale-independent); a double must be finite.

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <system_error>
#include <vector>

namespace ncsim::golden::text {

/// `s` without leading and trailing blanks (space, tab, CR).
inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

/// The blank-separated words of `s` (views into it).
inline std::vector<std::string_view> words(std::string_view s) {
  std::vector<std::string_view> out;
  while (true) {
    s = trim(s);
    if (s.empty()) return out;
    const std::size_t sp = s.find_first_of(" \t");
    out.push_back(s.substr(0, sp));
    if (sp == std::string_view::npos) return out;
    s.remove_prefix(sp);
  }
}

/// A finite double filling all of `s`.
inline bool parse_double(std::string_view s, double& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
}

/// An unsigned 64-bit integer filling all of `s`.
inline bool parse_u64(std::string_view s, std::uint64_t& v) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

}  // namespace ncsim::golden::text
