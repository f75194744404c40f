#include "cli/commands.hpp"

#include <fstream>
#include <ostream>
#include <string>
#include <system_error>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "grammar/check.hpp"
#include "machines/loader.hpp"

namespace ncsim::cli {
namespace {

namespace fs = std::filesystem;

// Where the bundled machines are: the source tree this command was built from.
fs::path source_root() {
  return NCSIM_SOURCE_ROOT;
}

// A program file must be an existing regular file; anything else is a usage error.
std::optional<std::string> program_file_problem(const fs::path& path) {
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return "no such file: '" + path.string() + "'";
  if (!fs::is_regular_file(status)) return "not a regular file: '" + path.string() + "'";
  return std::nullopt;
}

// The machine folder a program runs on (design.md §5): --machine, else the bundled machine
// named in the program folder's `machine` file, else the default bundled machine. Nothing when
// the `machine` file names none (reported on `err`).
std::optional<fs::path> machine_folder(const CheckOptions& options, std::ostream& err) {
  if (options.machine_dir) return *options.machine_dir;
  const fs::path named = options.program.parent_path() / "machine";
  std::string name(machines::kDefaultMachine);
  if (fs::is_regular_file(named)) {
    std::ifstream in(named);
    std::string line;
    std::getline(in, line);
    const auto first = line.find_first_not_of(" \t\r");
    const auto last = line.find_last_not_of(" \t\r");
    if (first == std::string::npos) {
      err << "ncsim: error: " << named.string() << " names no machine\n";
      return std::nullopt;
    }
    name = line.substr(first, last - first + 1);
  }
  return machines::bundled_machine_dir(source_root(), name);
}

}  // namespace

int run_check(const CheckOptions& options, std::ostream& out, std::ostream& err) {
  if (options.scenario) {
    err << "ncsim: error: not supported: --scenario (scenario files come with the conveyor "
           "simulation)\n";
    return kExitUsage;
  }
  if (const auto problem = program_file_problem(options.program)) {
    err << "ncsim: error: " << *problem << '\n';
    return kExitUsage;
  }
  const std::optional<fs::path> machine_dir = machine_folder(options, err);
  if (!machine_dir) return kExitUsage;
  const machines::LoadResult loaded = machines::load_machine(*machine_dir);
  for (const core::Diagnostic& d : loaded.diagnostics.items())
    err << core::format(d);
  if (!loaded.machine) {
    err << "ncsim: error: machine '" << machine_dir->string() << "' could not be loaded\n";
    return kExitUsage;
  }

  const core::SourceFile file = core::SourceFile::load(options.program);
  const core::DiagnosticList diagnostics = grammar::check_program(file);
  for (const core::Diagnostic& d : diagnostics.items())
    err << core::format(d, file);

  if (diagnostics.has_errors()) {
    const std::size_t n = diagnostics.error_count();
    err << file.name() << ": " << n << (n == 1 ? " error" : " errors") << '\n';
    return kExitProgramErrors;
  }
  out << file.name() << ": ok\n";
  return kExitOk;
}

}  // namespace ncsim::cli
