#include <doctest/doctest.h>

#include "grammar/keywords.hpp"
#include "grammar/test_support.hpp"

namespace ncsim::grammar::test {

namespace {
const ast::HashCommand& hash(const Parsed& p) {
  REQUIRE(p.diags.items().empty());
  return std::get<ast::HashCommand>(p.block.body);
}
std::string_view key_name(ast::TableId table, const ast::Item& item) {
  return keyword_table(table).entries[item.key].name;
}
}  // namespace

TEST_CASE("#SYNC IN takes its keyword list with optional '=' and comma or blank separators") {
  const Parsed p("N070 #SYNC IN [CONVEYOR=S1, CONV_VEL=18000 FEED_CONT=0]");
  const auto& h = hash(p);
  CHECK(h.kind == ast::HashKind::sync_in);
  REQUIRE(p.block.items.size() == 3);
  CHECK(p.block.items[0].text == "S1");
  CHECK(key_name(h.table, p.block.items[1]) == "CONV_VEL");
  CHECK(p.node(p.block.items[1].value).value == 18000);
  CHECK(p.block.items[2].loc.column == 44);
  CHECK(hash(Parsed("#SYNC OUT [FEED_CONT=5]")).kind == ast::HashKind::sync_out);
  CHECK(hash(Parsed("#SYNC OFF")).kind == ast::HashKind::sync_off);
  const Parsed v("#SYNC IN [CONV_VEL=200 VEL_RESOLUTION=mm/s]");
  CHECK(v.block.items[1].text == "mm/s");
}

TEST_CASE("keywords glued to their values: POS500, POS-750, FEED350000, ANGLIMIT 3") {
  const Parsed p("X[INDP_SYN G1 G90 POS-750 FEED350000 INTERRUPTIBLE] Y[INDP_ASYN G0 POS500]");
  REQUIRE(p.diags.items().empty());
  REQUIRE(p.block.axis_commands.size() == 2);
  const auto& x = p.block.axis_commands[0];
  CHECK(x.kind == ast::AxisCommandKind::indp_syn);
  CHECK(x.item_count == 6);
  CHECK(p.node(p.block.items[1].value).value == 1);     // G1
  CHECK(p.node(p.block.items[3].value).value == -750);  // POS-750
  CHECK(p.node(p.block.items[4].value).value == 350000);
  const Parsed c("#CAXTRACK ON [AX=C, ANGLIMIT 3, OFFSET 180, ROTMODE=1]");
  CHECK(hash(c).kind == ast::HashKind::caxtrack_on);
  CHECK(c.block.items.size() == 4);
}

TEST_CASE("#CS with ids, short vectors and empty components") {
  const Parsed p("#CS ON [1][0,0,10]");
  CHECK(hash(p).kind == ast::HashKind::cs_on);
  REQUIRE(p.block.items.size() == 4);
  CHECK(p.block.items[0].group == 0);
  CHECK(p.block.items[3].group == 1);
  const Parsed e("#CS DEF [2][,,5]");
  REQUIRE(e.block.items.size() == 4);
  CHECK(e.block.items[1].kind == ast::ItemKind::empty);
  CHECK(e.block.items[2].kind == ast::ItemKind::empty);
  CHECK(e.block.items[3].kind == ast::ItemKind::positional);
  CHECK(hash(Parsed("#CS OFF ALL")).kind == ast::HashKind::cs_off_all);
  CHECK(hash(Parsed("#CS OFF")).kind == ast::HashKind::cs_off);
}

TEST_CASE("spline, contour, slope, trafo, kin and flush commands") {
  CHECK(hash(Parsed("#SPLINE TYPE AKIMA")).kind == ast::HashKind::spline_type_akima);
  CHECK(hash(Parsed("#SET SPLINETYPE BSPLINE")).kind == ast::HashKind::spline_type_bspline);
  CHECK(hash(Parsed("#SET SPLINE ON")).kind == ast::HashKind::spline_on);
  CHECK(hash(Parsed("#SPLINE OFF")).kind == ast::HashKind::spline_off);
  CHECK(hash(Parsed("#CONTOUR MODE [DEV PATH_DEV 0.1 TRACK_DEV 1]")).kind ==
        ast::HashKind::contour_mode);
  CHECK(hash(Parsed("#CONTOUR MODE ON [DEV PATH_DEV=1.0]")).kind == ast::HashKind::contour_mode_on);
  CHECK(hash(Parsed("#CONTOUR MODE OFF")).kind == ast::HashKind::contour_mode_off);
  CHECK(hash(Parsed("#SLOPE [TYPE=TRAPEZ]")).kind == ast::HashKind::slope);
  CHECK(hash(Parsed("#SLOPE DEFAULT")).kind == ast::HashKind::slope_default);
  CHECK(hash(Parsed("#KIN ID[37]")).kind == ast::HashKind::kin_id);
  CHECK(hash(Parsed("#TRAFO ON")).kind == ast::HashKind::trafo_on);
  CHECK(hash(Parsed("#TRAFO [37, NONE]")).kind == ast::HashKind::trafo_steps);
  CHECK(hash(Parsed("#FLUSH CONTINUE")).kind == ast::HashKind::flush_continue);
  CHECK(hash(Parsed("#FLUSH WAIT")).kind == ast::HashKind::flush_wait);
  CHECK(hash(Parsed("#TIME 2.5")).kind == ast::HashKind::time);
  CHECK(hash(Parsed("#TRANSVELMIN ON [100]")).kind == ast::HashKind::transvelmin_on);
  CHECK(hash(Parsed("#WAIT INDP [X]")).kind == ast::HashKind::wait_indp);
  CHECK(hash(Parsed("#WAIT INDP ALL")).kind == ast::HashKind::wait_indp_all);
  CHECK(hash(Parsed("#DELETE V.S.A, V.S.B")).item_count == 2);
}

TEST_CASE("#MACHINE DATA and #MSG keep their strings") {
  const Parsed m("#MACHINE DATA SYN [AX=X AXPARAM=\"kenngr.swe_pos 15000000\" WAIT]");
  CHECK(hash(m).kind == ast::HashKind::machine_data);
  REQUIRE(m.block.items.size() == 4);
  CHECK(m.block.items[2].text == "kenngr.swe_pos 15000000");
  // The manual's parameter ids are one name each, with or without an index (§5.10).
  const Parsed ids("#MACHINE DATA [AX=X P-AXIS-00008=10000 P-AXIS-00209.0 5 p-chan-00262=2]");
  REQUIRE(ids.block.items.size() == 4);
  CHECK(ids.block.items[1].keyword == "P-AXIS-00008");
  CHECK(ids.block.items[1].value != ast::kNoNode);
  CHECK(ids.block.items[2].keyword == "P-AXIS-00209.0");
  CHECK(ids.block.items[3].keyword == "p-chan-00262");
  // An id without its number is no id: 'P' and then an expression that does not parse.
  CHECK(Parsed("#MACHINE DATA [AX=X P-AXIS-=1]").diags.has_errors());
  const Parsed s("#MSG HMI [\"Text_1\"]");
  CHECK(hash(s).kind == ast::HashKind::msg);
  REQUIRE(s.block.items.size() == 2);
  CHECK(s.block.items[1].text == "Text_1");
}

TEST_CASE("PLCopen commands: comments inside the bracket, blank before it") {
  const Parsed p(
      "N030 S1[MC_MoveVelocity Velocity=300000 (500000=30m/min) Acceleration=2000 "
      "Deceleration=2000 Jerk=750000 Direction=1]");
  REQUIRE(p.diags.items().empty());
  REQUIRE(p.block.axis_commands.size() == 1);
  CHECK(p.block.axis_commands[0].axis == "S1");
  CHECK(p.block.axis_commands[0].item_count == 6);
  const Parsed t("S1 [MC_TouchProbe Channel=1 Mode=2 Id=4 WaitSyn]");
  REQUIRE(t.diags.items().empty());
  CHECK(t.block.axis_commands[0].kind == ast::AxisCommandKind::mc_touch_probe);
  const Parsed a("S2[MC_MoveAbsolute Position=100 Velocity=10]");
  CHECK(a.block.axis_commands[0].kind == ast::AxisCommandKind::mc_move_absolute);
}

TEST_CASE("an axis bracket with an expression is a value, not a command") {
  const Parsed p("X[12.5*2+SIN[30]]");
  REQUIRE(p.diags.items().empty());
  CHECK(p.block.axis_commands.empty());
  CHECK(p.block.words.size() == 1);
}

TEST_CASE("unsupported commands are reported as such with their position") {
  const Parsed h("N10 #PTP ON");
  REQUIRE(h.diags.items().size() == 1);
  CHECK(h.diags.items()[0].id == "NC1002");
  CHECK(h.diags.items()[0].message == "not supported: #PTP");
  CHECK(h.diags.items()[0].loc.column == 5);
  const Parsed o("X[OSC ON]");
  REQUIRE(o.diags.items().size() == 1);
  CHECK(o.diags.items()[0].loc.column == 3);
  CHECK(check("G238 X1") == std::vector<std::string>{"1:1 NC1002"});
}

TEST_CASE("#TANGFEED [RMIN=..] and the old #SET TANGFEED RMIN [..] are read [PROG-207065483]") {
  CHECK(check("#TANGFEED [RMIN=3]").empty());
  CHECK(check("#TANGFEED").empty());
  CHECK(check("#SET TANGFEED RMIN [2.5*2]").empty());
  const Parsed t("#TANGFEED [RMIN=3]");
  CHECK(hash(t).kind == ast::HashKind::tangfeed);
  CHECK(t.block.items.at(0).keyword == "RMIN");
  CHECK(check("#SET TANGFEED [3]") == std::vector<std::string>{"1:15 NC1001"});
  CHECK_FALSE(check("#TANGFEED [RMAX=3]").empty());
}

TEST_CASE("#MCS TO WCS and #WCS TO MCS are not supported, with the reason and PROG-208525707") {
  // The manual's auxiliary transformations: not a syntax error, refused at the '#'.
  for (const char* text : {"N5 #MCS TO WCS [X1 Y2 Z3]", "N5 #WCS TO MCS [X1 Y2 Z3]"}) {
    const Parsed w(text);
    REQUIRE(w.diags.items().size() == 1);
    CHECK(w.diags.items()[0].id == "NC1002");
    CHECK(w.diags.items()[0].loc.column == 4);
    const std::string& m = w.diags.items()[0].message;
    CHECK(m.starts_with(std::string("not supported: ") + std::string(text + 3, 11)));
    CHECK(m.find("PROG-208525707") != std::string::npos);
    CHECK(m.find("result variables") != std::string::npos);
  }
  // Other words after #WCS are not the manual's command: the plain text.
  const Parsed other("#WCS ON");
  REQUIRE(other.diags.items().size() == 1);
  CHECK(other.diags.items()[0].message == "not supported: #WCS");
}

TEST_CASE("control statements: $IF one-line goto, $FOR header, $GOTO targets") {
  const Parsed a("$IF P1 > 2 $GOTO [END]");
  const auto& c = std::get<ast::Control>(a.block.body);
  CHECK(c.kind == ast::ControlKind::if_);
  CHECK(c.target.kind == ast::GotoKind::name);
  CHECK(c.target.name == "END");
  const Parsed f("$FOR P2 = 0, 24, 1");
  const auto& fc = std::get<ast::Control>(f.block.body);
  CHECK(fc.counter != ast::kNoNode);
  CHECK(fc.step != ast::kNoNode);
  const Parsed g("G01 X1 $GOTO N10");
  REQUIRE(g.block.trailing_goto);
  CHECK(g.block.trailing_goto->target.number == 10);
  CHECK(std::get<ast::Control>(Parsed("$WHILE [TRUE]").block.body).expr != ast::kNoNode);
  CHECK(std::get<ast::Control>(Parsed("$ENDDO P1 < 3").block.body).kind == ast::ControlKind::enddo);
}

}  // namespace ncsim::grammar::test

