#pragma once
// program/source_errors: the program errors of the adapter (ProgramSource and its parts).
//
// Purpose: any part of the adapter may find that a command cannot run; it raises the error
// here, which records the diagnostic and leaves the command with SourceErrors::Stop (caught in
// ProgramSource::next(), which then ends the stream).
// Inputs: the interpreter (file names), the file of the command being adapted (enter()).
// Outputs: error(): the diagnostic that ended the stream, at its file and line.
// Invariants: at most one error is current; an error deferred behind a held block (defer())
// becomes current again at raise_deferred().

#include <cstdint>
#include <optional>
#include <string>

#include "core/diagnostic.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::program {

/// Id of the adapter's `not supported: ...` program errors.
inline constexpr const char* kNotSupportedId = "NC6001";

class SourceErrors {
 public:
  struct Stop {};  ///< thrown by the raise functions to leave the command; caught in next()

  /// `interp` must outlive this.
  explicit SourceErrors(const interp::Interpreter& interp) noexcept : interp_(interp) {}

  /// The command being adapted comes from source file `file` (interp::Command::file).
  void enter(std::uint16_t file) noexcept { file_ = file; }
  /// The file of the command being adapted (of the last one pulled).
  std::uint16_t file() const noexcept { return file_; }
  /// The name of source file `file` (interp::Command::file).
  const std::string& file_name(std::uint16_t file) const { return interp_.file_name(file); }

  /// NC6001 `not supported: <what>` at `line` of the current file.
  [[noreturn]] void not_supported(std::uint32_t line, const std::string& what);
  /// The error `id` at `line` of the current file.
  [[noreturn]] void raise(std::uint32_t line, const std::string& id, const std::string& what);
  /// The error `id` at `line` of source file `file` (a Move's own, which may be older than
  /// file(): a block held for its tolerance ball).
  [[noreturn]] void raise_in(std::uint16_t file, std::uint32_t line, const std::string& id,
                             const std::string& what);

  /// The interpreter's error, which ended its stream.
  void adopt(const core::Diagnostic& d) { error_ = d; }
  /// The error that ended the stream; null while there is none.
  const core::Diagnostic* error() const noexcept { return error_ ? &*error_ : nullptr; }
  /// The current error waits until a held block went out (raise_deferred()).
  void defer() noexcept;
  /// Raises the deferred error, if any.
  void raise_deferred();

 private:
  const interp::Interpreter& interp_;
  std::uint16_t file_ = 0;  ///< Command::file of the last command
  std::optional<core::Diagnostic> error_;
  std::optional<core::Diagnostic> deferred_;  ///< the next Motion's error behind a held block
};

}  // namespace ncsim::program
