// The experiment file's reader (its refusals at FILE:LINE), the factor product
// and the episodes' ids and commands.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

#include <unistd.h>

#include "tools/experiment/episode_run.hpp"
#include "tools/experiment/episodes.hpp"
#include "tools/experiment/experiment_file.hpp"
#include "tools/experiment/value_lists.hpp"

namespace beft::experiment {
namespace {

namespace fs = std::filesystem;

class ExperimentFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("beft_experiment_file_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    for (const char* name : {"a.xml", "b.xml", "fast.pnml"}) std::ofstream(dir_ / name) << "<x/>\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& text) {
    const std::string path = (dir_ / "experiment.xml").string();
    std::ofstream(path) << text;
    return path;
  }
  // The error reading `text`; "" if it was read.
  std::string refusal(const std::string& text) {
    try {
      readExperiment(write(text));
    } catch (const ExperimentError& e) {
      return e.what();
    }
    return "";
  }
  std::string at(int line) { return (dir_ / "experiment.xml").string() + ":" + std::to_string(line) + ": "; }

  fs::path dir_;
};

TEST_F(ExperimentFileTest, RefusesWhatIsWrongAtItsLine) {
  const std::string head = "<experiment>\n  <scenario file=\"a.xml\"/>\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {head + "  <planner values=\"astar\"/>\n</experiment>\n", "unknown element <planner>"},
      {head + "  <seeds value=\"1\"/>\n</experiment>\n", "unknown attribute 'value' on <seeds>"},
      {head + "  <planners values=\"  \"/>\n</experiment>\n", "attribute 'values' of <planners> is empty"},
      {head + "  <seeds values=\"5-1\"/>\n</experiment>\n", "seeds and ranges"},
      {head + "  <seeds values=\"1 2x\"/>\n</experiment>\n", "seeds and ranges"},
      {head + "  <acoustics values=\"echo\"/>\n</experiment>\n", "'echo' is not a value of acoustics"},
      {head + "  <planners values=\"astar rrt\"/>\n</experiment>\n", "'rrt' is not a value of planner"},
      {head + "  <planners values=\"astar astar\"/>\n</experiment>\n", "'astar' is twice a value of planner"},
      {head + "  <scenario file=\"missing.xml\"/>\n</experiment>\n", "no such file: missing.xml"},
      {head + "  <scenario file=\"a.xml\"/>\n</experiment>\n", "two scenes named 'a'"},
      {head + "  <nets values=\"fast.pnml slow.pnml\"/>\n</experiment>\n", "no such file: slow.pnml"},
      {head + "  <generated kind=\"district\" size=\"80\" objects=\"9\" seeds=\"1\"/>\n</experiment>\n",
       "size must be two positive integers"},
      {head + "  <generated kind=\"district\" size=\"80 60\" objects=\"0\" seeds=\"1\"/>\n</experiment>\n",
       "'objects' of <generated> must be an integer >= 1, not '0'"},
      {head + "  <generated kind=\"city\" size=\"80 60\" objects=\"9\" seeds=\"1\"/>\n</experiment>\n",
       "kind must be 'district'"},
      {head + "  <set name=\"dw_alpha\"/>\n</experiment>\n", "<set> needs attribute 'values'"},
      {head + "  <compare factor=\"planner\" a=\"x\" b=\"y\"/>\n</experiment>\n", "no factor 'planner'"},
      {head + "  <compare factor=\"seed\" a=\"1\" b=\"2\"/>\n  <seeds values=\"1 2\"/>\n</experiment>\n",
       "paired by scene and seed"},
      {head + "  <compare factor=\"dw\" a=\"1\" b=\"3\"/>\n  <set name=\"dw\" values=\"1 2\"/>\n</experiment>\n",
       "'3' is not a value of set:dw"},
      {head + "  <episode scene=\"a\" planer=\"astar\"/>\n  <planners values=\"astar\"/>\n</experiment>\n",
       "unknown attribute 'planer' on <episode>"},
      {head + "  <episode scene=\"a\"/>\n  <planners values=\"astar\"/>\n</experiment>\n",
       "<episode> gives no planner"},
      {head + "  <episode scene=\"c\"/>\n</experiment>\n", "'c' is not a value of scene"},
  };
  for (const auto& [text, message] : cases) {
    const std::string error = refusal(text);
    EXPECT_EQ(error.rfind(at(3), 0), 0u) << error;
    EXPECT_NE(error.find(message), std::string::npos) << error;
  }
}

