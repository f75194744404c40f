#pragma once
// interp/test_support: helpers shared by the interpreter's tests (not part of the library).

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "interp/interpreter.hpp"
#include "interp/trace.hpp"
#include "machines/loader.hpp"

namespace ncsim::interp::test {

inline std::filesystem::path source_root() {
  const char* dir = std::getenv("NCSIM_SOURCE_DIR");
  return dir != nullptr ? std::filesystem::path(dir) : std::filesystem::path(NCSIM_SOURCE_ROOT);
}

inline const machines::Machine& machine(const std::string& name = "portal_3x") {
  static std::vector<std::pair<std::string, machines::Machine>> loaded;  // test-only cache
  for (const auto& [n, m] : loaded) {
    if (n == name) return m;
  }
  auto result = machines::load_machine(machines::bundled_machine_dir(source_root(), name));
  if (!result.machine) std::abort();
  loaded.emplace_back(name, std::move(*result.machine));
  return loaded.back().second;
}

struct Run {
  /// Trace lines without a motion's ` frame=... start ...` suffix (tests about other things
  /// stay readable); `full` holds the lines as `ncsim trace` prints them.
  std::vector<std::string> lines;
  std::vector<std::string> full;
  std::string error_id;
  std::uint32_t error_line = 0;
  std::string error_message;
};

/// Interprets `file` on machine `m`: trace lines of up to `max_commands` commands, and the
/// error that ended the stream; with `warnings`, each warning as a line "warning <id>" after
/// the commands.
inline Run run_on_machine(const core::SourceFile& file, const machines::Machine& m,
                          Options options = {}, std::size_t max_commands = 10000,
                          bool warnings = false) {
  Interpreter interp(file, m, std::move(options));
  Run r;
  while (r.lines.size() < max_commands) {
    auto c = interp.next_decode_only();
    if (!c) break;
    r.full.push_back(to_trace_line(*c, m));
    const std::size_t suffix =
        std::holds_alternative<Motion>(c->body) ? r.full.back().find(" frame=") : std::string::npos;
    r.lines.push_back(r.full.back().substr(0, suffix));
  }
  if (const auto* e = interp.error()) {
    r.error_id = e->id;
    r.error_line = e->loc.line;
    r.error_message = e->message;
  }
  if (warnings) {
    for (const auto& d : interp.diagnostics().items())
      if (d.severity == core::Severity::warning) r.lines.push_back("warning " + d.id);
  }
  return r;
}

/// Interprets `file` on a bundled machine (run_on_machine).
inline Run run_file(const core::SourceFile& file, const std::string& machine_name = "portal_3x",
                    Options options = {}, std::size_t max_commands = 10000) {
  return run_on_machine(file, machine(machine_name), std::move(options), max_commands);
}

/// run_file() of a program given as text (file name "test.nc").
inline Run run(const std::string& text, const std::string& machine_name = "portal_3x",
               Options options = {}, std::size_t max_commands = 10000) {
  return run_file(core::SourceFile("test.nc", text), machine_name, std::move(options),
                  max_commands);
}

/// The value of P1 after `expression` (the program writes it to X of a G00).
inline std::string value_line(const std::string& expression) {
  Run r = run("%t\nP1 = " + expression + "\nG00 X[P1]\nM30\n");
  if (!r.error_id.empty()) return "error " + r.error_id;
  return r.lines.empty() ? "" : r.lines[0];
}

}  // namespace ncsim::interp::test
