#pragma once
// conveyor/line_world: the workpieces shared along one belt by the channels of a line (issue 37
// step 2, docs/lines.md "Workpieces along the belt").
//
// Purpose: one belt (a World: the belt, its encoder, filters and delay-time compensation) and,
// per channel with a conveyor axis, a station: its own sensor at its own place along the belt
// (`sensor_at`, mm of travel after the line's sensor) and its own touch probe with the
// measuring method of its own machine (P-AXIS-00516..00518: at most one measured value, or the
// PLC's queue of them). Seed 004: each channel synchronises with the 1st axis of its own
// channel (l.227, l.452: one conveyor axis per channel), measures with its own MC_TouchProbe
// (l.258, l.1717-1719: per axis and measuring input, not retriggerable) and locates the
// workpiece by its own measuring unit's T0 (P-CHAN-00368..00373, l.645-647); several channels
// may synchronise with one physical conveyor (l.244); under method 3 the PLC assigns the
// measured values to the NC programs (l.653).
// Every workpiece that reaches the line's sensor (the scenario's stream) gets a fate: free on
// the belt, held by one channel (measured by it and not let go), taken by it (it reached
// #SYNC OUT after a catch-up: machined or picked), or missed (free when its front edge passed
// the belt's end, `belt_end` mm after the line's sensor). A held workpiece that its channel lets
// go (#SYNC OUT before any catch-up: the program decided not to take it) is free again and
// passes on to the stations downstream whose sensors it has not passed yet. Nothing is lost:
// arrived = free + held + taken + missed after every step.
// Inputs: the World (built without workpieces: this class senses them), the line's [conveyor]
// (its stream and sensor kind), the stations; per cycle step_once(t) and, from the line, what
// each channel did with its workpiece (let_go, done). Outputs: one Port per station for its
// channel; the fates and counts. The PLC writes, with every measured value it hands over, the
// V.E. values LINE_WORKPIECE (its number) and LINE_TRAVEL (mm it travelled since it passed
// the channel's sensor, by the NC's measured value at the hand-over) beside the workpiece's own.
// Invariants: deterministic (noise seeded); noexcept per cycle; memory: the workpieces on the
// belt and in the queues, plus one fate record per workpiece up to kMaxFateRecords (the counts
// stay exact beyond it).

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "conveyor/noise.hpp"
#include "conveyor/port.hpp"
#include "conveyor/sensor.hpp"
#include "conveyor/world.hpp"
#include "machines/machine.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::conveyor {

/// Fate records kept for the report (the counts are exact for any number).
inline constexpr std::size_t kMaxFateRecords = 100000;

/// The V.E. names the line's PLC writes with each measured value (docs/lines.md).
inline constexpr const char* kVeWorkpiece = "LINE_WORKPIECE";
inline constexpr const char* kVeTravel = "LINE_TRAVEL";
/// Written by the line every cycle: 1 while a workpiece can still reach the channel's probe.
inline constexpr const char* kVeMore = "LINE_MORE";

/// Where a workpiece is (docs/lines.md "Workpieces along the belt").
enum class Fate : std::uint8_t {
  free,    ///< on the belt, no channel holds it
  held,    ///< measured by a channel that has not let it go nor finished it
  taken,   ///< its channel reached #SYNC OUT after a catch-up on it
  missed,  ///< its front edge passed the belt's end while free
};

/// Name of a fate ("free", "held", "taken", "missed").
const char* fate_name(Fate f) noexcept;

/// One workpiece's fate.
struct WorkpieceFate {
  std::uint64_t workpiece = 0;  ///< 1-based, in order of arrival at the line's sensor
  double t_arrived = 0.0;       ///< [s] its front edge at the line's sensor
  Fate fate = Fate::free;
  std::uint8_t channel = 0;  ///< held / taken: the channel's number; 0 otherwise
  double t = 0.0;            ///< [s] taken / missed: when; held: when measured
};

/// One channel's station: where its sensor is and how its probe measures.
struct StationSpec {
  std::uint8_t channel = 1;  ///< the channel's number
  double sensor_at = 0.0;    ///< [mm] belt travel from the line's sensor to this one, >= 0
  std::uint8_t axis = 0;     ///< the conveyor axis's index in the channel's machine
  std::string axis_name;     ///< its name (messages)
  MeasuringMethod method = MeasuringMethod::drive;  ///< P-AXIS-00516
  int probe_input = 1;                              ///< P-AXIS-00517
  bool default_rising = true;                       ///< P-AXIS-00518 POS
  double sensor_x = 0.0;  ///< [mm] the sensor's MCS X in the channel (its P-CHAN-00368)
};

