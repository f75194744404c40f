#pragma once
// core/source_file: the text of one input file (NC program, machine list, scenario) with its
// name, and the mapping from byte offsets to 1-based line and column.
//
// Inputs: a name and the text, or a path. Outputs: line/column of an offset, the text of a
// line. Memory does not grow with the file: load() maps the file read-only instead of copying
// it, and release_before() hands the pages a reader has passed back to the kernel (they fault
// in again if read later, e.g. after a backward jump). Line positions come from a sparse
// index, one entry per kLineStride lines, built lazily as far as a query needs; a query scans
// at most kLineStride lines from its entry (memchr speed).
// Invariants: the text is never modified; offsets are 64-bit (files over 4 GiB); columns count
// bytes (the NC character set is ASCII).

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace ncsim::core {

/// What a file of mode `st_mode` is, for messages: "a pipe", "a device", "a socket",
/// "a directory", "a symbolic link", "a regular file", or "not a file".
std::string file_kind_text(unsigned st_mode);

/// A 1-based position in a source file; line 0 means "no position" (whole file, command line).
struct SourceLoc {
  std::uint32_t line = 0;    ///< 1-based line number
  std::uint32_t column = 0;  ///< 1-based byte column (saturates at 2^32 - 1)
  friend bool operator==(const SourceLoc&, const SourceLoc&) = default;
};

class SourceFile {
 public:
  /// Lines between two entries of the sparse line index.
  static constexpr std::uint32_t kLineStride = 1024;

  SourceFile(std::string name, std::string text);
  ~SourceFile();
  SourceFile(SourceFile&& other) noexcept;
  SourceFile& operator=(SourceFile&& other) noexcept;
  SourceFile(const SourceFile&) = delete;
  SourceFile& operator=(const SourceFile&) = delete;

  /// Maps a file from disk (reads it when it cannot be mapped: pipes, devices); throws
  /// std::runtime_error naming the path when it cannot.
  static SourceFile load(const std::filesystem::path& path);
  /// Like load(), for inputs that must be files (machine lists, scenarios): what is not a
  /// regular file (a pipe, a device, a socket, a directory) is refused before anything is read
  /// (the open does not wait for a pipe's writer), and so is a file over `max_bytes`. Throws
  /// std::runtime_error with the reason ("not a regular file (a pipe)", "N bytes, more than
  /// ..."); the caller names the path.
  static SourceFile load_regular(const std::filesystem::path& path, std::size_t max_bytes);

  const std::string& name() const { return name_; }
  std::string_view text() const { return {data(), size_}; }

  /// Line and column of a byte offset (offset == size() gives the position after the end).
  SourceLoc loc_of(std::size_t offset) const;
  /// Byte offset of the first character of a 1-based line (size() past the last line).
  std::size_t line_start(std::uint32_t line) const;
  /// The text of a 1-based line without its line end; empty if the line does not exist.
  std::string_view line_text(std::uint32_t line) const;
  /// Lines of the file (scans the whole file at the first call).
  std::uint32_t line_count() const;

  /// Bytes a reader keeps resident behind its position (its block, the echo of a diagnostic).
  static constexpr std::size_t kKeepBehind = std::size_t{4} << 20;
  /// A reader is at `offset`: the pages of a mapped file up to kKeepBehind before it leave
  /// memory (they are read again from the file if needed). A reader calls this about once per
  /// kKeepBehind bytes it advances; nothing happens for text held in memory.
  void release_before(std::size_t offset) const;

 private:
  const char* data() const { return map_ != nullptr ? map_ : owned_.data(); }
  /// Extends the sparse index until it covers `line` or `offset` (whichever comes first).
  void index_to(std::uint32_t line, std::size_t offset) const;
  /// Offset of line `line` (1-based) by scanning from the nearest index entry; size_ if none.
  std::size_t find_line(std::uint32_t line) const;

  std::string name_;
  std::string owned_;          // text held in memory (constructor, unmappable files)
  const char* map_ = nullptr;  // mapped file, or null
  std::size_t size_ = 0;       // bytes of text
  // Sparse line index: sparse_[i] is the offset of line i * kLineStride + 1.
  mutable std::vector<std::size_t> sparse_;
  mutable bool indexed_all_ = false;
  mutable std::uint32_t line_total_ = 0;  // line_count(), once computed
};

}  // namespace ncsim::core