TEST_F(ExperimentFileTest, RefusesABadRootOrDocument) {
  EXPECT_EQ(refusal("<experiment max_ticks=\"12x\">\n<scenario file=\"a.xml\"/></experiment>"),
            at(1) + "attribute 'max_ticks' of <experiment> must be an integer >= 1, not '12x'");
  EXPECT_EQ(refusal("<run>\n</run>\n"), at(1) + "the root element must be <experiment>");
  EXPECT_EQ(refusal("<experiment>\n</experiment>\n"), at(1) + "no scene: give <scenario file=...> or <generated ...>");
  const std::string unclosed = refusal("<experiment>\n  <scenario file=\"a.xml\">\n</experiment>\n");
  EXPECT_EQ(unclosed.rfind(at(2) + "cannot read the experiment file: ", 0), 0u) << unclosed;
}

TEST_F(ExperimentFileTest, EpisodesAreTheProductOfTheFactorsWithStableIds) {
  const auto x = readExperiment(write(
      "<experiment max_ticks=\"300\">\n  <scenario file=\"a.xml\"/>\n  <scenario file=\"b.xml\"/>\n"
      "  <seeds values=\"1-2\"/>\n  <planners values=\"pf-geodesic astar\"/>\n"
      "  <set name=\"dw_alpha\" values=\"0.5\"/>\n</experiment>\n"));
  const auto episodes = expandEpisodes(x);
  ASSERT_EQ(episodes.size(), 8u);
  EXPECT_EQ(episodes.front().id, "a_seed-1_planner-pf-geodesic_dw_alpha-0.5");
  EXPECT_EQ(episodes[1].id, "a_seed-1_planner-astar_dw_alpha-0.5");
  EXPECT_EQ(episodes.back().id, "b_seed-2_planner-astar_dw_alpha-0.5");
  EXPECT_EQ(episodes[1].condition(), "planner-astar_dw_alpha-0.5");
  EXPECT_EQ(episodes[1].pairing(), "a_seed-1");
  const auto again = expandEpisodes(readExperiment(x.file));
  for (size_t i = 0; i < episodes.size(); ++i) EXPECT_EQ(again[i].id, episodes[i].id);
}

TEST_F(ExperimentFileTest, GeneratedScenesAndTheRunCommand) {
  const auto x = readExperiment(write(
      "<experiment max_ticks=\"300\">\n  <generated kind=\"district\" size=\"80 60\" objects=\"110\" seeds=\"3-4 9\"/>\n"
      "  <acoustics values=\"binaural\"/>\n  <nets values=\"fast.pnml\"/>\n"
      "  <set name=\"dw_alpha\" values=\"0.5\"/>\n</experiment>\n"));
  const auto episodes = expandEpisodes(x);
  ASSERT_EQ(episodes.size(), 3u);
  EXPECT_EQ(episodes[2].id, "district-80x60-o110-s9_acoustics-binaural_net-fast_dw_alpha-0.5");
  EXPECT_EQ(x.scenes[2].generation->seed, 9u);
  const auto command = runCommand(x, episodes[0], "/out/e", "/bin");
  const std::vector<std::string> expected = {
      "/bin/beft-run", "",         "--out", "/out/e", "--max-ticks", "300", "--acoustics", "binaural", "--net",
      (dir_ / "fast.pnml").string(), "--set", "dw_alpha=0.5"};
  EXPECT_EQ(command, expected);  // the scene's file is filled in once it is generated
}

