#include "tools/task/task_cli.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "lib/task/task_messages.hpp"

namespace beft::task_cli {

namespace k = tasks::kinds;

double parseNumber(const std::string& text, const std::string& what) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value))
    throw std::invalid_argument(what + " must be a finite number, not '" + text + "'");
  return value;
}

std::string pushUsage() {
  return "  push goto X Y [YAW]      drive to (X, Y) [m], then face YAW [deg] (none: any heading)\n"
         "  push turn_head YAW       pan the head to YAW [deg] relative to the platform\n"
         "  push turn YAW            turn the platform to heading YAW [deg], world frame\n"
         "  push look_at OBJECT      face an object (head first, platform beyond its range)\n"
         "  push look_at X Y         face a point [m]\n"
         "  push wait SECONDS        hold still for SECONDS of simulated time\n"
         "  push KIND [OBJECT] [X Y [YAW]]  a composite task (approach, verify, explore, ...)\n"
         "                           owned by the expert named by --origin\n";
}

namespace {

void expectCount(const std::string& kind, const std::vector<std::string>& args, std::size_t min,
                 std::size_t max) {
  if (args.size() < min || args.size() > max)
    throw std::invalid_argument(kind + " takes " +
                                (min == max ? std::to_string(min) : std::to_string(min) + " to " + std::to_string(max)) +
                                " argument(s), got " + std::to_string(args.size()) + "\nusage:\n" + pushUsage());
}

bool isNumber(const std::string& text) {
  try {
    parseNumber(text, "");
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

tasks::Task parsePush(const std::string& kind, const std::vector<std::string>& args) {
  if (kind.empty()) throw std::invalid_argument("push needs a task kind\nusage:\n" + pushUsage());
  tasks::Task task;
  task.kind = kind;
  task.x = task.y = NAN;
  task.yaw = NAN;
  if (kind == k::kGoto) {
    expectCount(kind, args, 2, 3);
    task.x = parseNumber(args[0], "goto X");
    task.y = parseNumber(args[1], "goto Y");
    if (args.size() == 3) task.yaw = parseNumber(args[2], "goto YAW");
  } else if (kind == k::kTurnHead || kind == k::kTurn) {
    expectCount(kind, args, 1, 1);
    task.yaw = parseNumber(args[0], kind + " YAW");
  } else if (kind == k::kWait) {
    expectCount(kind, args, 1, 1);
    task.x = parseNumber(args[0], "wait SECONDS");
    if (task.x < 0) throw std::invalid_argument("wait SECONDS must be >= 0, not " + args[0]);
  } else if (kind == k::kLookAt) {
    expectCount(kind, args, 1, 2);
    if (args.size() == 1) {
      if (isNumber(args[0])) throw std::invalid_argument("look_at takes an OBJECT id or X Y, not one number");
      task.object_id = args[0];
    } else {
      task.x = parseNumber(args[0], "look_at X");
      task.y = parseNumber(args[1], "look_at Y");
    }
  } else {
    std::size_t next = 0;
    if (!args.empty() && !isNumber(args[0])) task.object_id = args[next++];
    const std::size_t numbers = args.size() - next;
    if (numbers != 0 && numbers != 2 && numbers != 3)
      throw std::invalid_argument(kind + " takes [OBJECT] [X Y [YAW]], got " + std::to_string(args.size()) +
                                  " argument(s)");
    if (numbers >= 2) {
      task.x = parseNumber(args[next], kind + " X");
      task.y = parseNumber(args[next + 1], kind + " Y");
    }
    if (numbers == 3) task.yaw = parseNumber(args[next + 2], kind + " YAW");
  }
  const std::string error = tasks::validateTask(task);
  if (!error.empty()) throw std::invalid_argument(error);
  return task;
}

namespace {

std::string cell(const std::string& text, std::size_t width) {
  return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

}  // namespace

std::string formatStack(const beft::task_stack_t& stack) {
  std::ostringstream out;
  char time[64];
  std::snprintf(time, sizeof(time), "%.2f", stack.utime / 1e6);
  out << "task stack at t = " << time << " s (tick " << stack.tick << "): ";
  if (stack.tasks.empty()) {
    out << "empty\n";
    return out.str();
  }
  out << stack.tasks.size() << (stack.tasks.size() == 1 ? " task" : " tasks") << ", top first\n";
  const std::vector<std::size_t> widths{5, 10, 9, 11, 8, 8, 24};
  out << "  " << cell("id", widths[0]) << cell("kind", widths[1]) << cell("priority", widths[2])
      << cell("status", widths[3]) << cell("origin", widths[4]) << cell("parent", widths[5])
      << cell("task", widths[6]) << "note\n";
  for (const auto& message : stack.tasks) {
    const tasks::Task task = tasks::fromMessage(message);
    const std::string note = task.note == tasks::describe(task) ? "" : task.note;
    out << "  " << cell(std::to_string(task.id), widths[0]) << cell(task.kind, widths[1])
        << cell(std::to_string(task.priority), widths[2]) << cell(tasks::statusName(task.status), widths[3])
        << cell(task.origin, widths[4]) << cell(task.parent ? std::to_string(task.parent) : "-", widths[5])
        << cell(tasks::describe(task), widths[6]) << note << "\n";
  }
  return out.str();
}

std::string stackJson(const beft::task_stack_t& stack) {
  nlohmann::json tasks = nlohmann::json::array();
  const auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  for (const auto& message : stack.tasks) {
    const tasks::Task task = tasks::fromMessage(message);
    tasks.push_back({{"id", task.id},
                     {"parent", task.parent},
                     {"kind", task.kind},
                     {"priority", task.priority},
                     {"status", tasks::statusName(task.status)},
                     {"x", number(task.x)},
                     {"y", number(task.y)},
                     {"yaw", number(task.yaw)},
                     {"object", task.object_id},
                     {"origin", task.origin},
                     {"note", task.note}});
  }
  nlohmann::json root = {{"utime", stack.utime}, {"tick", stack.tick}, {"tasks", tasks}};
  return root.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";  // received strings may not be UTF-8
}

}  // namespace beft::task_cli
