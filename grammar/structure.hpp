#pragma once
// grammar/structure: the structural checks of `ncsim check` over the block stream.
//
// Inputs: blocks from BlockParser, in file order. Outputs: diagnostics for unbalanced or
// misplaced control keywords (manual ids 20214, 20216, 20218, 20237, 20243, 20244, 21480, 20593,
// 20131 and ncsim's NC2xxx), labels, local subroutines, G/M codes and bracket keywords.
// Invariants: memory is O(open control blocks + labels + $GOTOs + distinct LL names) per
// program level; nothing is kept per block. Program levels are the main program and each %L
// subroutine (isg-language.md §4.7): labels and control blocks never cross a level.
// #IF/#ELSE/#ENDIF: the #IF branch is checked fully, the #ELSE branch for syntax only
// (docs/language.md "#IF in check mode"). A main program with no M02/M30 (nor M17/M29, for a
// global subroutine file) is warning NC2019 at its last block.

#include <map>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source_file.hpp"
#include "grammar/ast.hpp"

namespace ncsim::grammar {

class StructureChecker {
 public:
  explicit StructureChecker(const core::SourceFile& file) : file_(file) {}

  /// Checks one block.
  void feed(const ast::Block& block, core::DiagnosticList& diags);
  /// Ends the file: reports what is still open or unresolved.
  void finish(core::DiagnosticList& diags);

 private:
  struct Frame {
    ast::ControlKind kind;
    core::SourceLoc loc;
    bool has_else = false;      // $ELSE seen ($IF) / $DEFAULT seen ($SWITCH)
    std::uint32_t loop_id = 0;  // 0 when not a loop
  };
  struct LabelInfo {
    core::SourceLoc loc;
    std::vector<std::uint32_t> loops;  // loops open at the label
  };
  struct GotoInfo {
    std::string label;
    core::SourceLoc loc;
    std::vector<std::uint32_t> loops;
  };
  struct PreIf {
    core::SourceLoc loc;
    bool in_else = false;
    bool enabled_before = true;
  };

  void report(core::DiagnosticList& diags, core::SourceLoc loc, const char* id,
              std::string message) const;
  void start_level(bool local);
  void finish_level(core::DiagnosticList& diags);
  bool preprocessor(const ast::Block& block, core::DiagnosticList& diags);
  void control(const ast::Block& block, const ast::Control& c, core::DiagnosticList& diags);
  void add_goto(const ast::GotoTarget& target);
  void words(const ast::Block& block, core::DiagnosticList& diags);
  void items(const ast::Block& block, ast::TableId table, std::uint32_t first, std::uint32_t count,
             core::DiagnosticList& diags) const;
  std::vector<std::uint32_t> open_loops() const;

  const core::SourceFile& file_;
  bool level_open_ = false;
  bool main_seen_ = false;
  bool in_main_ = false;         // the current level is the main program
  bool main_has_end_ = false;    // a literal M02/M30 (or M17/M29) stands in the main program
  core::SourceLoc main_last_;    // the main program's last block
  core::SourceLoc main_header_;  // the main program's `%` line, if any
  std::vector<Frame> frames_;
  std::map<std::string, LabelInfo> labels_;
  std::vector<GotoInfo> gotos_;
  std::uint32_t next_loop_id_ = 1;
  std::vector<PreIf> pre_ifs_;
  bool enabled_ = true;
  std::map<std::string, core::SourceLoc> subroutines_;  // %L names (upper case)
  std::map<std::string, core::SourceLoc> local_calls_;  // LL names (upper case), first call
};

}  // namespace ncsim::grammar
