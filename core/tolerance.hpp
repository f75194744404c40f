#pragma once
// core/tolerance: the tolerances ncsim compares with, named once (issue 35).
//
// A comparison that allows for rounding uses one of these constants, so that one meaning has
// one name and one value everywhere: a relative tolerance on a limit is not the same thing as
// a length in mm, even where both are 1e-9. A multiple or a combination is written out at the
// use (`t_min * (1.0 - kRelRounding)`, `kRelTol * std::max(1.0, |x|)`).
// Invariants: the values are part of every trajectory; changing one changes goldens. One-off
// parameters that are not tolerances (a bisection's width on a curve parameter, a design bound
// of a machine parameter) stay named where they are used.

#include <limits>

namespace ncsim {

/// Relative tolerance [1] against a limit, a target or a second computation of the same
/// quantity: `x` within kRelTol * |limit| of `limit` is on it (a duration met, a velocity at its
/// limit, a phase shared, the interpreter's `==` on reals).
inline constexpr double kRelTol = 1e-9;

/// Tight relative tolerance [1] between values computed through the same formulas (a few
/// thousand ulp of rounding): a requested duration against the shortest one, a start on a
/// limit, the end of a bisection on a time or a velocity.
inline constexpr double kRelRounding = 1e-12;

/// Length tolerance [mm | deg]: two positions closer than this are the same point; a length, a
/// chord or a radius below it is zero.
inline constexpr double kSamePoint = 1e-9;

/// Zero length [mm | deg]: a distance below this is exactly 0 before it divides or decides
/// (a guard against 0 / 0, far below kSamePoint).
inline constexpr double kZeroLength = 1e-12;

/// Dimensionless zero [1]: a direction component, a derivative by the path parameter, a
/// weight, an angle in radians or a trigonometric value below this in magnitude is 0 (COS[90]
/// is 6e-17).
inline constexpr double kTiny = 1e-12;

/// Whole cycles [cycles]: a time within this of a whole number of cycles is that number, so
/// ceil(t / t_cycle - kCycleRounding) does not add a cycle for a rounding residue (0.003 s /
/// 0.001 s is 2.9999999999999996 in double and counts as 3 cycles).
inline constexpr double kCycleRounding = 1e-9;

/// Same instant [s]: two times closer than this are simultaneous (scenario events).
inline constexpr double kSameTime = 1e-9;

/// Curve parameter resolution [1] of t in [0, 1] (a Bezier piece): a bracket or a Newton step
/// on t narrower than this is a point (a few ulp of 1).
inline constexpr double kParameterWidth = 1e-15;

/// Machine epsilon [1] of double, 2^-52: the relative spacing of doubles near 1.
inline constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon();

/// Rounding residue [1]: a difference below kResidue times the size of its terms is rounding
/// and taken as 0 (8 ulp; docs/axes-profile.md "Numerics").
inline constexpr double kResidue = 8.0 * kMachineEpsilon;

/// Bisection width [1]: a bisection stops once its bracket is below kBisectWidth times its
/// bound (4 ulp: a narrower bracket no longer shrinks).
inline constexpr double kBisectWidth = 4.0 * kMachineEpsilon;

}  // namespace ncsim
