#pragma once
// axes/modulo: where a modulo positioning ends (000_* 9.1), as a pure function.
//
// A modulo axis keeps a continuous absolute position; a modulo start names the target as a
// modulo position in [0, Modulo Factor), a direction (MC_DIRECTION: positive, negative,
// shortest way) and a number of additional turns. The result is the relative path and the
// absolute end position. The rules, all from 000_* 9.1 and its example table:
//   - the move is referenced to the current (actual) position;
//   - positive / negative: the nearest occurrence of the target in that direction, plus
//     additional turns x factor in that direction; a start already on the target moves 0
//     (or exactly the additional turns);
//   - shortest way: the nearer occurrence; additional turns are not allowed with it
//     ("ERROR: INVALID ADDITIONAL TURN COUNT");
//   - Tolerance Window: if the shortest distance to the target is <= the window, the target is
//     driven to by the shortest route, also against the requested direction (the additional
//     turns still follow the requested direction: 110.9 -> 10 positive with 3 turns is 299.1);
//   - a modulo target outside [0, factor) is "ERROR: INVALID TARGET POSITION".
// The second form, from_signed_modulo_position(), is the convention of 002_* 2.1: the sign of
// the modulo position gives the direction (0.0 counts as positive) and |position| / factor the
// additional turns.
// Invariants: no state, no allocation, never throws on program values; a non-positive or
// non-finite factor or a negative tolerance is API misuse and throws std::invalid_argument.

#include <string_view>

namespace ncsim::axes {

/// MC_DIRECTION of a modulo start (000_* 9.1).
enum class ModuloDirection { positive, negative, shortest_way };

/// Encoder parameters of a modulo axis (000_* 7.2.1).
struct ModuloParams {
  double factor = 360.0;   ///< [deg] or [mm] "Modulo Factor": the path of one revolution, > 0
  double tolerance = 0.0;  ///< [deg] or [mm] "Tolerance Window for Modulo Start", >= 0
};

/// One modulo start.
struct ModuloRequest {
  double start = 0.0;   ///< [deg] or [mm] current absolute (actual) position
  double target = 0.0;  ///< [deg] or [mm] modulo target position, in [0, factor)
  ModuloDirection direction = ModuloDirection::shortest_way;
  int additional_turns = 0;  ///< >= 0; must be 0 with shortest_way
};

enum class ModuloStatus {
  ok,
  invalid_target_position,        ///< target outside [0, factor) or not finite [NC5510]
  invalid_additional_turn_count,  ///< negative turns, or turns with shortest way [NC5511]
};

/// ncsim diagnostic id of a non-ok status ("NC5510"); empty for ok.
std::string_view diagnostic_id(ModuloStatus status) noexcept;
/// The manual's wording of the status.
std::string_view describe(ModuloStatus status) noexcept;

struct ModuloMove {
  ModuloStatus status = ModuloStatus::ok;
  double distance = 0.0;      ///< [deg] or [mm] relative path, signed
  double end_position = 0.0;  ///< [deg] or [mm] absolute end position = start + distance
  double end_modulo = 0.0;    ///< [deg] or [mm] modulo end position (= the target)
};

/// The modulo position of an absolute position, in [0, factor).
double modulo_position(double absolute, double factor) noexcept;

/// Computes the move of a modulo start (000_* 9.1). Throws std::invalid_argument only for
/// invalid ModuloParams.
ModuloMove plan_modulo(const ModuloParams& params, const ModuloRequest& request);

/// 002_* 2.1: a signed modulo position (e.g. +540.0 with factor 360: one extra turn, then
/// 180.0 in positive direction; -1e-6: 0.0 approached in negative direction).
ModuloRequest from_signed_modulo_position(double start, double signed_position,
                                          double factor) noexcept;

}  // namespace ncsim::axes
