#include "cli/golden_command.hpp"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <fstream>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>

#include "cli/commands.hpp"
#include "cli/line_command.hpp"
#include "cli/run_commands.hpp"
#include "core/output_file.hpp"
#include "golden/golden.hpp"

namespace ncsim::cli {
namespace {

namespace fs = std::filesystem;

/// A program and its golden, or a line (a folder with line.toml) and its folder of goldens.
struct Target {
  fs::path program;   ///< the .nc file; a line: its line.toml
  fs::path golden;    ///< <name>.golden beside it; a line: its folder (ch<N>_<name>.golden)
  std::string label;  ///< how the user named it (the folder or the file)
  bool line = false;  ///< a production line (docs/golden.md "Lines")
  std::string
      bless_as;  ///< what `ncsim golden bless` takes for it ("": label; a channel: its line)
  const std::string& bless_label() const { return bless_as.empty() ? label : bless_as; }
};

std::string path_text(const fs::path& p) {
  std::string s = p.lexically_normal().string();
  while (s.size() > 1 && s.back() == '/')
    s.pop_back();
  return s;
}

// A program folder (holding <folder name>.nc) or an .nc file; nothing (reported) otherwise.
std::optional<Target> resolve(const fs::path& arg, std::ostream& err) {
  std::error_code ec;
  const std::string label = path_text(arg);
  if (fs::is_directory(arg, ec)) {
    const std::string name = fs::path(label).filename().string();
    const fs::path program = fs::path(label) / (name + ".nc");
    const fs::path line = fs::path(label) / "line.toml";
    if (!fs::is_regular_file(program, ec) && fs::is_regular_file(line, ec))
      return Target{line, fs::path(label), label, true, ""};
    if (!fs::is_regular_file(program, ec)) {
      err << "ncsim: error: program folder '" << label << "' holds no " << name
          << ".nc (nor a line.toml) [NC8008]\n";
      return std::nullopt;
    }
    return Target{program, fs::path(label) / (name + ".golden"), label, false, ""};
  }
  if (fs::is_regular_file(arg, ec)) {
    fs::path golden = arg;
    golden.replace_extension(".golden");
    return Target{arg, golden, label, false, ""};
  }
  err << "ncsim: error: no such program folder or file: '" << label << "' [NC8008]\n";
  return std::nullopt;
}

fs::path library_root(const GoldenOptions& options) {
  if (options.library) return *options.library;
  return fs::path(NCSIM_SOURCE_ROOT) / "programs";
}

// Every program folder of the library, by name.
std::optional<std::vector<Target>> library_targets(const GoldenOptions& options,
                                                   std::ostream& err) {
  const fs::path root = library_root(options);
  std::error_code ec;
  if (!fs::is_directory(root, ec)) {
    err << "ncsim: error: no program library at '" << root.string() << "' [NC8008]\n";
    return std::nullopt;
  }
  std::vector<fs::path> folders;
  for (const auto& entry : fs::directory_iterator(root, ec)) {
    const fs::path& p = entry.path();
    if (entry.is_directory() && fs::is_regular_file(p / (p.filename().string() + ".nc"), ec)) {
      folders.push_back(p);
    }
  }
  std::sort(folders.begin(), folders.end());
  if (folders.empty()) {
    err << "ncsim: error: no program folders in '" << root.string() << "' [NC8008]\n";
    return std::nullopt;
  }
  std::vector<Target> out;
  for (const fs::path& f : folders) {
    auto t = resolve(f, err);
    if (!t) return std::nullopt;
    const fs::path base = root.filename().empty() ? root.parent_path().filename() : root.filename();
    t->label = (base / f.filename()).string();
    out.push_back(std::move(*t));
  }
  // The library's lines: lines/<name>/line.toml, one golden per channel.
  std::vector<fs::path> lines;
  if (fs::is_directory(root / "lines", ec)) {
    for (const auto& entry : fs::directory_iterator(root / "lines", ec))
      if (entry.is_directory() && fs::is_regular_file(entry.path() / "line.toml", ec))
        lines.push_back(entry.path());
  }
  std::sort(lines.begin(), lines.end());
  for (const fs::path& f : lines) {
    auto t = resolve(f, err);
    if (!t) return std::nullopt;
    const fs::path base = root.filename().empty() ? root.parent_path().filename() : root.filename();
    t->label = (base / "lines" / f.filename()).string();
    out.push_back(std::move(*t));
  }
  return out;
}

std::optional<std::vector<Target>> targets_of(const GoldenOptions& options, bool whole_library,
                                              std::ostream& err) {
  if (whole_library) return library_targets(options, err);
  std::vector<Target> out;
  bool ok = true;
  for (const fs::path& p : options.programs) {
    auto t = resolve(p, err);
    if (t) {
      out.push_back(std::move(*t));
    } else {
      ok = false;
    }
  }
  if (!ok) return std::nullopt;
  return out;
}

/// A temporary file removed when the guard goes, and on SIGINT / SIGTERM / SIGHUP.
class TempFile {
 public:
  explicit TempFile(const std::string& tag) {
    std::string safe;
    for (const char c : tag)
      safe += (std::isalnum(static_cast<unsigned char>(c)) != 0) ? c : '_';
    if (safe.size() > 60) safe = safe.substr(safe.size() - 60);
    path_ = fs::temp_directory_path() /
            ("ncsim-golden-" + std::to_string(::getpid()) + "-" + safe + ".csv");
    cleanup_ = std::make_unique<core::SignalCleanup>(path_);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    std::error_code ec;
    fs::remove(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
  std::unique_ptr<core::SignalCleanup> cleanup_;
};

/// One run of a program, as `ncsim run --audit -o <temp>` makes it.
struct Run {
  golden::Outcome outcome;
  std::string err;  ///< what the run printed on stderr (diagnostics, the audit)
};

Run run_program(const Target& t, const fs::path& csv) {
  RunOptions options;
  options.program.program = t.program;
  options.output = csv.string();
  options.audit = true;
  std::ostringstream out;
  std::ostringstream err;
  Run r;
  r.outcome.status = run_run(options, out, err);
  r.err = err.str();
  if (r.outcome.status == kExitProgramErrors) r.outcome.error = golden::parse_error(r.err);
  // The golden names the program by its file name, wherever it was run from.
  const std::string prefix = t.program.string() + ":";
  if (r.outcome.error && r.outcome.error->text.rfind(prefix, 0) == 0) {
    r.outcome.error->text.replace(0, prefix.size() - 1, t.program.filename().string());
  }
  return r;
}

// The run's stderr, indented, for the report of a program that could not run or ended
// otherwise than its golden.
void print_run_err(const std::string& text, std::ostream& err) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    err << "  run: " << line << '\n';
}

// Opens the run CSV; an absent file is a run that wrote nothing (an empty stream).
std::unique_ptr<std::istream> open_csv(const fs::path& csv) {
  auto f = std::make_unique<std::ifstream>(csv, std::ios::binary);
  if (f->is_open()) return f;
  return std::make_unique<std::istringstream>(std::string());
}

enum class Verdict { ok, mismatch, failed };

Verdict compare_run(const Target& t, const fs::path& csv_path, const Run& run, std::ostream& out,
                    std::ostream& err);
Verdict write_blessed(const Target& t, core::OutputFile golden_file, const fs::path& csv_path,
                      const Run& run, std::ostream& out, std::ostream& err);

Verdict check_line(const Target& t, std::ostream& out, std::ostream& err);
Verdict bless_line(const Target& t, std::ostream& out, std::ostream& err);

Verdict check_one(const Target& t, std::ostream& out, std::ostream& err) {
  if (t.line) return check_line(t, out, err);
  std::error_code ec;
  if (!fs::is_regular_file(t.golden, ec)) {
    err << t.golden.string() << ": error: no golden for " << t.program.string()
        << "; review a run and bless it: ncsim golden bless " << t.label << " [NC8005]\n";
    out << t.label << ": NO GOLDEN\n";
    return Verdict::mismatch;
  }
  TempFile csv(t.label);
  const Run run = run_program(t, csv.path());
  if (run.outcome.status == kExitUsage) {
    err << t.label << ": error: the program could not be run (exit 2) [NC8007]\n";
    print_run_err(run.err, err);
    out << t.label << ": FAILED\n";
    return Verdict::failed;
  }
  return compare_run(t, csv.path(), run, out, err);
}

// Compares the run's CSV with t's golden (which exists) and reports.
Verdict compare_run(const Target& t, const fs::path& csv_path, const Run& run, std::ostream& out,
                    std::ostream& err) {
  std::ifstream a(t.golden, std::ios::binary);
  std::ifstream b(t.golden, std::ios::binary);
  golden::Comparison c;
  try {
    const auto in = open_csv(csv_path);
    golden::RunCsv reader(*in);
    c = golden::compare(reader, run.outcome, a, b);
  } catch (const golden::FormatError& e) {
    err << t.golden.string() << ':' << e.file_line() << ": error: malformed golden: " << e.what()
        << " [NC8006]\n";
    out << t.label << ": FAILED\n";
    return Verdict::failed;
  } catch (const std::runtime_error& e) {
    err << t.label << ": error: " << e.what() << " [NC8007]\n";
    out << t.label << ": FAILED\n";
    return Verdict::failed;
  }
  const auto time = [&](std::uint64_t cycle) { return golden::time_text(cycle, c.cycle_us); };
  if (c.ok()) {
    out << t.label << ": ok (" << c.rows << " golden rows, t=" << time(c.cycles) << " s, status "
        << run.outcome.status << ")\n";
    return Verdict::ok;
  }
  bool end = false;
  for (const golden::Deviation& d : c.deviations) {
    err << t.golden.string();
    if (d.file_line > 0) err << ':' << d.file_line;
    err << ": error: " << t.program.filename().string() << " t=" << time(d.cycle) << " s";
    if (d.line > 0) err << " line " << d.line;
    err << ": " << d.what << " [" << golden::id_of(d.kind) << "]\n";
    end = end || d.kind == golden::Deviation::Kind::end;
  }
  if (c.count > c.deviations.size())
    err << t.label << ": ... " << (c.count - c.deviations.size()) << " more deviations\n";
  if (end) print_run_err(run.err, err);
  const golden::Deviation& first = c.deviations.front();
  out << t.label << ": MISMATCH, " << c.count << " deviation" << (c.count == 1 ? "" : "s")
      << ", the first at t=" << time(first.cycle) << " s";
  if (first.line > 0) out << " line " << first.line;
  out << (first.axis.empty() ? "" : " axis " + first.axis) << "; if the change is intended, "
      << "review it and run: ncsim golden bless " << t.bless_label() << '\n';
  return Verdict::mismatch;
}

Verdict bless_one(const Target& t, std::ostream& out, std::ostream& err) {
  if (t.line) return bless_line(t, out, err);
  // The golden is opened before the run: an unwritable folder is reported at once.
  auto opened = core::OutputFile::open(t.golden);
  if (const auto* why = std::get_if<std::string>(&opened)) {
    err << t.label << ": error: " << *why << "; nothing blessed [NC8009]\n";
    return Verdict::failed;
  }
  core::OutputFile golden_file = std::move(std::get<core::OutputFile>(opened));
  TempFile csv(t.label);
  const Run run = run_program(t, csv.path());
  if (run.outcome.status == kExitUsage) {
    err << t.label << ": error: the program could not be run (exit 2); nothing blessed "
        << "[NC8007]\n";
    print_run_err(run.err, err);
    return Verdict::failed;
  }
  return write_blessed(t, std::move(golden_file), csv.path(), run, out, err);
}

// Writes t's golden from the run's CSV (the run done) and reports.
Verdict write_blessed(const Target& t, core::OutputFile golden_file, const fs::path& csv_path,
                      const Run& run, std::ostream& out, std::ostream& err) {
  // A previous golden's settings (sample interval, tolerances) are kept.
  std::optional<golden::Settings> kept;
  std::string before;
  std::error_code ec;
  if (fs::is_regular_file(t.golden, ec)) {
    std::ifstream old(t.golden, std::ios::binary);
    std::ostringstream text;
    text << old.rdbuf();
    before = text.str();
    try {
      std::istringstream in(before);
      kept = golden::GoldenReader(in).head().settings;
    } catch (const golden::FormatError& e) {
      err << t.golden.string() << ':' << e.file_line() << ": warning: the old golden is "
          << "malformed (" << e.what() << "); default settings are used [NC8006]\n";
    }
  }
  std::ostringstream text;
  golden::Summary sum;
  std::uint64_t cycle_us = 0;
  try {
    const auto in = open_csv(csv_path);
    golden::RunCsv reader(*in);
    cycle_us = reader.cycle_us();
    sum = golden::write_golden(reader, run.outcome, golden::settings_for(cycle_us, kept), text);
  } catch (const std::runtime_error& e) {
    err << t.label << ": error: " << e.what() << "; nothing blessed [NC8007]\n";
    return Verdict::failed;
  }
  golden_file.write(text.str());  // a write error is commit()'s reason
  std::string why;
  if (!golden_file.commit(why)) {
    err << t.label << ": error: " << why << "; nothing blessed [NC8009]\n";
    return Verdict::failed;
  }
  const char* change = before.empty() ? "new" : (before == text.str() ? "unchanged" : "changed");
  out << t.label << ": blessed, " << change << " (" << sum.rows << " rows, " << sum.blocks
      << " block ends, t=" << golden::time_text(sum.cycles, cycle_us) << " s, status "
      << run.outcome.status;
  if (run.outcome.error) {
    out << ", error " << run.outcome.error->id << " at line " << run.outcome.error->line;
  }
  out << ")\n";
  if (run.outcome.status == kExitAudit) {
    err << t.label << ": warning: the run has audit violations; they are now the expected "
        << "outcome (see ncsim run --audit)\n";
    print_run_err(run.err, err);
  }
  return Verdict::ok;
}

/// A line's run for its goldens: each channel's CSV in a temporary file, its outcome.
struct LineRunFiles {
  int status = 0;  ///< 2: the line did not run
  std::vector<LineGoldenChannel> channels;
  std::vector<std::unique_ptr<TempFile>> csvs;  ///< channel k's CSV
  std::string err;
};

LineRunFiles run_line_target(const Target& t) {
  LineRunFiles r;
  std::ostringstream err;
  const auto csv_path = [&](const std::string& name) {
    r.csvs.push_back(std::make_unique<TempFile>(t.label + "_" + name));
    return r.csvs.back()->path();
  };
  r.status = run_line_golden(t.program.string(), csv_path, r.channels, err);
  r.err = err.str();
  return r;
}

// Channel c of line t as a program target and its run (for compare_run / write_blessed).
std::pair<Target, Run> channel_of(const Target& t, const LineGoldenChannel& c,
                                  const std::string& line_err) {
  const std::string stem = fs::path(c.csv_name).stem().string();
  Target ct{c.program, t.golden / (stem + ".golden"), t.label + "/" + stem, false, t.label};
  Run run;
  run.outcome.status = c.status;
  run.err = c.error_text.empty() ? line_err : c.error_text;
  if (c.status == kExitProgramErrors) run.outcome.error = golden::parse_error(c.error_text);
  const std::string prefix = ct.program.string() + ":";
  if (run.outcome.error && run.outcome.error->text.rfind(prefix, 0) == 0)
    run.outcome.error->text.replace(0, prefix.size() - 1, ct.program.filename().string());
  return {ct, run};
}

Verdict check_line(const Target& t, std::ostream& out, std::ostream& err) {
  const LineRunFiles r = run_line_target(t);
  if (r.status == kExitUsage) {
    err << t.label << ": error: the line could not be run (exit 2) [NC8007]\n";
    print_run_err(r.err, err);
    out << t.label << ": FAILED\n";
    return Verdict::failed;
  }
  Verdict worst = Verdict::ok;
  for (std::size_t k = 0; k < r.channels.size(); ++k) {
    const auto [ct, run] = channel_of(t, r.channels[k], r.err);
    std::error_code ec;
    Verdict v = Verdict::mismatch;
    if (!fs::is_regular_file(ct.golden, ec)) {
      err << ct.golden.string() << ": error: no golden for channel " << ct.label
          << "; review a run and bless it: ncsim golden bless " << t.label << " [NC8005]\n";
      out << ct.label << ": NO GOLDEN\n";
    } else {
      v = compare_run(ct, r.csvs[k]->path(), run, out, err);
    }
    if (v == Verdict::failed || (v == Verdict::mismatch && worst == Verdict::ok)) worst = v;
  }
  return worst;
}

Verdict bless_line(const Target& t, std::ostream& out, std::ostream& err) {
  const LineRunFiles r = run_line_target(t);
  if (r.status == kExitUsage) {
    err << t.label << ": error: the line could not be run (exit 2); nothing blessed [NC8007]\n";
    print_run_err(r.err, err);
    return Verdict::failed;
  }
  Verdict worst = Verdict::ok;
  for (std::size_t k = 0; k < r.channels.size(); ++k) {
    const auto [ct, run] = channel_of(t, r.channels[k], r.err);
    auto opened = core::OutputFile::open(ct.golden);
    if (const auto* why = std::get_if<std::string>(&opened)) {
      err << ct.label << ": error: " << *why << "; nothing blessed [NC8009]\n";
      worst = Verdict::failed;
      continue;
    }
    if (write_blessed(ct, std::move(std::get<core::OutputFile>(opened)), r.csvs[k]->path(), run,
                      out, err) != Verdict::ok)
      worst = Verdict::failed;
  }
  return worst;
}

int finish(std::size_t n, std::size_t ok, std::size_t mismatched, std::size_t failed,
           const char* verb, std::ostream& out) {
  if (n > 1) {
    out << "golden: " << n << " programs, " << ok << ' ' << verb;
    if (mismatched > 0) out << ", " << mismatched << " mismatched";
    if (failed > 0) out << ", " << failed << " failed";
    out << '\n';
  }
  if (failed > 0) return kExitUsage;
  return mismatched > 0 ? kExitProgramErrors : kExitOk;
}

}  // namespace

int run_golden_check(const GoldenOptions& options, std::ostream& out, std::ostream& err) {
  const auto targets = targets_of(options, options.programs.empty(), err);
  if (!targets) return kExitUsage;
  std::size_t ok = 0;
  std::size_t mismatched = 0;
  std::size_t failed = 0;
  for (const Target& t : *targets) {
    switch (check_one(t, out, err)) {
      case Verdict::ok:
        ++ok;
        break;
      case Verdict::mismatch:
        ++mismatched;
        break;
      case Verdict::failed:
        ++failed;
        break;
    }
  }
  return finish(targets->size(), ok, mismatched, failed, "ok", out);
}

int run_golden_bless(const GoldenOptions& options, std::ostream& out, std::ostream& err) {
  if (options.all == !options.programs.empty()) {
    err << "ncsim: error: golden bless takes PROGRAM... or --all (one of them)\n";
    return kExitUsage;
  }
  const auto targets = targets_of(options, options.all, err);
  if (!targets) return kExitUsage;
  std::size_t ok = 0;
  std::size_t failed = 0;
  for (const Target& t : *targets) {
    if (bless_one(t, out, err) == Verdict::ok) {
      ++ok;
    } else {
      ++failed;
    }
  }
  return finish(targets->size(), ok, 0, failed, "blessed", out);
}

GoldenCommands::GoldenCommands(CLI::App& app) {
  auto* golden = app.add_subcommand(
      "golden", "Golden trajectories: check runs against programs' goldens, or bless new ones");
  golden->require_subcommand(1);
  check_cmd_ = golden->add_subcommand(
      "check", "Run programs and compare each with its golden (<name>.golden beside it)");
  check_cmd_->add_option("program", check_.programs,
                         "Program folders or .nc files (default: every program of the library)");
  check_cmd_->add_option("--programs", check_.library,
                         "The program library folder (default: the source tree's programs/)");
  bless_cmd_ = golden->add_subcommand(
      "bless", "Run programs and write their goldens (after reviewing the change)");
  bless_cmd_->add_option("program", bless_.programs, "Program folders or .nc files");
  bless_cmd_->add_flag("--all", bless_.all, "Every program of the library");
  bless_cmd_->add_option("--programs", bless_.library,
                         "The program library folder (default: the source tree's programs/)");
}

std::optional<int> GoldenCommands::dispatch(std::ostream& out, std::ostream& err) const {
  if (check_cmd_->parsed()) return run_golden_check(check_, out, err);
  if (bless_cmd_->parsed()) return run_golden_bless(bless_, out, err);
  return std::nullopt;
}

}  // namespace ncsim::cli
