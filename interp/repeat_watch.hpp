#pragma once
// interp/repeat_watch: programs that never end (docs/interp.md "Endless programs"): Brent's
// cycle finding over fingerprints of the decoder's state. Input: each block the decoder counts.
// Output: NC4901 when the state repeats without motion or time between; endless_from() when it
// repeats with them. Invariant: comparisons cost at most 1/16 of the blocks decoded.

#include <cstddef>
#include <cstdint>
#include <optional>

#include "interp/interpreter.hpp"

namespace ncsim::interp {

class RepeatWatch {
 public:
  explicit RepeatWatch(Interpreter::Impl& decoder) : ip_(decoder) {}

  bool watch(std::uint32_t block_line);  // counts the block at the decoder's pc; false: NC4901
  /// The line of the block the decoder came back to in the same state with motion between.
  std::optional<std::uint32_t> endless_from() const { return endless_from_; }
  /// The first repeat found took no run-time answer between the two states (no measured
  /// value, signal, V.E. answer or #SYNC IN): nothing from outside the program can end it.
  bool endless_on_its_own() const { return on_its_own_; }

 private:
  std::uint64_t fingerprint(std::size_t& cost) const;

  Interpreter::Impl& ip_;
  std::uint64_t pc_ = std::uint64_t{0xFFFF} << 32;  // the saved block: file << 32 | ordinal
  std::uint32_t line_ = 0;
  std::uint64_t fingerprint_ = 0;
  std::uint64_t at_ = 0;        // blocks decoded when saved
  std::uint64_t period_ = 1;    // blocks until the next save
  std::uint64_t credit_ = 0;    // blocks to decode before the next (costly) comparison
  std::uint64_t decoded_ = 0;   // blocks decoded in this run
  std::uint64_t world_at_ = 0;  // Impl::world_waits when saved
  std::optional<std::uint32_t> endless_from_;
  bool on_its_own_ = false;
};

}  // namespace ncsim::interp
