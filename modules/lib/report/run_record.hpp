// What the report needs from a run's LCM log, decoded once: the robot's
// trajectory, the hypotheses over time, the dynamic weights, the task on top
// of the stack, the last obstacle map and the ground truth the world published.
#pragma once

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <beft/record_status_t.hpp>

#include "lib/wire/obstacle_map_codec.hpp"

namespace beft::report {

// A log or scenario the report cannot use: what is wrong, naming the file.
class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct RobotSample {
  double t = 0;              // simulated time [s]
  int64_t tick = 0;
  double x = 0, y = 0;       // [m]
  double yaw = 0;            // platform heading [deg]
  double head_yaw = 0;       // head pan relative to the platform [deg]
  double path_length = 0;    // driven since start [m]
  int collisions = 0;        // contacts since start
};

// One hypothesis as fusion published it (hypothesis_t, without the
// per-category table).
struct HypothesisState {
  std::string object_id;
  double x = 0, y = 0;       // estimated position [m]
  std::string best_category;
  double confidence = 0;     // of best_category [0..1]
  bool seen = false, heard = false, verified = false, falsified = false;
  std::string seen_as, heard_as;
  double first_heard_s = -1, first_seen_s = -1, settled_s = -1;  // sim time, -1 = never
  // When fusion last moved its estimate (x, y): the tick and sim time of the
  // first sample with the current position, as the log showed it.
  int64_t placed_tick = -1;
  double placed_s = -1;
};

struct HypothesesSample {
  double t = 0;              // simulated time [s]
  int64_t tick = -1;
  std::vector<HypothesisState> hypotheses;
};

struct WeightSample {
  double t = 0;                       // simulated time [s]
  double viewing_direction = 0;       // world heading the head is told to face [deg]
  std::string current_task;
  std::string attended_object;
  std::map<std::string, double> weights;  // acoustic object id -> w
};

struct TaskSample {
  double t = 0;              // simulated time [s]
  std::string top;           // "kind object" of the top task, "" for an empty stack
};

// A ground-truth object as the world published it (or as the scenario file
// describes it when the log carries no GT_OBJECTS).
struct TruthObject {
  std::string id, label;
  double x = 0, y = 0, yaw = 0;       // [m], [deg]
  enum class Shape { None, Box, Cylinder } shape = Shape::None;
  double size_x = 0, size_y = 0;      // box footprint [m]
  double radius = 0;                  // cylinder [m]
  bool acoustic = false;
};

// Where an object truly was from a tick on (GT_OBJECTS of that tick).
struct TruthPosition {
  int64_t tick = 0;
  double x = 0, y = 0;       // [m]
};

// The audio expert's last position estimate of a sounding object (AUDIO),
// beside where the object truly was then (GT_OBJECTS of the same tick).
struct HeardPosition {
  double t = 0;                 // simulated time [s]
  double x = 0, y = 0;          // estimate p_hat [m]
  double true_x = 0, true_y = 0;  // [m]
};

// What one process said it refused (PROCESS_REJECTS, lib/wire/reject_report.hpp):
// its last account, the accounts of its restarts added.
struct ProcessRejects {
  int64_t unauthenticated = 0;  // in a keyed run: no valid tag of the run's key
  int64_t other_run = 0;        // another run's, on the same URL
  int64_t malformed = 0;        // refused by the guard or a payload's reader
};

struct RunRecord {
  std::string log_path;
  std::string scenario_name;          // from GT_OBJECTS
  double world_width = 0, world_height = 0;  // [m]
  double dt = 0, duration = 0;        // [s]
  std::vector<std::string> categories;
  std::vector<TruthObject> truth;     // as of the last GT_OBJECTS
  std::map<std::string, std::vector<std::pair<double, double>>> trails;  // moving objects' positions
  // Each object's true position when first published and at every tick it
  // moved since, in tick order: where a walker was when it was seen.
  std::map<std::string, std::vector<TruthPosition>> truth_positions;
  std::vector<RobotSample> robot;     // one per tick, in tick order
  double robot_radius = 0;            // [m]
  std::vector<HypothesesSample> hypotheses;  // in log order
  std::vector<WeightSample> weights;  // in log order
  std::vector<TaskSample> tasks;      // in log order
  std::map<std::string, HeardPosition> heard;  // by object id: the last AUDIO estimate
  std::optional<planners::ObstacleCells> obstacle_map;  // the last one received
  std::string stop_reason;            // last STOP_REQUEST message, or ""
  std::string run_status;             // last RUN_STATUS message, or ""
  int64_t first_timestamp_us = 0, last_timestamp_us = 0;  // logger receive times
  int64_t first_fire_us = -1, last_done_us = -1;  // receive times of the first FIRE and last DONE
  int64_t events = 0;
  std::map<std::string, int64_t> rejected;  // channel -> messages the guard refused (malformed, foreign type)
  std::string log_damage;                   // the log reader's account of skipped bytes, "" if none
  int64_t other_run_messages = 0;           // valid messages of another run on the same URL, left out
  std::map<std::string, ProcessRejects> process_rejects;  // by process name, as the processes told it
  std::optional<beft::record_status_t> record_status;  // the recorder's last account of the log (RECORD_STATUS)

  double simTime() const { return robot.empty() ? 0.0 : robot.back().t; }
  double wallSpan() const { return (last_timestamp_us - first_timestamp_us) * 1e-6; }
  // Wall time of the lockstep loop itself, first FIRE to last DONE (0 if unknown).
  double tickingSpan() const {
    return first_fire_us >= 0 && last_done_us > first_fire_us ? (last_done_us - first_fire_us) * 1e-6 : 0.0;
  }
  // Where the object truly was at `tick` (the last published position of a
  // tick up to it); nullopt when GT_OBJECTS never gave one that early.
  std::optional<TruthPosition> truthAt(const std::string& id, int64_t tick) const {
    const auto found = truth_positions.find(id);
    if (found == truth_positions.end()) return std::nullopt;
    const auto& positions = found->second;
    const auto after = std::upper_bound(positions.begin(), positions.end(), tick,
                                        [](int64_t k, const TruthPosition& p) { return k < p.tick; });
    if (after == positions.begin()) return std::nullopt;
    return *std::prev(after);
  }
  // Ticks run: from the tick indices, so a robot state the logger lost does not count less.
  int64_t tickCount() const { return robot.empty() ? 0 : robot.back().tick - robot.front().tick + 1; }
};

// Reads the whole log, damaged stretches skipped. Throws ReportError when the
// file cannot be opened or holds no event at all; every message is checked
// by the guard, and what it refuses is counted, not fatal.
RunRecord readRunLog(const std::string& path);

}  // namespace beft::report
