// Launch files and the process supervisor, with small shell processes.
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "lib/launch/free_port.hpp"
#include "lib/launch/launch_file.hpp"
#include "lib/launch/run_key.hpp"
#include "lib/launch/run_parameters.hpp"
#include "lib/launch/supervisor.hpp"

using namespace beft::launch;

namespace {

struct TempDir {
  std::string path;
  TempDir() {
    char pattern[] = "/tmp/beft_launch_XXXXXX";
    path = mkdtemp(pattern);
  }
  ~TempDir() { std::system(("rm -rf '" + path + "'").c_str()); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string file = path + "/" + name;
    std::ofstream(file) << text;
    return file;
  }
};

std::string readAll(const std::string& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string errorOf(const std::string& file, std::map<std::string, std::string> overrides = {}) {
  try {
    loadLaunchFile(file, overrides);
  } catch (const LaunchError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(LaunchFile, ResolvesArgumentsAndDefaults) {
  TempDir dir;
  const auto file = dir.write("a.xml", R"(<launch name="t">
  <arg name="who" default="world"/>
  <process name="p1" command="echo" args="hello ${who} 'two words'" group="low" restart="on-failure" max_restarts="2"/>
  <process name="p2" command="true" host="robot" role="arbiter" lcm_url="0"/>
</launch>)");
  const auto spec = loadLaunchFile(file, {{"who", "there"}});
  ASSERT_EQ(spec.processes.size(), 2u);
  const auto& p1 = spec.processes[0];
  EXPECT_EQ(p1.command, "echo");
  EXPECT_EQ(p1.args, (std::vector<std::string>{"hello", "there", "two words"}));
  EXPECT_EQ(p1.group, "low");
  EXPECT_EQ(p1.restart, RestartPolicy::OnFailure);
  EXPECT_EQ(p1.max_restarts, 2);
  EXPECT_EQ(p1.line, 3);
  EXPECT_TRUE(spec.processes[1].is_arbiter);
  EXPECT_EQ(spec.processes[1].host, "robot");
  EXPECT_FALSE(spec.processes[1].append_lcm_url);
}

TEST(LaunchFile, ErrorsNameFileAndLine) {
  TempDir dir;
  auto f1 = dir.write("unknown_var.xml", "<launch>\n<process name=\"p\" command=\"x\" args=\"${nope}\"/>\n</launch>");
  EXPECT_NE(errorOf(f1).find(f1 + ":2: unknown variable '${nope}'"), std::string::npos) << errorOf(f1);
  auto f2 = dir.write("dup.xml", "<launch>\n<process name=\"p\" command=\"x\"/>\n\n<process name=\"p\" command=\"y\"/>\n</launch>");
  EXPECT_NE(errorOf(f2).find(f2 + ":4: duplicate process name 'p'"), std::string::npos) << errorOf(f2);
  auto f3 = dir.write("policy.xml", "<launch>\n<process name=\"p\" command=\"x\" restart=\"always\"/>\n</launch>");
  EXPECT_NE(errorOf(f3).find(f3 + ":2: restart must be"), std::string::npos) << errorOf(f3);
  auto f4 = dir.write("attr.xml", "<launch>\n<process name=\"p\" command=\"x\" colour=\"red\"/>\n</launch>");
  EXPECT_NE(errorOf(f4).find(f4 + ":2: unknown attribute 'colour'"), std::string::npos) << errorOf(f4);
  auto f5 = dir.write("missing.xml", "<launch>\n<process name=\"p\"/>\n</launch>");
  EXPECT_NE(errorOf(f5).find(f5 + ":2: <process> needs attribute 'command'"), std::string::npos) << errorOf(f5);
  auto f6 = dir.write("bad.xml", "<launch>\n<process name=\"p\" command=\"x\">\n</launch>");
  EXPECT_NE(errorOf(f6).find(f6 + ":"), std::string::npos);
  auto f7 = dir.write("ok.xml", "<launch><process name=\"p\" command=\"x\"/></launch>");
  EXPECT_NE(errorOf(f7, {{"undeclared", "1"}}).find("declares no <arg name=\"undeclared\">"), std::string::npos);
}

TEST(LaunchFile, ReadsPriorities) {
  TempDir dir;
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="store" command="true" priority="background"/>
  <process name="loop" command="true" priority="normal"/>
  <process name="plain" command="true"/>
</launch>)");
  const LaunchSpec spec = loadLaunchFile(file, {});
  EXPECT_EQ(spec.processes[0].priority, Priority::Background);
  EXPECT_EQ(spec.processes[1].priority, Priority::Normal);
  EXPECT_EQ(spec.processes[2].priority, Priority::Normal);
  const auto bad = dir.write("bad.xml", "<launch>\n  <process name=\"a\" command=\"true\" priority=\"high\"/>\n</launch>");
  EXPECT_EQ(errorOf(bad), bad + ":2: priority must be 'normal' or 'background', not 'high'");
}

TEST(LaunchFile, StartsAProcessOnlyWhenItsConditionHolds) {
  TempDir dir;
  const auto file = dir.write("if.xml", R"(<launch>
  <arg name="ears" default="0"/>
  <process name="always" command="true"/>
  <process name="ears" command="true" if="${ears}"/>
</launch>)");
  auto names = [](const LaunchSpec& spec) {
    std::vector<std::string> out;
    for (const auto& p : spec.processes) out.push_back(p.name);
    return out;
  };
  EXPECT_EQ(names(loadLaunchFile(file, {})), (std::vector<std::string>{"always"}));
  EXPECT_EQ(names(loadLaunchFile(file, {{"ears", "1"}})), (std::vector<std::string>{"always", "ears"}));
  EXPECT_EQ(names(loadLaunchFile(file, {{"ears", "true"}})), (std::vector<std::string>{"always", "ears"}));
  EXPECT_EQ(names(loadLaunchFile(file, {{"ears", ""}})), (std::vector<std::string>{"always"}));
  EXPECT_EQ(errorOf(file, {{"ears", "maybe"}}), file + ":4: if must be 1, true, 0, false or empty, not 'maybe'");
}

TEST(RunParameters, KeepEachProcesssParamsForAReplay) {
  TempDir dir;
  const auto file = dir.write("run.xml", R"(<launch>
  <arg name="acoustics" default="ground_truth"/>
  <process name="audio" command="beft-audio" args="--param seed=7 --verbose --param acoustics=${acoustics}"/>
  <process name="fusion" command="beft-fusion"/>
</launch>)");
  const std::string path = dir.path + "/parameters.json";
  ASSERT_TRUE(writeRunParameters(loadLaunchFile(file, {{"acoustics", "binaural"}}), path));
  EXPECT_EQ(readRunParameters(path, "audio"),
            (std::map<std::string, std::string>{{"acoustics", "binaural"}, {"seed", "7"}}));
  EXPECT_TRUE(readRunParameters(path, "fusion").empty());
  EXPECT_TRUE(readRunParameters(path, "nobody").empty());
  EXPECT_TRUE(readRunParameters(dir.path + "/missing.json", "audio").empty());
  const auto bad = dir.write("bad.json", R"({"audio": {"seed": 7}})");
  try {
    readRunParameters(bad, "audio");
    FAIL() << "a number where a string belongs was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad + ": not a run's parameters file"), std::string::npos) << e.what();
  }
  EXPECT_THROW(readRunParameters(dir.write("cut.json", R"({"audio": {"se)"), "audio"), std::runtime_error);
}

TEST(LaunchFile, SplitsQuotedArguments) {
  EXPECT_EQ(splitArguments("  a  'b c' \"d e\" f'g h'  "),
            (std::vector<std::string>{"a", "b c", "d e", "fg h"}));
  EXPECT_THROW(splitArguments("a 'b"), LaunchError);
}

TEST(Supervisor, PrefixesOutputRestartsOnFailureAndEndsWithTheArbiter) {
  TempDir dir;
  const std::string counter = dir.path + "/starts";
  const std::string out_log = dir.path + "/out.log";
  // The arbiter ends once flaky has used up its restarts (at most a minute).
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="flaky" command="sh" args="-c 'echo started >> )" + counter + R"(; echo flaky says hi; exit 3'" restart="on-failure" max_restarts="2" lcm_url="0"/>
  <process name="sleeper" command="sleep" args="100" lcm_url="0"/>
  <process name="arbiter" command="sh" args="-c 'i=0; until grep -q restart.limit.reached )" + out_log +
                                          R"( || [ $i -ge 1200 ]; do sleep 0.05; i=$((i+1)); done; echo done; exit 0'" role="arbiter" lcm_url="0"/>
</launch>)");
  SupervisorOptions options;
  options.quiet_children = true;
  options.output_file = out_log;
  const auto start = std::chrono::steady_clock::now();
  const auto outcome = supervise(loadLaunchFile(file, {}), options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  EXPECT_TRUE(outcome.arbiter_ran);
  EXPECT_EQ(outcome.arbiter_exit_code, 0);
  EXPECT_LT(seconds, 20.0);  // the sleeper was stopped, not waited for
  const std::string log = readAll(options.output_file);
  EXPECT_NE(log.find("[flaky] flaky says hi"), std::string::npos) << log;
  EXPECT_NE(log.find("[arbiter] done"), std::string::npos) << log;
  EXPECT_NE(log.find("restarting (2/2)"), std::string::npos) << log;
  EXPECT_NE(log.find("restart limit reached"), std::string::npos) << log;
  EXPECT_EQ(readAll(counter), "started\nstarted\nstarted\n");  // first start + 2 restarts
}

// At the end, listeners (group="listener": the SSR bridge) are stopped
// while the rest still runs: the bridge may ask the blackboard for the
// state it ends on.
TEST(Supervisor, StopsListenersWhileTheOthersStillRun) {
  TempDir dir;
  const std::string pid_file = dir.path + "/infra.pid", seen = dir.path + "/seen", ready = dir.path + "/ready";
  // The arbiter ends the run only once the blackboard wrote its pid and the
  // bridge set its TERM handler (at most 60 s), however slow the machine; the
  // handler reads the pid when it runs (\$), not when it is set.
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="blackboard" group="infra" command="sh" args="-c 'echo $$ > )" + pid_file +
                                               R"(; trap &quot;exit 0&quot; TERM; while :; do sleep 0.05; done'" lcm_url="0"/>
  <process name="bridge" group="listener" command="sh" args="-c 'trap &quot;sleep 0.3; kill -0 \$(cat )" + pid_file +
                                               R"() &amp;&amp; echo alive > )" + seen + R"( || echo gone > )" + seen +
                                               R"(; exit 0&quot; TERM; touch )" + ready +
                                               R"(; while :; do sleep 0.05; done'" lcm_url="0"/>
  <process name="arbiter" command="sh" args="-c 'n=0; while [ ! -s )" + pid_file + R"( ] || [ ! -e )" + ready +
                                               R"( ]; do n=$((n+1)); [ $n -gt 1200 ] &amp;&amp; exit 1; sleep 0.05; done; exit 0'" role="arbiter" lcm_url="0"/>
</launch>)");
  SupervisorOptions options;
  options.quiet_children = true;
  options.output_file = dir.path + "/out.log";
  const auto outcome = supervise(loadLaunchFile(file, {}), options);
  EXPECT_TRUE(outcome.arbiter_ran);
  EXPECT_EQ(readAll(seen), "alive\n") << readAll(options.output_file);
}

TEST(Supervisor, ExceptAndOtherHostsAreNotStarted) {
  TempDir dir;
  const std::string marker = dir.path + "/ran";
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="skipped" command="touch" args=")" + marker + R"(" lcm_url="0"/>
  <process name="remote" command="touch" args=")" + marker + R"(" host="robot2" lcm_url="0"/>
  <process name="arbiter" command="true" role="arbiter" lcm_url="0"/>
</launch>)");
  SupervisorOptions options;
  options.quiet_children = true;
  options.except = {"skipped"};
  options.output_file = dir.path + "/out.log";
  const auto outcome = supervise(loadLaunchFile(file, {}), options);
  EXPECT_EQ(outcome.arbiter_exit_code, 0);
  EXPECT_NE(access(marker.c_str(), F_OK), 0);
  const std::string log = readAll(options.output_file);
  EXPECT_NE(log.find("not starting skipped (--except); start it by hand with:"), std::string::npos) << log;
  EXPECT_NE(log.find("not starting remote: it runs on host 'robot2'"), std::string::npos) << log;
}

TEST(Supervisor, HostsCanBeLaunchArguments) {
  TempDir dir;
  const std::string marker = dir.path + "/ran";
  const auto file = dir.write("run.xml", R"(<launch>
  <arg name="expert_host" default="local"/>
  <process name="expert" command="touch" args=")" + marker + R"(" host="${expert_host}" lcm_url="0"/>
  <process name="arbiter" command="sleep" args="0.3" role="arbiter" lcm_url="0"/>
</launch>)");
  SupervisorOptions options;
  options.quiet_children = true;
  options.output_file = dir.path + "/out.log";
  const auto moved = loadLaunchFile(file, {{"expert_host", "robot"}});
  EXPECT_EQ(moved.processes[0].host, "robot");
  supervise(moved, options);
  EXPECT_NE(access(marker.c_str(), F_OK), 0) << "started on the wrong host";
  EXPECT_NE(readAll(options.output_file).find("not starting expert: it runs on host 'robot'"), std::string::npos);
  supervise(loadLaunchFile(file, {}), options);  // the default: this machine
  EXPECT_EQ(access(marker.c_str(), F_OK), 0);
}

namespace {

// Fields of /proc/PID/stat after the command name: nice is field 19, policy field 41.
std::vector<std::string> statFields(const std::string& stat) {
  std::vector<std::string> fields;
  std::istringstream rest(stat.substr(stat.rfind(')') + 2));
  for (std::string field; rest >> field;) fields.push_back(field);
  return fields;
}

}  // namespace

TEST(Supervisor, BackgroundProcessesRunNicedAndBatch) {
  TempDir dir;
  const std::string background = dir.path + "/background", normal = dir.path + "/normal";
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="store" command="sh" args="-c 'cat /proc/$$/stat > )" + background + R"('" priority="background" lcm_url="0"/>
  <process name="loop" command="sh" args="-c 'cat /proc/$$/stat > )" + normal + R"('" lcm_url="0"/>
  <process name="arbiter" command="sleep" args="0.5" role="arbiter" lcm_url="0"/>
</launch>)");
  SupervisorOptions options;
  options.quiet_children = true;
  options.output_file = dir.path + "/out.log";
  supervise(loadLaunchFile(file, {}), options);
  const auto lowered = statFields(readAll(background)), plain = statFields(readAll(normal));
  ASSERT_GE(lowered.size(), 39u) << readAll(options.output_file);
  ASSERT_GE(plain.size(), 39u);
  // Counted from field 3 (state): nice is field 19, policy field 41.
  EXPECT_GE(std::stoi(lowered[19 - 3]), 10);
  EXPECT_EQ(std::stoi(lowered[41 - 3]), SCHED_BATCH);
  EXPECT_EQ(std::stoi(plain[41 - 3]), SCHED_OTHER);
  EXPECT_EQ(std::stoi(plain[19 - 3]), getpriority(PRIO_PROCESS, 0));

  // BEFT_BACKGROUND=0: everything at the normal priority.
  setenv("BEFT_BACKGROUND", "0", 1);
  supervise(loadLaunchFile(file, {}), options);
  unsetenv("BEFT_BACKGROUND");
  const auto kept = statFields(readAll(background));
  ASSERT_GE(kept.size(), 39u);
  EXPECT_EQ(std::stoi(kept[41 - 3]), SCHED_OTHER);
  EXPECT_EQ(std::stoi(kept[19 - 3]), getpriority(PRIO_PROCESS, 0));
}

TEST(Supervisor, ReportsAFailedArbiter) {
  TempDir dir;
  const auto file = dir.write("run.xml",
                              "<launch><process name=\"arbiter\" command=\"sh\" args=\"-c 'exit 4'\" role=\"arbiter\" lcm_url=\"0\"/></launch>");
  SupervisorOptions options;
  options.quiet_children = true;
  const auto outcome = supervise(loadLaunchFile(file, {}), options);
  EXPECT_EQ(outcome.arbiter_exit_code, 4);
  EXPECT_EQ(outcome.message, "run failed");
}

TEST(Supervisor, RecordsFromTheFirstMessageOfTheFirstProcess) {
  // beft-task publishes its command the moment it starts: it is in the log
  // only if nothing starts before the recorder listens.
  TempDir dir;
  SupervisorOptions options;
  options.lcm_url = "udpm://239.255.76.67:" + std::to_string(findFreeUdpPort(35000, 39999)) + "?ttl=0";
  // beft-task takes --lcm-url before its subcommand, so it is written here;
  // --run-id 0: no listening for the run on the URL first.
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="talker" command="beft-task" args="--lcm-url )" + options.lcm_url +
                                             R"( --run-id 0 push --no-wait goto 1 2 90" lcm_url="0"/>
  <process name="arbiter" command="sh" args="-c 'sleep 0.5'" role="arbiter" lcm_url="0"/>
</launch>)");
  options.quiet_children = true;
  options.output_file = dir.path + "/out.log";
  options.bin_dir = BEFT_BIN_DIR;
  options.record_log = dir.path + "/run.lcmlog";
  std::ofstream(options.record_log) << "an old log, replaced";
  const auto outcome = supervise(loadLaunchFile(file, {}), options);
  EXPECT_EQ(outcome.arbiter_exit_code, 0) << readAll(options.output_file);
  const std::string log = readAll(options.record_log);
  EXPECT_EQ(log.find("an old log"), std::string::npos);
  EXPECT_NE(log.find("TASK_COMMAND"), std::string::npos) << readAll(options.output_file);
}

TEST(Supervisor, SaysWhenTheRecorderCannotStart) {
  TempDir dir;
  const std::string marker = dir.path + "/ran";
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="arbiter" command="touch" args=")" + marker + R"(" role="arbiter" lcm_url="0"/>
</launch>)");
  SupervisorOptions options;
  options.quiet_children = true;
  options.output_file = dir.path + "/out.log";
  options.bin_dir = BEFT_BIN_DIR;
  options.record_log = dir.path + "/no/such/folder/run.lcmlog";
  const auto outcome = supervise(loadLaunchFile(file, {}), options);
  EXPECT_EQ(outcome.message, "the recorder did not start");
  EXPECT_NE(access(marker.c_str(), F_OK), 0) << "a process started without a recorder";
  EXPECT_NE(readAll(options.output_file).find("cannot be written"), std::string::npos) << readAll(options.output_file);
}

