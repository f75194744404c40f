#pragma once
// conveyor/noise: ncsim's own seeded generators: Gaussian noise on the encoder (docs/conveyor.md
// "The world"), uniform gaps of a random workpiece stream (docs/scenario.md). The standard
// library's distributions differ between implementations; these give the same numbers
// everywhere for the same seed.
// Inputs: a seed. Outputs: standard normal samples (mean 0, standard deviation 1).
// Invariants: deterministic; no allocation; never NaN (the uniform draw is in (0, 1]).

#include <cmath>
#include <cstdint>
#include <numbers>

namespace ncsim::conveyor {

/// SplitMix64 (Steele, Lea, Flood 2014): 64 random bits per call, and uniforms from them.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) noexcept : state_(seed) {}
  std::uint64_t bits() noexcept {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  /// Uniform in (0, 1]: 53 bits, shifted by one ulp off zero.
  double uniform() noexcept {
    return (static_cast<double>(bits() >> 11) + 1.0) * (1.0 / 9007199254740992.0);
  }

 private:
  std::uint64_t state_;
};

class Gaussian {
 public:
  explicit Gaussian(std::uint64_t seed) noexcept : random_(seed) {}

  /// The next standard normal sample (Box-Muller on SplitMix64 uniforms).
  double next() noexcept {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = random_.uniform();  // (0, 1]
    const double u2 = random_.uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double phi = 2.0 * std::numbers::pi * u2;
    spare_ = r * std::sin(phi);
    has_spare_ = true;
    return r * std::cos(phi);
  }

 private:
  SplitMix64 random_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace ncsim::conveyor
