#include "cli/commands.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <system_error>
#include <variant>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "grammar/check.hpp"
#include "grammar/keywords.hpp"
#include "interp/trace.hpp"
#include "machines/loader.hpp"
#include "scenario/loader.hpp"

namespace ncsim::cli {
namespace {

namespace fs = std::filesystem;

// Where the bundled machines are: the source tree this command was built from.
fs::path source_root() {
  return NCSIM_SOURCE_ROOT;
}

// `-` names standard input (read whole into memory; a file is read in place).
bool is_stdin(const fs::path& path) {
  return path == "-";
}

// A program file must be an existing regular file; anything else is a usage error.
std::optional<std::string> program_file_problem(const fs::path& path) {
  if (is_stdin(path)) return std::nullopt;
  std::error_code ec;
  const auto status = fs::status(path, ec);
  if (ec || !fs::exists(status)) return "no such file: '" + path.string() + "'";
  if (!fs::is_regular_file(status)) return "not a regular file: '" + path.string() + "'";
  return std::nullopt;
}

// `--ve NAME=value` into the interpreter's V.E. table (names upper case, values numbers).
std::optional<std::string> parse_external(const std::vector<std::string>& items,
                                          interp::Options& options) {
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      return "--ve expects NAME=value, got '" + item + "'";
    }
    std::string name = item.substr(0, eq);
    if (name.rfind("V.E.", 0) == 0 || name.rfind("v.e.", 0) == 0) name.erase(0, 4);
    name = grammar::to_upper(name);
    const std::string text = item.substr(eq + 1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) {
      return "--ve " + name + ": '" + text + "' is not a number";
    }
    // Decision (docs/decisions.md): a name given twice is a usage error, not last-wins.
    if (!options.external.emplace(name, value).second) {
      return "--ve " + name + " is given more than once";
    }
  }
  return std::nullopt;
}

// The program text: the file, or standard input for `-` (named "<stdin>").
core::SourceFile load_program(const fs::path& path) {
  if (!is_stdin(path)) return core::SourceFile::load(path);
  std::string text(std::istreambuf_iterator<char>(std::cin), {});
  if (std::cin.bad()) throw std::runtime_error("cannot read standard input");
  return core::SourceFile("<stdin>", std::move(text));
}

// The program and its machine, loaded and syntax-checked: what every subcommand starts from.
struct Loaded {
  core::SourceFile file;
  machines::Machine machine;
  interp::Options interp;
  core::DiagnosticList syntax;  ///< check_program's diagnostics
};

// Loads program and machine; on a usage or configuration problem prints it and returns the
// exit status instead.
std::variant<Loaded, int> load(const ProgramOptions& options, std::ostream& err) {
  if (const auto problem = program_file_problem(options.program)) {
    err << "ncsim: error: " << *problem << '\n';
    return kExitUsage;
  }
  interp::Options interp_options;
  apply_cycle_options(options, interp_options);
  if (const auto problem = parse_external(options.external, interp_options)) {
    err << "ncsim: error: " << *problem << '\n';
    return kExitUsage;
  }
  const std::optional<fs::path> machine_dir = machine_folder(options, err);
  if (!machine_dir) return kExitUsage;
  machines::LoadResult loaded = machines::load_machine(*machine_dir);
  for (const core::Diagnostic& d : loaded.diagnostics.items())
    err << core::format(d);
  if (!loaded.machine) {
    err << "ncsim: error: machine '" << machine_dir->string() << "' could not be loaded\n";
    return kExitUsage;
  }
  core::SourceFile file = load_program(options.program);
  // The scenario's V.E. values are the decode-only state; a --ve of the same name wins
  // (docs/scenario.md "Decisions").
  auto scenario = load_scenario_for(options, file, *loaded.machine, err);
  if (const int* status = std::get_if<int>(&scenario)) return *status;
  if (const auto& s = std::get<std::optional<scenario::Scenario>>(scenario)) {
    for (const scenario::VeInitial& v : s->ve)
      interp_options.external.emplace(v.name, v.value);
  }
  core::DiagnosticList syntax = grammar::check_program(file);
  return Loaded{std::move(file), std::move(*loaded.machine), std::move(interp_options),
                std::move(syntax)};
}

