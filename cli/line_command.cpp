#include "cli/line_command.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <ostream>
#include <vector>

#include "cli/csv_sink.hpp"
#include "cli/line_page.hpp"
#include "cli/line_report.hpp"
#include "cli/line_sweep.hpp"
#include "cli/number_format.hpp"
#include "cli/run_commands.hpp"
#include "core/number_text.hpp"
#include "core/output_file.hpp"
#include "runner/line_run.hpp"
#include "runner/texts.hpp"

namespace ncsim::cli {
namespace {

using core::seconds;

// One channel's CSV: its output file and sink.
struct ChannelCsv {
  std::optional<core::OutputFile> file;
  std::unique_ptr<CsvSink> sink;
};

// "ch2_sorter.csv": the channel's number and its name's letters, digits, '-' and '_'.
std::string csv_name(const scenario::LineChannel& c) {
  std::string name = "ch" + std::to_string(c.number) + "_";
  for (const char ch : c.name)
    name += (std::isalnum(static_cast<unsigned char>(ch)) != 0 || ch == '-') ? ch : '_';
  return name + ".csv";
}

// Opens channel k's CSV at `path`; false (reported) when it cannot be.
bool open_csv(const runner::LineRun& line, std::size_t k, const std::filesystem::path& path,
              ChannelCsv& csv, std::ostream& err) {
  auto opened = core::OutputFile::open(path);
  if (const auto* why = std::get_if<std::string>(&opened)) {
    err << "ncsim: error: " << *why << " [NC9150]\n";
    return false;
  }
  csv.file.emplace(std::move(std::get<core::OutputFile>(opened)));
  const std::vector<std::string> names = runner::axis_names(line.channel(k).loaded().machine);
  csv.sink = std::make_unique<CsvSink>(csv.file->stream(), names.size(), 1, false);
  return true;
}

// The CSV's head and the channel's state it reads (after start()).
void wire_csv(const runner::LineRun& line, std::size_t k, CsvSink& csv) {
  const runner::Run& run = line.channel(k);
  std::string head = "# ncsim line " + line.file().file +
                     "\n# channel: " + std::to_string(line.channel_spec(k).number) + " " +
                     line.channel_spec(k).name + "\n# program: " + run.loaded().file.name() +
                     "\n# machine: " + run.loaded().machine.name +
                     "\n# cycle: " + num(line.t_cycle()) + " s\n# units: mm | deg, s\nt,line";
  for (const std::string& n : runner::axis_names(run.loaded().machine))
    head += ',' + n;
  csv.text(head + '\n');
  csv.set_axes(&run.channel().axes());
  csv.set_setpoints(&run.channel().setpoints());
}

// The CSVs' ends and commits; false (reported) on a write error.
bool close_csvs(runner::LineRun& line, std::vector<ChannelCsv>& csvs, std::ostream& err) {
  bool ok = true;
  for (std::size_t k = 0; k < csvs.size(); ++k) {
    CsvSink& csv = *csvs[k].sink;
    csv.write_last();
    const runner::Ending end = line.channel(k).ending(line.status(k));
    if (end.failed) csv.text("# error: " + runner::first_line(end.error_text) + "\n");
    csv.text("# stop: " + end.stop + "\n");
    std::string why;
    if (!csv.flush()) {
      err << "ncsim: error: cannot write '" << csvs[k].file->written().string()
          << "': " << std::strerror(csv.error_number()) << " [NC9151]\n";
      ok = false;
    } else if (!csvs[k].file->commit(why)) {
      err << "ncsim: error: " << why << " [NC9151]\n";
      ok = false;
    }
  }
  return ok;
}

// The page's file, opened before the run (an unwritable one is reported at once, NC8100).
bool open_page(const std::string& path, std::optional<core::OutputFile>& file, std::ostream& err) {
  auto opened = core::OutputFile::open(path);
  if (const auto* why = std::get_if<std::string>(&opened)) {
    err << "ncsim: error: the report: " << *why << " [NC8100]\n";
    return false;
  }
  file.emplace(std::move(std::get<core::OutputFile>(opened)));
  return true;
}

int run_line(const LineOptions& options, std::ostream& out, std::ostream& err) {
  runner::LineSpec spec;
  spec.file = options.file;
  spec.cycle_us = options.cycle_us;
  spec.max_time = options.max_time;
  spec.audit = options.audit;
  runner::LineLoadResult loaded = runner::load_line_run(spec);
  err << loaded.messages;
  if (!loaded.ok()) return static_cast<int>(loaded.exit);
  runner::LineRun& line = *loaded.line;
  const std::string page_path = options.mode == "report" ? options.output : options.report;
  std::optional<core::OutputFile> page_file;
  if (!page_path.empty() && !open_page(page_path, page_file, err)) return kExitUsage;
  std::vector<ChannelCsv> csvs(options.mode == "run" ? line.size() : 0);
  std::vector<std::vector<ipo::Sink*>> sinks(line.size());
  for (std::size_t k = 0; k < csvs.size(); ++k) {
    const std::filesystem::path path =
        std::filesystem::path(options.output) / csv_name(line.channel_spec(k));
    if (!open_csv(line, k, path, csvs[k], err)) return kExitUsage;
    sinks[k].push_back(csvs[k].sink.get());
  }
  std::unique_ptr<LinePage> page;  // the same cycles as the CSVs
  if (page_file) page = std::make_unique<LinePage>(line);
  for (std::size_t k = 0; page && k < line.size(); ++k)
    sinks[k].push_back(page->sink(k));
  line.start(sinks);
  for (std::size_t k = 0; k < csvs.size(); ++k)
    wire_csv(line, k, *csvs[k].sink);
  if (page) page->wire(line);
  line.run([&] {
    if (page) page->on_cycle(line);
  });
  if (!csvs.empty() && !close_csvs(line, csvs, err)) return kExitUsage;
  if (page) {
    std::string why;
    if (!report::write_line_html_file(page->finish(line), *page_file, why)) {
      err << "ncsim: error: " << why << '\n';
      return kExitUsage;
    }
    (options.mode == "report" ? out : err) << "report: " << page_path << '\n';
  }
  if (options.mode == "report") {
    // as `ncsim report`: the page and its name; the results are on it
  } else if (options.json) {
    print_line_json(line, out);
  } else {
    print_line_text(line, out);
  }
  bool failed = false;
  bool audit_failed = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const runner::Ending end = line.channel(k).ending(line.status(k));
    err << runner::warnings_text(line.channel(k));
    if (end.failed) err << end.error_text;
    failed = failed || end.failed;
    if (const audit::Audit* a = line.channel(k).audit(); a != nullptr && !a->verdict().ok()) {
      err << "ncsim: channel " << int{line.channel_spec(k).number}
          << ": the audit found violations (ncsim time --audit on its program lists them)\n";
      audit_failed = true;
    }
  }
  if (failed) return kExitProgramErrors;
  return audit_failed ? kExitAudit : kExitOk;
}

}  // namespace

