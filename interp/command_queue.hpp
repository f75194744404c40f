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
#include <utility>
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
  void emplace_back(std::uint32_t line, std::uint16_t file, CommandBody&& body) {
    items_.push_back(Command{line, file, std::move(body)});
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
