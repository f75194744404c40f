// Dynamics weightings G127..G133, G230, G231, G233 (TF5200 PROG-206573067, PROG-206578955,
// PROG-206590731, PROG-206596619): each selection from 100 %, limits ncsim keeps (NC4314).
#include "interp/weights.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "interp/interpreter.hpp"
#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

const std::vector<std::string> kNames{"X", "Y", "Z"};

TEST_CASE("an axis-specific weighting sets the named axes and puts the others back to 100 %") {
  DynamicsWeights w;
  const std::pair<std::uint8_t, double> x70[] = {{0, 70.0}};
  CHECK(apply_weighting(w, 130, {}, x70, kNames).empty());
  CHECK(w.a_feed[0] == doctest::Approx(0.7));
  CHECK(w.a_feed[1] == 1.0);
  const std::pair<std::uint8_t, double> y60[] = {{1, 60.0}};
  apply_weighting(w, 130, {}, y60, kNames);
  CHECK(w.a_feed[0] == 1.0);  // "each further selection ... signifies 100 %"
  CHECK(w.a_feed[1] == doctest::Approx(0.6));
  CHECK(w.a_rapid[1] == 1.0);  // G130 weights feed blocks only
}

TEST_CASE("group weightings: 50 % twice is 50 %; G129 and G233 weight G00") {
  DynamicsWeights w;
  apply_weighting(w, 131, 50.0, {}, kNames);
  apply_weighting(w, 131, 50.0, {}, kNames);
  for (double a : w.a_feed)
    CHECK(a == doctest::Approx(0.5));
  apply_weighting(w, 129, 70.0, {}, kNames);
  CHECK(w.v_rapid == doctest::Approx(0.7));
  apply_weighting(w, 233, 200.0, {}, kNames);
  CHECK(w.ramp_rapid == doctest::Approx(2.0));
  apply_weighting(w, 128, 25.0, {}, kNames);
  CHECK(w.v_feed[2] == doctest::Approx(0.25));
  apply_weighting(w, 131, 100.0, {}, kNames);
  CHECK(w.a_feed == DynamicsWeights{}.a_feed);
}

TEST_CASE("NC4314: more than the lists allow is limited to 100 %, 0 % to 1 %") {
  DynamicsWeights w;
  const std::pair<std::uint8_t, double> x150[] = {{0, 150.0}};
  const auto notes = apply_weighting(w, 130, {}, x150, kNames);
  REQUIRE(notes.size() == 1);
  CHECK(notes[0].find("G130 X = 150 % is limited to 100 %") != std::string::npos);
  CHECK(w.a_feed[0] == 1.0);
  CHECK(apply_weighting(w, 133, 50.0, {}, kNames).size() == 1);  // a shorter ramp: more jerk
  CHECK(w.ramp_feed[0] == 1.0);
  CHECK(apply_weighting(w, 128, 0.0, {}, kNames).size() == 1);
  CHECK(w.v_feed[0] == doctest::Approx(0.01));
  CHECK(apply_weighting(w, 131, std::nan(""), {}, kNames).size() == 1);
  CHECK(w.a_feed[0] == 1.0);  // a weight that is no number changes nothing
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
