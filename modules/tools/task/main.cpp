// beft-task: change or show the task stack of a running system (see --help).
#include <CLI/CLI.hpp>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>

#include <beft/task_command_t.hpp>
#include <beft/task_events_t.hpp>
#include <beft/task_stack_t.hpp>

#include "lib/common/command_line.hpp"
#include "lib/common/channels.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/common/lcm_url.hpp"
#include "lib/transport/publisher.hpp"
#include "lib/wire/run_discovery.hpp"
#include "lib/wire/run_identity.hpp"
#include "tools/task/task_cli.hpp"
#include "lib/task/task_commands.hpp"
#include "lib/task/task_messages.hpp"

namespace {

using Clock = std::chrono::steady_clock;

int64_t wallMicros() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// An LCM handler calling a function (LCM 1.3.1 takes no lambdas). It takes
// the raw bytes and decodes them through the message guard: LCM's typed
// subscribe decodes unguarded, and a malformed message would kill the tool.
template <typename Message>
struct Handler {
  std::function<void(const Message&)> on_message;
  static void handle(const lcm::ReceiveBuffer* buffer, const std::string& channel, Handler* self) {
    Message message;
    if (beft::wire::decodeFrom(channel, buffer->data, buffer->data_size, message)) self->on_message(message);
  }
};

// Handles LCM until done() or the deadline; false on timeout.
template <typename Done>
bool waitFor(lcm::LCM& lcm, double timeout_s, Done done) {
  const auto deadline = Clock::now() + std::chrono::microseconds(static_cast<int64_t>(timeout_s * 1e6));
  while (!done()) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return false;
    if (lcm.handleTimeout(static_cast<int>(std::min<int64_t>(left, 100))) < 0) return false;
  }
  return true;
}

// Publishes a command and, when asked, waits for the stack's answer on TASK_EVENTS.
int sendCommand(lcm::LCM& lcm, beft::task_command_t command, bool wait, double timeout_s, const std::string& what) {
  std::vector<beft::task_event_t> answers;
  Handler<beft::task_events_t> events_handler;
  Handler<beft::task_stack_t> stack_handler;
  lcm::Subscription* subscription = nullptr;
  if (wait) {
    events_handler.on_message = [&](const beft::task_events_t& m) {
      for (const auto& e : m.events)
        if (e.command_id == command.command_id) answers.push_back(e);
    };
    subscription = lcm.subscribeFunction(beft::wire::runChannel(beft::channels::kTaskEvents), &Handler<beft::task_events_t>::handle, &events_handler);
    subscription->setQueueCapacity(1000);
  }
  // A clear of an empty stack changes no task: an empty stack confirms it too.
  bool empty_stack_seen = false;
  lcm::Subscription* stack_subscription = nullptr;
  if (wait && command.command == beft::task_command_t::COMMAND_CLEAR) {
    stack_handler.on_message = [&](const beft::task_stack_t& m) {
      if (m.tasks.empty()) empty_stack_seen = true;
    };
    stack_subscription = lcm.subscribeFunction(beft::wire::runChannel(beft::channels::kTaskStack), &Handler<beft::task_stack_t>::handle, &stack_handler);
  }
  if (beft::transport::publish(lcm, beft::wire::runChannel(beft::channels::kTaskCommand), command) != 0) {
    std::fprintf(stderr, "beft-task: error: could not publish on %s\n", beft::channels::kTaskCommand.name);
    return 1;
  }
  if (!wait) {
    std::printf("sent %s (command %lld)\n", what.c_str(), static_cast<long long>(command.command_id));
    return 0;
  }
  if (!waitFor(lcm, timeout_s, [&] { return !answers.empty() || empty_stack_seen; })) {
    std::fprintf(stderr,
                 "beft-task: sent %s (command %lld), but the task stack did not confirm it within %.1f s: "
                 "is beft-tasks running on this LCM URL and being fired? It applies the command at its next "
                 "firing.\n",
                 what.c_str(), static_cast<long long>(command.command_id), timeout_s);
    return 3;
  }
  // The events of one firing arrive in one message: collect the rest of it.
  waitFor(lcm, 0.05, [] { return false; });
  int status = 0;
  for (const auto& e : answers) {
    const beft::tasks::Task task = beft::tasks::fromMessage(e.task);
    switch (e.event) {
      case beft::task_event_t::EVENT_PUSHED:
        std::printf("pushed %s as task %lld\n", beft::tasks::describe(task).c_str(), static_cast<long long>(task.id));
        break;
      case beft::task_event_t::EVENT_REJECTED:
        std::fprintf(stderr, "beft-task: error: %s rejected: %s\n",
                     task.kind.empty() ? what.c_str() : beft::tasks::describe(task).c_str(), e.reason.c_str());
        status = 1;
        break;
      case beft::task_event_t::EVENT_DONE:
      case beft::task_event_t::EVENT_FAILED:
      case beft::task_event_t::EVENT_REMOVED:
        std::printf("%s task %lld %s%s%s\n",
                    e.event == beft::task_event_t::EVENT_DONE     ? "finished"
                    : e.event == beft::task_event_t::EVENT_FAILED ? "failed"
                                                                  : "removed",
                    static_cast<long long>(task.id), beft::tasks::describe(task).c_str(),
                    e.reason.empty() ? "" : ": ", e.reason.c_str());
        break;
      default:
        break;
    }
  }
  if (answers.empty()) std::printf("cleared: the stack is empty\n");
  if (subscription) lcm.unsubscribe(subscription);
  if (stack_subscription) lcm.unsubscribe(stack_subscription);
  return status;
}

