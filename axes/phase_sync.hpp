#pragma once
// axes/phase_sync: phase-synchronised multi-axis PTP motion (issue 11: "every axis gets a
// profile of exactly the slowest axis's duration ..., or the documented phase-synchronised
// variant"; docs/axes-phase-sync.md).
//
// Purpose: all axes of a rest-to-rest motion share the same phase times, each axis's profile
// the common one scaled by its distance, so the motion is a straight line in axis space (the
// public idea is Ruckig's "phase synchronization").
// Inputs: per axis a start (at rest), a target (reached at rest), Dynamics; the ProfileRule;
// a minimum duration [s] (INDP TIME=).
// Outputs: one Profile per axis, all of one duration; which variant was used.
// Invariants: in the phase-synchronised variant (p_i(t) - p_i0) / D_i is the same for every
// moving axis to rounding, every axis stays within its V, A+, A-, J, every axis ends exactly
// on its target. Where the phases cannot be shared (a moving start, an arrival velocity, or the
// common profile slower than the slowest axis alone), the time-synchronised plan_synchronized
// is used instead, and `used` says so.

#include <cstdint>
#include <span>

#include "axes/profile.hpp"

namespace ncsim::axes {

/// Which synchronisation a multi-axis plan used.
enum class SyncKind : std::uint8_t {
  phase,  ///< same phase times on every axis, a straight line in axis space
  time,   ///< same duration only (plan_synchronized)
};

/// Phase-synchronised multi-axis motion: the 1-D motion u: 0 -> 1 is planned under the
/// tightest scaled limits (V_u = min V_i / |D_i|, likewise A+, A-, J) with `rule`, and every
/// axis follows p_i0 + D_i u(t). Its duration is max(its own, min_duration [s]); used when it
/// is not slower than the slowest axis alone (relative kRelTol), else falls back to
/// plan_synchronized. All spans have one size; `used` (optional) receives the variant.
Result plan_phase_synchronized(std::span<const MotionState> starts,
                               std::span<const PositionTarget> targets,
                               std::span<const Dynamics> dynamics, ProfileRule rule,
                               double min_duration, std::span<Profile> out,
                               SyncKind* used = nullptr) noexcept;

}  // namespace ncsim::axes
