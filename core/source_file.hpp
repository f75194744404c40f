#pragma once
// core/source_file: the text of one input file (NC program, machine list, scenario) with its
// name, and the mapping from byte offsets to 1-based line and column.
//
// Inputs: a name and the whole text. Outputs: line/column of an offset, the text of a line.
// Invariants: the text is never modified; line starts are computed once, in the constructor,
// so lookups are O(log lines). Columns count bytes (the NC character set is ASCII).

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ncsim::core {

/// A 1-based position in a source file; line 0 means "no position" (whole file, command line).
struct SourceLoc {
  std::uint32_t line = 0;    ///< 1-based line number
  std::uint32_t column = 0;  ///< 1-based byte column
  friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

class SourceFile {
 public:
  SourceFile(std::string name, std::string text);

  /// Reads a file from disk; throws std::runtime_error naming the path when it cannot.
  static SourceFile load(const std::filesystem::path& path);

  const std::string& name() const { return name_; }
  std::string_view text() const { return text_; }

  /// Line and column of a byte offset (offset == size() gives the position after the end).
  SourceLoc loc_of(std::size_t offset) const;
  /// Byte offset of the first character of a 1-based line.
  std::size_t line_start(std::uint32_t line) const;
  /// The text of a 1-based line without its line end; empty if the line does not exist.
  std::string_view line_text(std::uint32_t line) const;
  std::uint32_t line_count() const { return static_cast<std::uint32_t>(line_starts_.size()); }

 private:
  std::string name_;
  std::string text_;
  std::vector<std::size_t> line_starts_;  // offset of each line's first byte
};

}  // namespace ncsim::core
