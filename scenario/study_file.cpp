#include "scenario/study_file.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <exception>
#include <limits>
#include <utility>

#include "scenario/loader_detail.hpp"

namespace ncsim::scenario {
namespace {

using namespace detail;

constexpr const char* kStudyUnknownKey = "NC7201";
constexpr const char* kStudyBase = "NC7202";
constexpr const char* kStudyDuplicate = "NC7203";
constexpr const char* kStudyTooMany = "NC7204";
constexpr std::int64_t kCycleUsMax = 1'000'000;  // [us] as a line file's cycle_us
constexpr double kBeltVelocityMax = 1e6;         // [mm/s] as the scenario's belt velocity
constexpr double kPitchMax = 1e6;                // [mm] 1 km between front edges
constexpr std::int64_t kSeedMax = std::numeric_limits<std::int64_t>::max();

// One numeric axis's limits: values in [lo, hi], strictly above lo when `above`.
struct Limits {
  double lo;
  double hi;
  bool above;
  const char* unit;
};

// Reads a study file's tables, reporting every problem.
class StudyReader : public ReaderBase {
 public:
  using ReaderBase::ReaderBase;

  StudyFile read(const toml::table& root) {
    StudyFile s;
    s.file = file_.name();
    s.vary_loc = core::SourceLoc{1, 1};
    for (auto&& [key, node] : root) {
      key_ = key.source();
      const std::string name(key.str());
      if (name == "description") {
        if (auto v = text(node, name)) s.description = std::move(*v);
      } else if (name == "line") {
        s.line = path(node, name);
      } else if (name == "program") {
        s.program = path(node, name);
      } else if (name == "machine") {
        s.machine = path(node, name);
      } else if (name == "scenario") {
        s.scenario = path(node, name);
      } else if (name == "cycle_us") {
        s.cycle_us = integer(node, name, 1, kCycleUsMax);
      } else if (name == "max_time") {
        s.max_time = number(node, name, 0.0, kTimeMax, "s");
        if (s.max_time && *s.max_time <= 0.0) {
          error(kRange, node.source(), "max_time = 0 s: give a time > 0 s");
          s.max_time.reset();
        }
      } else if (name == "audit") {
        if (const auto* b = node.as_boolean()) {
          s.audit = b->get();
        } else {
          wrong_type(node, name, "a boolean");
        }
      } else if (name == "vary") {
        read_vary(node, s);
      } else {
        error(kStudyUnknownKey, key.source(),
              "unknown key `" + name + "`" +
                  suggestion(name, {"description", "line", "program", "machine", "scenario",
                                    "cycle_us", "max_time", "audit", "vary"}));
      }
    }
    check_base(root, s);
    return s;
  }

 private:
  std::optional<StudyPath> path(const toml::node& node, const std::string& item) {
    const auto v = text(node, item, "a string (a path relative to the study file)");
    if (!v) return std::nullopt;
    if (v->empty()) {
      error(kRange, node.source(), item + " is empty: give a path");
      return std::nullopt;
    }
    return StudyPath{*v, loc(node.source())};
  }

  void read_vary(const toml::node& node, StudyFile& s) {
    const toml::table* t = node.as_table();
    if (t == nullptr) {
      wrong_type(node, "vary", "a table ([vary])");
      return;
    }
    s.vary_loc = loc(t->source());
    for (auto&& [key, value] : *t) {
      key_ = key.source();
      const std::string name(key.str());
      const std::string item = "vary." + name;
      if (name == "program") {
        read_paths(value, item, s.programs);
      } else if (name == "machine") {
        read_paths(value, item, s.machines);
      } else if (name == "belt_velocity") {
        read_numbers(value, item, Limits{0.0, kBeltVelocityMax, true, "mm/s"}, s.belt_velocity);
      } else if (name == "pitch") {
        read_numbers(value, item, Limits{0.0, kPitchMax, true, "mm"}, s.pitch);
      } else if (name == "fluctuation") {
        read_numbers(value, item, Limits{0.0, 100.0, false, "%"}, s.fluctuation);
      } else if (name == "seed") {
        read_seeds(value, item, s.seed);
      } else {
        error(kStudyUnknownKey, key.source(),
              "unknown key `" + item + "`" +
                  suggestion(name, {"program", "machine", "belt_velocity", "pitch", "fluctuation",
                                    "seed"}));
        continue;
      }
    }
  }

  void read_paths(const toml::node& node, const std::string& item, StudyAxis<StudyPath>& axis) {
    axis.loc = loc(key_);
    const toml::array* list = node.as_array();
    if (list == nullptr || list->empty()) {
      wrong_type(node, item, "a non-empty array of strings (paths relative to the study file)");
      return;
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string at = item + "[" + std::to_string(i + 1) + "]";
      auto p = path(*list->get(i), at);
      if (!p) continue;
      bool seen = false;
      for (const StudyPath& o : axis.values)
        seen = seen || o.text == p->text;
      if (seen) {
        error(kStudyDuplicate, list->get(i)->source(),
              at + " = \"" + p->text + "\" is given twice: each value once (one job each)");
        continue;
      }
      axis.values.push_back(std::move(*p));
    }
    size_check(node, item, list->size());
  }

