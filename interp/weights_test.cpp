// Dynamics weightings G127..G133, G230, G231, G233 (TF5200 PROG-206573067, PROG-206578955,
// PROG-206590731, PROG-206596619): each selection from 100 %, limits ncsim keeps (NC4314).
#include "interp/weights.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "interp/interpreter.hpp"
#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

// portal_3x's axes X, Y, Z (machine indices 0, 1, 2) name the weighted axes in the notes.
std::span<const machines::AxisParams> axes() {
  return test::machine("portal_3x").axes;
}

TEST_CASE("an axis-specific weighting sets the named axes and puts the others back to 100 %") {
  DynamicsWeights w;
  const std::pair<std::uint8_t, double> x70[] = {{0, 70.0}};
  CHECK(apply_weighting(w, 130, {}, x70, axes()).empty());
  CHECK(w.a_feed[0] == doctest::Approx(0.7));
  CHECK(w.a_feed[1] == 1.0);
  const std::pair<std::uint8_t, double> y60[] = {{1, 60.0}};
  apply_weighting(w, 130, {}, y60, axes());
  CHECK(w.a_feed[0] == 1.0);  // "each further selection ... signifies 100 %"
  CHECK(w.a_feed[1] == doctest::Approx(0.6));
  CHECK(w.a_rapid[1] == 1.0);  // G130 weights feed blocks only
}

TEST_CASE("group weightings: 50 % twice is 50 %; G129 and G233 weight G00") {
  DynamicsWeights w;
  apply_weighting(w, 131, 50.0, {}, axes());
  apply_weighting(w, 131, 50.0, {}, axes());
  for (double a : w.a_feed)
    CHECK(a == doctest::Approx(0.5));
  apply_weighting(w, 129, 70.0, {}, axes());
  CHECK(w.v_rapid == doctest::Approx(0.7));
  apply_weighting(w, 233, 200.0, {}, axes());
  CHECK(w.ramp_rapid == doctest::Approx(2.0));
  apply_weighting(w, 128, 25.0, {}, axes());
  CHECK(w.v_feed[2] == doctest::Approx(0.25));
  apply_weighting(w, 131, 100.0, {}, axes());
  CHECK(w.a_feed == DynamicsWeights{}.a_feed);
}

TEST_CASE("NC4314: more than the lists allow is limited to 100 %, 0 % to 1 %") {
  DynamicsWeights w;
  const std::pair<std::uint8_t, double> x150[] = {{0, 150.0}};
  const auto notes = apply_weighting(w, 130, {}, x150, axes());
  REQUIRE(notes.size() == 1);
  CHECK(notes[0].find("G130 X = 150 % is limited to 100 %") != std::string::npos);
  CHECK(w.a_feed[0] == 1.0);
  CHECK(apply_weighting(w, 133, 50.0, {}, axes()).size() == 1);  // a shorter ramp: more jerk
  CHECK(w.ramp_feed[0] == 1.0);
  CHECK(apply_weighting(w, 128, 0.0, {}, axes()).size() == 1);
  CHECK(w.v_feed[0] == doctest::Approx(0.01));
  CHECK(apply_weighting(w, 131, std::nan(""), {}, axes()).size() == 1);
  CHECK(w.a_feed[0] == 1.0);  // a weight that is no number changes nothing
}

TEST_CASE("the interpreter warns NC4314 at the weighting's block for each limited value") {
  const test::Run r =
      test::run_on_machine(core::SourceFile("t.nc", "%t\nG130 X150 Y50\nG133=50\nM30\n"),
                           test::machine("portal_3x"), {}, 1000, true);
  REQUIRE(r.error_id.empty());
  int limited = 0;
  for (const auto& l : r.lines)
    limited += l.find("warning NC4314") != std::string::npos;
  CHECK(limited == 2);  // X at 150 %, the ramp time at 50 %; Y's 50 % is applied as written
}

TEST_CASE("the interpreter carries the weights in force with each motion, one shared value") {
  const machines::Machine m = test::machine("portal_3x");
  const core::SourceFile file("t.nc",
                              "%t\nG01 X1 F600\nG131=50 X2\nG01 X3\nG131=100\nG01 X4\nM30\n");
  Interpreter interp(file, m);
  std::vector<std::shared_ptr<const DynamicsWeights>> seen;
  while (auto c = interp.next())
    if (const auto* mo = std::get_if<Motion>(&c->body)) seen.push_back(mo->modal.weights);
  REQUIRE(seen.size() == 4);
  CHECK(seen[0] == nullptr);
  REQUIRE(seen[1] != nullptr);  // G131=50 X2: the block's own motion is weighted
  CHECK(seen[1]->a_feed[0] == doctest::Approx(0.5));
  CHECK(seen[2] == seen[1]);  // modal, and the same value, not a copy
  CHECK(seen[3] == nullptr);  // back to 100 %: none
}

}  // namespace
}  // namespace ncsim::interp