enum class Action { Push, Pop, Clear, List };

struct Options {
  Action action = Action::List;
  std::string lcm_url = beft::defaultLcmUrl();
  double timeout_s = 3.0;  // how long to wait for an answer [s]
  bool no_wait = false;
  std::vector<std::string> words;  // push: KIND ARGS...
  int priority = 50;
  int64_t parent = 0;
  std::string origin = "user", note;
  int64_t pop_id = 0;  // pop: 0 = the top task
  bool pop_done = false, pop_failed = false;
  std::string reason;
  bool json = false;  // list as JSON
  std::string run_id;  // "" : the one run heard on the URL
};

std::optional<int> parseOptions(int argc, char** argv, Options& o) {
  CLI::App app(
      "Change or show the task stack of a running BEFT system (beft-tasks). Commands go out on "
      "TASK_COMMAND and apply at the stack's next firing, ordered by origin, then arrival; push and pop wait for "
      "the stack's confirmation on TASK_EVENTS (--no-wait to skip). list prints the next "
      "TASK_STACK message.",
      "beft-task");
  app.require_subcommand(1);
  app.add_option("--lcm-url", o.lcm_url, "LCM URL of the running system (env BEFT_LCM_URL)")->capture_default_str();
  app.add_option("--timeout", o.timeout_s, "how long to wait for an answer [s]")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--run-id", o.run_id,
                 "the run to talk to (hex as its channels show it after '@', or 0x...); default: BEFT_RUN_ID, "
                 "else the one run whose heartbeats are heard on the URL");
  app.footer(
      "Tasks (push):\n" + beft::task_cli::pushUsage() +
      "\nExamples:\n"
      "  beft-task push goto 12 8 90\n"
      "  beft-task push look_at victim1 --priority 100\n"
      "  beft-task push turn_head -45 --priority 80\n"
      "  beft-task list\n"
      "  beft-task pop                            (cancel the top task)\n"
      "  beft-task pop 7 --done --reason seen     (an owner ends its composite task 7)\n"
      "  beft-task clear\n"
      "  beft-task --lcm-url 'udpm://239.255.76.67:7701?ttl=0' list --json");

  auto* push = app.add_subcommand("push", "push a task onto the stack");
  push->add_option("task", o.words, "KIND ARGS... (see below)")->required()->allow_extra_args();
  push->add_option("--priority", o.priority, "higher interrupts lower (the reflex uses 100)")->capture_default_str();
  push->add_option("--parent", o.parent, "id of the task this one is a sub-task of")->capture_default_str();
  push->add_option("--origin", o.origin, "who pushes it (the owner of a composite task)")->capture_default_str();
  push->add_option("--note", o.note, "human-readable description");
  push->add_flag("--no-wait", o.no_wait, "do not wait for the stack's confirmation");

  auto* pop = app.add_subcommand("pop", "cancel the top task, or end task ID");
  pop->add_option("id", o.pop_id, "task to end (default: the top task, cancelled)");
  auto* done_flag = pop->add_flag("--done", o.pop_done, "end task ID as done");
  pop->add_flag("--failed", o.pop_failed, "end task ID as failed")->excludes(done_flag);
  pop->add_option("--reason", o.reason, "why, for the stack's log and TASK_EVENTS");
  pop->add_flag("--no-wait", o.no_wait, "do not wait for the stack's confirmation");

  auto* clear = app.add_subcommand("clear", "cancel every task");
  clear->add_flag("--no-wait", o.no_wait, "do not wait for the stack's confirmation");

  auto* list = app.add_subcommand("list", "print the task stack, top first");
  list->add_flag("--json", o.json, "print it as JSON");

  if (const auto code = beft::parseCommandLine(app, argc, argv)) return code;
  o.action = *push ? Action::Push : *pop ? Action::Pop : *clear ? Action::Clear : Action::List;
  return std::nullopt;

}

