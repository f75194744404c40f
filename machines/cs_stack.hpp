#pragma once
// machines/cs_stack: the #CS coordinate-system stack (isg-language.md §5.8) as a value type.
//
// Inputs: #CS DEF / ON / OFF / OFF ALL operations with an optional id and optional values
// (v1..v3 [mm], phi1..phi3 [deg]). Outputs: the composed frame PCS -> PCS1 of all active
// systems, and errors as values (never thrown).
// Rules (§5.8 [C]): at most 5 systems are stored; ON without an id activates the last defined
// system; OFF deactivates the last activated one; OFF ALL deactivates all; activating again
// chains (stacks) the systems; a system defined without an id gets an automatic one that is
// lost when it is switched off.
// Decisions (docs/machines.md "#CS stack"): ids are integers >= 1; at most 5 activations are
// chained; the chain keeps the frame a system had when it was activated (a later DEF of the
// same id applies from its next activation); the frame of a system is built with the rotation
// sequence in force when it is defined.
// The base (docs/interp.md "Zero offsets under #CS"): a CS is defined relative to the workpiece
// coordinate system, whose position in the MCS the zero offset, #PSET and G92 give (TF5200
// "Definition of a machining coordinate system"); the X/Y/Z offsets in force are the base the
// chain sits on while a system is active.
// Invariants: stored().size() <= kMaxStored, active_count() <= kMaxActive.

#include <optional>
#include <string>
#include <vector>

#include "machines/frame.hpp"

namespace ncsim::machines {

struct CsError {
  std::string id;       ///< NC31xx
  std::string message;  ///< names the id and what was wrong
};

/// The bracket values of a #CS command.
struct CsValues {
  Eigen::Vector3d v_mm = Eigen::Vector3d::Zero();  ///< v1..v3 [mm], G17 main-axis order
  std::array<double, 3> phi_deg{0.0, 0.0, 0.0};    ///< phi1..phi3 [deg] in sequence order
};

class CsStack {
 public:
  static constexpr std::size_t kMaxStored = 5;  ///< §5.8: at most 5 systems stored
  static constexpr std::size_t kMaxActive = 5;  ///< ncsim decision: chain depth

  explicit CsStack(RotationSequence sequence = RotationSequence::ZYX) : sequence_(sequence) {}

  /// #CS DEF [id][values]
  std::optional<CsError> def(std::optional<int> id, const CsValues& values);
  /// #CS ON [id][values] / #CS ON [id] / #CS ON
  std::optional<CsError> on(std::optional<int> id, const std::optional<CsValues>& values);
  /// #CS OFF
  std::optional<CsError> off();
  /// #CS OFF ALL
  void off_all();
  /// #CS MODE ON [ROTATION_SEQUENCE ..]: applies to systems defined afterwards.
  void set_rotation_sequence(RotationSequence sequence) { sequence_ = sequence; }

  /// The X/Y/Z zero offsets [mm] (MCS) the active chain sits on.
  void set_base(const Eigen::Vector3d& base_mm) { base_mm_ = base_mm; }
  const Eigen::Vector3d& base() const { return base_mm_; }

  /// Composition of the active systems on their base: first activated is outermost (maps
  /// PCS -> PCS1); the identity when none is active.
  Frame active_frame() const;
  std::size_t active_count() const { return active_.size(); }
  std::size_t stored_count() const { return stored_.size(); }
  bool is_defined(int id) const;

 private:
  struct Stored {
    int id;          // >= 1 for user ids, < 0 for automatic ones
    bool automatic;  // lost after OFF
    Frame frame;
  };
  struct Active {
    int id;
    Frame frame;
  };

  std::optional<CsError> store(int id, bool automatic, const CsValues& values);
  std::optional<CsError> activate(int id);
  void drop_automatic_if_inactive(int id);

  RotationSequence sequence_;
  std::vector<Stored> stored_;
  std::vector<Active> active_;
  Eigen::Vector3d base_mm_ = Eigen::Vector3d::Zero();  // [mm]
  int last_defined_ = 0;                               // 0: none yet
  int next_automatic_ = -1;                            // automatic ids count downwards
};

}  // namespace ncsim::machines
