// Technology functions' synchronisation types (TF5200 P-CHAN-00041 / 00027 / 00081 / 00086):
// when each is output and which acknowledgement waits the block gets (interp/tech_functions).
#include "interp/tech_functions.hpp"

#include <doctest/doctest.h>

#include <string>

#include "interp/test_support.hpp"

namespace ncsim::interp {
namespace {

using machines::TechSync;

machines::Machine tech_machine() {
  machines::Machine m = test::machine("portal_3x");
  m.channel.tech.m[6] = {TechSync::mvs_svs, 2.5};
  m.channel.tech.m[8] = {TechSync::mns_sns, 0.5};
  m.channel.tech.m[9] = {TechSync::mvs_sns, 1.0};
  m.channel.tech.m[10] = {TechSync::none, 3.0};
  m.channel.tech.m[11] = {TechSync::mos, 3.0};
  m.channel.tech.h[2] = {TechSync::mvs_svs, 4.0};
  m.channel.tech.t = {TechSync::mvs_svs, 0.0};
  return m;
}

std::vector<std::string> trace_of(const std::string& text) {
  const test::Run r =
      test::run_on_machine(core::SourceFile("t.nc", text), tech_machine(), {}, 1000, false);
  REQUIRE_MESSAGE(r.error_id.empty(), r.error_message);
  return r.lines;
}

// The index of the first line containing `text`, or -1.
int at(const std::vector<std::string>& lines, const std::string& text) {
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (lines[i].find(text) != std::string::npos) return static_cast<int>(i);
  return -1;
}

TEST_CASE("MVS_SVS: output before the block, then a wait of its time before the motion") {
  const auto l = trace_of("%t\nG01 X10 F600\nG01 X20 M6\nM30\n");
  const int tech = at(l, "TECH M=6.0000 sync=MVS_SVS");
  const int wait = at(l, "TECH-WAIT t=2.5000");
  const int motion = at(l, "X=20");
  REQUIRE(tech >= 0);
  CHECK(wait == tech + 1);
  CHECK(motion == wait + 1);
}

TEST_CASE("MNS_SNS: the motion first, then the output and its wait") {
  const auto l = trace_of("%t\nG01 X20 F600 M8\nM30\n");
  const int motion = at(l, "X=20");
  const int tech = at(l, "TECH M=8.0000 sync=MNS_SNS");
  REQUIRE(motion >= 0);
  CHECK(tech == motion + 1);
  CHECK(at(l, "TECH-WAIT t=0.5000") == tech + 1);
}

TEST_CASE("MVS_SNS: output before the motion, the rest of its time waited after it") {
  const auto l = trace_of("%t\nG01 X20 F600 M9\nM30\n");
  const int tech = at(l, "TECH M=9.0000 sync=MVS_SNS");
  const int motion = at(l, "X=20");
  REQUIRE(tech >= 0);
  CHECK(motion == tech + 1);
  CHECK(at(l, "TECH-WAIT t=1.0000 since=output") == motion + 1);
}

TEST_CASE("NO_SYNCH and MOS never wait, whatever their time; the default type is MOS") {
  const auto l = trace_of("%t\nG01 X20 F600 M10 M11 M12\nM30\n");
  CHECK(at(l, "TECH-WAIT") == -1);
  CHECK(at(l, "TECH M=10.0000 sync=NO_SYNCH") >= 0);
  CHECK(at(l, "TECH M=11.0000") >= 0);
  CHECK(at(l, "TECH M=12.0000") >= 0);
  CHECK(at(l, "M=12.0000 sync=") == -1);  // MOS is not shown
}

TEST_CASE("the functions of a block are acknowledged side by side: the longest time is waited") {
  const auto l = trace_of("%t\nG01 X20 F600 M6 H2 T1\nM30\n");
  CHECK(at(l, "TECH-WAIT t=4.0000") >= 0);  // H2's 4 s over M6's 2.5 s and T's 0 s
  int waits = 0;
  for (const auto& s : l)
    waits += s.find("TECH-WAIT") != std::string::npos;
  CHECK(waits == 1);
}

TEST_CASE("an MVS_SVS function of 0 s still stops the path: a 0 s wait") {
  const auto l = trace_of("%t\nG01 X20 F600 T3\nM30\n");
  CHECK(at(l, "TECH-WAIT t=0.0000") >= 0);
}

TEST_CASE("resolve_tech: numbers outside 0..999 or not whole are never configured (MOS)") {
  machines::TechTable table;
  table.m[1] = {TechSync::mns_sns, 1.0};
  std::vector<Tech> f{{TechKind::m, 1.5, {}}, {TechKind::m, 1e6, {}}, {TechKind::d, 1, {}}};
  const TechWaits w = resolve_tech(f, table);
  CHECK(!w.before);
  CHECK(!w.after);
  CHECK(!w.since);
  for (const Tech& t : f)
    CHECK(t.sync == TechSync::mos);
}

// P-CHAN-00014 einrechnen_mit_t (TF5200 channel parameters): "T80" is "T80 D80".
std::vector<std::string> tech_lines(const std::string& text, bool d_with_t) {
  machines::Machine m = test::machine("portal_3x");
  m.channel.d_with_t = d_with_t;
  const test::Run r = test::run_on_machine(core::SourceFile("t.nc", text), m, {}, 1000, false);
  REQUIRE_MESSAGE(r.error_id.empty(), r.error_message);
  std::vector<std::string> out;
  for (const auto& l : r.lines)
    if (l.find("TECH T=") != std::string::npos || l.find("TECH D=") != std::string::npos)
      out.push_back(l);
  return out;
}

TEST_CASE("P-CHAN-00014 = 1: a T word also executes the D word of its number (T80 = T80 D80)") {
  const auto l = tech_lines("%t\nT80\nM30\n", true);
  REQUIRE(l.size() == 2);
  CHECK(l[0] == "2: TECH T=80.0000");
  CHECK(l[1] == "2: TECH D=80.0000");  // after the T, as "T80 D80" is written
}

TEST_CASE("P-CHAN-00014 = 0 (the manual's default): a T word is only the T function") {
  CHECK(tech_lines("%t\nT80\nM30\n", false) == std::vector<std::string>{"2: TECH T=80.0000"});
  CHECK(machines::ChannelParams{}.d_with_t == false);
}

TEST_CASE("P-CHAN-00014 = 1: a D programmed in the T's block is the one executed") {
  const auto l = tech_lines("%t\nT80 D5\nM30\n", true);
  CHECK(l == std::vector<std::string>{"2: TECH T=80.0000", "2: TECH D=5.0000"});
}

TEST_CASE("P-CHAN-00014 = 1: the D a T implies selects the tool radius compensation's tool") {
  // portal_3x_tools: D2 has radius 5 mm; G41 runs the tool centre 5 mm left of Y = 0.
  machines::Machine m = test::machine("portal_3x_tools");
  m.channel.d_with_t = true;
  const test::Run r = test::run_on_machine(
      core::SourceFile("t.nc", "%t\nG00 X0 Y0\nT2\nG41 G01 X10 F600\nG01 X20\nG40 G01 X30\nM30\n"),
      m, {}, 1000, false);
  REQUIRE_MESSAGE(r.error_id.empty(), r.error_message);
  bool offset_seen = false;
  for (const auto& l : r.lines)
    offset_seen = offset_seen || l.find("Y=5.0000") != std::string::npos;
  CHECK(offset_seen);
}

}  // namespace
}  // namespace ncsim::interp
