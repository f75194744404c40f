#include "axes/modulo.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace ncsim::axes {
namespace {

struct TableRow {
  ModuloDirection direction;
  double start;
  double target;
  int turns;
  double distance;  // relative path of the manual's table
  ModuloStatus status;
};

constexpr ModuloDirection kPos = ModuloDirection::positive;
constexpr ModuloDirection kNeg = ModuloDirection::negative;
constexpr ModuloDirection kShort = ModuloDirection::shortest_way;
constexpr ModuloStatus kOk = ModuloStatus::ok;
constexpr ModuloStatus kBadTarget = ModuloStatus::invalid_target_position;
constexpr ModuloStatus kBadTurns = ModuloStatus::invalid_additional_turn_count;

TEST_CASE("every example of 000 9.1 (modulo factor 100, tolerance window 1) is reproduced") {
  // 000_* 9.1, example table. For start 112 the table's "absolute end position" column says
  // 110 / 410 while its relative path (98 / 398) gives 210 / 510; we follow the relative path
  // and the modulo end position, which agree with each other and with every other row.
  const TableRow rows[] = {
      {kPos, 110, 10, 0, 0, kOk},         {kPos, 110.9, 10, 0, -0.9, kOk},
      {kPos, 112, 10, 0, 98, kOk},        {kPos, 95, 10, 0, 15, kOk},
      {kPos, 110, 110, 0, 0, kBadTarget}, {kPos, 110, 10, 3, 300, kOk},
      {kPos, 110.9, 10, 3, 299.1, kOk},   {kPos, 112, 10, 3, 398, kOk},
      {kPos, 95, 10, 3, 315, kOk},        {kPos, 110, 110, 3, 0, kBadTarget},
      {kNeg, 110, 10, 0, 0, kOk},         {kNeg, 109.9, 10, 0, 0.1, kOk},
      {kNeg, 108, 10, 0, -98, kOk},       {kNeg, 95, 10, 0, -85, kOk},
      {kNeg, 110, 110, 0, 0, kBadTarget}, {kNeg, 410, 10, 3, -300, kOk},
      {kNeg, 409.9, 10, 3, -299.9, kOk},  {kNeg, 408, 10, 3, -398, kOk},
      {kNeg, 495, 10, 3, -385, kOk},      {kNeg, 410, 110, 3, 0, kBadTarget},
      {kShort, 440, 50, 0, 10, kOk},      {kShort, 440, 10, 0, -30, kOk},
      {kShort, 440, 50, 1, 0, kBadTurns},
  };
  const ModuloParams params{100.0, 1.0};
  for (const TableRow& row : rows) {
    CAPTURE(row.start);
    CAPTURE(row.target);
    CAPTURE(row.turns);
    const ModuloMove move =
        plan_modulo(params, ModuloRequest{row.start, row.target, row.direction, row.turns});
    CHECK(move.status == row.status);
    if (row.status != kOk) continue;
    CHECK(move.distance == doctest::Approx(row.distance).epsilon(1e-12));
    CHECK(move.end_position == doctest::Approx(row.start + row.distance).epsilon(1e-12));
    CHECK(move.end_modulo == row.target);
    CHECK(modulo_position(move.end_position, 100.0) == doctest::Approx(row.target));
  }
}

TEST_CASE("outside the tolerance window the requested direction is kept") {
  const ModuloParams params{360.0, 0.5};
  // 0.6 deg past the target: a full turn less 0.6 forward, 0.6 back.
  CHECK(plan_modulo(params, {90.6, 90.0, kPos, 0}).distance == doctest::Approx(359.4));
  CHECK(plan_modulo(params, {90.4, 90.0, kPos, 0}).distance == doctest::Approx(-0.4));
  CHECK(plan_modulo(params, {89.4, 90.0, kNeg, 0}).distance == doctest::Approx(-359.4));
  // Exactly on the window edge still counts as inside ("less than or equal").
  CHECK(plan_modulo(ModuloParams{100.0, 1.0}, {111.0, 10.0, kPos, 0}).distance ==
        doctest::Approx(-1.0));
}

TEST_CASE("negative absolute positions and a negative turn count") {
  const ModuloParams params{360.0, 0.0};
  CHECK(modulo_position(-30.0, 360.0) == doctest::Approx(330.0));
  const ModuloMove move = plan_modulo(params, {-30.0, 10.0, kPos, 0});
  CHECK(move.distance == doctest::Approx(40.0));
  CHECK(move.end_position == doctest::Approx(10.0));
  CHECK(plan_modulo(params, {0.0, 10.0, kPos, -1}).status == kBadTurns);
  CHECK(plan_modulo(params, {0.0, -1.0, kPos, 0}).status == kBadTarget);
  CHECK(plan_modulo(params, {0.0, 360.0, kPos, 0}).status == kBadTarget);
}

TEST_CASE("the shortest way takes half a turn in positive direction") {
  const ModuloParams params{360.0, 0.0};
  CHECK(plan_modulo(params, {0.0, 180.0, kShort, 0}).distance == doctest::Approx(180.0));
  CHECK(plan_modulo(params, {0.0, 181.0, kShort, 0}).distance == doctest::Approx(-179.0));
}

TEST_CASE("a signed modulo position sets direction and turns (002 2.1)") {
  // +540 with factor 360: one extra turn, then 180 positive.
  ModuloRequest request = from_signed_modulo_position(0.0, 540.0, 360.0);
  CHECK(request.direction == kPos);
  CHECK(request.additional_turns == 1);
  CHECK(request.target == doctest::Approx(180.0));
  CHECK(plan_modulo(ModuloParams{}, request).distance == doctest::Approx(540.0));
  // 0.0 counts as positive; -1e-6 approaches 0 in negative direction.
  CHECK(from_signed_modulo_position(10.0, 0.0, 360.0).direction == kPos);
  request = from_signed_modulo_position(10.0, -1e-6, 360.0);
  CHECK(request.direction == kNeg);
  CHECK(plan_modulo(ModuloParams{}, request).distance == doctest::Approx(-10.0));
  // Keeping the direction: from 350, +10 goes forward 20, -10 goes back 340.
  CHECK(plan_modulo(ModuloParams{}, from_signed_modulo_position(350.0, 10.0, 360.0)).distance ==
        doctest::Approx(20.0));
  CHECK(plan_modulo(ModuloParams{}, from_signed_modulo_position(350.0, -10.0, 360.0)).distance ==
        doctest::Approx(-340.0));
  CHECK(plan_modulo(ModuloParams{}, from_signed_modulo_position(0.0, NAN, 360.0)).status ==
        kBadTarget);
}

TEST_CASE("invalid modulo parameters throw naming the parameter") {
  CHECK_THROWS_WITH_AS(plan_modulo(ModuloParams{0.0, 0.0}, {}), doctest::Contains("Modulo Factor"),
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(plan_modulo(ModuloParams{360.0, -1.0}, {}),
                       doctest::Contains("Tolerance Window"), std::invalid_argument);
}

TEST_CASE("property: the end position always lies on the target, in the requested direction") {
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> start_dist(-5000.0, 5000.0);
  std::uniform_real_distribution<double> target_dist(0.0, 360.0);
  std::uniform_int_distribution<int> turns_dist(0, 4);
  const ModuloParams params{360.0, 0.2};
  for (int i = 0; i < 2000; ++i) {
    const double start = start_dist(rng);
    const double target = target_dist(rng);
    const int turns = turns_dist(rng);
    const auto direction = static_cast<ModuloDirection>(i % 3);
    const ModuloMove move =
        plan_modulo(params, {start, target, direction, direction == kShort ? 0 : turns});
    REQUIRE(move.status == kOk);
    const double end_mod = modulo_position(move.end_position, 360.0);
    const double off = std::fabs(end_mod - target);
    CHECK(std::min(off, 360.0 - off) < 1e-9);
    const double base = direction == kPos   ? move.distance - 360.0 * turns
                        : direction == kNeg ? move.distance + 360.0 * turns
                                            : move.distance;
    CHECK(std::fabs(base) < 360.0);
    if (std::fabs(base) > params.tolerance + 1e-9) {
      if (direction == kPos) CHECK(base > 0.0);
      if (direction == kNeg) CHECK(base < 0.0);
      if (direction == kShort) CHECK(std::fabs(base) <= 180.0 + 1e-9);
    }
  }
}

}  // namespace
}  // namespace ncsim::axes