int run_line_golden(const std::string& file,
                    const std::function<std::filesystem::path(const std::string&)>& csv_path,
                    std::vector<LineGoldenChannel>& channels, std::ostream& err) {
  runner::LineSpec spec;
  spec.file = file;
  spec.audit = true;
  runner::LineLoadResult loaded = runner::load_line_run(spec);
  err << loaded.messages;
  if (!loaded.ok()) return kExitUsage;
  runner::LineRun& line = *loaded.line;
  std::vector<ChannelCsv> csvs(line.size());
  std::vector<std::vector<ipo::Sink*>> sinks(line.size());
  for (std::size_t k = 0; k < line.size(); ++k) {
    if (!open_csv(line, k, csv_path(csv_name(line.channel_spec(k))), csvs[k], err))
      return kExitUsage;
    sinks[k].push_back(csvs[k].sink.get());
  }
  line.start(sinks);
  for (std::size_t k = 0; k < csvs.size(); ++k)
    wire_csv(line, k, *csvs[k].sink);
  line.run();
  if (!close_csvs(line, csvs, err)) return kExitUsage;
  channels.clear();
  for (std::size_t k = 0; k < line.size(); ++k) {
    const runner::Ending end = line.channel(k).ending(line.status(k));
    LineGoldenChannel c;
    c.csv_name = csv_name(line.channel_spec(k));
    c.program = line.file().resolved(line.channel_spec(k).program).string();
    const audit::Audit* a = line.channel(k).audit();
    c.status = end.failed                             ? kExitProgramErrors
               : (a != nullptr && !a->verdict().ok()) ? kExitAudit
                                                      : kExitOk;
    c.error_text = end.failed ? end.error_text : std::string();
    channels.push_back(std::move(c));
  }
  return kExitOk;
}

int run_line_command(const LineOptions& options, std::ostream& out, std::ostream& err) {
  if (options.mode == "run" && options.output.empty()) {
    err << "ncsim: error: line run needs -o DIR (one CSV per channel)\n";
    return kExitUsage;
  }
  if (options.mode == "report" && options.output.empty()) {
    err << "ncsim: error: line report needs -o PAGE (the HTML page) [NC8101]\n";
    return kExitUsage;
  }
  if (!options.report.empty() && options.mode != "run") {
    err << "ncsim: error: --report PAGE is an option of line run (line report -o PAGE writes "
           "the page alone)\n";
    return kExitUsage;
  }
  if (options.mode == "sweep") return run_line_sweep(options, out, err);
  if (!options.belt_velocity.empty()) {
    err << "ncsim: error: --belt-velocity is an option of line sweep\n";
    return kExitUsage;
  }
  if (options.mode != "check") return run_line(options, out, err);
  runner::LineSpec spec;
  spec.file = options.file;
  spec.cycle_us = options.cycle_us;
  std::string text;
  const runner::Exit exit = runner::check_line(spec, text);
  err << text;
  if (exit == runner::Exit::ok) out << options.file << ": ok\n";
  return static_cast<int>(exit);
}

LineCommand::LineCommand(CLI::App& app) {
  cmd_ =
      app.add_subcommand("line", "Several channels in one run: a production line (docs/lines.md)");
  cmd_->add_option("mode", options_.mode, "check, time, run, report or sweep")
      ->required()
      ->check(CLI::IsMember({"check", "time", "run", "report", "sweep"}));
  cmd_->add_option("line", options_.file, "The line file (TOML)")->required();
  cmd_->add_option("-o,--output", options_.output,
                   "run: the folder of the channels' CSVs; report: the HTML page");
  cmd_->add_option("--report", options_.report, "run: the line's HTML page too, same pass");
  cmd_->add_option("--max-time", options_.max_time,
                   "Stop every channel after S seconds of machine time")
      ->check(CLI::PositiveNumber);
  cmd_->add_flag("--audit", options_.audit, "Audit every channel's setpoints");
  cmd_->add_flag("--json", options_.json,
                 "time, run: the channels' and the belt's results as one JSON object");
  add_cycle_us_option(*cmd_, options_.cycle_us);
  add_line_sweep_options(*cmd_, options_);
}

std::optional<int> LineCommand::dispatch(std::ostream& out, std::ostream& err) const {
  if (!cmd_->parsed()) return std::nullopt;
  return run_line_command(options_, out, err);
}

}  // namespace ncsim::cli
