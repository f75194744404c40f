// The conveyor workspace (seed 004 §2.1.3, §4.4.1; A16: laser X [-200, 4000], Y [-200, 2500],
// Z [-100, 300] from the soft limits).

#include "tracking/workspace.hpp"

#include <doctest/doctest.h>

namespace {

using namespace ncsim::tracking;

ncsim::machines::Workspace laser() {
  ncsim::machines::Workspace w;
  w.lower = Eigen::Vector3d(-200.0, -200.0, -100.0);
  w.upper = Eigen::Vector3d(4000.0, 2500.0, 300.0);
  return w;
}

TEST_CASE("inside the cuboid nothing is reported, faces included") {
  const Eigen::Vector3d e = Eigen::Vector3d::UnitX();
  CHECK_FALSE(check_workspace(laser(), e, Eigen::Vector3d(0.0, 0.0, 0.0)));
  CHECK_FALSE(check_workspace(laser(), e, Eigen::Vector3d(4000.0, 2500.0, -100.0)));
}

TEST_CASE("the faces are classed by the conveying direction") {
  const Eigen::Vector3d e = Eigen::Vector3d::UnitX();
  auto v = check_workspace(laser(), e, Eigen::Vector3d(4000.5, 0.0, 0.0));
  REQUIRE(v);
  CHECK(v->face == WorkspaceFace::conveying);
  CHECK(v->upper);
  CHECK(v->limit == 4000.0);
  v = check_workspace(laser(), e, Eigen::Vector3d(-201.0, 0.0, 0.0));
  REQUIRE(v);
  CHECK(v->face == WorkspaceFace::against);
  // The laser program's first violation (A16): Y -> 2550 against 2500.
  v = check_workspace(laser(), e, Eigen::Vector3d(100.0, 2550.0, 0.0));
  REQUIRE(v);
  CHECK(v->face == WorkspaceFace::side);
  CHECK(v->coord == 1);
  CHECK(v->value == 2550.0);
  // A belt moving in -X of MCS (T0 C = 180 deg): the lower X face is the conveying one.
  v = check_workspace(laser(), -e, Eigen::Vector3d(-201.0, 0.0, 0.0));
  REQUIRE(v);
  CHECK(v->face == WorkspaceFace::conveying);
}

}  // namespace
