#pragma once
// interp/block_words: what one block's G codes and addresses say (isg-language.md §2). Input: a
// block's words, G codes first (modal ones take effect at once), then the addresses. Output:
// BlockWords for run_words to act on, the modal state G codes and F set, the weightings.
// Invariant: BlockWords holds one block (read() clears it first).

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include "grammar/ast.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::interp {

/// What one block's G codes and addresses say (run_words reads them, then acts).
struct BlockWords {
  std::optional<MotionKind> motion_word;  ///< G00..G03 in this block
  bool g04 = false, g74 = false, g92 = false, g60 = false, g61 = false, g09 = false;
  bool weights_axes = false;  ///< G130/G132/G230/G333/G338: the axis words are weights
  double unit = 1.0;          ///< [mm per program unit] (G70: 25.4)
  std::array<std::optional<double>, 3> ijk;  ///< [mm]
  std::optional<double> radius, bare, end_feed, block_time;
  std::vector<Tech> tech;
  std::optional<int> program_m;                             ///< M00/M01/M02/M30/M17/M29
  std::vector<std::pair<std::uint8_t, double>> axis_words;  ///< machine index, value
  std::optional<TrcSide> trc_side;                          ///< G40/G41/G42 in this block
  core::SourceLoc trc_loc;                                  ///< where that G code stands
  std::optional<double> d_word;                             ///< D in this block
  core::SourceLoc d_loc;
  struct Weighting {
    std::uint32_t code = 0;       ///< G127 .. G233 (interp/weights.hpp)
    std::optional<double> group;  ///< the group form's value [%]
    core::SourceLoc loc;
  };
  std::vector<Weighting> weightings;  ///< applied after the addresses (apply_weightings)
  void clear() {
    motion_word.reset();
    g04 = g74 = g92 = g60 = g61 = g09 = weights_axes = false;
    unit = 1.0;
    ijk = {};
    radius.reset();
    bare.reset();
    end_feed.reset();
    block_time.reset();
    tech.clear();
    program_m.reset();
    axis_words.clear();
    trc_side.reset();
    d_word.reset();
    weightings.clear();
  }
};

class WordReader {
 public:
  explicit WordReader(Interpreter::Impl& decoder) : ip_(decoder) {}

  bool read(const grammar::ast::Block& b, BlockWords& bw);  // the G codes, then the addresses
  void apply_weightings(const BlockWords& bw);              // G127..G233 into modal.weights

 private:
  using Block = grammar::ast::Block;
  using Word = grammar::ast::Word;
  bool read_g_codes(const Block& b, BlockWords& bw);
  bool read_weighting(const Block& b, const Word& w, BlockWords& bw);  // G127..G339
  bool read_addresses(const Block& b, BlockWords& bw);
  /// The additional value of M/H word `w` (`M200=1200`), nullopt if none; NC4033 if it is not
  /// a whole number or its function takes none.
  bool additional_value(const Block& b, const Word& w, std::optional<double>& out);
  static bool has_d_word(const Block& b);
  /// Tool offset D `d` at `loc`: the technology output, TRC's tool and the P-CHAN-00429 call.
  bool read_d(double d, const core::SourceLoc& loc, BlockWords& bw);

  Interpreter::Impl& ip_;
  std::set<std::uint32_t> said_g_;  // weightings noted once (NC4313 G134, NC4315 G333..G339)
};

}  // namespace ncsim::interp
