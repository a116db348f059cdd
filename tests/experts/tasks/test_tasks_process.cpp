// beft-tasks and beft-task over real LCM, each test on its own UDP port: the
// test plays the world (ROBOT_STATE), the arbiter (FIRE, waits for DONE) and
// the planner service (answers PLAN_REQUEST), while beft-task pushes, lists
// and clears.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <beft/done_t.hpp>
#include <beft/fire_t.hpp>
#include <beft/plan_request_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/robot_command_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/task_events_t.hpp>
#include <beft/task_stack_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/launch/free_port.hpp"
#include "lib/common/channels.hpp"
#include "lib/common/lcm_url.hpp"

extern char** environ;

using namespace beft;

namespace {

using Clock = std::chrono::steady_clock;

// A child process with its stdout and stderr in a file.
class Child {
 public:
  Child(const std::vector<std::string>& args, const std::string& output_file) : output_file_(output_file) {
    posix_spawn_file_actions_t actions{};
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, output_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
  }
  ~Child() {
    if (running()) {
      kill(pid_, SIGTERM);
      wait(5.0);
    }
    std::remove(output_file_.c_str());
  }
  bool started() const { return pid_ > 0; }
  bool running() {
    if (pid_ <= 0 || exited_) return false;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      exited_ = true;
      code_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    return !exited_;
  }
  // Waits for the exit; the exit code, or -1 if still running after the budget.
  int wait(double seconds) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (running()) {
      if (Clock::now() > deadline) {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
        exited_ = true;
        return -1;
      }
      usleep(5000);
    }
    return code_;
  }
  std::string output() const {
    std::ifstream in(output_file_);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
  int code_ = -1;
  std::string output_file_;
};

class TasksProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    // A port no other test holds now (a hash of the pid once collided).
    port_ = beft::launch::findFreeUdpPort(21000, 40999);
    ASSERT_GT(port_, 0);
    url_ = lcmUrlForPort(port_);
    lcm_ = std::make_unique<lcm::LCM>(url_);
    ASSERT_TRUE(lcm_->good()) << url_;
    subscribe<done_t>(channels::kDone, [this](const done_t& m) { done_[m.firing_id] = m; });
    subscribe<task_stack_t>(channels::kTaskStack, [this](const task_stack_t& m) { stack_ = m; });
    subscribe<robot_command_t>(channels::kRobotCommand, [this](const robot_command_t& m) { command_ = m; });
    subscribe<task_events_t>(channels::kTaskEvents, [this](const task_events_t& m) {
      for (const auto& e : m.events) events_.push_back(e);
    });
    subscribe<plan_request_t>(channels::kPlanRequest, [this](const plan_request_t& m) {
      requests_.push_back(m);
      if (planner_) planner_(m);
    });
    const std::string log = "/tmp/beft-test-tasks-" + std::to_string(getpid()) + "-" + std::to_string(port_) + ".log";
    tasks_ = std::make_unique<Child>(std::vector<std::string>{BEFT_TASKS_BIN, "--lcm-url", url_, "--no-catch-up",
                                                              "--ready-timeout", "0.3"},
                                     log);
    ASSERT_TRUE(tasks_->started());
    state_.x = 1;
    state_.y = 1;
    state_.yaw = 0;
    state_.head_yaw = state_.head_pitch = 0;
    state_.radius = 0.35;
    state_.collisions = 0;
    state_.collided = false;
  }
  void TearDown() override {
    if (HasFailure()) std::fprintf(stderr, "beft-tasks said:\n%s\n", tasks_->output().c_str());
  }

  // LCM 1.3.1 takes no lambdas: a typed handler object per subscription.
  struct HandlerBase {
    virtual ~HandlerBase() = default;
  };
  template <typename Message>
  struct Handler : HandlerBase {
    explicit Handler(std::function<void(const Message&)> s) : store(std::move(s)) {}
    void handle(const lcm::ReceiveBuffer*, const std::string&, const Message* m) { store(*m); }
    std::function<void(const Message&)> store;
  };
  template <typename Message>
  void subscribe(const std::string& channel, std::function<void(const Message&)> store) {
    handlers_.push_back(std::make_unique<Handler<Message>>(std::move(store)));
    auto* handler = static_cast<Handler<Message>*>(handlers_.back().get());
    lcm_->subscribe(channel, &Handler<Message>::handle, handler)->setQueueCapacity(1000);
  }
  std::vector<std::unique_ptr<HandlerBase>> handlers_;

  bool handleUntil(const std::function<bool()>& condition, double seconds) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (!condition()) {
      if (Clock::now() > deadline) return false;
      lcm_->handleTimeout(10);
    }
    return true;
  }

  // One tick: the robot state of the tick, then FIRE until DONE (the first
  // FIREs may come before the process listens).
  bool fireTick() {
    ++tick_;
    const int64_t utime = tick_ * 100000;
    state_.utime = utime;
    state_.tick = tick_;
    fire_t fire{};
    fire.utime = utime;
    fire.expert = "tasks";
    fire.transition = "t_tasks";
    fire.tick = tick_;
    fire.firing_id = tick_;
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    while (Clock::now() < deadline) {
      lcm_->publish(channels::kRobotState, &state_);
      lcm_->publish(channels::kFire, &fire);
      if (handleUntil([&] { return done_.count(tick_) > 0; }, 0.2)) {
        handleUntil([] { return false; }, 0.01);  // the rest of the tick's output
        return true;
      }
    }
    return false;
  }

  // Runs a beft-task command while ticking until it exits.
  std::pair<int, std::string> runCli(std::vector<std::string> args, int max_ticks = 40) {
    args.insert(args.begin(), {BEFT_TASK_BIN, "--lcm-url", url_, "--timeout", "3"});
    const std::string file = "/tmp/beft-test-task-cli-" + std::to_string(getpid()) + "-" + std::to_string(++cli_runs_);
    Child cli(args, file);
    handleUntil([] { return false; }, 0.1);  // let it subscribe before the stack answers
    for (int i = 0; i < max_ticks && cli.running(); ++i) {
      EXPECT_TRUE(fireTick());
      handleUntil([] { return false; }, 0.05);
    }
    const int code = cli.wait(5.0);
    return {code, cli.output()};
  }

  int port_ = 0;
  std::string url_;
  std::unique_ptr<lcm::LCM> lcm_;
  std::unique_ptr<Child> tasks_;
  robot_state_t state_{};
  int64_t tick_ = 0;
  int cli_runs_ = 0;
  std::map<int64_t, done_t> done_;
  std::optional<task_stack_t> stack_;
  std::optional<robot_command_t> command_;
  std::vector<task_event_t> events_;
  std::vector<plan_request_t> requests_;
  std::function<void(const plan_request_t&)> planner_;
};

