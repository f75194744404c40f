// cli/study_job: one job of a study, and the check of its axes against the base (see the
// header).

#include "cli/study_job.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "cli/line_world.hpp"
#include "core/number_text.hpp"
#include "runner/line_run.hpp"
#include "runner/load.hpp"
#include "runner/locate.hpp"
#include "runner/run.hpp"
#include "runner/texts.hpp"
#include "scenario/loader.hpp"

namespace ncsim::cli {
namespace fs = std::filesystem;
namespace {

using scenario::StudyFile;

// Why a varied value cannot be applied to the base, at its axis in the study file.
struct AxisProblem {
  core::SourceLoc loc;
  std::string text;
  bool operator==(const AxisProblem& o) const {
    return loc.line == o.loc.line && loc.column == o.loc.column && text == o.text;
  }
};

// A line's encoder belt at velocity v: velocity and profile scaled as cli/line_world scales a
// program's encoder belt (set_belt_velocity), fluctuation and noise kept relative.
std::optional<AxisProblem> line_belt(const StudyFile& s, scenario::Conveyor* c, double v) {
  if (c == nullptr)
    return AxisProblem{s.belt_velocity.loc, "vary.belt_velocity: the line has no [conveyor] belt"};
  if (c->mode != scenario::ConveyorMode::encoder)
    return AxisProblem{s.belt_velocity.loc,
                       "not supported: vary.belt_velocity on a line whose belt its programs drive "
                       "(mode = \"spindle\"); a line's encoder belt is varied"};
  if (c->velocity == 0.0)
    return AxisProblem{s.belt_velocity.loc,
                       "vary.belt_velocity: the line's encoder belt has velocity 0 at t = 0: no "
                       "velocity to scale (give [conveyor] velocity > 0)"};
  const double k = v / std::abs(c->velocity);
  c->velocity *= k;
  for (scenario::BeltChange& change : c->profile)
    change.velocity *= k;
  return std::nullopt;
}

// The job's world values (pitch, fluctuation, seed) applied to `c` (null: the base has no
// [conveyor]); the first that cannot be applied.
std::optional<AxisProblem> apply_conveyor(const StudyFile& s, const runner::StudyJob& j,
                                          scenario::Conveyor* c) {
  if (j.pitch) {
    if (c == nullptr || !c->series)
      return AxisProblem{s.pitch.loc,
                         "vary.pitch: the base's [conveyor] has no [conveyor.workpieces] series "
                         "to space"};
    if (!c->series->first.travel)
      return AxisProblem{s.pitch.loc,
                         "vary.pitch: the base's series is by time (first_at, period); vary.pitch "
                         "spaces a series by travel (first, pitch) in mm"};
    if (*j.pitch <= c->series->first.length)
      return AxisProblem{s.pitch.loc, "vary.pitch = " + core::human(*j.pitch) +
                                          " mm is not above the workpieces' length " +
                                          core::human(c->series->first.length) +
                                          " mm: they would overlap (NC7018)"};
    c->series->pitch = *j.pitch;
  }
  if (j.fluctuation) {
    if (c == nullptr || !c->fluctuation)
      return AxisProblem{s.fluctuation.loc,
                         "vary.fluctuation: the base's [conveyor] has no fluctuation; give it "
                         "`fluctuation = { amplitude = 0, frequency = F }` (the study varies the "
                         "amplitude, the frequency is the base's)"};
    c->fluctuation->amplitude = *j.fluctuation / 100.0;
  }
  if (j.seed) {
    bool used = false;
    if (c != nullptr && c->series && c->series->scatter > 0.0) {
      c->series->seed = *j.seed;
      used = true;
    }
    if (c != nullptr && c->noise) {
      c->noise->seed = *j.seed;
      used = true;
    }
    if (!used)
      return AxisProblem{s.seed.loc,
                         "vary.seed: the base's world has nothing random to seed (no "
                         "[conveyor.workpieces] scatter > 0, no [conveyor] noise)"};
  }
  return std::nullopt;
}

// The program base's machine folder: relative to the study file, else a bundled machine.
fs::path machine_dir(const StudyFile& s, const scenario::StudyPath& m) {
  const fs::path relative = s.resolved(m);
  std::error_code ec;
  if (fs::is_directory(relative, ec)) return relative;
  return runner::bundled_machine(m.text);
}

runner::RunSpec program_spec(const StudyFile& s, const runner::StudyJob& j) {
  runner::RunSpec rs;
  rs.program.program = s.resolved(j.program ? *j.program : *s.program);
  const scenario::StudyPath* m = j.machine ? j.machine : (s.machine ? &*s.machine : nullptr);
  if (m != nullptr) rs.program.machine_dir = machine_dir(s, *m);
  if (s.scenario) rs.program.scenario = s.resolved(*s.scenario);
  rs.program.max_time = s.max_time;
  rs.cycle_us = s.cycle_us;
  rs.audit = s.audit;
  return rs;
}

// A program's belt at velocity v (as `ncsim sweep` sets it); the problem when it has none.
std::optional<AxisProblem> program_belt(const StudyFile& s, const machines::Machine& m,
                                        std::optional<scenario::Scenario>& sc, double v) {
  const BeltSetting b = set_belt_velocity(m, sc, v);
  if (!b.conveyor)
    return AxisProblem{s.belt_velocity.loc,
                       "vary.belt_velocity: the machine has no conveyor axis with conveyor "
                       "tracking: no belt to vary"};
  if (b.encoder_zero)
    return AxisProblem{s.belt_velocity.loc,
                       "vary.belt_velocity: the scenario's encoder belt has velocity 0 at t = 0: "
                       "no velocity to scale (give [conveyor] velocity > 0)"};
  return std::nullopt;
}

// The id in the first "[ID]" of an error line of `messages` ("" when none).
std::string first_id(const std::string& messages) {
  std::istringstream in(messages);
  for (std::string line; std::getline(in, line);) {
    if (line.find(": error: ") == std::string::npos) continue;
    const auto close = line.rfind(']');
    const auto open = line.rfind('[', close);
    if (close != std::string::npos && open != std::string::npos && close == line.size() - 1)
      return line.substr(open + 1, close - open - 1);
  }
  return {};
}

// The first error line of `messages`, else `failure`.
std::string first_error(const std::string& messages, const std::string& failure) {
  std::istringstream in(messages);
  for (std::string line; std::getline(in, line);)
    if (line.find("error: ") != std::string::npos) return line;
  return failure;
}

// A run's error id and text (after it ended) into `o`.
void take_error(const runner::Run& run, const runner::Ending& end, runner::StudyOutcome& o) {
  o.error = runner::first_line(end.error_text);
  if (const auto& e = run.channel().run_time_error()) {
    o.error_id = e->id;
  } else if (const core::Diagnostic* d =
                 run.source().error() ? run.source().error() : run.interpreter().error()) {
    o.error_id = d->id;
  }
}

runner::StudyOutcome not_started(runner::Exit exit, std::string id, std::string error) {
  runner::StudyOutcome o;
  o.exit = exit;
  o.stop = "not started";
  o.error_id = std::move(id);
  o.error = std::move(error);
  return o;
}

runner::StudyOutcome run_program(const StudyFile& s, const runner::StudyJob& j) {
  runner::RunSpec rs = program_spec(s, j);
  std::optional<AxisProblem> problem;
  rs.adjust = [&](machines::Machine& m, std::optional<scenario::Scenario>& sc, double) {
    scenario::Conveyor* c = sc && sc->conveyor ? &*sc->conveyor : nullptr;
    problem = apply_conveyor(s, j, c);
    if (!problem && j.belt_velocity) problem = program_belt(s, m, sc, *j.belt_velocity);
  };
  if (j.belt_velocity) {
    const double v = *j.belt_velocity;
    rs.wrap = [v](std::unique_ptr<conveyor::Port> port) {
      return override_belt(std::move(port), v);
    };
    rs.conv_vel = v;
  }
  runner::LoadResult loaded = runner::load(rs);
  if (loaded.thrown) {
    try {
      std::rethrow_exception(loaded.thrown);
    } catch (const std::exception& e) {
      return not_started(runner::Exit::usage, "", e.what());
    }
  }
  if (problem) return not_started(runner::Exit::usage, kStudyAxisId, problem->text);
  if (!loaded.ok())
    return not_started(loaded.exit, first_id(loaded.messages),
                       first_error(loaded.messages, loaded.failure));
  runner::Run run(std::move(loaded.loaded), rs);
  run.start();
  if (run.tracks_conveyor()) run.count_workpieces([](const audit::WorkpieceCycle&) {});
  const ipo::Status status = run.run();
  const runner::Ending end = run.ending(status);
  runner::StudyOutcome o;
  o.t_end = run.channel().cycle().t;
  o.stop = end.stop;
  if (const auto w = run.workpiece_summary()) o.taken = w->complete;
  if (end.failed) {
    o.exit = runner::Exit::program_errors;
    take_error(run, end, o);
  }
  if (const audit::Audit* a = run.audit()) {
    o.audited = true;
    o.audit_violations = a->verdict().violation_count;
    if (!end.failed && o.audit_violations > 0) {
      o.exit = runner::Exit::audit;
      o.error = runner::first_violation(run);
    }
  }
  return o;
}

runner::LineSpec line_spec(const StudyFile& s, const runner::StudyJob& j) {
  runner::LineSpec ls;
  ls.file = s.resolved(*s.line);
  ls.cycle_us = s.cycle_us;
  ls.max_time = s.max_time;
  ls.audit = s.audit;
  if (j.belt_velocity) ls.conv_vel = *j.belt_velocity;
  return ls;
}

// A line's stop: the channels' common reason, else each channel's ("ch1 program end; ch2 error").
std::string line_stop(const runner::LineRun& line) {
  std::vector<std::string> stops;
  for (std::size_t k = 0; k < line.size(); ++k)
    stops.push_back(line.channel(k).ending(line.status(k)).stop);
  bool same = true;
  for (const std::string& st : stops)
    same = same && st == stops.front();
  if (same) return stops.empty() ? std::string() : stops.front();
  std::string out;
  for (std::size_t k = 0; k < stops.size(); ++k)
    out += (k ? "; ch" : "ch") + std::to_string(line.channel_spec(k).number) + " " + stops[k];
  return out;
}

runner::StudyOutcome run_line_job(const StudyFile& s, const runner::StudyJob& j) {
  runner::LineSpec ls = line_spec(s, j);
  std::optional<AxisProblem> problem;
  ls.adjust = [&](scenario::LineFile& lf) {
    scenario::Conveyor* c = lf.conveyor ? &*lf.conveyor : nullptr;
    problem = apply_conveyor(s, j, c);
    if (!problem && j.belt_velocity) problem = line_belt(s, c, *j.belt_velocity);
  };
  runner::LineLoadResult loaded;
  try {
    loaded = runner::load_line_run(ls);
  } catch (const std::exception& e) {
    return not_started(runner::Exit::usage, "", e.what());
  }
  if (problem) return not_started(runner::Exit::usage, kStudyAxisId, problem->text);
  if (!loaded.ok())
    return not_started(loaded.exit, first_id(loaded.messages),
                       first_error(loaded.messages, "the line could not be loaded"));
  runner::LineRun& line = *loaded.line;
  line.start();
  line.run();
  runner::StudyOutcome o;
  o.t_end = line.t_end();
  o.stop = line_stop(line);
  if (const conveyor::LineWorld* b = line.belt()) {
    o.arrived = b->arrived();
    o.taken = b->taken_total();
    o.missed = b->missed();
  }
  o.audited = s.audit;
  std::string first_violation;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const runner::Run& run = line.channel(k);
    const runner::Ending end = run.ending(line.status(k));
    if (end.failed && o.exit != runner::Exit::program_errors) {
      o.exit = runner::Exit::program_errors;
      take_error(run, end, o);
    }
    if (const audit::Audit* a = run.audit()) {
      o.audit_violations += a->verdict().violation_count;
      if (first_violation.empty()) first_violation = runner::first_violation(run);
    }
  }
  if (o.exit == runner::Exit::ok && o.audit_violations > 0) {
    o.exit = runner::Exit::audit;
    o.error = first_violation;
  }
  return o;
}

// One job per value of each world axis (the others the base's): what check_study_base tries.
std::vector<runner::StudyJob> probes(const StudyFile& s) {
  std::vector<runner::StudyJob> out;
  for (const double v : s.belt_velocity.values)
    out.emplace_back().belt_velocity = v;
  for (const double v : s.pitch.values)
    out.emplace_back().pitch = v;
  for (const double v : s.fluctuation.values)
    out.emplace_back().fluctuation = v;
  for (const std::uint64_t v : s.seed.values)
    out.emplace_back().seed = v;
  return out;
}

void add_problem(std::vector<AxisProblem>& all, std::optional<AxisProblem> p) {
  if (p && std::find(all.begin(), all.end(), *p) == all.end()) all.push_back(std::move(*p));
}

// The diagnostic of `p` in the study file, with its source line.
std::string study_error(const StudyFile& s, core::SourceLoc at, const char* id, std::string text) {
  core::Diagnostic d;
  d.file = s.file;
  d.loc = at;
  d.id = id;
  d.message = std::move(text);
  try {
    return core::format(d, core::SourceFile::load_regular(s.file, scenario::kMaxScenarioBytes));
  } catch (const std::exception&) {
    return core::format(d);
  }
}

}  // namespace

