// scenario/conveyor_loader: reads the `[conveyor]` table of a scenario (docs/scenario.md
// "[conveyor]", docs/conveyor.md "The world"): the belt (encoder or spindle mode, velocity
// profile, fluctuation, noise, dead time), the sensor and the workpieces. Units in the file:
// mm, mm/s, s, Hz; stored the same (the internal units), so nothing is converted but
// percentages. Every problem is reported with file, line, column and key path; ids NC7014..
// NC7049 for the conveyor's own rules (docs/diagnostics.md), the generic ones (NC7002 unknown
// key, NC7003 type, NC7004 range) as for the rest of the file.

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "scenario/loader_detail.hpp"

namespace ncsim::scenario::detail {
namespace {

constexpr const char* kChoice = "NC7014";      // a word outside its set (mode, kind, edge)
constexpr const char* kModeKey = "NC7015";     // a key the other mode owns / a mode missing
constexpr const char* kProfile = "NC7016";     // profile changes out of order or overlapping
constexpr const char* kArrival = "NC7017";     // workpiece arrival: travel xor time, pitch kind
constexpr const char* kWorkpieces = "NC7018";  // workpieces out of order or overlapping

constexpr double kVelocityMax = 1.0e6;   // [mm/s] |belt velocity| (1 km/s: no belt runs faster)
constexpr double kTravelMax = 1.0e12;    // [mm] |belt travel| of an arrival
constexpr double kDeadTimeMax = 10.0;    // [s]
constexpr double kSigmaMax = 1000.0;     // [mm]
constexpr double kFrequencyMax = 1.0e4;  // [Hz]
constexpr double kLengthMax = 1.0e6;     // [mm]
constexpr std::int64_t kCountMax = 1000000000;  // workpieces of a series
constexpr std::int64_t kQueueMax = 4096;        // PLC queue entries
constexpr std::int64_t kSeedMax = std::numeric_limits<std::int64_t>::max();  // 2^63-1

class ConveyorReader {
 public:
  explicit ConveyorReader(ReaderBase& r) : r_(r) {}

  void read(const toml::node& node, Scenario& s) {
    const toml::table* t = node.as_table();
    if (t == nullptr) {
      r_.wrong_type(node, "conveyor", "a table ([conveyor])");
      return;
    }
    Conveyor c;
    c.loc = ReaderBase::loc(t->source().begin.line != 0 ? t->source() : r_.key_);
    const std::size_t errors_before = r_.diags_.error_count();
    const toml::node* velocity_node = nullptr;
    const toml::node* profile_node = nullptr;
    bool mode_given = false;
    for (auto&& [key, value] : *t) {
      r_.key_ = key.source();
      const std::string name(key.str());
      const std::string item = "conveyor." + name;
      if (name == "mode") {
        if (const auto m = word(value, item, {"encoder", "spindle"})) {
          c.mode = *m == "encoder" ? ConveyorMode::encoder : ConveyorMode::spindle;
          mode_given = true;
        }
      } else if (name == "velocity") {
        velocity_node = &value;
        if (const auto v = r_.number(value, item, -kVelocityMax, kVelocityMax, "mm/s"))
          c.velocity = *v;
      } else if (name == "profile") {
        profile_node = &value;
        read_profile(value, item, c);
      } else if (name == "fluctuation") {
        read_fluctuation(value, item, c);
      } else if (name == "noise") {
        read_noise(value, item, c);
      } else if (name == "dead_time") {
        if (const auto v = r_.number(value, item, 0.0, kDeadTimeMax, "s")) c.dead_time = *v;
      } else if (name == "sensor") {
        read_sensor(value, item, c.sensor);
      } else if (name == "workpiece") {
        read_workpiece_list(value, item, c);
      } else if (name == "workpieces") {
        read_series(value, item, c);
      } else {
        r_.error(kUnknownKey, key.source(),
                 "unknown key `" + item + "`" +
                     suggestion(name, {"mode", "velocity", "profile", "fluctuation", "noise",
                                       "dead_time", "sensor", "workpiece", "workpieces"}));
      }
    }
    if (!t->contains("mode")) {
      r_.error(kModeKey, c.loc,
               "conveyor: give `mode = \"encoder\"` (the scenario moves the belt) or `mode = "
               "\"spindle\"` (the program's MC_MoveVelocity drives it)");
    } else if (mode_given && c.mode == ConveyorMode::spindle) {
      for (const toml::node* n : {velocity_node, profile_node}) {
        if (n == nullptr) continue;
        r_.error(kModeKey, n->source(),
                 std::string("conveyor.") + (n == velocity_node ? "velocity" : "profile") +
                     " moves an encoder belt; in mode = \"spindle\" the program's "
                     "MC_MoveVelocity sets the velocity");
      }
    }
    if (r_.diags_.error_count() != errors_before) return;
    if (!r_.context_.conveyor_wired) {
      r_.error(kConveyor, c.loc,
               "not supported: [conveyor] is valid, but the channel loop does not play the "
               "conveyor world yet (docs/conveyor.md)");
      return;
    }
    s.conveyor = std::move(c);
  }