TEST_F(TasksProcess, PushListAndClearAgainstARunningStack) {
  ASSERT_TRUE(fireTick());
  ASSERT_TRUE(stack_.has_value());
  EXPECT_EQ(stack_->num_tasks, 0);
  EXPECT_EQ(command_->mode, robot_command_t::MODE_STOP);

  // The planner service: a path via (4, 1).
  planner_ = [this](const plan_request_t& r) {
    plan_result_t result{};
    result.utime = r.utime;
    result.request_id = r.request_id;
    result.success = true;
    result.planner = "test";
    result.length = 10;
    result.planning_time = 0.001;
    for (auto p : std::vector<std::array<double, 3>>{{r.start_x, r.start_y, 0}, {4, 1, 90}, {r.goal_x, r.goal_y, r.goal_yaw}}) {
      waypoint_t w{};
      w.x = p[0];
      w.y = p[1];
      w.yaw = p[2];
      result.waypoints.push_back(w);
    }
    result.num_waypoints = 3;
    lcm_->publish(channels::kPlanResult, &result);
  };

  auto [code, out] = runCli({"push", "goto", "4", "6", "90"});
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("pushed goto(4, 6, 90) as task 1"), std::string::npos) << out;

  // The stack planned (start = robot pose) and drives to the first waypoint.
  ASSERT_TRUE(fireTick());
  ASSERT_TRUE(fireTick());
  ASSERT_FALSE(requests_.empty());
  EXPECT_DOUBLE_EQ(requests_[0].start_x, 1);
  EXPECT_DOUBLE_EQ(requests_[0].goal_y, 6);
  EXPECT_EQ(command_->mode, robot_command_t::MODE_GOTO);
  EXPECT_DOUBLE_EQ(command_->goal_x, 4);
  EXPECT_DOUBLE_EQ(command_->goal_y, 1);
  ASSERT_EQ(stack_->num_tasks, 1);
  EXPECT_EQ(stack_->tasks[0].origin, "user");
  EXPECT_EQ(stack_->tasks[0].status, task_t::STATUS_ACTIVE);

  // A reflex-like push interrupts it; list shows both, top first.
  std::tie(code, out) = runCli({"push", "turn_head", "-40", "--priority", "100"});
  EXPECT_EQ(code, 0) << out;
  std::tie(code, out) = runCli({"list"});
  EXPECT_EQ(code, 0) << out;
  const auto head = out.find("turn_head(-40)"), go = out.find("goto(4, 6, 90)");
  EXPECT_NE(head, std::string::npos) << out;
  EXPECT_NE(go, std::string::npos) << out;
  EXPECT_LT(head, go) << out;
  EXPECT_NE(out.find("suspended"), std::string::npos) << out;

  // A bad push is refused before anything is sent.
  std::tie(code, out) = runCli({"push", "goto", "4"}, 0);
  EXPECT_EQ(code, 2) << out;
  EXPECT_NE(out.find("goto takes 2 to 3 argument(s)"), std::string::npos) << out;

  // Clear empties it; the robot stops.
  std::tie(code, out) = runCli({"clear"});
  EXPECT_EQ(code, 0) << out;
  ASSERT_TRUE(fireTick());
  EXPECT_EQ(stack_->num_tasks, 0);
  EXPECT_EQ(command_->mode, robot_command_t::MODE_STOP);
  std::tie(code, out) = runCli({"list"});
  EXPECT_NE(out.find("empty"), std::string::npos) << out;
}

