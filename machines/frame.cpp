#include "machines/frame.hpp"

#include <cmath>
#include <numbers>

namespace ncsim::machines {
namespace {

struct SequenceName {
  RotationSequence sequence;
  std::string_view name;
};

constexpr std::array<SequenceName, 12> kSequences = {{
    {RotationSequence::XYZ, "XYZ"},
    {RotationSequence::XZY, "XZY"},
    {RotationSequence::YXZ, "YXZ"},
    {RotationSequence::YZX, "YZX"},
    {RotationSequence::ZXY, "ZXY"},
    {RotationSequence::ZYX, "ZYX"},
    {RotationSequence::XYX, "XYX"},
    {RotationSequence::XZX, "XZX"},
    {RotationSequence::YXY, "YXY"},
    {RotationSequence::YZY, "YZY"},
    {RotationSequence::ZXZ, "ZXZ"},
    {RotationSequence::ZYZ, "ZYZ"},
}};

Eigen::Vector3d unit_axis(char letter) {
  switch (letter) {
    case 'X':
      return Eigen::Vector3d::UnitX();
    case 'Y':
      return Eigen::Vector3d::UnitY();
    default:
      return Eigen::Vector3d::UnitZ();
  }
}

double rad(double deg) {
  return deg * std::numbers::pi / 180.0;
}

}  // namespace

std::optional<RotationSequence> parse_rotation_sequence(std::string_view text) {
  for (const SequenceName& s : kSequences) {
    if (s.name == text) return s.sequence;
  }
  return std::nullopt;
}

std::string_view to_string(RotationSequence sequence) {
  for (const SequenceName& s : kSequences) {
    if (s.sequence == sequence) return s.name;
  }
  return "?";
}

Eigen::Matrix3d rotation_from_angles(const std::array<double, 3>& angles_deg,
                                     RotationSequence sequence) {
  const std::string_view letters = to_string(sequence);
  // Intrinsic rotations: the first letter is the outermost factor.
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  for (std::size_t i = 0; i < 3; ++i) {
    r = r * Eigen::AngleAxisd(rad(angles_deg[i]), unit_axis(letters[i])).toRotationMatrix();
  }
  return r;
}

Frame Frame::shift(const Eigen::Vector3d& translation_mm) {
  Frame f;
  f.translation = translation_mm;
  return f;
}

Frame Frame::from_angles(const Eigen::Vector3d& translation_mm,
                         const std::array<double, 3>& angles_deg, RotationSequence sequence) {
  Frame f;
  f.rotation = rotation_from_angles(angles_deg, sequence);
  f.translation = translation_mm;
  return f;
}

Frame Frame::inverse() const {
  Frame f;
  f.rotation = rotation.transpose();
  f.translation = -(f.rotation * translation);
  return f;
}

Frame operator*(const Frame& outer, const Frame& inner) {
  Frame f;
  f.rotation = outer.rotation * inner.rotation;
  f.translation = outer.rotation * inner.translation + outer.translation;
  return f;
}

Frame t0_frame(const Eigen::Vector3d& shift_mm, const Eigen::Vector3d& rot_abc_deg) {
  // R = Rz(C) * Ry(B) * Rx(A): the ZYX sequence with angles (C, B, A).
  return Frame::from_angles(shift_mm, {rot_abc_deg.z(), rot_abc_deg.y(), rot_abc_deg.x()},
                            RotationSequence::ZYX);
}

}  // namespace ncsim::machines
