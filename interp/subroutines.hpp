#pragma once
// interp/subroutines: subroutine calls and program levels (`L name`, `LL name`, macros and
// STRING variables as names, global subroutine files checked whole at their first call,
// M17/M29 and the next `%` returning) and cycle calls: the implicit calls G80-G89 and
// G800-G839 with their parameter lists (TF5200 PROG-206278923, P-CHAN-00160..00169 and
// P-CHAN-00187, `#FILE NAME`), the implicit calls by M6 and by a D word (P-CHAN-00118,
// P-CHAN-00429) and `L CYCLE [NAME=.. @P1=..]` (PROG-206859019); where a cycle's file is
// found (docs/interp.md "Cycles").
//
// Input: the call of a block, the G word of an implicit call. Output: the decoder's pc in the
// called level, a CallFrame on the decoder's call stack, a new variable level (@P parameters).
// Invariant: a level returns to the pc and control depth it was called from.

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "grammar/ast.hpp"
#include "interp/interpreter.hpp"

namespace ncsim::interp {

struct ProgramFile;
struct Pc;

/// The words that may call a configured subroutine besides the G codes (P-CHAN-00118, 00429).
enum class WordCall : std::uint8_t { m6, d };

class Subroutines {
 public:
  explicit Subroutines(Interpreter::Impl& decoder) : ip_(decoder) {}

  /// A cycle call read from a block, run after the block's words: G80-G89 / G800-G839 with
  /// their parameter list (PROG-206278923) or `L CYCLE [NAME=.. @P1=..]` (PROG-206859019).
  struct CycleCall {
    std::uint32_t g_code = 0;      ///< 0: L CYCLE, M6 or D
    std::optional<WordCall> word;  ///< M6 / D: an implicit call without parameters
    core::SourceLoc loc;
    std::string name;                           ///< L CYCLE's NAME; G: found at run_cycle_call
    std::vector<std::optional<double>> params;  ///< [k]: @P(k+1); nullopt: a gap
  };

  bool call(const grammar::ast::Block& b, const grammar::ast::Call& c);  // L, LL, L CYCLE
  bool subroutine_return();  // M17/M29 or the next %: back to the caller (M17 in main: none)
  /// Records the local subroutines before the main part of `pf` and where the main part starts.
  bool find_main_start(ProgramFile& pf, std::uint16_t index);
  bool read_implicit_call(const grammar::ast::Block& b, const grammar::ast::Word& w);  // G80..
  /// M6 or a D word: reads its implicit call when a subroutine is configured (P-CHAN-00118,
  /// P-CHAN-00429, `#FILE NAME [M6=..]`); `called` says whether it was. False: an error (a
  /// second implicit call in the block, NC4308).
  bool read_word_call(WordCall word, core::SourceLoc at, bool& called);
  /// "G805", "M6", "D" or "L CYCLE": what made the call, for messages.
  static std::string call_name(const CycleCall& c);
  bool run_cycle_call();  // enters cycle_call's subroutine (or skips it) and clears it
  bool hash_file_name(const grammar::ast::Block& b, const grammar::ast::HashCommand& h);

  std::optional<CycleCall> cycle_call;                   // read from the block being decoded
  std::map<std::uint32_t, std::string> file_names;       // #FILE NAME [G80="x.nc"] until M30
  std::array<std::optional<std::string>, 2> word_files;  // #FILE NAME [M6=.. D=..] until M30
  std::set<std::string> skipped_cycles;  // G codes and cycle names warned about (NC4307)

 private:
  bool read_cycle_call(const grammar::ast::Block& b, const grammar::ast::Call& c);
  /// Loads global subroutine file `path` (checked whole), remembered as `key`.
  std::optional<std::uint16_t> load_global_file(const std::string& key,
                                                const std::filesystem::path& path,
                                                core::SourceLoc at);
  void enter_level(Pc target, std::uint32_t header);  // a subroutine level starts at target

  Interpreter::Impl& ip_;
};

}  // namespace ncsim::interp