 private:
  // A string among `choices`; NC7014 otherwise.
  std::optional<std::string> word(const toml::node& node, const std::string& path,
                                  std::initializer_list<std::string_view> choices) {
    const auto text = r_.text(node, path);
    if (!text) return std::nullopt;
    const std::string& v = *text;
    std::string list;
    for (const std::string_view c : choices) {
      if (v == c) return v;
      list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
    }
    r_.error(kChoice, node.source(),
             path + " = \"" + v + "\" is not one of " + list + suggestion(v, choices));
    return std::nullopt;
  }

  const toml::table* table(const toml::node& node, const std::string& path) {
    const toml::table* t = node.as_table();
    if (t == nullptr) r_.wrong_type(node, path, "a table");
    return t;
  }

  void unknown(const toml::key& key, const std::string& item,
               std::initializer_list<std::string_view> known) {
    r_.error(kUnknownKey, key.source(),
             "unknown key `" + item + "`" + suggestion(std::string(key.str()), known));
  }

  void read_profile(const toml::node& node, const std::string& path, Conveyor& c) {
    const toml::array* list = node.as_array();
    if (list == nullptr) {
      r_.wrong_type(node, path, "an array of { at, velocity, ramp } tables");
      return;
    }
    double end_of_last = -1.0;  // [s] when the previous change ends
    std::string last_path;
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string item = path + "[" + std::to_string(i + 1) + "]";
      const toml::table* t = table(*list->get(i), item);
      if (t == nullptr) continue;
      BeltChange b;
      bool ok = true;
      for (auto&& [key, value] : *t) {
        r_.key_ = key.source();
        const std::string name(key.str());
        std::optional<double> v;
        if (name == "at") {
          v = r_.number(value, item + ".at", 0.0, kTimeMax, "s");
          if (v) b.t = *v;
        } else if (name == "velocity") {
          v = r_.number(value, item + ".velocity", -kVelocityMax, kVelocityMax, "mm/s");
          if (v) b.velocity = *v;
        } else if (name == "ramp") {
          v = r_.number(value, item + ".ramp", 0.0, kTimeMax, "s");
          if (v) b.ramp = *v;
        } else {
          unknown(key, item + "." + name, {"at", "velocity", "ramp"});
        }
        ok = ok && v.has_value();
      }
      for (const char* need : {"at", "velocity"}) {
        if (!t->contains(need)) {
          r_.error(kProfile, t->source(), item + " needs `" + need + "`");
          ok = false;
        }
      }
      if (!ok) continue;
      if (b.t < end_of_last) {
        r_.error(kProfile, t->get("at")->source(),
                 item + ".at = " + value_text(b.t) + " s starts before " + last_path +
                     " ends (at + ramp = " + value_text(end_of_last) +
                     " s): changes must follow each other in time");
      }
      end_of_last = b.t + b.ramp;
      last_path = item;
      c.profile.push_back(b);
    }
  }

  void read_fluctuation(const toml::node& node, const std::string& path, Conveyor& c) {
    const toml::table* t = table(node, path);
    if (t == nullptr) return;
    BeltFluctuation f;
    bool ok = true;
    for (auto&& [key, value] : *t) {
      r_.key_ = key.source();
      const std::string name(key.str());
      if (name == "amplitude") {
        const auto v = r_.number(value, path + ".amplitude", 0.0, 100.0, "%");
        if (v) f.amplitude = *v / 100.0;
        ok = ok && v.has_value();
      } else if (name == "frequency") {
        const auto v = r_.number(value, path + ".frequency", 0.0, kFrequencyMax, "Hz");
        if (v && *v <= 0.0) {
          r_.error(kRange, value.source(), path + ".frequency = 0 Hz: give a frequency > 0");
          ok = false;
        } else if (v) {
          f.frequency = *v;
        }
        ok = ok && v.has_value();
      } else {
        unknown(key, path + "." + name, {"amplitude", "frequency"});
        ok = false;
      }
    }
    for (const char* need : {"amplitude", "frequency"}) {
      if (!t->contains(need)) {
        r_.error(kRange, t->source(), path + " needs `" + need + "`");
        ok = false;
      }
    }
    if (ok) c.fluctuation = f;
  }

