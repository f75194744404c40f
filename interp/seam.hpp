#pragma once
// interp/seam: the run-time half of the seam (docs/interp.md "The seam"). Which blocks need
// run-time state (a Barrier before them: V.E. reads, the probe latch before #SYNC IN, actual
// positions of unknown axes), how the run time's answer (RunState) enters the decoder, and the
// decode-only answer `check` and `trace` use.
//
// Input: the block about to be decoded; the RunState answering a Barrier. Output: the Barrier
// command; the decoder's V.E. values, latch, position and unknown axes after the answer.
// Invariant: a block is decoded once, after its barrier was answered.

#include <array>
#include <cstdint>

#include "grammar/ast.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::interp {

class Seam {
 public:
  explicit Seam(Interpreter::Impl& decoder) : ip_(decoder) {}

  /// Emits a Barrier when `b` needs run-time state; true: the block waits for resume().
  bool barrier_before(const grammar::ast::Block& b);
  void apply(const RunState& state, const Barrier& barrier);  // the run time's answer
  RunState decode_only(const Barrier& barrier) const;         // check's and trace's answer

 private:
  bool emit_barrier(const grammar::ast::Block& b, bool sync_in,
                    AxisMask position_needed);                  // slow path
  AxisMask position_needs(const grammar::ast::Block& b) const;  // unknown axes the block needs
  /// The block has a V.E. node or a string (a possible macro): remembered per block text.
  bool may_read_external(const grammar::ast::Block& b);

  struct ExternalScan {
    std::uint64_t key = 0;  // file and Block::offset of the block scanned, + 1; 0: empty
    bool may_read = false;
  };
  Interpreter::Impl& ip_;
  std::array<ExternalScan, 256> external_scans_{};
};

}  // namespace ncsim::interp
