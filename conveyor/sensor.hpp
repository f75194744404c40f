#pragma once
// conveyor/sensor: the measuring unit (light barrier or camera) and the workpieces passing it
// (seed 004 §4.3: "a measured value corresponds to a position of the linear conveyor at a
// specific point in time ... the position of the front edge of the workpiece at the measuring
// system position"; docs/conveyor.md "The world").
//
// Purpose: from the real belt's motion over one cycle, the signal edges the sensor gives in
// that cycle, in time order, each with the workpiece and the real belt position at the edge.
// Workpieces arrive at a belt travel (their front edge reaches the sensor when the travel in
// the conveying direction passes it) or at a time; a light barrier is on from a front edge to
// the rear edge (length later) and gives the configured polarity; a camera gives one pulse
// (rising and falling edge) at each front edge.
// Inputs: the scenario's workpieces (list and series), the conveying sign (P-CHAN-00363), the
// belt state at the start and end of each cycle. Outputs: Edge records.
// Invariants: memory bounded by the workpieces inside the beam at once and the edges of one
// cycle, never by the run time or the series' count (a series is generated as it arrives).

#include <cstdint>
#include <optional>
#include <vector>

#include "conveyor/noise.hpp"
#include "conveyor/port.hpp"
#include "scenario/scenario.hpp"

namespace ncsim::conveyor {

/// One signal edge of the sensor.
struct Edge {
  bool rising = true;           ///< rising (signal 0 -> 1) or falling
  bool front = true;            ///< caused by a front edge (else a rear edge)
  double t = 0.0;               ///< [s] when it happened
  double position = 0.0;        ///< [mm] the real conveyor axis position then
  std::uint64_t workpiece = 0;  ///< 1-based number in order of arrival at the sensor
  const scenario::Workpiece* source = nullptr;  ///< its scenario entry (length, V.E.)
};

class Sensor {
 public:
  /// `sign`: +1 when the conveyor axis position grows as the belt conveys (P-CHAN-00363 = 0),
  /// -1 otherwise. The scenario `conveyor` may be null (no workpieces).
  Sensor(const scenario::Conveyor* conveyor, double sign);

  /// The edges in (t0, t1] for the belt going from s0 (at t0) to s1 (at t1); the returned
  /// list is valid until the next call.
  const std::vector<Edge>& cycle(double t0, const BeltState& s0, double t1, const BeltState& s1);

  /// True while a workpiece that has not reached the sensor remains in the scenario.
  bool more_to_come() const noexcept;

 private:
  struct Pending {  // a front edge due at a travel or a time
    std::optional<double> travel;
    std::optional<double> t;
    const scenario::Workpiece* source = nullptr;
  };
  struct Rear {  // a workpiece in the beam: its rear edge's travel
    double travel = 0.0;
    std::uint64_t workpiece = 0;
    const scenario::Workpiece* source = nullptr;
  };
  std::optional<Pending> next_by_travel() const;
  std::optional<Pending> next_by_time() const;
  void consume(const Pending& p);
  double series_at() const;  // the series' next front edge (travel or time)
  void emit(bool front, double t, double position, std::uint64_t workpiece,
            const scenario::Workpiece* source);

  const scenario::Conveyor* conveyor_;
  double sign_;
  bool camera_ = false;
  bool front_rising_ = true;
  std::vector<std::size_t> travel_list_;  // indices of list workpieces arriving by travel
  std::vector<std::size_t> time_list_;    // ... by time
  std::size_t next_travel_ = 0;
  std::size_t next_time_ = 0;
  std::uint64_t next_series_ = 0;  // index of the series' next workpiece
  double series_next_ = 0.0;       // a random stream (scatter > 0): its next front edge
  SplitMix64 scatter_{1};          // ... and its gaps
  scenario::Workpiece series_item_;
  std::uint64_t arrived_ = 0;  // workpieces that reached the sensor
  std::vector<Rear> in_beam_;
  std::vector<Edge> edges_;
};

}  // namespace ncsim::conveyor