/// The station of the channel `number` on `machine`; throws std::invalid_argument naming the
/// parameter (as make_port) when the machine has no conveyor axis or a method none uses.
StationSpec station_of(const machines::Machine& machine, std::uint8_t number, double sensor_at);

class LineWorld {
 public:
  /// `world`: the belt (built on a scenario without workpieces); `conveyor`: the line's
  /// [conveyor] (its stream; may be null); `sign`: +1 when the conveyor axis grows as the belt
  /// conveys (P-CHAN-00363 = 0) of the world's machine; `belt_end` [mm] after the line's sensor.
  LineWorld(std::unique_ptr<Port> world, const scenario::Conveyor* conveyor, double sign,
            std::vector<StationSpec> stations, double belt_end);
  ~LineWorld();
  LineWorld(const LineWorld&) = delete;
  LineWorld& operator=(const LineWorld&) = delete;

  std::size_t stations() const noexcept { return stations_.size(); }
  /// Station k's Port, for its channel (valid as long as this world).
  Port& port(std::size_t k) noexcept;
  /// The belt's Port (the world itself).
  Port& world() noexcept { return *world_; }

  /// Steps the belt to `t` unless it is there, then senses the workpieces (once per t).
  /// `arrivals` false: workpieces reaching the line's sensor are not taken in (the line's
  /// channels have all ended; drain()).
  void step_once(double t, bool arrivals = true) noexcept;
  /// After the last channel ended: runs the belt on in steps of `dt` from `t` until no free
  /// workpiece is on it (each leaves past the belt's end, missed) or `t_max` [s]; nothing new
  /// arrives meanwhile. Returns the time reached.
  double drain(double t, double dt, double t_max) noexcept;
  /// Free workpieces on the belt.
  std::uint64_t free_on_belt() const noexcept { return on_belt() - held(); }
  /// Station k's channel let `workpiece` (its measured value taken) go before any catch-up
  /// (at t [s]); nothing when it does not hold it.
  void let_go(std::size_t k, std::uint64_t workpiece, double t) noexcept;
  /// Station k's channel finished `workpiece` (#SYNC OUT after a catch-up, at t [s]).
  void done(std::size_t k, std::uint64_t workpiece, double t) noexcept;

  /// A workpiece can still reach station k's probe: more to come, one on the belt (free or
  /// held) before its sensor, or a free one in its PLC queue.
  bool more_for(std::size_t k) const noexcept;

  std::uint64_t arrived() const noexcept { return arrived_; }
  std::uint64_t missed() const noexcept { return missed_; }
  std::uint64_t taken(std::size_t k) const noexcept;
  std::uint64_t taken_total() const noexcept;
  /// Workpieces on the belt: free or held.
  std::uint64_t on_belt() const noexcept { return pieces_.size(); }
  std::uint64_t held() const noexcept;
  /// Every workpiece's fate in order of arrival (the first kMaxFateRecords).
  const std::vector<WorkpieceFate>& fates() const noexcept { return fates_; }

 private:
  class StationPort;
  struct Piece {
    std::uint64_t workpiece = 0;
    double u_front = 0.0;  ///< [mm] travel at which its front edge was at the line's sensor
    const scenario::Workpiece* source = nullptr;
    Fate fate = Fate::free;
    std::size_t holder = 0;  ///< the station holding it
    std::size_t next = 0;    ///< the first station whose sensor it has not passed
    double t_end = 0.0;      ///< [s] when its front edge passed the belt's end
  };
  Piece* find(std::uint64_t workpiece) noexcept;
  const Piece* find_const(std::uint64_t workpiece) const noexcept;
  void hold(Piece& p, std::size_t k, double t) noexcept;
  void record(const Piece& p, double t) noexcept;
  void arrive(const Edge& e) noexcept;
  void sense(double t0, double u0, double t1, double u1) noexcept;
  void finish(std::uint64_t workpiece, Fate fate, double t) noexcept;

  std::unique_ptr<Port> world_;
  std::optional<scenario::Conveyor> conveyor_;  // a copy: the Sensor points into it
  double sign_;
  double belt_end_;
  Sensor sensor_;
  bool camera_ = false;
  std::vector<std::unique_ptr<StationPort>> stations_;
  std::deque<Piece> pieces_;  // free and held, in order of arrival
  std::vector<WorkpieceFate> fates_;
  std::uint64_t arrived_ = 0;
  std::uint64_t missed_ = 0;
  std::optional<double> stepped_;  // [s]
  double t_ = 0.0;
  Gaussian latch_noise_;
  double sigma_ = 0.0;
};

}  // namespace ncsim::conveyor
