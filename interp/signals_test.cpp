// #SIGNAL, #WAIT and #SIGNAL READ in the interpreter (docs/lines.md): the commands and the
// barrier they make, their answers, and the manual's ids (PROG-207409035, PROG-207421579,
// PROG-913718283; diagnosis 20995, 20996, 21056, 21344, 21549, 250008).
#include <doctest/doctest.h>

#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

using test::run;

Options channels(std::vector<std::uint8_t> list) {
  Options o;
  o.channels = std::move(list);
  return o;
}

TEST_CASE("#SIGNAL, #SIGNAL SYN and #WAIT SYN become commands with their ids and channels") {
  auto r =
      run("%t\nP1 = 2.5\n#SIGNAL [ID3 COUNT2 P[0]=P1 CH2]\n#SIGNAL SYN [ID=4]\n"
          "#WAIT SYN [ID=5 CH=1 CH=2]\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(0) == "3: SIGNAL ID3 COUNT2 P[0]=2.5000 CH2");
  CHECK(r.lines.at(1) == "4: SIGNAL SYN ID4 BROADCAST");
  CHECK(r.lines.at(2) == "5: WAIT SYN ID5 CH1 CH2");
}

TEST_CASE("#WAIT and #SIGNAL READ stop the decoder at a barrier; check reads no signal") {
  auto r =
      run("%t\n#WAIT [ID7 CH2]\n#SIGNAL READ [ID8]\n$IF V.G.SIGNAL_READ == 0\nG01 X5 F100\n$ENDIF\n"
          "M30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(0) == "2: BARRIER WAIT ID7 CH2");
  CHECK(r.lines.at(1) == "3: BARRIER SIGNAL_READ ID8 BROADCAST");
  CHECK(r.lines.at(2).rfind("5: G01", 0) == 0);  // decode-only: V.G.SIGNAL_READ is FALSE
  // decode-only: the parameters received are 0, so a program computing with them checks
  const auto p = run("%t\n#WAIT [ID7 P[0]=P6 CH2]\nG01 X[P6 + 1] F100\nM30\n");
  REQUIRE(p.error_id.empty());
  CHECK(p.full.at(1).find("X=1.0000") != std::string::npos);
}

TEST_CASE("the run time's answer reaches the #WAIT's targets and V.G.SIGNAL_READ") {
  const core::SourceFile file("t.nc",
                              "%t\n#WAIT [ID7 P[1]=P6 P[0]=P5 CH2]\n#SIGNAL READ [ID8]\n"
                              "G01 X[P6 + P5 + V.G.SIGNAL_READ] F100\nM30\n");
  Options o = channels({1, 2});
  Interpreter interp(file, test::machine(), o);
  auto c = interp.next();
  REQUIRE(c);
  const auto* b = std::get_if<Barrier>(&c->body);
  REQUIRE(b != nullptr);
  REQUIRE(b->signal);
  CHECK(b->signal->id == 7);
  CHECK(b->signal->senders == std::vector<std::uint8_t>{2});
  RunState s = interp.decode_only_state(*b);
  s.signal_decode_only = false;
  s.signal.received = true;
  s.signal.params[0] = 10.0;
  s.signal.params[1] = 1.0;
  interp.resume(s);
  c = interp.next();
  REQUIRE(c);
  const auto* read = std::get_if<Barrier>(&c->body);
  REQUIRE(read != nullptr);
  CHECK(read->signal->read);
  s = interp.decode_only_state(*read);
  s.signal_decode_only = false;
  s.signal.received = true;
  interp.resume(s);
  c = interp.next();
  REQUIRE(c);
  const auto* m = std::get_if<Motion>(&c->body);
  REQUIRE(m != nullptr);
  CHECK(m->end[0] == doctest::Approx(12.0));  // 1 + 10 + TRUE
}

TEST_CASE("a #WAIT parameter the signal does not carry is the manual's 21549") {
  const core::SourceFile file("t.nc", "%t\n#WAIT [ID7 P[3]=P5 CH2]\nM30\n");
  Interpreter interp(file, test::machine(), channels({1, 2}));
  auto c = interp.next();
  REQUIRE(c);
  RunState s = interp.decode_only_state(std::get<Barrier>(c->body));
  s.signal_decode_only = false;
  s.signal.received = true;
  interp.resume(s);
  while (interp.next()) {
  }
  REQUIRE(interp.error() != nullptr);
  CHECK(interp.error()->id == "21549");
  CHECK(interp.error()->loc.line == 2);
}

TEST_CASE("signal numbers, channel numbers and parameters out of range have the manual's ids") {
  CHECK(run("%t\n#SIGNAL [ID0]\nM30\n").error_id == "20995");
  CHECK(run("%t\n#SIGNAL [ID1.5]\nM30\n").error_id == "20995");
  CHECK(run("%t\n#SIGNAL [ID1 CH13]\nM30\n").error_id == "20996");
  CHECK(run("%t\n#WAIT SYN [ID1 CH0]\nM30\n").error_id == "20996");
  CHECK(run("%t\n#SIGNAL [ID1 ID2]\nM30\n").error_id == "21056");
  CHECK(run("%t\n#WAIT SYN [ID1 P[0]=P2 CH1]\nM30\n").error_id == "21344");
  CHECK(run("%t\n#SIGNAL [CH1]\nM30\n").error_id == "NC4805");
  CHECK(run("%t\n#WAIT SYN [ID1 COUNT2]\nM30\n").error_id == "NC4801");
  CHECK(run("%t\n#SIGNAL [ID1 P[12]=1]\nM30\n").error_id == "NC4803");
  CHECK(run("%t\n#WAIT [ID1 P[0]=3]\nM30\n").error_id == "NC4804");
}

TEST_CASE("#SIGNAL REMOVE [SYN] becomes a removing signal command [PROG-207414923]") {
  auto r =
      run("%t\n#SIGNAL REMOVE [ID3]\n#SIGNAL REMOVE SYN [IDMIN=2 IDMAX=9 CH2]\n"
          "#SIGNAL REMOVE [IDMIN5]\nM30\n");
  REQUIRE(r.error_id.empty());
  CHECK(r.lines.at(0) == "2: SIGNAL_REMOVE ID3 BROADCAST");
  CHECK(r.lines.at(1) == "3: SIGNAL_REMOVE SYN ID2..9 CH2");
  CHECK(r.lines.at(2) == "4: SIGNAL_REMOVE ID5..2147483647 BROADCAST");
  CHECK(run("%t\n#SIGNAL REMOVE [ID3 IDMIN4]\nM30\n").error_id == "21056");
  CHECK(run("%t\n#SIGNAL REMOVE [ID3 IDMAX4]\nM30\n").error_id == "NC4806");
  CHECK(run("%t\n#SIGNAL REMOVE [ID3 COUNT2]\nM30\n").error_id == "NC4806");
  CHECK(run("%t\n#SIGNAL [ID3 IDMAX4]\nM30\n").error_id == "NC4806");
  CHECK(run("%t\n#SIGNAL REMOVE [IDMIN5 IDMAX4]\nM30\n").error_id == "NC4807");
  CHECK(run("%t\n#SIGNAL REMOVE [CH2]\nM30\n").error_id == "NC4805");
  CHECK(run("%t\n#SIGNAL REMOVE [ID0]\nM30\n").error_id == "20995");
}

TEST_CASE("a channel the run does not have is 250008 at its CH; any 1 .. 12 without a run") {
  const auto r = run("%t\nG01 X1 F100\n#WAIT SYN [ID1 CH2]\nM30\n", "portal_3x", channels({1}));
  CHECK(r.error_id == "250008");
  CHECK(r.error_line == 3);
  CHECK(r.error_message.find("its channels: 1") != std::string::npos);
  CHECK(run("%t\n#WAIT SYN [ID1 CH2]\nM30\n").error_id.empty());
  CHECK(run("%t\n#SIGNAL [ID1 CH3]\nM30\n", "portal_3x", channels({1, 3})).error_id.empty());
}

}  // namespace
}  // namespace ncsim::interp
