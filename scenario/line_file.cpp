#include "scenario/line_file.hpp"

#include <toml++/toml.h>

#include <exception>
#include <limits>
#include <utility>

#include "scenario/loader_detail.hpp"

namespace ncsim::scenario {
namespace {

using namespace detail;

constexpr const char* kLineUnknownKey = "NC7101";
constexpr const char* kLineMissing = "NC7102";
constexpr const char* kLineDuplicate = "NC7103";
constexpr const char* kLineNoChannel = "NC7104";
constexpr const char* kLineSensorPosition = "NC7110";
constexpr std::int64_t kCycleUsMax = 1'000'000;  // [us] 1 s: the longest cycle a line takes
constexpr double kBeltMax = 1e6;                 // [mm] 1 km: sensor_at and belt_end

// Reads a line file's tables, reporting every problem.
class LineReader : public ReaderBase {
 public:
  using ReaderBase::ReaderBase;

  LineFile read(const toml::table& root) {
    LineFile line;
    line.file = file_.name();
    for (auto&& [key, node] : root) {
      key_ = key.source();
      const std::string name(key.str());
      if (name == "description") {
        if (auto v = text(node, name)) line.description = std::move(*v);
      } else if (name == "cycle_us") {
        line.cycle_us = integer(node, name, 1, kCycleUsMax);
        line.cycle_loc = loc(node.source());
      } else if (name == "channel") {
        read_channels(node, line);
      } else if (name == "belt_end") {
        line.belt_end = number(node, name, 0.0, kBeltMax, "mm");
        line.belt_end_loc = loc(node.source());
      } else if (name == "conveyor") {
        Scenario s;
        read_conveyor(*this, node, s);
        line.conveyor = std::move(s.conveyor);
      } else {
        error(kLineUnknownKey, key.source(),
              "unknown key `" + name + "`" +
                  suggestion(name, {"description", "cycle_us", "channel", "conveyor", "belt_end"}));
      }
    }
    if (line.belt_end)
      for (const LineChannel& c : line.channels)
        if (c.sensor_at > *line.belt_end)
          error(kRange, line.belt_end_loc,
                "belt_end = " + value_text(*line.belt_end) +
                    " mm is before the sensor of channel " + std::to_string(c.number) +
                    " (sensor_at = " + value_text(c.sensor_at) +
                    " mm): the belt ends after the last sensor");
    if (line.conveyor && line.conveyor->sensor.position)
      error(kLineSensorPosition, line.conveyor->loc,
            "conveyor.sensor.position is not played in a line: each channel's sensor is its "
            "own, at its T0 (P-CHAN-00368) in its machine and at its `sensor_at` along the belt "
            "(docs/lines.md)");
    if (!root.contains("channel"))
      error(kLineNoChannel, core::SourceLoc{1, 1},
            "the line has no channel: give one [[channel]] table per channel");
    return line;
  }

 private:
  std::optional<LinePath> path(const toml::node& node, const std::string& item) {
    const auto v = text(node, item, "a string (a path relative to the line file)");
    if (!v) return std::nullopt;
    if (v->empty()) {
      error(kRange, node.source(), item + " is empty: give a path");
      return std::nullopt;
    }
    return LinePath{*v, loc(node.source())};
  }

  void read_channels(const toml::node& node, LineFile& line) {
    const toml::array* list = node.as_array();
    if (list == nullptr) {
      wrong_type(node, "channel", "an array of tables ([[channel]])");
      return;
    }
    if (list->size() > kLineChannelsMax)
      error(kRange, node.source(),
            "the line has " + std::to_string(list->size()) + " channels; at most " +
                std::to_string(kLineChannelsMax));
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string item = "channel[" + std::to_string(i + 1) + "]";
      const toml::table* t = list->get(i)->as_table();
      if (t == nullptr) {
        wrong_type(*list->get(i), item, "a table ([[channel]])");
        continue;
      }
      if (std::optional<LineChannel> c = read_channel(*t, item, line)) line.channels.push_back(*c);
    }
  }

  std::optional<LineChannel> read_channel(const toml::table& t, const std::string& item,
                                          const LineFile& line) {
    LineChannel c;
    c.loc = loc(t.source());
    const std::size_t errors_before = diags_.error_count();
    std::optional<LinePath> program;
    std::optional<LinePath> machine;
    bool numbered = false;
    for (auto&& [key, node] : t) {
      key_ = key.source();
      const std::string name(key.str());
      const std::string path_name = item + "." + name;
      if (name == "number") {
        if (const auto v = integer(node, path_name, 1, kLineChannelsMax)) {
          c.number = static_cast<std::uint8_t>(*v);
          numbered = true;
          for (const LineChannel& o : line.channels)
            if (o.number == c.number)
              error(kLineDuplicate, node.source(),
                    path_name + " = " + std::to_string(c.number) +
                        " is taken by the channel at line " + std::to_string(o.loc.line) +
                        ": channel numbers are unique (CH=..)");
        }
      } else if (name == "name") {
        if (auto v = text(node, path_name)) c.name = std::move(*v);
      } else if (name == "program") {
        program = path(node, path_name);
      } else if (name == "machine") {
        machine = path(node, path_name);
      } else if (name == "scenario") {
        c.scenario = path(node, path_name);
      } else if (name == "sensor_at") {
        if (const auto v = number(node, path_name, 0.0, kBeltMax, "mm")) c.sensor_at = *v;
      } else {
        error(kLineUnknownKey, key.source(),
              "unknown key `" + path_name + "`" +
                  suggestion(name,
                             {"number", "name", "program", "machine", "scenario", "sensor_at"}));
      }
    }
    const auto missing = [&](const char* key, const char* what) {
      error(kLineMissing, c.loc, item + " has no `" + std::string(key) + "` (" + what + ")");
    };
    if (!numbered && !t.contains("number")) missing("number", "its channel number, CH=..");
    if (!t.contains("program")) missing("program", "the NC program it runs");
    if (!t.contains("machine")) missing("machine", "its machine folder");
    if (diags_.error_count() != errors_before) return std::nullopt;
    c.program = *program;
    c.machine = *machine;
    if (c.name.empty()) c.name = "channel " + std::to_string(c.number);
    return c;
  }
};

}  // namespace

std::filesystem::path LineFile::resolved(const LinePath& path) const {
  const std::filesystem::path p(path.text);
  if (p.is_absolute()) return p;
  return std::filesystem::path(file).parent_path() / p;
}

LineLoad parse_line(const core::SourceFile& file) {
  LineLoad result;
  const std::optional<toml::table> root = parse_toml(file, result.diagnostics);
  if (!root) return result;
  Context context;
  context.conveyor_wired = true;  // the line plays its conveyor world
  LineReader reader(file, context, result.diagnostics);
  LineFile line = reader.read(*root);
  result.diagnostics.sort_by_position();
  if (!result.diagnostics.has_errors()) result.line = std::move(line);
  return result;
}

LineLoad load_line(const std::filesystem::path& path) {
  try {
    const core::SourceFile file = core::SourceFile::load_regular(path, kMaxScenarioBytes);
    return parse_line(file);
  } catch (const std::exception& e) {
    LineLoad result;
    add_unreadable(path, "line file", e, result.diagnostics);
    return result;
  }
}

}  // namespace ncsim::scenario