  void size_check(const toml::node& node, const std::string& item, std::size_t n) {
    if (n > kStudyAxisValuesMax)
      error(kRange, node.source(),
            item + " has " + std::to_string(n) + " values; at most " +
                std::to_string(kStudyAxisValuesMax));
  }

  std::optional<double> one_number(const toml::node& node, const std::string& at, const Limits& l) {
    const auto v = number(node, at, l.lo, l.hi, l.unit);
    if (v && l.above && *v <= l.lo) {
      error(kRange, node.source(),
            at + " = " + value_text(*v) + " " + l.unit + " must be > " + value_text(l.lo) + " " +
                l.unit);
      return std::nullopt;
    }
    return v;
  }

  // A list of numbers, or a range { from, to, step } (step > 0; from, from + step, ... <= to).
  void read_numbers(const toml::node& node, const std::string& item, const Limits& l,
                    StudyAxis<double>& axis) {
    axis.loc = loc(key_);
    if (const toml::table* range = node.as_table()) {
      read_range(*range, item, l, axis);
      return;
    }
    const toml::array* list = node.as_array();
    if (list == nullptr || list->empty()) {
      wrong_type(node, item,
                 "a non-empty array of numbers or a range { from = .., to = .., step = .. }");
      return;
    }
    size_check(node, item, list->size());
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string at = item + "[" + std::to_string(i + 1) + "]";
      const auto v = one_number(*list->get(i), at, l);
      if (!v) continue;
      if (std::find(axis.values.begin(), axis.values.end(), *v) != axis.values.end()) {
        error(kStudyDuplicate, list->get(i)->source(),
              at + " = " + value_text(*v) + " is given twice: each value once (one job each)");
        continue;
      }
      axis.values.push_back(*v);
    }
  }

  void read_range(const toml::table& range, const std::string& item, const Limits& l,
                  StudyAxis<double>& axis) {
    std::optional<double> from;
    std::optional<double> to;
    double step = 0.0;  // 0: not given or refused (an optional tripped g++ 12's -O3 flow check)
    for (auto&& [key, value] : range) {
      key_ = key.source();
      const std::string name(key.str());
      const std::string at = item + "." + name;
      if (name == "from") {
        from = one_number(value, at, l);
      } else if (name == "to") {
        to = one_number(value, at, l);
      } else if (name == "step") {
        const auto v = number(value, at, 0.0, l.hi, l.unit);
        if (v && *v <= 0.0) error(kRange, value.source(), at + " = 0: give a step > 0");
        if (v && *v > 0.0) step = *v;
      } else {
        error(kStudyUnknownKey, key.source(),
              "unknown key `" + at + "`" + suggestion(name, {"from", "to", "step"}));
      }
    }
    const core::SourceLoc at = loc(range.source());
    for (const char* k : {"from", "to", "step"})
      if (!range.contains(k))
        error(kStudyBase, at, item + " has no `" + k + "` (a range is { from, to, step })");
    if (!from || !to || step <= 0.0) return;
    const double lo = *from;
    const double hi = *to;
    const double d = step;
    if (hi < lo) {
      error(kRange, at, item + ": to = " + value_text(hi) + " is below from = " + value_text(lo));
      return;
    }
    // The values are from + k step (not accumulated), up to `to` within a millionth of a step.
    const double n = std::floor((hi - lo) / d + 1e-6) + 1.0;
    if (n > static_cast<double>(kStudyAxisValuesMax)) {
      error(kRange, at,
            item + " spans " + value_text(n) + " values; at most " +
                std::to_string(kStudyAxisValuesMax));
      return;
    }
    for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k)
      axis.values.push_back(lo + static_cast<double>(k) * d);
  }