// Prints the next TASK_STACK message.
int listStack(lcm::LCM& lcm, const Options& o) {
  std::optional<beft::task_stack_t> stack;
  Handler<beft::task_stack_t> handler;
  handler.on_message = [&](const beft::task_stack_t& m) {
    if (!stack) stack = m;
  };
  auto* sub = lcm.subscribeFunction(beft::wire::runChannel(beft::channels::kTaskStack), &Handler<beft::task_stack_t>::handle, &handler);
  sub->setQueueCapacity(100);
  if (!waitFor(lcm, o.timeout_s, [&] { return stack.has_value(); })) {
    std::fprintf(stderr,
                 "beft-task: error: no TASK_STACK within %.1f s on %s: is beft-tasks running there and being "
                 "fired (a run in progress)?\n",
                 o.timeout_s, o.lcm_url.c_str());
    return 1;
  }
  std::fputs(o.json ? beft::task_cli::stackJson(*stack).c_str() : beft::task_cli::formatStack(*stack).c_str(), stdout);
  return 0;
}

// The command asked for, and a word on it for the messages; an exit code
// when the task given does not parse.
std::optional<int> buildCommand(const Options& o, beft::task_command_t& command, std::string& what) {
  const int64_t now = wallMicros();
  if (o.action == Action::Push) {
    beft::tasks::Task task;
    try {
      const std::vector<std::string> args(o.words.begin() + 1, o.words.end());
      task = beft::task_cli::parsePush(o.words.front(), args);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "beft-task: error: %s\n", e.what());
      return 2;
    }
    task.priority = o.priority;
    task.parent = o.parent;
    task.origin = o.origin;
    task.note = o.note;
    command = beft::tasks::pushCommand(task, now, now);
    what = "push " + beft::tasks::describe(task);
  } else if (o.action == Action::Pop) {
    const auto outcome = o.pop_done     ? beft::tasks::Status::Done
                         : o.pop_failed ? beft::tasks::Status::Failed
                                        : beft::tasks::Status::Pending;
    command = beft::tasks::popCommand(o.pop_id, outcome, o.reason, "user", now, now);
    what = o.pop_id ? "pop of task " + std::to_string(o.pop_id) : "pop of the top task";
  } else {
    command = beft::tasks::clearCommand("user", now, now);
    what = "clear";
  }
  return std::nullopt;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const auto code = parseOptions(argc, argv, o)) return *code;
  lcm::LCM lcm(o.lcm_url);
  if (!lcm.good()) {
    std::fprintf(stderr, "beft-task: error: cannot open LCM at %s\n", o.lcm_url.c_str());
    return 1;
  }
  std::unique_ptr<beft::transport::PublisherScope> publishing;
  try {
    publishing = beft::transport::attachPublisher(lcm, o.lcm_url, "beft-task");
    if (!o.run_id.empty()) beft::wire::setRunId(beft::wire::parseRunId(o.run_id));
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "beft-task: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "beft-task: error: cannot publish on %s: %s\n", o.lcm_url.c_str(), e.what());
    return 1;
  }
  const std::string why = o.run_id.empty() ? beft::wire::adoptTheRunHeard(lcm, std::min(o.timeout_s, 2.0)) : "";
  if (!why.empty()) {
    std::fprintf(stderr, "beft-task: error: %s\n", why.c_str());
    return 2;
  }
  if (o.action == Action::List) return listStack(lcm, o);
  beft::task_command_t command{};
  std::string what;
  if (const auto code = buildCommand(o, command, what)) return *code;
  return sendCommand(lcm, command, !o.no_wait, o.timeout_s, what);
}