// A keyed run: every process gets the key file's absolute path as
// BEFT_KEY_FILE, the launcher says the run is keyed and never prints the key.
TEST(Supervisor, GivesEveryProcessTheRunsKeyFileAndSaysTheRunIsKeyed) {
  TempDir dir;
  const std::string key_text = "00112233445566778899aabbccddeeff00112233445566778899aabbccddeeff\n";
  const std::string key = dir.write("run.key", key_text);
  const auto file = dir.write("run.xml", R"(<launch>
  <process name="worker" command="sh" args="-c 'echo worker has $BEFT_KEY_FILE'" lcm_url="0"/>
  <process name="arbiter" command="sh" args="-c 'sleep 0.3; echo arbiter has $BEFT_KEY_FILE'" role="arbiter" lcm_url="0"/>
</launch>)");
  SupervisorOptions options;
  options.quiet_children = true;
  options.output_file = dir.path + "/out.log";
  options.key_file = runKeyFile(key);
  EXPECT_EQ(options.key_file, key);
  supervise(loadLaunchFile(file, {}), options);
  const std::string log = readAll(options.output_file);
  EXPECT_NE(log.find("[worker] worker has " + key), std::string::npos) << log;
  EXPECT_NE(log.find("[arbiter] arbiter has " + key), std::string::npos) << log;
  EXPECT_NE(log.find("the run is keyed (" + key + ")"), std::string::npos) << log;
  EXPECT_EQ(log.find(key_text.substr(0, 16)), std::string::npos) << "the key itself was printed";
  EXPECT_NE(commandLineOf(loadLaunchFile(file, {}).processes[0], options).find("BEFT_KEY_FILE='" + key + "'"),
            std::string::npos);

  // Without a key, no process inherits one from the launcher's environment.
  options.key_file.clear();
  supervise(loadLaunchFile(file, {}), options);
  const std::string unkeyed = readAll(options.output_file).substr(log.size());
  EXPECT_NE(unkeyed.find("[worker] worker has\n"), std::string::npos) << unkeyed;
  EXPECT_EQ(unkeyed.find("the run is keyed"), std::string::npos) << unkeyed;
}

