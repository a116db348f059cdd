// The PNML that editors write: namespaces and prefixes, WoPeD's nodes under
// <net>, PIPE's values, several nets, declared encodings, references; and
// what is no P/T net, refused with file:line and the reason.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lib/petri/pnml_reader.hpp"

namespace beft::arbiter {
namespace {

PnmlReadOptions anyNet(const std::string& net_id = "") {
  PnmlReadOptions options;
  options.schedule = false;
  options.net_id = net_id;
  return options;
}

// The one problem of a refused text, or "" when it was read.
std::string refusal(const std::string& text, const PnmlReadOptions& options = anyNet()) {
  try {
    readPnmlString(text, "f.pnml", options);
  } catch (const NetError& e) {
    return e.problems().empty() ? "(no problem listed)" : e.problems()[0];
  }
  return "";
}

void expectRefused(const std::string& text, const std::string& line_prefix, const std::string& reason) {
  const std::string problem = refusal(text);
  EXPECT_EQ(problem.rfind(line_prefix, 0), 0u) << problem;
  EXPECT_NE(problem.find(reason), std::string::npos) << problem;
}

TEST(PnmlDialects, IsoPtNetWithAPrefixedNamespace) {
  const Net net = readPnmlString(R"(<?xml version="1.0"?>
<pnml:pnml xmlns:pnml="http://www.pnml.org/version-2009/grammar/pnml">
 <pnml:net id="n" type="http://www.pnml.org/version-2009/grammar/ptnet">
  <pnml:page id="pg">
   <pnml:place id="p"><pnml:initialMarking><pnml:text>2</pnml:text></pnml:initialMarking></pnml:place>
   <pnml:transition id="t"/>
   <pnml:arc id="a" source="p" target="t"><pnml:inscription><pnml:text>2</pnml:text></pnml:inscription></pnml:arc>
  </pnml:page>
 </pnml:net>
</pnml:pnml>)", "f.pnml", anyNet());
  ASSERT_EQ(net.places.size(), 1u);
  EXPECT_EQ(net.places[0].initial_tokens, 2);
  ASSERT_EQ(net.transitions[0].inputs.size(), 1u);
  EXPECT_EQ(net.transitions[0].inputs[0].weight, 2);
  EXPECT_TRUE(net.warnings.empty());
  EXPECT_FALSE(net.annotated);
}

TEST(PnmlDialects, WoPeDNodesDirectlyUnderTheNetAndArcsBeforeTheirNodes) {
  const Net net = readPnmlString(R"(<pnml><net id="w" type="http://www.informatik.hu-berlin.de/top/pntd/ptNetb">
  <arc id="a1" source="p1" target="t1"><inscription><text>1</text></inscription></arc>
  <arc id="a2" source="t1" target="p1"/>
  <place id="p1"><name><text>start</text><graphics><offset x="0" y="0"/></graphics></name>
    <initialMarking><graphics><offset x="1" y="1"/></graphics><text>1</text></initialMarking>
    <toolspecific tool="WoPeD" version="1.0"><unknownThing/></toolspecific></place>
  <transition id="t1"><toolspecific tool="WoPeD" version="1.0"><time>0</time></toolspecific></transition>
</net></pnml>)", "f.pnml", anyNet());
  EXPECT_EQ(net.places[0].name, "start");
  EXPECT_EQ(net.places[0].initial_tokens, 1);
  // A self-loop stays two arcs: one in, one out.
  EXPECT_EQ(net.transitions[0].inputs.size(), 1u);
  EXPECT_EQ(net.transitions[0].outputs.size(), 1u);
  EXPECT_EQ(net.arcCount(), 2u);
}

TEST(PnmlDialects, PipeValuesForNamesMarkingsAndWeights) {
  const Net net = readPnmlString(R"(<pnml><net id="Net-One" type="P/T net">
  <token id="Default" enabled="true" red="0" green="0" blue="0"/>
  <place id="P0"><name><value>P0</value></name><initialMarking><value>Default,3</value></initialMarking></place>
  <transition id="T0"><name><value>T0</value></name></transition>
  <arc id="P0 to T0" source="P0" target="T0"><inscription><value>Default,2</value></inscription><type value="normal"/></arc>
</net></pnml>)", "f.pnml", anyNet());
  EXPECT_EQ(net.places[0].name, "P0");
  EXPECT_EQ(net.places[0].initial_tokens, 3);
  EXPECT_EQ(net.transitions[0].inputs[0].weight, 2);
}

TEST(PnmlDialects, ProMCoreModelAndUnknownToolDataAreRead) {
  const Net net = readPnmlString(R"(<pnml><net id="net1" type="http://www.pnml.org/version-2009/grammar/pnmlcoremodel">
  <name><text>from ProM</text></name>
  <page id="n0"><place id="n1"><name><text>source</text></name><initialMarking><text>1</text></initialMarking></place>
  <transition id="n2"><name><text>a</text></name><toolspecific tool="ProM" version="6.4" activity="$invisible$" localNodeID="x"/></transition>
  <arc id="arc3" source="n1" target="n2"/></page>
  <finalmarkings><marking><place idref="n1"><text>0</text></place></marking></finalmarkings>
</net></pnml>)", "f.pnml", anyNet());
  EXPECT_EQ(net.name, "from ProM");
  EXPECT_EQ(net.transitions[0].name, "a");
  EXPECT_TRUE(net.warnings.empty());
}

TEST(PnmlDialects, ReferenceChainsResolveToTheirTargetsOnOtherPages) {
  const Net net = readPnmlString(R"(<pnml><net id="n"><page id="top">
  <place id="p"><initialMarking><text>1</text></initialMarking></place>
  <page id="inner"><page id="deeper">
    <referencePlace id="r2" ref="r1"/>
    <referencePlace id="r1" ref="p"/>
    <transition id="t"/>
    <arc id="a" source="r2" target="t"/>
  </page></page></page></net></pnml>)", "f.pnml", anyNet());
  ASSERT_EQ(net.places.size(), 1u);
  ASSERT_EQ(net.transitions[0].inputs.size(), 1u);
  EXPECT_EQ(net.transitions[0].inputs[0].place, 0);
}

TEST(PnmlDialects, SeveralNetsTheFirstWithAWarningOrTheOneAskedFor) {
  const std::string text = R"(<pnml>
<net id="first"><place id="a"/></net>
<net id="second"><place id="b"/><place id="c"/></net>
</pnml>)";
  const Net first = readPnmlString(text, "f.pnml", anyNet());
  EXPECT_EQ(first.id, "first");
  ASSERT_GE(first.warnings.size(), 1u);  // and: place 'a' has no arcs
  EXPECT_NE(first.warnings[0].find("f.pnml:2: the file holds 2 nets ('first', 'second'); reading the first"),
            std::string::npos)
      << first.warnings[0];
  const Net second = readPnmlString(text, "f.pnml", anyNet("second"));
  EXPECT_EQ(second.places.size(), 2u);
  EXPECT_NE(refusal(text, anyNet("third")).find("no <net> with id 'third' (the file has 'first', 'second')"),
            std::string::npos);
}

TEST(PnmlDialects, Iso88591NamesAreReadAsUtf8) {
  const std::string latin1 = "<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n<pnml><net id=\"n\">"
                             "<place id=\"p\"><name><text>Puffergr\xF6\xDF" "e</text></name></place></net></pnml>";
  const Net net = readPnmlString(latin1, "f.pnml", anyNet());
  EXPECT_EQ(net.places[0].name, "Puffergr\xC3\xB6\xC3\x9F" "e");
  expectRefused("<?xml version=\"1.0\" encoding=\"KLINGON-8\"?>\n<pnml/>", "f.pnml:1:",
                "the encoding 'KLINGON-8' is not known");
}

TEST(PnmlDialects, WhatIsNoPlaceTransitionNetIsRefusedWithTheReason) {
  expectRefused("<pnml>\n<net id=\"n\" type=\"http://www.pnml.org/version-2009/grammar/symmetricnet\"/>\n</pnml>",
                "f.pnml:2:", "is a high-level net");
  expectRefused("<pnml><net id=\"n\">\n<place id=\"p\">\n<type><text>Dot</text></type></place></net></pnml>",
                "f.pnml:3:", "only high-level nets have");
  expectRefused("<pnml><net id=\"n\" type=\"P/T net\">\n<token id=\"Default\" enabled=\"true\"/>\n"
                "<token id=\"Red\" enabled=\"true\"/><place id=\"p\"/></net></pnml>",
                "f.pnml:1:", "a coloured PIPE net (token classes Default, Red)");
  expectRefused("<pnml><net id=\"n\">\n<place id=\"p\"><initialMarking><value>Default,1,Red,2</value>"
                "</initialMarking></place></net></pnml>",
                "f.pnml:2:", "tokens of several colours");
  expectRefused("<pnml><net id=\"n\"><place id=\"p\"/><transition id=\"t\"/>\n"
                "<arc id=\"a\" source=\"p\" target=\"t\"><type value=\"inhibitor\"/></arc></net></pnml>",
                "f.pnml:2:", "arc 'a' is an inhibitor arc");
  expectRefused("<pnml><net id=\"n\"><place id=\"p\"/><transition id=\"t\"/>\n"
                "<arc id=\"a\" source=\"p\" target=\"t\" type=\"tapnInhibitor\"/></net></pnml>",
                "f.pnml:2:", "an inhibitor arc");
  expectRefused("<pnml xmlns=\"http://www.informatik.hu-berlin.de/top/pnml/ptNetb\">\n<net active=\"true\" "
                "id=\"TAPN1\" type=\"P/T net\"><place id=\"P0\" initialMarking=\"1\" invariant=\"&lt; inf\" "
                "name=\"P0\"/></net>\n<query name=\"q\"/></pnml>",
                "f.pnml:1:", "TAPAAL's own format");
  expectRefused("<pnml><net id=\"n\"><place id=\"x\"/>\n<transition id=\"x\"/></net></pnml>", "f.pnml:2:",
                "duplicate id 'x'");
}

TEST(PnmlDialects, AnyNetModeReportsWhatKeepsItFromBeingASchedule) {
  const std::string text = "<pnml><net id=\"n\">\n<place id=\"p\"/>\n<transition id=\"t\"/>\n"
                           "<arc id=\"a\" source=\"t\" target=\"p\"/></net></pnml>";
  const Net net = readPnmlString(text, "f.pnml", anyNet());
  EXPECT_FALSE(net.annotated);
  ASSERT_EQ(net.schedule_problems.size(), 3u);
  EXPECT_NE(net.schedule_problems[0].find("f.pnml:3: transition 't' names no expert"), std::string::npos);
  EXPECT_NE(net.schedule_problems[1].find("f.pnml:3: transition 't' has no input place"), std::string::npos);
  EXPECT_NE(net.schedule_problems[2].find("no tick transition"), std::string::npos);
  // The arbiter refuses the same file.
  EXPECT_NE(refusal(text, PnmlReadOptions{}).find("names no expert"), std::string::npos);
}

TEST(PnmlDialects, ParallelArcsOfAnyNetAddTheirWeights) {
  const Net net = readPnmlString("<pnml><net id=\"n\"><place id=\"p\"/><transition id=\"t\"/>\n"
                                 "<arc id=\"a\" source=\"p\" target=\"t\"/>\n"
                                 "<arc id=\"b\" source=\"p\" target=\"t\"><inscription><text>2</text></inscription>"
                                 "</arc></net></pnml>",
                                 "f.pnml", anyNet());
  ASSERT_EQ(net.transitions[0].inputs.size(), 1u);
  EXPECT_EQ(net.transitions[0].inputs[0].weight, 3);
  ASSERT_EQ(net.warnings.size(), 1u);
  EXPECT_NE(net.warnings[0].find("f.pnml:3: second arc from 'p' to 't'"), std::string::npos) << net.warnings[0];
}

}  // namespace
}  // namespace beft::arbiter