TEST(ExperimentEpisodeRun, TheRecordedCommandHoldsNoFolderOfThisMachine) {
  const std::vector<std::string> command = {"/build/bin/beft-run", "/x/out/scenes/s1.xml", "--out",
                                            "/x/out/episodes/e", "--seed", "3"};
  const std::vector<std::string> recorded = {"OUT/scenes/s1.xml", "--out", "OUT/episodes/e", "--seed", "3"};
  EXPECT_EQ(recordedCommand(command, "/x/out"), recorded);
}

TEST_F(ExperimentFileTest, AComparisonOfAParameterByItsName) {
  const auto x = readExperiment(write("<experiment>\n  <scenario file=\"a.xml\"/>\n  <compare factor=\"dw\" a=\"2\" b=\"1\"/>\n"
                                      "  <set name=\"dw\" values=\"1 2\"/>\n</experiment>\n"));
  ASSERT_EQ(x.comparisons.size(), 1u);
  EXPECT_EQ(x.comparisons[0].factor, "set:dw");
  EXPECT_EQ(x.comparisons[0].a, "2");
}

TEST_F(ExperimentFileTest, AListOfEpisodesInsteadOfTheProduct) {
  const auto x = readExperiment(write(
      "<experiment>\n  <scenario file=\"a.xml\"/>\n  <scenario file=\"b.xml\"/>\n  <seeds values=\"1-9\"/>\n"
      "  <set name=\"dw\" values=\"1 2\"/>\n  <episode dw=\"2\" seed=\"4\" scene=\"b\"/>\n"
      "  <episode scene=\"a\" seed=\"9\" dw=\"1\"/>\n</experiment>\n"));
  const auto episodes = expandEpisodes(x);
  ASSERT_EQ(episodes.size(), 2u);
  EXPECT_EQ(episodes[0].id, "b_seed-4_dw-2");
  EXPECT_EQ(episodes[1].id, "a_seed-9_dw-1");
  EXPECT_EQ(*episodes[0].value("set:dw"), "2");
  const auto twice = write("<experiment>\n  <scenario file=\"a.xml\"/>\n  <episode scene=\"a\"/>\n"
                           "  <episode scene=\"a\"/>\n</experiment>\n");
  EXPECT_THROW(expandEpisodes(readExperiment(twice)), ExperimentError);
}

TEST_F(ExperimentFileTest, IdsThatWouldCollideAreRefused) {
  const auto x = readExperiment(write(
      "<experiment>\n  <scenario file=\"a.xml\"/>\n  <set name=\"mode\" values=\"a:b a_b\"/>\n</experiment>\n"));
  EXPECT_THROW(expandEpisodes(x), ExperimentError);
}

TEST(ExperimentValueLists, SeedLists) {
  EXPECT_EQ(*parseSeedList("1-3 7"), (std::vector<uint64_t>{1, 2, 3, 7}));
  EXPECT_EQ(*parseSeedList(" 5 "), (std::vector<uint64_t>{5}));
  for (const char* bad : {"", "3-1", "-2", "1-", "x", "1.5", "1-2-3"}) EXPECT_FALSE(parseSeedList(bad)) << bad;
}

}  // namespace
}  // namespace beft::experiment

namespace beft::experiment {
namespace {

// The examples in scenarios/experiments/ read, and are the episodes their comments promise.
TEST(ShippedExperiments, ReadAndExpandToTheirEpisodes) {
  const std::filesystem::path folder = std::filesystem::path(BEFT_SOURCE_DIR) / "scenarios" / "experiments";
  const std::map<std::string, size_t> expected = {
      {"districts.xml", 80}, {"large_districts.xml", 3}, {"yard_planners.xml", 6}};
  int read = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    SCOPED_TRACE(entry.path().filename().string());
    const auto episodes = expandEpisodes(readExperiment(entry.path().string()));
    EXPECT_FALSE(episodes.empty());
    const auto known = expected.find(entry.path().filename().string());
    ASSERT_NE(known, expected.end()) << "an example this test does not know: add its episode count";
    EXPECT_EQ(episodes.size(), known->second);
    ++read;
  }
  EXPECT_GE(read, 3);
}

}  // namespace
}  // namespace beft::experiment