namespace ncsim::grammar::test {

// PROG-207409035 / 207421579 / 913718283: #SIGNAL, #WAIT, #SIGNAL READ (docs/lines.md).
TEST_CASE("#SIGNAL and #WAIT read ID, COUNT, CH and P[i]=.. with or without '=', glued or not") {
  const Parsed s("#SIGNAL [IDP100 P[0]= V.P.SYNC CH3]");
  CHECK(hash(s).kind == ast::HashKind::signal);
  REQUIRE(s.block.items.size() == 3);
  CHECK(s.block.items[0].keyword == "ID");
  CHECK(s.node(s.block.items[0].value).op == ast::Op::variable);  // P100, the manual's example
  CHECK(s.block.items[1].keyword == "P");
  CHECK(s.node(s.block.items[1].index).value == 0);
  CHECK(s.node(s.block.items[1].value).op == ast::Op::variable);
  CHECK(s.block.items[2].keyword == "CH");
  CHECK(s.node(s.block.items[2].value).value == 3);
  const Parsed syn("#SIGNAL SYN [ID=3 COUNT=1 CH=1 CH=2]");
  CHECK(hash(syn).kind == ast::HashKind::signal_syn);
  CHECK(syn.block.items.size() == 4);
  CHECK(hash(Parsed("#WAIT SYN [ID968 CH2 CH3]")).kind == ast::HashKind::wait_signal_syn);
  CHECK(hash(Parsed("#WAIT [ID814 P[0]= V.P.SIGNAL CH1]")).kind == ast::HashKind::wait_signal);
  CHECK(hash(Parsed("#SIGNAL READ [ID=7 CH=2]")).kind == ast::HashKind::signal_read);
  CHECK(hash(Parsed("#WAIT INDP ALL")).kind == ast::HashKind::wait_indp_all);  // unchanged
}

TEST_CASE("#SIGNAL and #WAIT without SYN or '[' are the manual's 20998; READ SYN is refused") {
  CHECK(check("#SIGNAL ID1\n") == std::vector<std::string>{"1:9 20998"});
  CHECK(check("#WAIT\n") == std::vector<std::string>{"1:6 20998"});
  CHECK(check("#SIGNAL SYN ID1\n") == std::vector<std::string>{"1:13 20998"});
  CHECK(check("#SIGNAL READ SYN [ID1]\n") == std::vector<std::string>{"1:9 NC1010"});
  CHECK(check("#SIGNAL [ID1 XYZ2]\n") == std::vector<std::string>{"1:14 NC1001"});
  CHECK(check("#WAIT [ID1 AHEAD]\n") == std::vector<std::string>{"1:12 NC1002"});
  CHECK(check("#SIGNAL REMOVE [ID1]\n").empty());
  CHECK(check("#SIGNAL REMOVE SYN [IDMIN1 IDMAX4 CH2]\n").empty());
  CHECK(check("#SIGNAL REMOVE ID1\n") == std::vector<std::string>{"1:16 20998"});
  CHECK(check("#WAIT FOR [X]\n") == std::vector<std::string>{"1:1 NC1002"});
}

}  // namespace ncsim::grammar::test
