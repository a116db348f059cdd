// A launch file: the processes of a run (scenarios/launch/*.xml).
//
//   <launch name="mission">
//     <arg name="planner" default="pf"/>
//     <process name="planner" command="beft-planner" args="--planner ${planner}"
//              group="infra" restart="on-failure" max_restarts="3" host="local"
//              priority="background"/>
//     <process name="arbiter" command="beft-arbiter" args="..." role="arbiter"/>
//   </launch>
//
// ${name} is replaced by an <arg> (its default, or the value given with --set);
// ${lcm_url} is always defined. Every process also gets --lcm-url appended
// unless lcm_url="0".
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace beft::launch {

enum class RestartPolicy { Never, OnFailure };

// How a process competes for the CPUs. Background: nice 10 and SCHED_BATCH,
// so that waking up (a message arrived) never preempts a running process and
// it takes about a tenth of a normal process's share when the cores are
// contended: for processes off the control loop (the recorder, the
// blackboard), which catch up whenever a core is free.
enum class Priority { Normal, Background };

struct ProcessSpec {
  std::string name;
  std::string command;            // a program in the build's bin/ or on PATH
  std::vector<std::string> args;  // after substitution
  std::string group;              // e.g. infra, sensor, low, mid, high, control
  RestartPolicy restart = RestartPolicy::Never;
  int max_restarts = 3;
  std::string host = "local";     // host label: where this process runs
  bool is_arbiter = false;        // the run ends when it exits
  bool append_lcm_url = true;
  Priority priority = Priority::Normal;
  int line = 0;
};

struct LaunchSpec {
  std::string file, name;
  std::map<std::string, std::string> args;  // resolved values
  std::vector<ProcessSpec> processes;       // file order = start order
};

class LaunchError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "NAME=VALUE" settings of launch-file arguments (--set), by name; LaunchError
// naming the first one that is not NAME=VALUE.
std::map<std::string, std::string> parseSettings(const std::vector<std::string>& settings);

// Reads and resolves a launch file; overrides set or add <arg> values.
// Throws LaunchError("FILE:LINE: what is wrong").
LaunchSpec loadLaunchFile(const std::string& path, const std::map<std::string, std::string>& overrides);

// What a launch is (wire::runDescriptionHash): from the launch file's name
// and its arguments but the LCM URL and host labels, so the launches of one
// run on several machines describe it alike, and a launch that does not run
// the arbiter knows the run to join by it (run_adoption.hpp). Not a run id:
// every launch draws a fresh one. Never 0.
int64_t launchDescriptionOf(const std::string& launch_file, const std::map<std::string, std::string>& args);

// Splits an argument string on whitespace, honouring "double" and 'single' quotes.
std::vector<std::string> splitArguments(const std::string& text);

}  // namespace beft::launch
