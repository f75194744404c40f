#pragma once
// conveyor/filter: the actual-value filters of the conveyor axis (seed 004 §2.1.4, §5.2.1;
// docs/conveyor.md "Filters").
//
// Purpose: smooth the measured conveyor position and velocity the PCS1 frame follows.
// "Order" is the manual's "number of filtered values": an FIR filter over the last n cycle
// samples, n = 0 (and 1) = off. Two kinds:
//  - FIR low-pass ("An FIR low-pass filter is used automatically", P-AXIS-00623/00625; "a sinc
//    (ideal low-pass) filter", §2.1.4): the ideal low-pass with cut-off 1/(n T), truncated to
//    its main lobe of n taps (the sinc's first zeros fall at the window's ends), normalised to
//    gain 1 at 0 Hz;
//  - average value filter (P-AXIS-00624): n equal taps 1/n.
// Both are symmetric, so they pass a constant unchanged once n samples are in, and delay a
// ramp by exactly (n - 1) T / 2 (linear phase).
// Chains (ActualValueFilter): position: P-AXIS-00620 enable, then NCSIM-AXIS-005/006 (type and
// order of the position filter, the listings' conv_sync.type_pos_filter / order_pos_filter);
// velocity: normal FIR(P-AXIS-00623); reduced (MCV_SetReducedFilter, conveyor feed hold)
// FIR(P-AXIS-00625) then average(P-AXIS-00624). Both velocity chains run every cycle on the
// same samples, so switching between them has no start-up transient.
// Inputs: one measured position per cycle. Outputs: filtered p, v, a (mm, mm/s, mm/s^2).
// Invariants: memory fixed at construction (orders <= 1000); never throws after construction;
// deterministic.

#include <cstddef>
#include <vector>

#include "conveyor/port.hpp"
#include "machines/machine.hpp"

namespace ncsim::conveyor {

/// Taps of the FIR low-pass of order n (n >= 1), sum 1, symmetric.
std::vector<double> sinc_taps(std::size_t n);
/// Taps of the average value filter of order n (n >= 1): n times 1/n.
std::vector<double> average_taps(std::size_t n);

/// An FIR filter over a ring of its last inputs.
class Fir {
 public:
  /// Order 0 or 1: the identity.
  explicit Fir(std::vector<double> taps);
  /// Fills the history with x (as if x had always been the input).
  void fill(double x) noexcept;
  /// Pushes one input and returns the output.
  double push(double x) noexcept;
  /// Group delay in samples: (n - 1) / 2.
  double delay_samples() const noexcept;

 private:
  std::vector<double> taps_;
  std::vector<double> ring_;
  std::size_t head_ = 0;
};

/// The conveyor axis's filters: measured position in, filtered p, v, a out.
class ActualValueFilter {
 public:
  /// `params`: P-AXIS-00620..00625 and NCSIM-AXIS-005/006; `t_cycle` [s] > 0.
  ActualValueFilter(const machines::ConveyorAxisParams& params, double t_cycle);
  /// Starts from a belt at position p moving at v: histories as if it had always done so.
  void reset(double p, double v) noexcept;
  /// One cycle: the measured position [mm] and the measured velocity [mm/s] (the position
  /// difference over the cycle). Returns the filtered state.
  const BeltState& push(double p, double v) noexcept;
  /// The reduced filter (P-AXIS-00625 then P-AXIS-00624) on or off.
  void set_reduced(bool on) noexcept { reduced_ = on; }
  bool reduced() const noexcept { return reduced_; }
  const BeltState& state() const noexcept { return out_; }
  /// Delay of the position filter [s] ((n - 1) T / 2; 0 when off).
  double position_delay() const noexcept;

 private:
  bool enabled_;
  double t_cycle_;
  Fir position_;
  Fir normal_;
  Fir dyn_;
  Fir post_;
  bool reduced_ = false;
  double v_prev_ = 0.0;  // filtered velocity of the last cycle [mm/s]
  BeltState out_;
};

}  // namespace ncsim::conveyor
