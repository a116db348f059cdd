// Experts written in Python take part through the run's bridge
// (modules/python/README.md): yard run with the Python dw or geometry in
// place of the C++ one must write exactly the data messages of the run with
// the C++ experts, also when the Python expert is killed mid-run and
// restarted (it resumes from the run's history, which the bridge sends it).
// Skipped without Debian's python3 and python3-websockets.
#include <gtest/gtest.h>

#include <string>

#include "lib/launch/free_port.hpp"
#include "lib/launch/tcp_port.hpp"
#include "tests/system/run_support.hpp"

using namespace beft::system_test;

namespace {

constexpr int kTicks = 200;
const std::string kRecorderInFront = "BEFT_BACKGROUND=0 ";
const std::string kPython = "/usr/bin/python3";

bool pythonWithWebsockets() {
  return runCommand(kPython + " -c 'import websockets'", 30).exit_code == 0;
}

struct YardRun {
  ProgramResult result;
  std::vector<LoggedMessage> log;
  std::string dir;
};

YardRun runYard(const std::string& tag, const std::string& extra_args) {
  YardRun run;
  run.dir = makeTempDir("external_" + tag);
  run.result = runCommand(kRecorderInFront + binDir() + "/beft-run " + sourceDir() + "/scenarios/yard.xml --max-ticks " +
                              std::to_string(kTicks) + " --no-report --out " + run.dir + " " + extra_args,
                          600);
  try {
    run.log = readLog(run.dir + "/run.lcmlog");
  } catch (const std::exception&) {
    // no log: the run's exit code says why
  }
  return run;
}

std::string external(const std::string& name) {
  return "--external " + name + "=\"" + kPython + " " + sourceDir() + "/modules/python/examples/" + name +
         "_expert.py\"";
}

class ExternalExpertRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!pythonWithWebsockets()) return;
    cpp_ = new YardRun(runYard("cpp", ""));
  }
  static void TearDownTestSuite() {
    delete cpp_;
    cpp_ = nullptr;
  }
  void SetUp() override {
    if (cpp_ == nullptr) GTEST_SKIP() << "needs " << kPython << " with python3-websockets (apt-get install python3-websockets)";
    ASSERT_EQ(cpp_->result.exit_code, 0) << cpp_->result.output;
  }
  // Every data message as the C++ run's, none repeated (a restarted expert's
  // outputs already on the bus are not sent again).
  void expectSameDataMessages(const YardRun& run) {
    ASSERT_EQ(run.result.exit_code, 0) << run.result.output;
    const DataComparison comparison = compareDataMessages(cpp_->log, run.log);
    EXPECT_GT(comparison.expected, 1000u);
    EXPECT_TRUE(comparison.identical()) << comparison.first_difference;
  }
  static YardRun* cpp_;
};
YardRun* ExternalExpertRun::cpp_ = nullptr;

TEST_F(ExternalExpertRun, ThePythonDwWritesTheDataMessagesOfTheCppOne) {
  expectSameDataMessages(runYard("python_dw", external("dw")));
}

TEST_F(ExternalExpertRun, ThePythonGeometryWritesTheDataMessagesOfTheCppOne) {
  expectSameDataMessages(runYard("python_geometry", external("geometry")));
}

TEST_F(ExternalExpertRun, APythonDwKilledMidRunIsRestartedAndChangesNothing) {
  const YardRun run = runYard("python_dw_killed", external("dw") + " --kill dw@80");
  expectSameDataMessages(run);
  EXPECT_NE(runCommand("cat " + run.dir + "/processes.log", 10).output.find("resumed from the run's history"),
            std::string::npos);
}

// Through a running bridge (no run needed): a wrong field type, a missing
// field and an undeclared channel are refused, each with a status naming it.
TEST(ExternalExpertRefusals, TheBridgeNamesTheFieldOrChannelItRefuses) {
  if (!pythonWithWebsockets()) GTEST_SKIP() << "needs " << kPython << " with python3-websockets";
  const int port = beft::launch::findFreeTcpPort();
  const std::string url = "udpm://239.255.76.67:" + std::to_string(beft::launch::findFreeUdpPort()) + "?ttl=0";
  const std::string client = sourceDir() + "/tests/experts/python/refusals_client.py";
  const ProgramResult result = runCommand(
      binDir() + "/beft-bridge --port " + std::to_string(port) + " --lcm-url '" + url + "' >/dev/null 2>&1 & bridge=$!; " +
          "for i in $(seq 50); do " + kPython + " -c 'import socket; socket.create_connection((\"127.0.0.1\", " +
          std::to_string(port) + "))' 2>/dev/null && break; sleep 0.1; done; " + kPython + " " + client +
          " ws://127.0.0.1:" + std::to_string(port) + "; kill $bridge",
      60);
  EXPECT_NE(result.output.find("expert dw accepted"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("DYNAMIC_WEIGHTS refused: weights[0].weight: not a number"), std::string::npos)
      << result.output;
  EXPECT_NE(result.output.find("DYNAMIC_WEIGHTS refused: tick: missing"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("TASK_COMMAND refused: expert dw does not declare it"), std::string::npos)
      << result.output;
}

}  // namespace
