#pragma once
// report/decimate: bounded-memory reductions of a run's cycle stream for display (docs/report.md).
//
// Purpose: a 10-minute run at 1 ms is 600,000 cycles per series; the HTML report embeds at most
// a few thousand points per series and still shows every peak.
// Inputs: MinMaxDecimator: one sample of S series per cycle (time ascending); PathThinner: one
// tool point (up to 3 coordinates) per cycle.
// Outputs: MinMaxDecimator::finish(): at most max_buckets buckets of consecutive samples, two
// rows per bucket (its first and last sample time), each series with its minimum and maximum
// in the order they occurred; PathThinner::finish(): a polyline through the points.
// Invariants: memory is bounded by max_buckets / max_points, never by the run length; the
// global minimum and maximum of every series are kept exactly; every point of the path lies
// within 2 * tolerance() of the thinned polyline's vertices; the first and last points are
// kept; deterministic (no clock, ties go to the earlier sample).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace ncsim::report {

/// Rows of decimated series sharing one time axis.
struct Decimated {
  std::vector<double> t;                    ///< row times [s], non-decreasing
  std::vector<std::vector<double>> series;  ///< per series, one value per row (NaN: no value)
};

/// Min/max per bucket of consecutive samples; the bucket width doubles (pairs merged) whenever
/// max_buckets are full, so the buckets are always equal in sample count but the last.
class MinMaxDecimator {
 public:
  /// Throws std::invalid_argument if max_buckets < 2 or odd.
  explicit MinMaxDecimator(std::size_t series, std::size_t max_buckets = 2000);
  /// One sample: `values.size()` must equal the series count (checked: std::invalid_argument);
  /// a NaN value is "no value" for that series.
  void add(double t, std::span<const double> values);
  Decimated finish() const;
  std::size_t series() const noexcept { return series_; }
  std::uint64_t samples() const noexcept { return samples_; }
  std::uint64_t bucket_width() const noexcept { return width_; }  ///< samples per bucket

 private:
  struct Bucket {
    double t0 = 0.0;          ///< first sample time [s]
    double t1 = 0.0;          ///< last sample time [s]
    std::uint64_t count = 0;  ///< samples in the bucket
  };
  struct Extreme {
    double min = 0.0, max = 0.0;         ///< NaN while the bucket has no value
    std::uint64_t i_min = 0, i_max = 0;  ///< sample index of each (order within the bucket)
  };
  void merge_pairs();

  std::size_t series_;
  std::size_t max_buckets_;
  std::uint64_t width_ = 1;
  std::uint64_t samples_ = 0;
  std::vector<Bucket> buckets_;
  std::vector<Extreme> ext_;  ///< buckets_.size() * series_, bucket-major
};

/// A polyline of at most max_points vertices: a point is kept when it is at least tolerance()
/// away (largest coordinate difference) from the last kept one; when max_points are kept the
/// tolerance doubles and the kept points are thinned again.
class PathThinner {
 public:
  /// `dims` 1..3; throws std::invalid_argument otherwise or if max_points < 4 or tolerance <= 0.
  explicit PathThinner(std::size_t dims, std::size_t max_points = 4000, double tolerance = 1e-4);
  /// One point of `dims` coordinates (mm | deg); non-finite points are skipped.
  void add(std::span<const double> p);
  /// The kept points then the last point given (if not kept), dims values each, point-major.
  std::vector<double> finish() const;
  double tolerance() const noexcept { return tol_; }  ///< current tolerance [mm | deg]
  std::size_t dims() const noexcept { return dims_; }

 private:
  bool far(const double* a, const double* b) const noexcept;
  void rethin();

  std::size_t dims_;
  std::size_t max_points_;
  double tol_;
  std::vector<double> kept_;  ///< kept points, dims_ each
  std::vector<double> last_;  ///< the last point added
};

}  // namespace ncsim::report