  void read_noise(const toml::node& node, const std::string& path, Conveyor& c) {
    const toml::table* t = table(node, path);
    if (t == nullptr) return;
    BeltNoise n;
    for (auto&& [key, value] : *t) {
      r_.key_ = key.source();
      const std::string name(key.str());
      if (name == "sigma") {
        if (const auto v = r_.number(value, path + ".sigma", 0.0, kSigmaMax, "mm")) n.sigma = *v;
      } else if (name == "seed") {
        if (const auto v = r_.integer(value, path + ".seed", 0, kSeedMax)) n.seed = *v;
      } else {
        unknown(key, path + "." + name, {"sigma", "seed"});
      }
    }
    if (!t->contains("sigma")) r_.error(kRange, t->source(), path + " needs `sigma` (mm)");
    c.noise = n;
  }

  void read_sensor(const toml::node& node, const std::string& path, Sensor& s) {
    const toml::table* t = table(node, path);
    if (t == nullptr) return;
    for (auto&& [key, value] : *t) {
      r_.key_ = key.source();
      const std::string name(key.str());
      const std::string item = path + "." + name;
      if (name == "kind") {
        if (const auto w = word(value, item, {"light_barrier", "camera"}))
          s.kind = *w == "camera" ? SensorKind::camera : SensorKind::light_barrier;
      } else if (name == "position") {
        s.position = r_.number(value, item, -kTravelMax, kTravelMax, "mm");
      } else if (name == "front_edge") {
        if (const auto w = word(value, item, {"rising", "falling"}))
          s.front_edge_rising = *w == "rising";
      } else if (name == "queue") {
        if (const auto v = r_.integer(value, item, 1, kQueueMax))
          s.queue = static_cast<std::uint32_t>(*v);
      } else {
        unknown(key, item, {"kind", "position", "front_edge", "queue"});
      }
    }
    if (s.kind == SensorKind::camera && t->contains("front_edge")) {
      r_.error(kChoice, t->get("front_edge")->source(),
               path +
                   ".front_edge belongs to a light barrier: a camera gives one pulse per "
                   "front edge (both edges there)");
    }
  }

  // A belt travel at which a front edge reaches the sensor: > 0 (the belt starts at 0).
  std::optional<double> arrival_travel(const toml::node& value, const std::string& item) {
    const auto v = r_.number(value, item, 0.0, kTravelMax, "mm");
    if (v && *v <= 0.0) {
      r_.error(kRange, value.source(),
               item +
                   " = 0 mm: the front edge is at the sensor when the belt starts (travel "
                   "0); give the travel > 0 at which it arrives");
      return std::nullopt;
    }
    return v;
  }

  // The keys a workpiece and a series share: length and ve. True when `name` was one.
  bool common_key(const std::string& name, const toml::node& value, const std::string& item,
                  Workpiece& w) {
    if (name == "length") {
      const auto v = r_.number(value, item, 0.0, kLengthMax, "mm");
      if (v && *v <= 0.0) {
        r_.error(kRange, value.source(), item + " = 0 mm: a workpiece has a length > 0");
      } else if (v) {
        w.length = *v;
      }
      return true;
    }
    if (name == "ve") {
      r_.read_named(value, item, false, [&](const std::string& ve, double v, const auto&) {
        w.ve.push_back(VeWrite{ve, v});
      });
      return true;
    }
    return false;
  }