TEST(RunKey, IsTheOptionElseTheEnvironmentMadeAbsoluteAndChecked) {
  TempDir dir;
  const std::string key = dir.write("run.key", std::string(32, 'k'));
  const std::string short_key = dir.write("short.key", "0011");
  unsetenv("BEFT_KEY_FILE");
  EXPECT_EQ(runKeyFile(""), "");
  ASSERT_EQ(chdir(dir.path.c_str()), 0);
  EXPECT_EQ(runKeyFile("run.key"), key);  // relative to where the launcher runs
  EXPECT_EQ(std::string(getenv("BEFT_KEY_FILE")), key);  // the launcher's own LCM instances use it too
  setenv("BEFT_KEY_FILE", key.c_str(), 1);
  EXPECT_EQ(runKeyFile(""), key);
  EXPECT_THROW(runKeyFile(short_key), LaunchError);
  EXPECT_THROW(runKeyFile(dir.path + "/no_such.key"), LaunchError);
  try {
    runKeyFile(dir.path + "/no_such.key");
  } catch (const LaunchError& e) {
    EXPECT_NE(std::string(e.what()).find("no_such.key"), std::string::npos) << e.what();
  }
  unsetenv("BEFT_KEY_FILE");
  ASSERT_EQ(chdir("/"), 0);
}

TEST(FreePort, ReturnsAPortInRange) {
  const int port = findFreeUdpPort(30000, 30100);
  EXPECT_GE(port, 30000);
  EXPECT_LE(port, 30100);
}
