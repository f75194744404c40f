#pragma once
// cli/commands: the subcommands of `ncsim`, callable with explicit streams so that they are
// testable without a process. Exit statuses: 0 ok, 1 program errors, 2 usage or configuration.

#include <filesystem>
#include <iosfwd>
#include <optional>

namespace ncsim::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitProgramErrors = 1;
inline constexpr int kExitUsage = 2;

struct CheckOptions {
  std::filesystem::path program;                     ///< NC program file
  std::optional<std::filesystem::path> machine_dir;  ///< --machine
  std::optional<std::filesystem::path> scenario;     ///< --scenario
};

/// `ncsim check`: prints every diagnostic to `err`, a one-line verdict to `out`.
int run_check(const CheckOptions& options, std::ostream& out, std::ostream& err);

}  // namespace ncsim::cli
