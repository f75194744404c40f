#include "runner/line_run.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "conveyor/world.hpp"
#include "core/diagnostic.hpp"
#include "core/number_text.hpp"
#include "interp/trace.hpp"
#include "runner/load.hpp"
#include "runner/locate.hpp"
#include "scenario/loader.hpp"

namespace ncsim::runner {
namespace {

namespace fs = std::filesystem;

// The line file read and validated; its diagnostics (with their source lines) on `err`.
std::optional<scenario::LineFile> read_line_file(const fs::path& path, std::ostream& err) {
  std::optional<core::SourceFile> file;
  try {
    file.emplace(core::SourceFile::load_regular(path, scenario::kMaxScenarioBytes));
  } catch (const std::exception& e) {
    err << "ncsim: error: cannot read the line file '" << path.string() << "': " << e.what()
        << '\n';
    return std::nullopt;
  }
  scenario::LineLoad loaded = scenario::parse_line(*file);
  for (const core::Diagnostic& d : loaded.diagnostics.items())
    err << core::format(d, *file);
  if (!loaded.line) {
    const std::size_t n = loaded.diagnostics.error_count();
    err << "ncsim: error: line '" << path.string() << "': " << n << " error" << (n == 1 ? "" : "s")
        << '\n';
  }
  return std::move(loaded.line);
}

// A positioned error of the line file (runner's checks of what the file names).
void line_error(std::ostream& err, const scenario::LineFile& line, core::SourceLoc at,
                const char* id, const std::string& message) {
  core::Diagnostic d;
  d.file = line.file;
  d.loc = at;
  d.id = id;
  d.message = message;
  try {
    err << core::format(d, core::SourceFile::load_regular(line.file, scenario::kMaxScenarioBytes));
  } catch (const std::exception&) {
    err << core::format(d);
  }
}

// The machine folder a channel names: a folder relative to the line file, else a bundled
// machine of that name (docs/lines.md).
fs::path machine_dir(const scenario::LineFile& line, const scenario::LineChannel& c) {
  const fs::path relative = line.resolved(c.machine);
  std::error_code ec;
  if (fs::is_directory(relative, ec)) return relative;
  return bundled_machine(c.machine.text);
}

// Channel `c` as a RunSpec: `time PROG --machine DIR [--scenario FILE]`.
RunSpec channel_spec(const scenario::LineFile& line, const scenario::LineChannel& c,
                     const LineSpec& spec) {
  RunSpec rs;
  rs.program.program = line.resolved(c.program);
  rs.program.machine_dir = machine_dir(line, c);
  if (c.scenario) rs.program.scenario = line.resolved(*c.scenario);
  rs.program.scenario_lookup = false;
  rs.program.max_time = spec.max_time;
  rs.cycle_us = spec.cycle_us ? spec.cycle_us : line.cycle_us;
  rs.audit = spec.audit;
  return rs;
}

// The files a channel names exist (positioned at their values; NC7106).
bool files_exist(const scenario::LineFile& line, const scenario::LineChannel& c,
                 std::ostream& err) {
  std::error_code ec;
  bool ok = true;
  const auto need = [&](const scenario::LinePath& p, const fs::path& at, const char* what) {
    if (fs::exists(at, ec)) return;
    line_error(err, line, p.loc, "NC7106",
               std::string("no such ") + what + ": '" + at.string() +
                   "' (paths are relative to "
                   "the line file's folder)");
    ok = false;
  };
  need(c.program, line.resolved(c.program), "program");
  need(c.machine, machine_dir(line, c), "machine folder (nor a bundled machine of that name)");
  if (c.scenario) need(*c.scenario, line.resolved(*c.scenario), "scenario");
  return ok;
}

}  // namespace

LineRun::~LineRun() = default;

LineLoadResult load_line_run(const LineSpec& spec) {
  LineLoadResult r;
  std::ostringstream err;
  r.exit = Exit::usage;
  std::optional<scenario::LineFile> file = read_line_file(spec.file, err);
  if (!file) {
    r.messages = err.str();
    return r;
  }
  std::unique_ptr<LineRun> line(new LineRun);
  line->file_ = std::move(*file);
  const scenario::LineFile& lf = line->file_;
  line->order_ = lf.channels;
  std::sort(line->order_.begin(), line->order_.end(),
            [](const auto& a, const auto& b) { return a.number < b.number; });
  std::vector<std::uint8_t> numbers;
  std::vector<std::string> names;
  for (const scenario::LineChannel& c : line->order_) {
    numbers.push_back(c.number);
    names.push_back(c.name);
  }
  line->hub_ = std::make_unique<program::SignalHub>(numbers, names);
  bool files_ok = true;
  for (const scenario::LineChannel& c : line->order_)
    files_ok = files_exist(lf, c, err) && files_ok;
  if (!files_ok) {
    r.messages = err.str();
    return r;
  }
  std::vector<std::unique_ptr<Loaded>> loaded;
  const scenario::LineChannel* first = nullptr;  // the channel whose cycle the others match
  for (const scenario::LineChannel& c : line->order_) {
    LoadResult one = load(channel_spec(lf, c, spec));
    err << one.messages;
    if (one.thrown) std::rethrow_exception(one.thrown);
    if (!one.ok()) {
      r.messages = err.str();
      r.exit = one.exit;
      return r;
    }
    Loaded& in = *one.loaded;
    in.interp.channels = numbers;  // CH=.. of a channel the line does not have: 250008
    if (first == nullptr) {
      first = &c;
      line->t_cycle_ = in.t_cycle;
    } else if (in.t_cycle != line->t_cycle_) {
      line_error(err, lf, c.machine.loc, "NC7105",
                 "channel " + std::to_string(c.number) + " runs at a cycle of " +
                     core::human(in.t_cycle * 1e6) + " us, channel " +
                     std::to_string(first->number) + " at " + core::human(line->t_cycle_ * 1e6) +
                     " us: a line steps all channels in one cycle (NCSIM-CHAN-610 of the "
                     "machines, or cycle_us / --cycle-us)");
      r.messages = err.str();
      return r;
    }
    if (in.machine.conveyor_axis() != nullptr) {
      if (in.scenario && in.scenario->conveyor && c.scenario) {
        line_error(err, lf, c.scenario->loc, "NC7107",
                   "channel " + std::to_string(c.number) +
                       "'s scenario has a [conveyor] table: the line's [conveyor] is the one "
                       "world its channels share (docs/lines.md)");
        r.messages = err.str();
        return r;
      }
      if (!in.scenario) in.scenario.emplace();
      in.scenario->conveyor = lf.conveyor;
      if (!line->world_) {
        try {
          line->world_ = conveyor::make_port(in.machine, &*in.scenario, in.t_cycle);
        } catch (const std::invalid_argument& e) {
          line_error(err, lf, c.machine.loc, "NC7108",
                     std::string("the line's conveyor on channel ") + std::to_string(c.number) +
                         "'s machine: " + e.what());
          r.messages = err.str();
          return r;
        }
        line->shared_ = std::make_unique<conveyor::SharedWorld>(*line->world_);
      }
      in.port = std::make_unique<conveyor::SharedPort>(*line->shared_);
    }
    loaded.push_back(std::move(one.loaded));
  }
  if (lf.conveyor && !line->world_) {
    core::Diagnostic d;
    d.severity = core::Severity::warning;
    d.file = lf.file;
    d.loc = lf.conveyor->loc;
    d.id = "NC7109";
    d.message = "[conveyor] is not played: no channel's machine has a conveyor axis";
    err << core::format(d);
  }
  for (std::size_t k = 0; k < loaded.size(); ++k) {
    RunSpec rs = channel_spec(lf, line->order_[k], spec);
    line->runs_.push_back(
        std::make_unique<Run>(std::move(loaded[k]), rs, line->hub_.get(), line->order_[k].number));
  }
  line->status_.assign(line->runs_.size(), ipo::Status::running);
  line->times_.assign(line->runs_.size(), LineChannelTime{});
  r.messages = err.str();
  r.exit = Exit::ok;
  r.line = std::move(line);
  return r;
}

Exit check_line(const LineSpec& spec, std::string& out) {
  std::ostringstream err;
  std::optional<scenario::LineFile> file = read_line_file(spec.file, err);
  if (!file) {
    out = err.str();
    return Exit::usage;
  }
  std::vector<std::uint8_t> numbers;
  for (const scenario::LineChannel& c : file->channels)
    numbers.push_back(c.number);
  Exit exit = Exit::ok;
  for (const scenario::LineChannel& c : file->channels) {
    if (!files_exist(*file, c, err)) {
      exit = Exit::usage;
      continue;
    }
    LoadResult one = load(channel_spec(*file, c, spec));
    err << one.messages;
    if (!one.ok()) {
      if (exit == Exit::ok || one.exit == Exit::usage) exit = one.exit;
      continue;
    }
    Loaded& in = *one.loaded;
    in.interp.channels = numbers;
    const core::DiagnosticList semantics = interp::check_semantics(in.file, in.machine, in.interp);
    for (const core::Diagnostic& d : semantics.items())
      err << core::format(d, in.file);
    if (semantics.has_errors() && exit == Exit::ok) exit = Exit::program_errors;
  }
  out = err.str();
  return exit;
}

void LineRun::start(const std::vector<std::vector<ipo::Sink*>>& sinks) {
  for (std::size_t k = 0; k < runs_.size(); ++k)
    runs_[k]->start(k < sinks.size() ? sinks[k] : std::vector<ipo::Sink*>{});
}

bool LineRun::step() {
  hub_->begin_cycle(cycle_);
  bool any = false;
  for (std::size_t k = 0; k < runs_.size(); ++k) {
    if (status_[k] != ipo::Status::running) continue;
    status_[k] = runs_[k]->step();
    if (status_[k] == ipo::Status::running) {
      any = true;
      times_[k].t_end = static_cast<double>(cycle_ + 1) * t_cycle_;
      if (hub_->blocked(order_[k].number)) times_[k].t_waiting += t_cycle_;
    }
  }
  ++cycle_;
  // The world is at the cycle's end whether a channel stepped it or not.
  if (shared_) shared_->step_once(static_cast<double>(cycle_) * t_cycle_);
  hub_->mark_stuck();  // a doomed wait fails in its channel's next cycle (NC6401)
  return any;
}

void LineRun::run() {
  while (step()) {
  }
}

double LineRun::t_end() const noexcept {
  double t = 0.0;
  for (const LineChannelTime& c : times_)
    t = std::max(t, c.t_end);
  return t;
}

}  // namespace ncsim::runner
