#include "scenario/loader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <initializer_list>
#include <limits>
#include <string_view>
#include <utility>

#include "core/limits.hpp"
#include "core/number_text.hpp"
#include "scenario/loader_detail.hpp"

namespace ncsim::scenario {
namespace detail {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return out;
}

// "; did you mean `x`?" for the closest candidate within two edits (case ignored); else "".
std::string suggestion(std::string_view word, std::initializer_list<std::string_view> known) {
  std::string_view best;
  std::size_t best_distance = 3;
  const std::string w = upper(word);
  for (const std::string_view k : known) {
    const std::size_t d = core::edit_distance(w, upper(k));
    if (d < best_distance) {
      best = k;
      best_distance = d;
    }
  }
  return best.empty() ? "" : "; did you mean `" + std::string(best) + "`?";
}

std::string_view type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a floating-point number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time of day";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

// A V.E. or axis name: a letter or '_', then letters, digits, '_' (the NC language's names).
bool is_name(std::string_view s) {
  if (s.empty()) return false;
  const auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); };
  if (!letter(s[0]) && s[0] != '_') return false;
  return std::all_of(s.begin(), s.end(),
                     [&](char c) { return letter(c) || (c >= '0' && c <= '9') || c == '_'; });
}

// The last line of a file: a final line end does not start another line.
std::uint32_t last_line(const core::SourceFile& file) {
  const std::uint32_t n = file.line_count();
  const std::string_view text = file.text();
  return !text.empty() && text.back() == '\n' && n > 1 ? n - 1 : n;
}

// True when a program line holds no block at all: blank, a `;` comment, or one `( ... )`
// comment (such a line never starts executing, so a trigger on it never fires).
bool holds_no_block(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return true;
  const auto last = text.find_last_not_of(" \t\r");
  const std::string_view t = text.substr(first, last - first + 1);
  if (t.front() == ';') return true;
  return t.front() == '(' && t.back() == ')' && t.find(')') == t.size() - 1;
}

// The number text a user wrote (integers without ".0").
std::string value_text(double v) {
  return core::number_text(v);
}

std::optional<toml::table> parse_toml(const core::SourceFile& file, core::DiagnosticList& diags) {
  try {
    return toml::parse(file.text(), file.name());
  } catch (const toml::parse_error& e) {
    core::Diagnostic d;
    d.file = file.name();
    d.loc = core::SourceLoc{e.source().begin.line, e.source().begin.column};
    d.id = kSyntax;
    d.message = "TOML syntax: " + std::string(e.description());
    diags.add(std::move(d));
    return std::nullopt;
  }
}

void add_unreadable(const std::filesystem::path& path, std::string_view what,
                    const std::exception& e, core::DiagnosticList& diags) {
  core::Diagnostic d;
  d.file = path.string();
  d.id = kUnreadable;
  d.message = "cannot read the " + std::string(what) + ": " + e.what();
  diags.add(std::move(d));
}

}  // namespace detail

namespace {

using namespace detail;

// Tables an earlier docs/scenario.md reserved for conveyor tracking; [conveyor] holds them now.
constexpr std::string_view kOldConveyorTables[] = {"belt", "workpiece", "probe", "filter"};

// Reads one file's tables into a Scenario, reporting every problem.
class Reader : public ReaderBase {
 public:
  using ReaderBase::ReaderBase;

  Scenario read(const toml::table& root) {
    Scenario s;
    s.file = file_.name();
    for (auto&& [key, node] : root) {
      key_ = key.source();
      const std::string name(key.str());
      if (name == "description") {
        if (auto v = text(node, name)) s.description = std::move(*v);
      } else if (name == "ve") {
        read_ve(node, s);
      } else if (name == "event") {
        read_events(node, s);
      } else if (name == "stop") {
        read_stop(node, s);
      } else if (name == "tech") {
        read_tech(node, s);
      } else if (name == "conveyor") {
        read_conveyor(*this, node, s);
        if (context_.conveyor_axis == false) {
          // Not an error: one scenario may serve a program on several machines; but never
          // silent (issue 34 item 14).
          core::Diagnostic d;
          d.severity = core::Severity::warning;
          d.file = file_.name();
          d.loc = loc(key.source());
          d.id = kNoConveyorAxis;
          d.message =
              "[conveyor] is not played: the machine has no conveyor axis (FCT_DLM, "
              "conv_sync.is_master; docs/conveyor.md)";
          diags_.add(std::move(d));
          s.conveyor.reset();
        }
      } else if (std::find(std::begin(kOldConveyorTables), std::end(kOldConveyorTables), name) !=
                 std::end(kOldConveyorTables)) {
        error(kUnknownKey, key.source(),
              "unknown key `" + name +
                  "`: the belt, its sensor and the workpieces are the [conveyor] table "
                  "(docs/scenario.md \"[conveyor]\")");
      } else {
        error(kUnknownKey, key.source(),
              "unknown key `" + name + "`" +
                  suggestion(name, {"description", "ve", "event", "stop", "conveyor", "tech"}));
      }
    }
    return s;
  }

