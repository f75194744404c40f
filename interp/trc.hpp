#pragma once
// interp/trc: tool radius compensation (TRC, G40/G41/G42 with D), a filter over the
// interpreter's command stream.
//
// Purpose: the programmed contour describes the workpiece; the tool centre must run beside it
// at the tool radius. This unit turns the motions the interpreter decodes under G41/G42 into
// the compensated path, so that everything downstream of `Interpreter::next()` (check, trace,
// the planner, the audit, the report) sees the path the tool centre really takes
// (docs/trc.md has the semantics, each with its TF5200 page).
// Inputs: the interpreter's commands in order; each Motion carries its TRC state in
// `ModalSnapshot::trc` (side, radius in mm, G25/G26, G138/G139) and its plane.
// Outputs: the same commands, motions in the TRC plane moved onto the offset path, plus the
// transition motions inserted at outer corners (G25 lines, G26 circles); or a program error
// (the manual's id where it names one) at the line of the block that cannot be compensated.
// Memory: one held plane motion (its end needs the next element to close the corner) and the
// commands decoded behind it, at most kMaxHeldCommands (the manual's 90011 beyond).
// Invariants: commands leave in program order; inserted transitions carry the line of the
// block they lead into; a compensated arc keeps its centre, start and end lie on its radius.
// Deterministic: pure geometry in doubles, no state but the held element.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "interp/command.hpp"
#include "interp/command_queue.hpp"

namespace ncsim::interp::trc {

/// A point or direction in the TRC plane: first and second plane axis (G17 X/Y, G18 Z/X,
/// G19 Y/Z, as the interpreter's arcs).
struct Vec2 {
  double x = 0.0;  ///< [mm]
  double y = 0.0;  ///< [mm]
};

/// One path element in the plane.
struct Element {
  bool arc = false;
  Vec2 start;         ///< [mm]
  Vec2 end;           ///< [mm]
  Vec2 centre;        ///< [mm], arcs
  bool ccw = false;   ///< arcs: G03 (counter-clockwise in the plane)
  bool full = false;  ///< arcs: a full circle (start == end)
};

/// Unit tangent at the start / end of an element.
Vec2 start_tangent(const Element& e);
Vec2 end_tangent(const Element& e);

/// The element moved by `d` [mm] to the left of its travel direction (d < 0: right). An arc
/// keeps its centre and gets the radius R - d (counter-clockwise) or R + d (clockwise);
/// nullopt when that radius is not above kMinRadius (the manual's 90017, "tool radius greater
/// or equal to contour radius").
std::optional<Element> offset(const Element& e, double d);

/// Smallest compensated arc radius [mm]; below it the arc is 90017.
inline constexpr double kMinRadius = 1e-6;

/// How two compensated elements meet at a programmed corner.
struct Join {
  Vec2 a_end;                     ///< the first element's new end
  Vec2 b_start;                   ///< the second element's new start
  std::vector<Element> inserted;  ///< transition elements between them (G25 lines, G26 arc)
};
enum class JoinError : std::uint8_t { none, no_intersection };

/// Joins the offset elements `a` (ending at its perpendicular offset point) and `b` (starting
/// at its own) at the programmed corner `corner`, offset `d` (> 0 left). Inner corners (the
/// contour turns towards the tool side) end both at the intersection of the offset elements
/// nearest the corner; outer corners are bypassed with a circle about the corner (G26) or with
/// linear blocks (G25: the elements' tangents extended to their intersection up to 90 degrees
/// of turn, beyond it extended by |d| and connected; TF5200 "Generation of compensation
/// blocks" gives the block counts). `error` is set when an inner corner has no intersection.
Join join(const Element& a, const Element& b, Vec2 corner, double d, TrcCorner mode,
          JoinError& error);

/// True when the element trimmed to [start, end] still runs the programmed way (a line keeps
/// its direction, an arc turns no further back than its start): false is the contour
/// violation of TF5200 "Limits of TRC".
bool keeps_direction(const Element& offset_element, Vec2 start, Vec2 end);

/// A program error of the compensation, at the block of `line` / `file`.
struct Error {
  std::uint32_t line = 0;
  std::uint16_t file = 0;
  std::string id;
  std::string message;
};

/// Commands a held element may have behind it (the manual's block memory for non-relevant
/// blocks, error 90011 beyond; the size is ncsim's decision).
inline constexpr std::size_t kMaxHeldCommands = 64;

/// The offset of the path from the programmed contour [mm]: + left (G41), - right (G42), 0 off.
inline double signed_offset(const ToolRadiusComp& t) {
  if (t.side == TrcSide::off) return 0.0;
  return t.side == TrcSide::left ? t.radius : -t.radius;
}

/// The stream filter. `push()` each command in order; ready commands are appended to `out`.
class Compensator {
 public:
  /// `xyz`: machine indices of the X, Y and Z axes (none when the machine lacks one).
  explicit Compensator(std::array<std::optional<std::uint8_t>, 3> xyz = {}) : xyz_(xyz) {}

  /// Takes the next command of the stream. Returns the error that ends the stream, if any.
  std::optional<Error> push(Command&& c, CommandQueue& out);
  /// True when push(c) would put `c` into `out` unchanged and return no error: nothing is held
  /// and `c` is no motion under an active compensation.
  bool passes(const Command& c) const {
    if (held_) return false;
    const auto* m = std::get_if<Motion>(&c.body);
    return m == nullptr || signed_offset(m->modal.trc) == 0.0;
  }
  /// The stream ended (End or an error): releases what is held, the held element ending at
  /// its perpendicular offset point.
  void finish(CommandQueue& out);
  /// True while nothing is held (commands pass straight through).
  bool idle() const { return !held_; }

 private:
  struct Held {
    Command command;     ///< the programmed motion
    Element programmed;  ///< its plane element
    Element offset;      ///< offset by d (a line for a selection block)
    Vec2 start;          ///< compensated start
    double d = 0.0;      ///< [mm] signed offset: + left
    bool selection = false;
  };
  std::optional<Error> plane_motion(Command c, const Motion& m, CommandQueue& out);
  /// Holds `pe` as the first element of a compensation that starts at `from` (a selection, or
  /// the selection half of a change of side or radius).
  std::optional<Error> select(Command c, const Element& pe, const Motion& m, Vec2 from,
                              CommandQueue& out);
  void release(const Vec2& end, CommandQueue& out);
  void emit(const Command& pattern, const Element& e, std::uint32_t line, CommandQueue& out,
            bool transition) const;
  bool plane_of(const Motion& m, std::uint8_t& a1, std::uint8_t& a2) const;
  Error error_at(const Command& c, std::string id, std::string message) const;
  /// Keeps `c` behind the held element (90011 beyond kMaxHeldCommands).
  std::optional<Error> hold_behind(Command c);

  std::array<std::optional<std::uint8_t>, 3> xyz_;
  std::optional<Held> held_;
  std::vector<Command> behind_;   // commands decoded after the held element
  std::uint8_t a1_ = 0, a2_ = 0;  // the plane axes of the held element
};

}  // namespace ncsim::interp::trc