runner::StudyOutcome run_study_job(const StudyFile& study, const runner::StudyJob& job) {
  // A configuration the channel refuses throws (the second error tier): the row says so.
  try {
    return study.line ? run_line_job(study, job) : run_program(study, job);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    return not_started(runner::Exit::usage, "", e.what());
  }
}

bool check_study_base(const StudyFile& s, std::string& messages) {
  std::vector<AxisProblem> problems;
  bool files_ok = true;
  const auto need = [&](const scenario::StudyPath& p, const fs::path& at, const char* what) {
    std::error_code ec;
    if (fs::exists(at, ec)) return;
    messages += study_error(s, p.loc, kStudyNoFileId,
                            std::string("no such ") + what + ": '" + at.string() +
                                "' (paths are relative to the study file's folder)");
    files_ok = false;
  };
  if (s.line) need(*s.line, s.resolved(*s.line), "line file");
  if (s.program) need(*s.program, s.resolved(*s.program), "program");
  for (const scenario::StudyPath& p : s.programs.values)
    need(p, s.resolved(p), "program");
  if (s.scenario) need(*s.scenario, s.resolved(*s.scenario), "scenario");
  if (s.machine)
    need(*s.machine, machine_dir(s, *s.machine), "machine folder (nor bundled machine)");
  for (const scenario::StudyPath& m : s.machines.values)
    need(m, machine_dir(s, m), "machine folder (nor bundled machine)");
  if (!files_ok) return false;
  const std::vector<runner::StudyJob> tries = probes(s);
  bool loads = true;
  if (s.line) {
    runner::LineSpec ls = line_spec(s, runner::StudyJob{});
    ls.adjust = [&](scenario::LineFile& lf) {
      for (const runner::StudyJob& j : tries) {
        std::optional<scenario::Conveyor> c = lf.conveyor;
        add_problem(problems, apply_conveyor(s, j, c ? &*c : nullptr));
        if (j.belt_velocity)
          add_problem(problems, line_belt(s, c ? &*c : nullptr, *j.belt_velocity));
      }
    };
    const runner::LineLoadResult r = runner::load_line_run(ls);
    messages += r.messages;
    loads = r.ok();
  } else {
    // Every program x machine of the study, loaded once.
    const std::uint64_t n = std::max<std::size_t>(1, s.programs.values.size()) *
                            std::max<std::size_t>(1, s.machines.values.size());
    for (std::uint64_t k = 0; k < n; ++k) {
      runner::StudyJob base;
      const std::size_t nm = std::max<std::size_t>(1, s.machines.values.size());
      if (s.programs.given()) base.program = &s.programs.values[k / nm];
      if (s.machines.given()) base.machine = &s.machines.values[k % nm];
      runner::RunSpec rs = program_spec(s, base);
      rs.adjust = [&](machines::Machine& m, std::optional<scenario::Scenario>& sc, double) {
        for (const runner::StudyJob& j : tries) {
          std::optional<scenario::Scenario> copy = sc;
          add_problem(problems,
                      apply_conveyor(s, j, copy && copy->conveyor ? &*copy->conveyor : nullptr));
          if (j.belt_velocity) add_problem(problems, program_belt(s, m, copy, *j.belt_velocity));
        }
      };
      const runner::LoadResult r = runner::load(rs);
      messages += r.messages;
      if (r.thrown) {
        try {
          std::rethrow_exception(r.thrown);
        } catch (const std::exception& e) {
          messages += std::string("ncsim: error: study: ") + e.what() + "\n";
        }
      }
      loads = loads && r.ok();
    }
  }
  for (const AxisProblem& p : problems)
    messages += study_error(s, p.loc, kStudyAxisId, p.text);
  return loads && problems.empty();
}

}  // namespace ncsim::cli