 private:
  std::optional<std::uint32_t> line_number(const toml::node& node, const std::string& path) {
    const auto v = integer(node, path, 1, kLineMax);
    if (!v) return std::nullopt;
    const auto line = static_cast<std::uint32_t>(*v);
    if (context_.program != nullptr && line > last_line(*context_.program)) {
      error(kLineBeyond, node.source(),
            path + " = " + std::to_string(line) + " is beyond the last line (" +
                std::to_string(last_line(*context_.program)) + ") of " + context_.program->name());
      return std::nullopt;
    }
    if (context_.program != nullptr && holds_no_block(context_.program->line_text(line))) {
      core::Diagnostic d;
      d.severity = core::Severity::warning;
      d.file = file_.name();
      d.loc = loc(node.source());
      d.id = kLineEmpty;
      d.message = path + " = " + std::to_string(line) + ": line " + std::to_string(line) + " of " +
                  context_.program->name() +
                  " holds no block (blank or a comment): it never starts, so this never fires";
      diags_.add(std::move(d));
    }
    return line;
  }

  void read_ve(const toml::node& node, Scenario& s) {
    read_named(node, "ve", false, [&](const std::string& name, double v, const auto& at) {
      s.ve.push_back(VeInitial{name, v, loc(at)});
    });
  }

  // [tech] M6 = 4.5: names M<n> / H<n> (n 0 .. 999), S, T; seconds 0 .. 86400.
  void read_tech(const toml::node& node, Scenario& s) {
    read_named(node, "tech", false, [&](const std::string& name, double v, const auto& at) {
      TechDuration d;
      d.kind = name[0];
      d.seconds = v;
      const std::string digits = name.substr(1);
      const bool numbered = d.kind == 'M' || d.kind == 'H';
      const bool digits_ok = !digits.empty() && digits.size() <= 3 &&
                             digits.find_first_not_of("0123456789") == std::string::npos;
      if (numbered ? !digits_ok : !(name == "S" || name == "T")) {
        error(
            kName, at,
            "tech." + name + ": name a technology function: M<n> or H<n> with n 0 .. 999, S or T");
        return;
      }
      if (numbered) d.number = static_cast<std::uint32_t>(std::stoul(digits));
      if (!(v >= 0.0 && v <= core::kLongestTime)) {
        error(kRange, at, "tech." + name + " = " + value_text(v) + " s is outside 0 .. 86400 s");
        return;
      }
      s.tech.push_back(d);
    });
  }

  void read_events(const toml::node& node, Scenario& s) {
    const toml::array* list = node.as_array();
    if (list == nullptr) {
      wrong_type(node, "event", "an array of tables ([[event]])");
      return;
    }
    std::optional<double> last_at;  // [s] of the last event with `at`
    std::uint32_t last_at_line = 0;
    std::string last_at_path;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const toml::node& item = *list->get(i);
      const std::string path = "event[" + std::to_string(i + 1) + "]";
      const toml::table* t = item.as_table();
      if (t == nullptr) {
        wrong_type(item, path, "a table ([[event]])");
        continue;
      }
      std::optional<Event> e = read_event(*t, path);
      if (!e) continue;
      if (const auto* at = std::get_if<AtTime>(&e->trigger)) {
        const toml::node* at_node = t->get("at");
        if (last_at && at->t < *last_at) {
          error(kOrder, at_node->source(),
                path + ".at = " + value_text(at->t) + " s comes before " + last_at_path +
                    ".at = " + value_text(*last_at) + " s (line " + std::to_string(last_at_line) +
                    "): events with `at` must be in time order");
        }
        last_at = at->t;
        last_at_line = at_node->source().begin.line;
        last_at_path = path;
      }
      s.events.push_back(std::move(*e));
    }
  }

