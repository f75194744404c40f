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

// [mm] the belt's end after the last channel's sensor when the line file gives no `belt_end`
// (docs/lines.md "Workpieces along the belt").
constexpr double kBeltBeyondLastSensor = 1000.0;
// [s] how long the belt runs on after the last channel ended, at most (LineRun::run).
constexpr double kDrainMax = 600.0;

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
  rs.conv_vel = spec.conv_vel;
  rs.build_world = false;  // the line's belt (LineWorld) gives the channel its Port
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

// The line's belt as its channels load: built on the first machine with a conveyor axis, one
// station per such channel (docs/lines.md "Workpieces along the belt").
struct BeltParts {
  std::unique_ptr<conveyor::Port> belt;           // the belt alone (no workpieces)
  double sign = 1.0;                              // its conveying sign (P-CHAN-00363)
  std::vector<conveyor::StationSpec> stations;    // one per channel with a conveyor axis
  std::vector<std::optional<std::size_t>> index;  // per channel: its station
  WrapPort wrap;                                  // LineSpec::wrap

  // Channel c (loaded as `in`) joins the belt if its machine has a conveyor axis; false (the
  // positioned error on `err`) when it cannot (NC7107, NC7108).
  bool attach(const scenario::LineFile& lf, const scenario::LineChannel& c, Loaded& in,
              std::ostream& err) {
    if (in.machine.conveyor_axis() == nullptr) {
      index.push_back(std::nullopt);
      return true;
    }
    if (in.scenario && in.scenario->conveyor && c.scenario) {
      line_error(err, lf, c.scenario->loc, "NC7107",
                 "channel " + std::to_string(c.number) +
                     "'s scenario has a [conveyor] table: the line's [conveyor] is the one "
                     "world its channels share (docs/lines.md)");
      return false;
    }
    if (!in.scenario) in.scenario.emplace();
    in.scenario->conveyor = lf.conveyor;
    in.scenario->line_plc = true;
    try {
      if (!belt) {
        // The belt alone: the workpieces are the line's to sense (conveyor::LineWorld).
        scenario::Scenario belt_only = *in.scenario;
        if (belt_only.conveyor) {
          belt_only.conveyor->workpieces.clear();
          belt_only.conveyor->series.reset();
        }
        belt = conveyor::make_port(in.machine, &belt_only, in.t_cycle);
        if (wrap) belt = wrap(std::move(belt));
        const auto& cc = in.machine.channel.conveyor;
        sign = cc && cc->direction == machines::MoveDirection::negative_x ? -1.0 : 1.0;
      }
      stations.push_back(conveyor::station_of(in.machine, c.number, c.sensor_at));
    } catch (const std::invalid_argument& e) {
      line_error(err, lf, c.machine.loc, "NC7108",
                 std::string("the line's conveyor on channel ") + std::to_string(c.number) +
                     "'s machine: " + e.what());
      return false;
    }
    index.push_back(stations.size() - 1);
    return true;
  }
};

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
  if (spec.adjust) spec.adjust(*file);
  std::unique_ptr<LineRun> line(new LineRun);
  line->file_ = std::move(*file);
  // line sweep: the belt's velocity set before anything is built from it.
  if (spec.adjust_conveyor && line->file_.conveyor) spec.adjust_conveyor(*line->file_.conveyor);
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
  BeltParts belt;
  belt.wrap = spec.wrap;
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
    if (!belt.attach(lf, c, in, err)) {
      r.messages = err.str();
      return r;
    }
    loaded.push_back(std::move(one.loaded));
  }
  if (lf.conveyor && !belt.belt) {
    core::Diagnostic d;
    d.severity = core::Severity::warning;
    d.file = lf.file;
    d.loc = lf.conveyor->loc;
    d.id = "NC7109";
    d.message = "[conveyor] is not played: no channel's machine has a conveyor axis";
    err << core::format(d);
  }
  if (belt.belt) {
    double last = 0.0;
    for (const conveyor::StationSpec& st : belt.stations)
      last = std::max(last, st.sensor_at);
    const double end = lf.belt_end ? *lf.belt_end : last + kBeltBeyondLastSensor;
    line->belt_ = std::make_unique<conveyor::LineWorld>(std::move(belt.belt),
                                                        lf.conveyor ? &*lf.conveyor : nullptr,
                                                        belt.sign, std::move(belt.stations), end);
  }
  line->watch_.assign(loaded.size(), LineRun::Watch{});
  for (std::size_t k = 0; k < loaded.size(); ++k) {
    line->watch_[k].station = belt.index[k];
    if (belt.index[k])
      loaded[k]->port = std::make_unique<conveyor::SharedPort>(line->belt_->port(*belt.index[k]));
  }
  for (std::size_t k = 0; k < loaded.size(); ++k) {
    RunSpec rs = channel_spec(lf, line->order_[k], spec);
    line->runs_.push_back(
        std::make_unique<Run>(std::move(loaded[k]), rs, line->hub_.get(), line->order_[k].number));
  }
  line->status_.assign(line->runs_.size(), ipo::Status::running);
  line->times_.assign(line->runs_.size(), LineChannelTime{});
  line->waiting_.assign(line->runs_.size(), 0);
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
    if (in.machine.conveyor_axis() != nullptr) {  // the line's PLC words, as a first workpiece
      in.interp.external.emplace(conveyor::kVeMore, 1.0);
      in.interp.external.emplace(conveyor::kVeWorkpiece, 1.0);
      in.interp.external.emplace(conveyor::kVeTravel, 0.0);
    }
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