// Prints diagnostics with their source lines and counts them for the verdict.
class Report {
 public:
  Report(const core::SourceFile& file, std::ostream& err) : file_(file), err_(err) {}

  /// Prints every diagnostic of `list`; returns its error count.
  std::size_t print(const core::DiagnosticList& list) {
    for (const core::Diagnostic& d : list.items()) {
      err_ << core::format(d, file_);
      if (d.severity == core::Severity::warning) ++warnings_;
    }
    if (list.dropped() > 0) {
      err_ << file_.name() << ": note: " << list.dropped()
           << " more diagnostics not shown (the first " << list.items().size() << " are above)\n";
    }
    errors_ += list.error_count();
    return list.error_count();
  }

  /// The one-line verdict: "prog.nc: 2 errors, 1 warning" on `err`, or "prog.nc: ok" (with
  /// `what` and the warnings) on `out`. Returns the exit status.
  int verdict(std::ostream& out, std::string_view what = {}) const {
    if (errors_ > 0) {
      err_ << file_.name() << ": " << count(errors_, "error") << warning_text() << '\n';
      return finish(out, kExitProgramErrors);
    }
    out << file_.name() << ": ok" << what << warning_text() << '\n';
    return finish(out, kExitOk);
  }

  /// `status`, unless writing to `out` or `err` failed (disk full, closed pipe): then a
  /// message (if stderr still takes one) and kExitUsage.
  int finish(std::ostream& out, int status) const {
    out.flush();
    err_.flush();
    if (!out.good()) {
      err_ << "ncsim: error: cannot write the output (disk full or closed pipe?)\n";
      err_.flush();
      return kExitUsage;
    }
    return err_.good() ? status : kExitUsage;
  }

 private:
  static std::string count(std::size_t n, std::string_view noun) {
    return std::to_string(n) + ' ' + std::string(noun) + (n == 1 ? "" : "s");
  }
  std::string warning_text() const {
    return warnings_ > 0 ? ", " + count(warnings_, "warning") : "";
  }

  const core::SourceFile& file_;
  std::ostream& err_;
  std::size_t errors_ = 0;
  std::size_t warnings_ = 0;
};

}  // namespace

void apply_cycle_options(const ProgramOptions& options, interp::Options& interp) {
  interp.cycle_dirs = options.cycle_dirs;
  interp.skip_missing_cycles = options.missing_cycles == "skip";
}

int run_check(const CheckOptions& options, std::ostream& out, std::ostream& err) {
  if (options.syntax_only) {
    // Syntax and structure need neither machine nor interpreter.
    if (options.program.scenario || options.program.machine_dir ||
        !options.program.external.empty()) {
      err << "ncsim: error: --syntax-only takes no --machine, --scenario or --ve\n";
      return kExitUsage;
    }
    if (const auto problem = program_file_problem(options.program.program)) {
      err << "ncsim: error: " << *problem << '\n';
      return kExitUsage;
    }
    const core::SourceFile file = load_program(options.program.program);
    Report report(file, err);
    report.print(grammar::check_program(file));
    return report.verdict(out, " (syntax)");
  }

  auto loaded = load(options.program, err);
  if (const int* status = std::get_if<int>(&loaded)) return *status;
  const Loaded& in = std::get<Loaded>(loaded);

  Report report(in.file, err);
  // Semantics need a program that parses: the interpreter would stop at the first syntax error.
  std::string what;
  if (report.print(in.syntax) == 0) {
    const core::DiagnosticList semantics = interp::check_semantics(in.file, in.machine, in.interp);
    report.print(semantics);
    for (const core::Diagnostic& d : semantics.items()) {
      if (d.id == "NC4904") what = " (runs endlessly from line " + std::to_string(d.loc.line) + ")";
      if (d.id == "NC4902") what = " up to the command limit (not checked to its end)";
    }
  }
  return report.verdict(out, what);
}