  std::optional<Event> read_event(const toml::table& t, const std::string& path) {
    Event e;
    e.loc = loc(t.source());
    const std::size_t errors_before = diags_.error_count();
    std::optional<double> at;
    std::optional<std::uint32_t> line;
    std::optional<std::uint32_t> pass;
    std::optional<double> path_override;
    std::vector<Action> axis_overrides;
    std::optional<bool> feed_hold;
    std::optional<double> duration;
    std::vector<Action> ve_writes;
    std::optional<bool> reduced_filter;
    const toml::node* duration_node = nullptr;
    const toml::node* pass_node = nullptr;
    bool unknown_key = false;  // a misspelt trigger or action: no "missing" error besides
    for (auto&& [key, node] : t) {
      key_ = key.source();
      const std::string name(key.str());
      const std::string item = path + "." + name;
      if (name == "at") {
        at = number(node, item, 0.0, kTimeMax, "s");
      } else if (name == "line") {
        line = line_number(node, item);
      } else if (name == "pass") {
        pass_node = &node;
        if (const auto v = integer(node, item, 1, kLineMax)) pass = static_cast<std::uint32_t>(*v);
      } else if (name == "override") {
        if (const auto v = percent(node, item)) {
          path_override = *v / 100.0;
          if (context_.path_override_max && *path_override > *context_.path_override_max) {
            error(kOverrideBeyondType, node.source(),
                  item + " = " + value_text(*v) + " % is above " +
                      value_text(*context_.path_override_max * 100.0) +
                      " %, the largest of the machine's path override type (NCSIM-CHAN-630 "
                      "ncsim.path_override_type; only REDUCED_ABOVE_100 goes beyond)");
          }
        }
      } else if (name == "axis_override") {
        read_named(node, item, true, [&](const std::string& axis, double v, const auto& at_key) {
          if (context_.axes && std::find(context_.axes->begin(), context_.axes->end(), axis) ==
                                   context_.axes->end()) {
            std::string names;
            for (const std::string& a : *context_.axes)
              names += (names.empty() ? "" : ", ") + a;
            error(
                kUnknownAxis, at_key,
                item + "." + axis + ": the machine has no axis " + axis + " (axes: " + names + ")");
            return;
          }
          if (context_.axis_override_max && v > *context_.axis_override_max) {
            error(kIndpOverride, at_key,
                  item + "." + axis + " = " + value_text(v * 100.0) + " % is above " +
                      value_text(*context_.axis_override_max * 100.0) +
                      " %, the largest an INDP axis accepts (002 2.2)");
            return;
          }
          if (context_.path_axes &&
              std::find(context_.path_axes->begin(), context_.path_axes->end(), axis) !=
                  context_.path_axes->end()) {
            core::Diagnostic d;
            d.severity = core::Severity::warning;
            d.file = file_.name();
            d.loc = loc(at_key);
            d.id = kPathAxisOverride;
            d.message = item + "." + axis + ": " + axis +
                        " is a path axis: an axis override acts on its INDP motions only (002 "
                        "2.2), the path's blocks keep the path override (`override`)";
            diags_.add(std::move(d));
          }
          axis_overrides.emplace_back(AxisOverride{axis, v});
        });
      } else if (name == "feed_hold") {
        if (const auto* b = node.as_boolean()) {
          feed_hold = b->get();
        } else {
          wrong_type(node, item, "a boolean (true: hold, false: release)");
        }
      } else if (name == "duration") {
        duration_node = &node;
        const auto v = number(node, item, 0.0, kTimeMax, "s");
        if (v && *v <= 0.0) {
          error(kRange, node.source(), item + " = 0 s: a hold lasts longer than 0 s");
        } else {
          duration = v;
        }
      } else if (name == "ve") {
        read_named(node, item, false, [&](const std::string& ve, double v, const auto&) {
          ve_writes.emplace_back(VeWrite{ve, v});
        });
      } else if (name == "reduced_filter") {
        if (const auto* b = node.as_boolean()) {
          reduced_filter = b->get();
          if (!context_.conveyor_wired) {
            error(kConveyor, key.source(),
                  "not supported: " + item +
                      " (MCV_SetReducedFilter): the channel loop does not play the conveyor "
                      "yet (docs/conveyor.md)");
          }
        } else {
          wrong_type(node, item, "a boolean (true: reduced filter, false: normal filter)");
        }
      } else {
        unknown_key = true;
        error(kUnknownKey, key.source(),
              "unknown key `" + item + "`" +
                  suggestion(name, {"at", "line", "pass", "override", "axis_override", "feed_hold",
                                    "duration", "ve", "reduced_filter"}));
      }
    }
    // Combinations, reported at the event's first key.
    const bool has_at = t.contains("at");
    const bool has_line = t.contains("line");
    if (!has_at && !has_line && !unknown_key) {
      error(kCombination, e.loc, path + " has no trigger: give `at` (s) or `line`");
    } else if (has_at && has_line) {
      error(kCombination, e.loc, path + " has both `at` and `line`: give one trigger");
    }
    if (pass_node != nullptr && !has_line) {
      error(kCombination, pass_node->source(), path + ".pass counts passes of a `line`: give one");
    }
    if (duration_node != nullptr && !(feed_hold && *feed_hold)) {
      error(kCombination, duration_node->source(),
            path + ".duration is how long a feed hold lasts: it needs feed_hold = true");
    }
    const bool has_action = t.contains("override") || t.contains("axis_override") ||
                            t.contains("feed_hold") || t.contains("ve") ||
                            t.contains("reduced_filter");
    if (!has_action && !unknown_key) {
      error(kCombination, e.loc,
            path + " does nothing: give override, axis_override, feed_hold, ve or reduced_filter");
    }
    if (diags_.error_count() != errors_before) return std::nullopt;

    if (at) {
      e.trigger = AtTime{*at};
    } else {
      e.trigger = AtLine{*line, pass.value_or(1)};
    }
    // Documented order: path override, axis overrides (by name), feed hold, V.E. writes,
    // reduced filter.
    if (path_override) e.actions.emplace_back(PathOverride{*path_override});
    e.actions.insert(e.actions.end(), axis_overrides.begin(), axis_overrides.end());
    if (feed_hold) e.actions.emplace_back(FeedHold{*feed_hold});
    e.actions.insert(e.actions.end(), ve_writes.begin(), ve_writes.end());
    if (reduced_filter) e.actions.emplace_back(ReducedFilter{*reduced_filter});
    e.hold_release = duration;
    return e;
  }

