#include "interp/block_source.hpp"

#include <cstdlib>
#include <string>

namespace ncsim::interp {
namespace {

constexpr std::uint32_t kDeclarationBit = 0x80000000u;

void shift(core::SourceLoc& loc, std::uint32_t delta) {
  if (loc.line != 0) loc.line += delta;
}

}  // namespace

void shift_lines(grammar::ast::Block& block, std::uint32_t delta) {
  namespace ast = grammar::ast;
  shift(block.loc, delta);
  if (block.number) shift(block.number->loc, delta);
  if (block.label) shift(block.label->loc, delta);
  if (auto* c = std::get_if<ast::Control>(&block.body)) {
    shift(c->loc, delta);
    shift(c->target.loc, delta);
  } else if (auto* h = std::get_if<ast::HashCommand>(&block.body)) {
    shift(h->loc, delta);
  } else if (auto* d = std::get_if<ast::Declaration>(&block.body)) {
    shift(d->loc, delta);
  }
  for (auto& w : block.words)
    shift(w.loc, delta);
  for (auto& a : block.axis_commands)
    shift(a.loc, delta);
  if (block.call) shift(block.call->loc, delta);
  if (block.trailing_goto) {
    shift(block.trailing_goto->loc, delta);
    shift(block.trailing_goto->target.loc, delta);
  }
  for (auto& i : block.items)
    shift(i.loc, delta);
  for (auto& e : block.exprs)
    shift(e.loc, delta);
}

BlockSource::BlockSource(const core::SourceFile& file)
    : file_(file), parser_(file), slots_(kCacheSlots) {}

bool BlockSource::parse_next(Slot& slot, core::DiagnosticList& diags) {
  if (parser_done_) return false;
  if (!parser_.next(slot.block, diags)) {
    parser_done_ = true;
    return false;
  }
  slot.own.reset();
  const bool declaration = std::holds_alternative<grammar::ast::Declaration>(slot.block.body);
  std::uint32_t length = static_cast<std::uint32_t>(slot.block.text.size());
  if (declaration) length |= kDeclarationBit;
  index_.push_back({static_cast<std::uint32_t>(slot.block.offset), length, slot.block.loc.line});
  slot.ordinal = static_cast<std::uint32_t>(index_.size() - 1);
  return true;
}

void BlockSource::reparse(std::uint32_t ordinal, Slot& slot) {
  const IndexEntry& entry = index_[ordinal];
  const bool declaration = (entry.length & kDeclarationBit) != 0;
  const std::uint32_t length = entry.length & ~kDeclarationBit;
  std::string text(file_.text().substr(entry.offset, length));
  if (declaration) text = "#VAR\n" + text + "\n#ENDVAR\n";
  auto own = std::make_unique<core::SourceFile>(file_.name(), std::move(text));
  grammar::BlockParser parser(*own);
  core::DiagnosticList ignored;  // reported at the first parse already
  bool ok = parser.next(slot.block, ignored);
  if (ok && declaration) ok = parser.next(slot.block, ignored);
  if (!ok) std::abort();  // the same text parsed before: broken invariant
  shift_lines(slot.block, entry.line - 1 - (declaration ? 1u : 0u));
  slot.block.offset = entry.offset;
  slot.own = std::move(own);
  slot.ordinal = ordinal;
}

const grammar::ast::Block* BlockSource::fetch(std::uint32_t ordinal, core::DiagnosticList& diags) {
  Slot& slot = slots_[ordinal & (kCacheSlots - 1)];
  if (slot.ordinal == ordinal) return &slot.block;
  if (ordinal < index_.size()) {
    reparse(ordinal, slot);
    return &slot.block;
  }
  while (index_.size() <= ordinal) {
    Slot& target = slots_[index_.size() & (kCacheSlots - 1)];
    target.ordinal = 0xFFFFFFFFu;
    if (!parse_next(target, diags)) return nullptr;
  }
  return &slot.block;
}

const grammar::ast::Block* BlockSource::parse_text(std::string text, std::uint32_t line,
                                                   core::DiagnosticList& diags) {
  auto own = std::make_unique<core::SourceFile>(file_.name(), std::move(text));
  grammar::BlockParser parser(*own);
  core::DiagnosticList local;
  if (!parser.next(scratch_.block, local)) return nullptr;
  for (auto d : local.items()) {
    d.loc.line += line - 1;
    diags.add(std::move(d));
  }
  shift_lines(scratch_.block, line - 1);
  scratch_.own = std::move(own);
  return &scratch_.block;
}

}  // namespace ncsim::interp
