#pragma once
// core/output_file: the one way ncsim writes a file (run's CSV, the report page, a golden;
// docs/design.md "Output files").
//
// Inputs: the target path. Outputs: a FILE* to write to, then commit() or discard().
// - A regular file or a new name is written to a unique temporary file in the target's folder
//   (`<name>.XXXXXX.tmp`, mkstemps) and renamed over the target by commit(): a reader sees the
//   old file or the new one, never a part; two writers never share a temporary file. The new
//   file keeps an existing target's permissions (else 0666 less the umask).
// - A symbolic link is followed to its final target, which is written as above; the link stays.
// - A pipe or a character device (/dev/null, /dev/stdout, a shell's `>(...)`) is a stream: it
//   is written in place, never replaced.
// - A directory, a socket or a block device is refused, as is an empty name.
// open() runs before a command does its work, so an unwritable target is reported at once.
// While a temporary file exists its path is registered: SIGINT, SIGTERM and SIGHUP remove it
// (the handler only unlinks recorded paths, then re-raises the signal with its default action).
// Invariants: the target is only ever replaced by a complete file; discard() and the destructor
// leave it untouched and remove the temporary file.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <variant>

namespace ncsim::core {

/// A path removed on SIGINT / SIGTERM / SIGHUP while the guard lives (the guard itself removes
/// nothing). Up to kSlots paths at once; more are simply not removed on a signal.
class SignalCleanup {
 public:
  static constexpr int kSlots = 16;
  explicit SignalCleanup(const std::filesystem::path& path);
  ~SignalCleanup();
  SignalCleanup(const SignalCleanup&) = delete;
  SignalCleanup& operator=(const SignalCleanup&) = delete;

 private:
  int slot_ = -1;
};

class OutputFile {
 public:
  /// Opens `target` for writing (see the file comment); on failure the reason, naming the
  /// path ("cannot write 'x': its folder 'd' does not exist").
  static std::variant<OutputFile, std::string> open(const std::filesystem::path& target);

  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&& other) = delete;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile();

  /// Where to write; null after commit() or discard().
  std::FILE* stream() const { return file_; }
  /// The file being written: the temporary file, or the target itself for a stream.
  const std::filesystem::path& written() const { return written_; }
  /// The target as given.
  const std::filesystem::path& target() const { return target_; }
  /// A pipe or device written in place (no temporary file).
  bool in_place() const { return written_ == resolved_; }

  /// Writes `text`; false on a write error (errno kept for commit()'s reason).
  bool write(std::string_view text);
  /// Flushes and closes the stream and renames the temporary file over the target; false with
  /// the reason in `why` (the temporary file removed, the target untouched).
  bool commit(std::string& why);
  /// Closes the stream and removes the temporary file; the target is untouched.
  void discard();

 private:
  OutputFile() = default;
  std::filesystem::path target_;    // as given
  std::filesystem::path resolved_;  // symbolic links followed
  std::filesystem::path written_;   // temporary file, or resolved_ for a stream
  std::FILE* file_ = nullptr;
  int write_errno_ = 0;  // first write error
  std::unique_ptr<SignalCleanup> cleanup_;
};

/// Ignores SIGPIPE for the process: a write to a closed pipe then fails with EPIPE, which the
/// commands report as an output error (exit 2) instead of dying silently (status 141).
void ignore_sigpipe();

}  // namespace ncsim::core