int run_trace(const TraceOptions& options, std::ostream& out, std::ostream& err) {
  auto loaded = load(options.program, err);
  if (const int* status = std::get_if<int>(&loaded)) return *status;
  const Loaded& in = std::get<Loaded>(loaded);

  Report report(in.file, err);
  if (report.print(in.syntax) > 0) return report.verdict(out);
  interp::TraceOptions trace_options;
  trace_options.interp = in.interp;
  trace_options.max_commands = options.max_commands;
  core::DiagnosticList diagnostics;
  const int status = interp::write_trace(in.file, in.machine, trace_options, out, diagnostics);
  report.print(diagnostics);
  return report.finish(out, status == 0 ? kExitOk : kExitProgramErrors);
}

int finish_stdout(int status, std::ostream& err) {
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  if (!failed || status == kExitUsage) return failed ? kExitUsage : status;
  err << "ncsim: error: cannot write to standard output (a closed pipe or a full disk) "
         "[NC9151]\n";
  err.flush();
  return kExitUsage;
}

std::optional<std::filesystem::path> scenario_file(const ProgramOptions& options) {
  if (options.scenario) return *options.scenario;
  const fs::path named =
      (is_stdin(options.program) ? fs::path(".") : options.program.parent_path()) /
      scenario::kDefaultScenarioFile;
  std::error_code ec;
  if (fs::is_regular_file(named, ec)) return named;
  return std::nullopt;
}

std::variant<std::optional<scenario::Scenario>, int> load_scenario_for(
    const ProgramOptions& options, const core::SourceFile& program,
    const machines::Machine& machine, std::ostream& err) {
  const std::optional<fs::path> path = scenario_file(options);
  if (!path) return std::optional<scenario::Scenario>{};
  std::error_code ec;
  if (!fs::exists(*path, ec)) {
    err << "ncsim: error: no such scenario file: '" << path->string() << "'\n";
    return kExitUsage;
  }
  scenario::Context context;
  context.program = &program;
  context.conveyor_wired = true;  // run / time play the conveyor world (docs/conveyor.md)
  context.conveyor_axis = machine.conveyor_axis() != nullptr;  // NC7019
  // NC6102, NC6105 at their values: check refuses the overrides time / run cannot play.
  context.path_override_max =
      machine.channel.path_override_type == machines::PathOverrideType::reduced_above_100
          ? scenario::kOverrideMax
          : 1.0;
  context.axis_override_max = 1.0;  // 002 2.2: an INDP axis takes 0 .. 100 %
  // NC7020: an axis override of a path axis. The path axes as ipo::interpolated_axes has them
  // (check and trace do not link the interpolator): not a spindle, an encoder or the conveyor.
  context.path_axes.emplace();
  for (const machines::AxisParams& a : machine.axes) {
    if (a.kind != machines::AxisKind::spindle && !a.encoder_only && &a != machine.conveyor_axis())
      context.path_axes->push_back(a.name);
  }
  context.axes.emplace();
  for (const machines::AxisParams& axis : machine.axes)
    context.axes->push_back(axis.name);
  std::optional<core::SourceFile> file;
  try {
    // No pipe or device: refused before anything is read (docs/scenario.md).
    file.emplace(core::SourceFile::load_regular(*path, std::numeric_limits<std::size_t>::max()));
  } catch (const std::exception& e) {
    err << "ncsim: error: cannot read the scenario '" << path->string() << "': " << e.what()
        << '\n';
    return kExitUsage;
  }
  scenario::LoadResult loaded = scenario::parse_scenario(*file, context);
  for (const core::Diagnostic& d : loaded.diagnostics.items())
    err << core::format(d, *file);
  if (!loaded.scenario) {
    err << "ncsim: error: scenario '" << path->string() << "': " << loaded.diagnostics.error_count()
        << " error" << (loaded.diagnostics.error_count() == 1 ? "" : "s") << '\n';
    return kExitUsage;
  }
  return std::move(loaded.scenario);
}

std::optional<std::filesystem::path> machine_folder(const ProgramOptions& options,
                                                    std::ostream& err) {
  if (options.machine_dir) return *options.machine_dir;
  const fs::path named =
      (is_stdin(options.program) ? fs::path(".") : options.program.parent_path()) / "machine";
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

}  // namespace ncsim::cli
