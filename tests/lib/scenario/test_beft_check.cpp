// beft-check as a user runs it: exit codes, the error line, the summary.
#include <sys/wait.h>

#include <array>
#include <cstdio>

#include <gtest/gtest.h>

#include "tests/lib/scenario/scenario_test_dir.hpp"

namespace beft::scenario {
namespace {

struct CheckRun {
  int exit_code = -1;
  std::string out, err;
};

// Runs beft-check with `arguments` (already shell-quoted), stdout and stderr apart.
CheckRun runCheck(const std::string& arguments, const std::filesystem::path& err_file) {
  const std::string command =
      std::string("'") + BEFT_CHECK_BINARY + "' " + arguments + " 2>'" + err_file.string() + "'";
  CheckRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  std::array<char, 4096> buffer{};
  for (size_t n; (n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) run.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_file);
  run.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return run;
}

using BeftCheck = testing::ScenarioTestDir;

TEST_F(BeftCheck, GoodScenarioPrintsItsSummaryAndExitsZero) {
  const std::string yard = std::string(BEFT_SCENARIOS_DIR) + "/yard.xml";
  const CheckRun run = runCheck("'" + yard + "'", dir_ / "err.txt");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  for (const char* expected :
       {"scenario   yard", "world      30 x 20 m, resolution 0.1 m (300 x 200 cells)",
        "dt 0.1 s, duration 120 s (1200 ticks), seed 7", "robot      start (2, 2) yaw 0 deg",
        "victim_hidden: sounds/help.wav (2.15 s, 16000 Hz, mono), active", "sounds like person, yelling",
        "  car       1: car1", "  person    2: victim_seen victim_hidden", "congruency 7 pairs",
        "  person    idle 0.25 walking 0.25 yelling 0.75"}) {
    EXPECT_NE(run.out.find(expected), std::string::npos) << "missing '" << expected << "' in:\n" << run.out;
  }
}

TEST_F(BeftCheck, BrokenScenarioPrintsFileLineAndMessageAndExitsOne) {
  const std::string path = write(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\"/>\n"
      "  <robot y=\"2\"/>\n</scenario>\n");
  const CheckRun run = runCheck("'" + path + "'", dir_ / "err.txt");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err, path + ":4: <robot> is missing required attribute 'x'\n");
}

TEST_F(BeftCheck, EventsArePrintedInTimeOrder) {
  const std::string path = write(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\" duration=\"60\">\n  <world width=\"30\" height=\"20\"/>\n"
      "  <robot x=\"2\" y=\"2\"/>\n  <object id=\"p\" label=\"person\" x=\"9\" y=\"9\"/>\n  <events>\n"
      "    <event t=\"20\" object=\"p\" activity=\"late\"/>\n    <event t=\"5\" object=\"p\" activity=\"early\"/>\n"
      "  </events>\n</scenario>\n");
  const CheckRun run = runCheck("'" + path + "'", dir_ / "err.txt");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto early = run.out.find("t=   5.0 s  p: activity=early");
  const auto late = run.out.find("t=  20.0 s  p: activity=late");
  ASSERT_NE(early, std::string::npos) << run.out;
  ASSERT_NE(late, std::string::npos) << run.out;
  EXPECT_LT(early, late);
}

TEST_F(BeftCheck, QuietPrintsNothingAndStrictRefusesWarnings) {
  const std::string path = write(
      "<?xml version=\"1.0\"?>\n<scenario name=\"t\">\n  <world width=\"30\" height=\"20\" floor=\"mud\"/>\n"
      "  <robot x=\"2\" y=\"2\"/>\n</scenario>\n");
  const std::string warning = path + ":3: warning: unknown attribute 'floor' on <world>\n";
  const CheckRun quiet = runCheck("--quiet '" + path + "'", dir_ / "err.txt");
  EXPECT_EQ(quiet.exit_code, 0);
  EXPECT_EQ(quiet.out, "");
  EXPECT_EQ(quiet.err, warning);
  const CheckRun strict = runCheck("--quiet --strict '" + path + "'", dir_ / "err.txt");
  EXPECT_EQ(strict.exit_code, 1);
  EXPECT_EQ(strict.err, warning + path + ": 1 warning(s), refused by --strict\n");
}

TEST_F(BeftCheck, UsageErrorsExitTwoAndHelpExitsZero) {
  const CheckRun missing = runCheck("", dir_ / "err.txt");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("file is required"), std::string::npos) << missing.err;
  const CheckRun help = runCheck("--help", dir_ / "err.txt");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("--quiet"), std::string::npos) << help.out;
}

}  // namespace
}  // namespace beft::scenario
