#pragma once
// interp/hash_commands: the # commands of a block (isg-language.md §5): #SYNC IN/OUT,
// #CS, #TRAFO / #KIN, #CAXTRACK, #CONTOUR MODE, #SLOPE, #MACHINE DATA (through
// machines/param_table), #MSG, #TIME, #TRANSVELMIN, #WAIT INDP, #DELETE, #IF/#ELSE skips,
// #SPLINE, the offset commands (handed to Offsets), #FILE NAME (to Subroutines) and the
// commands read without an effect. docs/interp.md and docs/language.md.
//
// Input: a block whose body is a HashCommand. Output: commands emitted through the decoder
// and the decoder's modal state; program errors through the decoder.

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "grammar/ast.hpp"
#include "interp/interpreter.hpp"
#include "machines/param_table.hpp"

namespace ncsim::interp {

struct Items;

class HashCommands {
 public:
  explicit HashCommands(Interpreter::Impl& decoder) : ip_(decoder) {}

  bool run_hash(const grammar::ast::Block& b, const grammar::ast::HashCommand& h);  // dispatch
  /// The value of a # command item (nullopt after an error).
  std::optional<double> item_value(const grammar::ast::Block& b, const grammar::ast::Item* it);
  /// What a #WAIT / #SIGNAL READ block waits for (signals.cpp), without reporting: nullopt
  /// when the block is faulty (its decoding then reports why).
  std::optional<SignalWait> signal_wait(const grammar::ast::Block& b,
                                        const grammar::ast::HashCommand& h);

 private:
  using Block = grammar::ast::Block;
  using HashCommand = grammar::ast::HashCommand;
  bool hash_sync_in(const Block& b, const HashCommand& h);
  bool hash_sync_out(const Block& b, const HashCommand& h);
  bool duplicate_free(const Block& b, const HashCommand& h,
                      std::initializer_list<std::string_view> keywords);  // else NC4507
  bool feed_cont(const Block& b, const Items& items, std::optional<double>& out);
  bool hash_cs(const Block& b, const HashCommand& h);
  bool hash_kinematics(const Block& b, const HashCommand& h);
  bool hash_caxtrack(const Block& b, const HashCommand& h);
  bool hash_contour_mode(const Block& b, const HashCommand& h);
  bool hash_slope(const Block& b, const HashCommand& h);
  bool hash_machine_data(const Block& b, const HashCommand& h);  // machine_data.cpp
  bool machine_setting(core::SourceLoc at, const machines::ParamSpec& spec,
                       std::optional<std::uint16_t> index, double value, MachineData& md);
  bool hash_msg(const Block& b, const HashCommand& h);
  bool hash_time(const Block& b, const HashCommand& h);
  bool hash_transvelmin_on(const Block& b, const HashCommand& h);
  bool hash_wait_indp(const Block& b, const HashCommand& h);
  bool hash_delete(const Block& b, const HashCommand& h);
  bool hash_pre_if(const Block& b, const HashCommand& h);  // #IF / #ELSE skips
  // channel synchronisation (signals.cpp)
  bool hash_signal(const Block& b, const HashCommand& h);  // #SIGNAL, #WAIT, #SIGNAL READ
  std::optional<Signal> signal_parts(const Block& b, const HashCommand& h, bool report);
  std::optional<double> signal_value(const Block& b, grammar::ast::NodeIndex n, bool report);
  std::optional<std::uint32_t> signal_integer(const Block& b, const grammar::ast::Item& it,
                                              const char* id, double low, double high,
                                              const std::string& what, bool report);
  bool hash_accepted(const Block& b);  // # commands read without an effect

  Interpreter::Impl& ip_;
};

}  // namespace ncsim::interp