  void read_workpiece_list(const toml::node& node, const std::string& path, Conveyor& c) {
    const toml::array* list = node.as_array();
    if (list == nullptr) {
      r_.wrong_type(node, path, "an array of tables ([[conveyor.workpiece]])");
      return;
    }
    std::optional<Workpiece> last_travel;  // the previous workpiece arriving by travel
    std::optional<Workpiece> last_time;    // ... by time
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string item = path + "[" + std::to_string(i + 1) + "]";
      const toml::table* t = table(*list->get(i), item);
      if (t == nullptr) continue;
      Workpiece w;
      w.loc = ReaderBase::loc(t->source());
      const std::size_t errors_before = r_.diags_.error_count();
      for (auto&& [key, value] : *t) {
        r_.key_ = key.source();
        const std::string name(key.str());
        if (name == "travel") {
          w.travel = arrival_travel(value, item + ".travel");
        } else if (name == "at") {
          w.t = r_.number(value, item + ".at", 0.0, kTimeMax, "s");
        } else if (!common_key(name, value, item + "." + name, w)) {
          unknown(key, item + "." + name, {"travel", "at", "length", "ve"});
        }
      }
      if (t->contains("travel") == t->contains("at")) {
        r_.error(kArrival, w.loc,
                 item +
                     ": give exactly one of `travel` (mm: the belt travel at which its front "
                     "edge reaches the sensor) and `at` (s)");
      }
      if (r_.diags_.error_count() != errors_before) continue;
      const Workpiece& now = w;
      // Front edges reach the sensor in file order; on the belt, the next front edge comes
      // after the previous rear edge (the beam must clear between two workpieces).
      if (now.travel && last_travel) {
        const double clear = *last_travel->travel + last_travel->length;
        if (*now.travel < clear) {
          r_.error(kWorkpieces, t->get("travel")->source(),
                   item + ".travel = " + value_text(*now.travel) +
                       " mm comes before the previous workpiece's rear edge leaves the sensor "
                       "(travel + length = " +
                       value_text(clear) + " mm): workpieces in travel order, not overlapping");
        }
      }
      if (now.t && last_time && *now.t <= *last_time->t) {
        r_.error(kWorkpieces, t->get("at")->source(),
                 item + ".at = " + value_text(*now.t) + " s is not after the previous " +
                     value_text(*last_time->t) + " s: workpieces in time order");
      }
      (now.travel ? last_travel : last_time) = now;
      c.workpieces.push_back(w);
    }
  }

  void read_series(const toml::node& node, const std::string& path, Conveyor& c) {
    const toml::table* t = table(node, path);
    if (t == nullptr) return;
    WorkpieceSeries s;
    s.first.loc = ReaderBase::loc(t->source());
    const std::size_t errors_before = r_.diags_.error_count();
    for (auto&& [key, value] : *t) {
      r_.key_ = key.source();
      const std::string name(key.str());
      const std::string item = path + "." + name;
      if (name == "first") {
        s.first.travel = arrival_travel(value, item);
      } else if (name == "first_at") {
        s.first.t = r_.number(value, item, 0.0, kTimeMax, "s");
      } else if (name == "pitch") {
        if (const auto v = r_.number(value, item, 0.0, kTravelMax, "mm")) s.pitch = *v;
      } else if (name == "period") {
        if (const auto v = r_.number(value, item, 0.0, kTimeMax, "s")) s.pitch = *v;
      } else if (name == "count") {
        if (const auto v = r_.integer(value, item, 1, kCountMax)) s.count = *v;
      } else if (name == "scatter") {
        if (const auto v = r_.number(value, item, 0.0, kTravelMax, "mm or s")) s.scatter = *v;
      } else if (name == "seed") {
        if (const auto v = r_.integer(value, item, 0, kSeedMax)) s.seed = *v;
      } else if (!common_key(name, value, item, s.first)) {
        unknown(
            key, item,
            {"first", "first_at", "pitch", "period", "count", "length", "ve", "scatter", "seed"});
      }
    }
    const bool by_travel = t->contains("first");
    if (by_travel == t->contains("first_at")) {
      r_.error(kArrival, s.first.loc,
               path + ": give exactly one of `first` (mm of belt travel) and `first_at` (s)");
    } else if (by_travel ? !t->contains("pitch") || t->contains("period")
                         : !t->contains("period") || t->contains("pitch")) {
      r_.error(kArrival, s.first.loc,
               path + (by_travel ? ": `first` (mm) goes with `pitch` (mm between front edges)"
                                 : ": `first_at` (s) goes with `period` (s between front edges)"));
    }
    if (!t->contains("count")) r_.error(kArrival, s.first.loc, path + " needs `count`");
    if (r_.diags_.error_count() != errors_before) return;
    if (s.pitch <= 0.0) {
      r_.error(kRange, s.first.loc, path + ": the pitch or period must be > 0");
      return;
    }
    if (by_travel && s.pitch <= s.first.length) {
      r_.error(kWorkpieces, t->get("pitch")->source(),
               path + ".pitch = " + value_text(s.pitch) + " mm is not more than the length (" +
                   value_text(s.first.length) +
                   " mm): the workpieces would touch and the beam never clears");
      return;
    }
    c.series = s;
  }

  ReaderBase& r_;
};

}  // namespace

void read_conveyor(ReaderBase& reader, const toml::node& node, Scenario& s) {
  ConveyorReader(reader).read(node, s);
}

}  // namespace ncsim::scenario::detail
