#include "machines/cs_stack.hpp"

#include <algorithm>

namespace ncsim::machines {
namespace {

CsError error(std::string id, std::string message) {
  return CsError{std::move(id), std::move(message)};
}

std::optional<CsError> check_id(int id) {
  if (id < 1) return error("NC3101", "#CS id " + std::to_string(id) + " must be 1 or more");
  return std::nullopt;
}

}  // namespace

std::optional<CsError> CsStack::store(int id, bool automatic, const CsValues& values) {
  const Frame frame = Frame::from_angles(values.v_mm, values.phi_deg, sequence_);
  const auto it =
      std::find_if(stored_.begin(), stored_.end(), [id](const Stored& s) { return s.id == id; });
  if (it != stored_.end()) {
    it->frame = frame;
  } else {
    if (stored_.size() >= kMaxStored) {
      return error("NC3102", "#CS: cannot store another coordinate system; at most " +
                                 std::to_string(kMaxStored) + " are stored");
    }
    stored_.push_back(Stored{id, automatic, frame});
  }
  last_defined_ = id;
  return std::nullopt;
}

std::optional<CsError> CsStack::activate(int id) {
  const auto it =
      std::find_if(stored_.begin(), stored_.end(), [id](const Stored& s) { return s.id == id; });
  if (it == stored_.end()) {
    return error("NC3103", "#CS ON: coordinate system " + std::to_string(id) + " is not defined");
  }
  if (active_.size() >= kMaxActive) {
    return error("NC3104", "#CS ON: at most " + std::to_string(kMaxActive) +
                               " coordinate systems can be chained");
  }
  active_.push_back(Active{id, it->frame});
  return std::nullopt;
}

std::optional<CsError> CsStack::def(std::optional<int> id, const CsValues& values) {
  if (id) {
    if (auto e = check_id(*id)) return e;
    return store(*id, false, values);
  }
  const int automatic_id = next_automatic_;
  if (auto e = store(automatic_id, true, values)) return e;
  --next_automatic_;
  return std::nullopt;
}

std::optional<CsError> CsStack::on(std::optional<int> id, const std::optional<CsValues>& values) {
  if (values) {
    const int target = id.value_or(next_automatic_);
    if (auto e = def(id, *values)) return e;
    return activate(target);
  }
  if (id) {
    if (auto e = check_id(*id)) return e;
    return activate(*id);
  }
  if (last_defined_ == 0 || !is_defined(last_defined_)) {
    return error("NC3103", "#CS ON without an id: no coordinate system is defined");
  }
  return activate(last_defined_);
}

std::optional<CsError> CsStack::off() {
  if (active_.empty()) return error("NC3105", "#CS OFF: no coordinate system is active");
  const int id = active_.back().id;
  active_.pop_back();
  drop_automatic_if_inactive(id);
  return std::nullopt;
}

void CsStack::off_all() {
  while (!active_.empty()) {
    const int id = active_.back().id;
    active_.pop_back();
    drop_automatic_if_inactive(id);
  }
}

void CsStack::drop_automatic_if_inactive(int id) {
  const bool still_active =
      std::any_of(active_.begin(), active_.end(), [id](const Active& a) { return a.id == id; });
  if (still_active) return;
  std::erase_if(stored_, [id](const Stored& s) { return s.id == id && s.automatic; });
}

Frame CsStack::active_frame() const {
  if (active_.empty()) return Frame::identity();
  Frame f = Frame::shift(base_mm_);
  for (const Active& a : active_)
    f = f * a.frame;
  return f;
}

bool CsStack::is_defined(int id) const {
  return std::any_of(stored_.begin(), stored_.end(), [id](const Stored& s) { return s.id == id; });
}

}  // namespace ncsim::machines