  // Seeds: a list of integers or a range { from, to } (every integer between, both included).
  void read_seeds(const toml::node& node, const std::string& item, StudyAxis<std::uint64_t>& axis) {
    axis.loc = loc(key_);
    if (const toml::table* range = node.as_table()) {
      std::optional<std::uint64_t> from;
      std::optional<std::uint64_t> to;
      for (auto&& [key, value] : *range) {
        key_ = key.source();
        const std::string name(key.str());
        if (name == "from") {
          from = integer(value, item + ".from", 0, kSeedMax);
        } else if (name == "to") {
          to = integer(value, item + ".to", 0, kSeedMax);
        } else {
          error(kStudyUnknownKey, key.source(),
                "unknown key `" + item + "." + name + "`" + suggestion(name, {"from", "to"}));
        }
      }
      const core::SourceLoc at = loc(range->source());
      for (const char* k : {"from", "to"})
        if (!range->contains(k))
          error(kStudyBase, at, item + " has no `" + k + "` (a range of seeds is { from, to })");
      if (!from || !to) return;
      if (*to < *from || *to - *from >= kStudyAxisValuesMax) {
        error(kRange, at,
              item + " = { from = " + std::to_string(*from) + ", to = " + std::to_string(*to) +
                  " }: give from <= to and at most " + std::to_string(kStudyAxisValuesMax) +
                  " seeds");
        return;
      }
      for (std::uint64_t v = *from; v <= *to; ++v)
        axis.values.push_back(v);
      return;
    }
    const toml::array* list = node.as_array();
    if (list == nullptr || list->empty()) {
      wrong_type(node, item, "a non-empty array of integers or a range { from = .., to = .. }");
      return;
    }
    size_check(node, item, list->size());
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string at = item + "[" + std::to_string(i + 1) + "]";
      const auto v = integer(*list->get(i), at, 0, kSeedMax);
      if (!v) continue;
      if (std::find(axis.values.begin(), axis.values.end(), *v) != axis.values.end()) {
        error(kStudyDuplicate, list->get(i)->source(),
              at + " = " + std::to_string(*v) + " is given twice: each value once (one job each)");
        continue;
      }
      axis.values.push_back(*v);
    }
  }

  // Exactly one base: a line, or a program (`program` or `vary.program`); machine and scenario
  // belong to a program base; the product of the axes is at most kStudyJobsMax.
  void check_base(const toml::table& root, const StudyFile& s) {
    const bool programs = root.contains("vary") && root["vary"].as_table() != nullptr &&
                          root["vary"].as_table()->contains("program");
    const bool program = root.contains("program") || programs;
    if (root.contains("line") && program) {
      const core::SourceLoc at = s.line ? s.line->loc : core::SourceLoc{1, 1};
      error(kStudyBase, at,
            "a study has one base: `line` (a line file) or `program` / `vary.program`, not both");
    } else if (!root.contains("line") && !program) {
      error(kStudyBase, core::SourceLoc{1, 1},
            "the study has no base: give `line = \"LINE.toml\"` or `program = \"PROG.nc\"` (or "
            "`vary.program`)");
    }
    if (root.contains("program") && programs)
      error(kStudyBase, s.programs.loc,
            "vary.program and `program` both given: the varied programs are the base");
    const bool machines = root.contains("vary") && root["vary"].as_table() != nullptr &&
                          root["vary"].as_table()->contains("machine");
    if (root.contains("machine") && machines)
      error(kStudyBase, s.machines.loc,
            "vary.machine and `machine` both given: the varied machines are the base's");
    if (root.contains("line")) {
      const auto only_program = [&](bool given, core::SourceLoc at, const char* key) {
        if (given)
          error(kStudyBase, at,
                std::string(key) +
                    " belongs to a program base: a line file names its channels' programs, "
                    "machines and scenarios");
      };
      only_program(s.machine.has_value(), s.machine ? s.machine->loc : core::SourceLoc{1, 1},
                   "machine");
      only_program(s.scenario.has_value(), s.scenario ? s.scenario->loc : core::SourceLoc{1, 1},
                   "scenario");
      only_program(machines, s.machines.loc, "vary.machine");
    }
    double jobs = 1.0;
    const auto count = [&](std::size_t n) {
      jobs *= static_cast<double>(std::max<std::size_t>(n, 1));
    };
    count(s.programs.values.size());
    count(s.machines.values.size());
    count(s.belt_velocity.values.size());
    count(s.pitch.values.size());
    count(s.fluctuation.values.size());
    count(s.seed.values.size());
    if (jobs > static_cast<double>(kStudyJobsMax))
      error(kStudyTooMany, s.vary_loc,
            "the study has " + value_text(jobs) + " jobs; at most " +
                std::to_string(kStudyJobsMax) + " (split it into several studies)");
  }
};

}  // namespace

std::filesystem::path StudyFile::resolved(const StudyPath& path) const {
  const std::filesystem::path p(path.text);
  if (p.is_absolute()) return p;
  return (std::filesystem::path(file).parent_path() / p).lexically_normal();
}

StudyLoad parse_study(const core::SourceFile& file) {
  StudyLoad result;
  const std::optional<toml::table> root = parse_toml(file, result.diagnostics);
  if (!root) return result;
  Context context;
  StudyReader reader(file, context, result.diagnostics);
  StudyFile study = reader.read(*root);
  result.diagnostics.sort_by_position();
  if (!result.diagnostics.has_errors()) result.study = std::move(study);
  return result;
}

StudyLoad load_study(const std::filesystem::path& path) {
  try {
    const core::SourceFile file = core::SourceFile::load_regular(path, kMaxScenarioBytes);
    return parse_study(file);
  } catch (const std::exception& e) {
    StudyLoad result;
    add_unreadable(path, "study file", e, result.diagnostics);
    return result;
  }
}

}  // namespace ncsim::scenario
