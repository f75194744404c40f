#include "cli/commands.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
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
#include "interp/interpreter.hpp"
#include "interp/trace.hpp"
#include "machines/loader.hpp"
#include "scenario/loader.hpp"

namespace ncsim::cli {
namespace {

namespace fs = std::filesystem;

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
  core::DiagnosticList syntax;  ///< check_program's diagnostics (none: not checked here)
};

// Whether load() runs check_program: `check` leaves it to the interpreter's parse.
enum class SyntaxCheck : std::uint8_t { here, later };

// Loads program and machine; on a usage or configuration problem prints it and returns the
// exit status instead.
std::variant<Loaded, int> load(const ProgramOptions& options, std::ostream& err,
                               SyntaxCheck syntax_check = SyntaxCheck::here) {
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
  auto scenario = runner::load_scenario_for(options, file, *loaded.machine, err);
  if (const runner::Exit* status = std::get_if<runner::Exit>(&scenario))
    return static_cast<int>(*status);
  if (const auto& s = std::get<std::optional<scenario::Scenario>>(scenario)) {
    for (const scenario::VeInitial& v : s->ve)
      interp_options.external.emplace(v.name, v.value);
  }
  core::DiagnosticList syntax;
  if (syntax_check == SyntaxCheck::here) syntax = grammar::check_program(file);
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

  auto loaded = load(options.program, err, SyntaxCheck::later);
  if (const int* status = std::get_if<int>(&loaded)) return *status;
  const Loaded& in = std::get<Loaded>(loaded);

  Report report(in.file, err);
  // One parse of the program for both checks: the syntax and structure check is fed by the
  // interpreter's reading of the program. Semantics need a program that parses: they are
  // reported only when the syntax is clean (the interpreter stops at the first syntax error).
  grammar::ProgramCheck syntax(in.file);
  const core::DiagnosticList semantics =
      interp::check_semantics(in.file, in.machine, in.interp, &syntax);
  std::string what;
  if (report.print(syntax.finish()) == 0) {
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

}  // namespace ncsim::cli
