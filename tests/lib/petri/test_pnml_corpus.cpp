// Nets written by public tools (tests/data/pnml_corpus/, SOURCES.md says
// where each comes from): each is read or refused as expected.json says, the
// analysis agrees with what was published alongside it, and every trace it
// gives replays on the net.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>

#include "lib/petri/net_analysis.hpp"
#include "lib/petri/pnml_reader.hpp"

namespace beft::arbiter {
namespace {

const std::string kCorpus = BEFT_CORPUS_DIR;

nlohmann::json expectations() {
  std::ifstream in(kCorpus + "/expected.json");
  return nlohmann::json::parse(in);
}

Marking fire(const Net& net, Marking marking, const std::vector<int>& trace, size_t steps) {
  for (size_t i = 0; i < steps; ++i) {
    const Transition& t = net.transitions[trace[i]];
    EXPECT_TRUE(isEnabled(t, marking)) << "step " << i << ": " << t.id << " is not enabled";
    if (!isEnabled(t, marking)) break;
    consumeInputs(t, marking);
    produceOutputs(t, marking);
  }
  return marking;
}

void checkTraces(const Net& net, const NetAnalysis& analysis) {
  if (analysis.deadlock.value_or(false)) {
    const Marking end = fire(net, net.initialMarking(), analysis.deadlock_trace, analysis.deadlock_trace.size());
    EXPECT_EQ(end, analysis.deadlock_marking);
    for (const auto& t : net.transitions) EXPECT_FALSE(isEnabled(t, end)) << t.id << " is enabled at the deadlock";
  }
  if (analysis.unbounded_witness) {
    const auto& w = *analysis.unbounded_witness;
    EXPECT_EQ(fire(net, net.initialMarking(), w.trace, w.covered_after), w.covered);
    const Marking covering = fire(net, net.initialMarking(), w.trace, w.trace.size());
    EXPECT_EQ(covering, w.covering);
    bool strictly = false;
    for (size_t p = 0; p < covering.size(); ++p) {
      EXPECT_GE(covering[p], w.covered[p]);
      strictly = strictly || covering[p] > w.covered[p];
    }
    EXPECT_TRUE(strictly);
  }
}

TEST(PnmlCorpus, EveryFileIsReadOrRefusedAndAgreesWithWhatWasPublished) {
  const nlohmann::json expected = expectations();
  ASSERT_GE(expected.size(), 20u);
  size_t analysed = 0, refused = 0, with_published_property = 0;
  for (const auto& [file, expect] : expected.items()) {
    SCOPED_TRACE(file);
    PnmlReadOptions options;
    options.schedule = false;
    const std::string path = kCorpus + "/" + file;
    if (expect.contains("refuse")) {
      try {
        readPnmlFile(path, options);
        ADD_FAILURE() << "read, but should be refused";
      } catch (const NetError& e) {
        const std::string problem = e.problems().at(0);
        EXPECT_EQ(problem.rfind(path + ":", 0), 0u) << problem;  // file:line
        EXPECT_NE(problem.find(expect["refuse"].get<std::string>()), std::string::npos) << problem;
        ++refused;
      }
      continue;
    }
    Net net;
    try {
      net = readPnmlFile(path, options);
    } catch (const NetError& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    EXPECT_FALSE(net.places.empty());
    EXPECT_FALSE(net.transitions.empty());
    NetAnalysisOptions analysis_options;
    analysis_options.max_markings = expect.value("max_markings", size_t{200000});
    const NetAnalysis analysis = analyseNet(net, analysis_options);
    ++analysed;
    EXPECT_GE(analysis.markings, 1u);
    checkTraces(net, analysis);
    if (expect.contains("markings")) {
      ++with_published_property;
      EXPECT_TRUE(analysis.complete);
      EXPECT_EQ(analysis.markings, expect["markings"].get<size_t>());
    }
    if (expect.contains("deadlock")) {
      ++with_published_property;
      EXPECT_EQ(analysis.deadlock, expect["deadlock"].get<bool>());
    }
    if (expect.contains("bounded")) {
      ++with_published_property;
      EXPECT_EQ(analysis.bounded, expect["bounded"].get<bool>());
    }
    if (expect.contains("safe")) {
      ++with_published_property;
      EXPECT_EQ(analysis.safe(), expect["safe"].get<bool>());
    }
    if (expect.contains("nupn_safe")) {
      ++with_published_property;
      for (int tokens : analysis.max_tokens) EXPECT_LE(tokens, 1);
      if (analysis.complete) {
        EXPECT_EQ(analysis.safe(), true);
      }
    }
  }
  EXPECT_GE(analysed, 30u);
  EXPECT_GE(refused, 5u);
  EXPECT_GE(with_published_property, 15u);
}

}  // namespace
}  // namespace beft::arbiter