TEST_F(TasksProcess, GotoWithoutAPlannerFailsCleanly) {
  ASSERT_TRUE(fireTick());
  auto [code, out] = runCli({"push", "goto", "5", "5"});
  ASSERT_EQ(code, 0) << out;
  // Each unanswered request costs one --ready-timeout (0.3 s), then the task fails.
  for (int i = 0; i < 6; ++i) ASSERT_TRUE(fireTick());
  EXPECT_EQ(requests_.size(), 3u);
  bool failed = false;
  for (const auto& e : events_)
    if (e.event == task_event_t::EVENT_FAILED) {
      failed = true;
      EXPECT_NE(e.reason.find("no answer from the planner"), std::string::npos) << e.reason;
    }
  EXPECT_TRUE(failed);
  EXPECT_EQ(stack_->num_tasks, 0);
  EXPECT_TRUE(tasks_->running());
  handleUntil([] { return false; }, 0.1);
  EXPECT_NE(tasks_->output().find("no answer from the planner"), std::string::npos);
}

TEST_F(TasksProcess, OwnerEndsItsCompositeTaskAndPopOfAnUnknownTaskIsRefused) {
  ASSERT_TRUE(fireTick());
  auto [code, out] = runCli({"push", "verify", "victim1", "--origin", "exploration"});
  ASSERT_EQ(code, 0) << out;
  EXPECT_NE(out.find("as task 1"), std::string::npos) << out;
  std::tie(code, out) = runCli({"push", "wait", "10", "--parent", "1", "--origin", "exploration"});
  ASSERT_EQ(code, 0) << out;
  ASSERT_EQ(stack_->num_tasks, 2);
  EXPECT_EQ(stack_->tasks[0].parent_id, 1);
  std::tie(code, out) = runCli({"pop", "1", "--done", "--reason", "seen"});
  EXPECT_EQ(code, 0) << out;
  EXPECT_NE(out.find("finished task 1"), std::string::npos) << out;
  EXPECT_EQ(stack_->num_tasks, 0);
  std::tie(code, out) = runCli({"pop", "7"});
  EXPECT_EQ(code, 1) << out;
  EXPECT_NE(out.find("no task 7"), std::string::npos) << out;
}

TEST(TaskCliProcess, ListWithNothingRunningSaysSo) {
  const std::string url = lcmUrlForPort(41000 + static_cast<int>(getpid() % 9000));
  const std::string file = "/tmp/beft-test-task-cli-alone-" + std::to_string(getpid());
  Child cli({BEFT_TASK_BIN, "--lcm-url", url, "--timeout", "0.3", "list"}, file);
  EXPECT_EQ(cli.wait(5.0), 1);
  EXPECT_NE(cli.output().find("no TASK_STACK within 0.3 s"), std::string::npos) << cli.output();
}

}  // namespace