  void read_stop(const toml::node& node, Scenario& s) {
    const toml::table* t = node.as_table();
    if (t == nullptr) {
      wrong_type(node, "stop", "a table ([stop])");
      return;
    }
    StopConditions& c = s.stop;
    c.loc = loc(t->source().begin.line != 0 ? t->source() : key_);
    for (auto&& [key, value] : *t) {
      key_ = key.source();
      const std::string name(key.str());
      const std::string item = "stop." + name;
      if (name == "time") {
        const auto v = number(value, item, 0.0, kTimeMax, "s");
        if (v && *v <= 0.0) {
          error(kRange, value.source(), item + " = 0 s: the program would not start");
        } else {
          c.time = v;
        }
      } else if (name == "cycles") {
        c.cycles = integer(value, item, 1, kCyclesMax);
      } else if (name == "line") {
        c.line = line_number(value, item);
      } else if (name == "passes") {
        if (const auto v = integer(value, item, 1, kLineMax)) {
          c.passes = static_cast<std::uint32_t>(*v);
        }
      } else {
        error(
            kUnknownKey, key.source(),
            "unknown key `" + item + "`" + suggestion(name, {"time", "cycles", "line", "passes"}));
      }
    }
    if (t->contains("line") != t->contains("passes")) {
      error(kCombination, c.loc,
            "stop: `line` and `passes` go together (stop when the n-th pass of a line ends)");
      c.line.reset();
      c.passes.reset();
    }
  }
};

}  // namespace

std::string_view to_string(StopReason reason) {
  switch (reason) {
    case StopReason::program_end:
      return "program end";
    case StopReason::error:
      return "error";
    case StopReason::time:
      return "stop.time";
    case StopReason::cycles:
      return "stop.cycles";
    case StopReason::line_passes:
      return "stop.passes";
    case StopReason::endless:
      return "endless";
  }
  return "?";
}

std::optional<double> Scenario::ve_initial(std::string_view name) const {
  for (const VeInitial& v : ve) {
    if (v.name == name) return v.value;
  }
  return std::nullopt;
}

LoadResult parse_scenario(const core::SourceFile& file, const Context& context) {
  LoadResult result;
  if (file.text().size() > kMaxScenarioBytes) {
    core::Diagnostic d;
    d.file = file.name();
    d.id = kUnreadable;
    d.message = "the scenario has " + std::to_string(file.text().size()) +
                " bytes; a scenario file holds at most " + std::to_string(kMaxScenarioBytes) +
                " (is it the right file?)";
    result.diagnostics.add(std::move(d));
    return result;
  }
  const std::optional<toml::table> root = parse_toml(file, result.diagnostics);
  if (!root) return result;
  Reader reader(file, context, result.diagnostics);
  Scenario s = reader.read(*root);
  result.diagnostics.sort_by_position();
  if (!result.diagnostics.has_errors()) result.scenario = std::move(s);
  return result;
}

LoadResult load_scenario(const std::filesystem::path& path, const Context& context) {
  try {
    // No pipe or device (an open that waits, a read that never ends); the size is NC7010's.
    const core::SourceFile file =
        core::SourceFile::load_regular(path, std::numeric_limits<std::size_t>::max());
    return parse_scenario(file, context);
  } catch (const std::exception& e) {
    LoadResult result;
    add_unreadable(path, "scenario", e, result.diagnostics);
    return result;
  }
}

}  // namespace ncsim::scenario