void LineRun::write_more(std::size_t k) {
  // LINE_MORE: 1 while a workpiece can still reach the channel's probe (docs/lines.md).
  scenario::Player* player = runs_[k]->player();
  if (player == nullptr) return;
  const double more = belt_->more_for(*watch_[k].station) ? 1.0 : 0.0;
  if (more == watch_[k].more) return;
  watch_[k].more = more;
  player->ve().write(conveyor::kVeMore, more);
}

void LineRun::watch(std::size_t k, double t) noexcept {
  Watch& w = watch_[k];
  const tracking::ConveyorSync* sync = runs_[k]->channel().conveyor_sync();
  if (sync == nullptr) return;
  const auto resolve = [&] {  // the channel is through with w.workpiece
    w.open = false;
    if (w.caught) {
      belt_->done(*w.station, w.workpiece, t);
    } else {
      belt_->let_go(*w.station, w.workpiece, t);
    }
  };
  using tracking::SyncPhase;
  const SyncPhase p = sync->phase();
  const std::uint64_t taken = runs_[k]->loaded().port->last_latch().workpiece;
  if (taken != w.workpiece) {
    // Its #SYNC IN took another measured value: a #SYNC OUT and the next #SYNC IN may fall
    // into one cycle (no motion between), so the previous one ends here.
    if (w.open) resolve();
    w.workpiece = taken;
    w.open = true;
    w.caught = false;
  }
  if (!w.open) return;
  if (p == SyncPhase::catching_up || p == SyncPhase::tracking) w.caught = true;
  if (p == SyncPhase::off || p == SyncPhase::leaving || p == SyncPhase::departing ||
      p == SyncPhase::waiting)
    resolve();
}

bool LineRun::step() {
  hub_->begin_cycle(cycle_);
  const double t = static_cast<double>(cycle_ + 1) * t_cycle_;
  if (belt_) {
    for (std::size_t k = 0; k < runs_.size(); ++k)
      if (watch_[k].station && status_[k] == ipo::Status::running) write_more(k);
  }
  bool any = false;
  for (std::size_t k = 0; k < runs_.size(); ++k) {
    if (status_[k] != ipo::Status::running) continue;
    status_[k] = runs_[k]->step();
    if (belt_ && watch_[k].station) watch(k, t);
    waiting_[k] = 0;
    if (status_[k] == ipo::Status::running) {
      any = true;
      times_[k].t_end = t;
      if (hub_->blocked(order_[k].number)) {
        times_[k].t_waiting += t_cycle_;
        waiting_[k] = 1;
      }
    }
  }
  ++cycle_;
  // The belt is at the cycle's end whether a channel stepped it or not.
  if (belt_) belt_->step_once(t);
  hub_->mark_stuck();  // a doomed wait fails in its channel's next cycle (NC6401)
  return any;
}

void LineRun::run(const std::function<void()>& after_cycle) {
  for (bool more = true; more;) {
    more = step();
    if (after_cycle) after_cycle();
  }
  // The belt runs on until every free workpiece has left it (docs/lines.md "Workpieces along
  // the belt"); a belt that stands keeps them (on the belt at the end).
  if (belt_)
    belt_->drain(static_cast<double>(cycle_) * t_cycle_, t_cycle_,
                 static_cast<double>(cycle_) * t_cycle_ + kDrainMax);
}

const conveyor::BeltState* LineRun::belt_state() const noexcept {
  return belt_ ? &belt_->world().actual() : nullptr;
}

double LineRun::t_end() const noexcept {
  double t = 0.0;
  for (const LineChannelTime& c : times_)
    t = std::max(t, c.t_end);
  return t;
}

}  // namespace ncsim::runner
