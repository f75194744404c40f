#pragma once
// interp/command_queue: the decoder's first-in first-out queues of commands (the commands a
// block emitted, and those the tool radius compensation released).
//
// Purpose: std::deque allocates a node for every Command (a Command is larger than a deque
// node holds twice, so each node holds one), one allocation and one free per command on the
// path of every block. This queue keeps its storage: a vector and the index of its front; the
// storage is reused once the queue has run empty (Interpreter::next() decodes a block only
// when both queues are empty), and is compacted when half of it is taken, so that it stays
// about as large as the most commands queued at once.
// Invariant: head_ <= items_.size(); items_[head_, size) are the queued commands in order.

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "interp/command.hpp"

namespace ncsim::interp {

class CommandQueue {
 public:
  bool empty() const { return head_ == items_.size(); }
  std::size_t size() const { return items_.size() - head_; }
  /// The oldest command; the queue must not be empty.
  Command& front() { return items_[head_]; }
  void push_back(Command&& c) { items_.push_back(std::move(c)); }
  void push_back(const Command& c) { items_.push_back(c); }
  /// Appends Command{line, file, body}. (Command is an aggregate: emplace_back(line, file,
  /// body) needs parenthesised aggregate initialisation, which clang 14 lacks.)
  /// `body` is one of CommandBody's alternatives (or a CommandBody): it is moved once into the
  /// new Command, which is moved once into the storage.
  template <typename Body>
  void emplace_back(std::uint32_t line, std::uint16_t file, Body&& body) {
    items_.push_back(Command{line, file, CommandBody(std::forward<Body>(body))});
  }
  /// Appends a Command{line, file} holding a default Body and returns that body, to be filled
  /// in place (a motion is built where it is queued, not moved there).
  template <typename Body>
  Body& emplace_default(std::uint32_t line, std::uint16_t file) {
    Command& c = items_.emplace_back();
    c.line = line;
    c.file = file;
    if constexpr (std::is_same_v<Body, std::variant_alternative_t<0, CommandBody>>) {
      return *std::get_if<0>(&c.body);  // the default body, value-initialised already
    } else {
      return c.body.template emplace<Body>();
    }
  }
  /// Removes the newest command (one emplace_default() gave up); the queue must not be empty.
  void pop_back() {
    items_.pop_back();
    if (head_ == items_.size()) clear();
  }
  /// Removes the oldest command; the queue must not be empty.
  void pop_front() {
    ++head_;
    if (head_ == items_.size()) {
      clear();
    } else if (head_ >= kCompactAt && 2 * head_ >= items_.size()) {
      items_.erase(items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(head_));
      head_ = 0;
    }
  }
  void clear() {
    items_.clear();
    head_ = 0;
  }

 private:
  static constexpr std::size_t kCompactAt = 64;  // taken commands kept before compacting
  std::vector<Command> items_;
  std::size_t head_ = 0;
};

}  // namespace ncsim::interp
