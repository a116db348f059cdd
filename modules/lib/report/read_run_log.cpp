#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <tuple>


#include <beft/acoustic_percepts_t.hpp>
#include <beft/dynamic_weights_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/hypothesis_changes_t.hpp>
#include <beft/obstacle_map_changes_t.hpp>
#include <beft/obstacle_map_t.hpp>
#include <beft/process_rejects_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/run_status_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/task_stack_t.hpp>

#include <beft/record_status_t.hpp>

#include "lib/common/channels.hpp"
#include "lib/wire/guarded_decode.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/obstacle_map_changes.hpp"
#include "lib/wire/run_identity.hpp"
#include "lib/report/run_record.hpp"

namespace beft::report {
namespace {

constexpr double kTrailStep = 0.05;  // a moving object's trail gets a point every 5 cm

double seconds(int64_t utime) { return utime * 1e-6; }
double secondsOrNever(int64_t utime) { return utime < 0 ? -1.0 : seconds(utime); }

// Every event was checked by the guard before it reaches a decoder here.
template <typename Message>
bool decode(const wire::LogEvent& event, Message& message) {
  return message.decode(event.data.data(), 0, static_cast<int>(event.data.size())) ==
         static_cast<int>(event.data.size());
}

TruthObject toTruth(const scene_object_t& object) {
  TruthObject truth;
  truth.id = object.id;
  truth.label = object.label;
  truth.x = object.x;
  truth.y = object.y;
  truth.yaw = object.yaw;
  switch (object.shape) {
    case scene_object_t::SHAPE_BOX: truth.shape = TruthObject::Shape::Box; break;
    case scene_object_t::SHAPE_CYLINDER: truth.shape = TruthObject::Shape::Cylinder; break;
    default: truth.shape = TruthObject::Shape::None; break;
  }
  truth.size_x = object.size_x;
  truth.size_y = object.size_y;
  truth.radius = object.radius;
  truth.acoustic = object.has_acoustic;
  return truth;
}

class RecordBuilder {
 public:
  explicit RecordBuilder(RunRecord& record) : record_(record) {}

  void add(const wire::LogEvent& event) {
    if (record_.events == 0) record_.first_timestamp_us = event.timestamp;
    record_.last_timestamp_us = std::max(record_.last_timestamp_us, event.timestamp);
    ++record_.events;
    const std::string& channel = event.channel;
    if (channel == channels::kFire && record_.first_fire_us < 0) record_.first_fire_us = event.timestamp;
    if (channel == channels::kDone) record_.last_done_us = std::max(record_.last_done_us, event.timestamp);
    const wire::Verdict verdict =
        wire::MessageRules::beftTypes().checkForChannel(channel, event.data.data(), event.data.size());
    if (!verdict.ok()) {
      ++record_.rejected[channel];
      return;
    }
    bool ok = true;
    if (channel == channels::kGroundTruth) ok = addGroundTruth(event);
    else if (channel == channels::kRobotState) ok = addRobotState(event);
    else if (channel == channels::kHypotheses) ok = addHypotheses(event);
    else if (channel == channels::kHypothesisChanges) ok = addHypothesisChanges(event);
    else if (channel == channels::kAudio) ok = addAudio(event);
    else if (channel == channels::kDynamicWeights) ok = addWeights(event);
    else if (channel == channels::kTaskStack) ok = addTaskStack(event);
    else if (channel == channels::kObstacleMap) ok = addObstacleMap(event);
    else if (channel == channels::kObstacleMapChanges) ok = addObstacleMapChanges(event);
    else if (channel == channels::kStopRequest) ok = addStatus(event, record_.stop_reason);
    else if (channel == channels::kRunStatus) ok = addStatus(event, record_.run_status);
    else if (channel == channels::kProcessRejects) ok = addRejects(event);
    else if (channel == channels::kRecordStatus) ok = addRecordStatus(event);
    if (!ok) ++record_.rejected[channel];
  }

  // The recorder's account of its log; the last one holds.
  bool addRecordStatus(const wire::LogEvent& event) {
    beft::record_status_t status;
    if (!wire::guardedDecode(event.data.data(), event.data.size(), status).ok()) return false;
    record_.record_status = status;
    return true;
  }

  void finish() {
    finishObstacleMap();
    finishRejects();
    // Ticks in order, the last message of a tick wins (a re-sent tick).
    std::stable_sort(record_.robot.begin(), record_.robot.end(),
                     [](const RobotSample& a, const RobotSample& b) { return a.tick < b.tick; });
    std::vector<RobotSample> unique;
    for (const auto& sample : record_.robot) {
      if (!unique.empty() && unique.back().tick == sample.tick) unique.back() = sample;
      else unique.push_back(sample);
    }
    record_.robot.swap(unique);
  }

 private:
  bool addGroundTruth(const wire::LogEvent& event) {
    scene_objects_t scene{};
    if (!decode(event, scene)) return false;
    record_.scenario_name = scene.scenario;
    record_.world_width = scene.world_width;
    record_.world_height = scene.world_height;
    record_.dt = scene.dt;
    record_.duration = scene.duration;
    record_.categories = scene.categories;
    record_.truth.clear();
    for (const auto& object : scene.objects) {
      record_.truth.push_back(toTruth(object));
      auto& trail = record_.trails[object.id];
      if (trail.empty() || std::hypot(trail.back().first - object.x, trail.back().second - object.y) >= kTrailStep)
        trail.emplace_back(object.x, object.y);
      addTruthPosition(object, scene.tick);
    }
    return true;
  }

  // A new entry only when the object moved (or on a later tick than any
  // before: a tick sent again or late changes nothing).
  void addTruthPosition(const scene_object_t& object, int64_t tick) {
    auto& positions = record_.truth_positions[object.id];
    if (!positions.empty() && (tick < positions.back().tick ||
                               (positions.back().x == object.x && positions.back().y == object.y)))
      return;
    positions.push_back({tick, object.x, object.y});
  }

  // The world publishes a tick's GT_OBJECTS before the experts fire, so the
  // truth at hand is that of the estimate's tick.
  bool addAudio(const wire::LogEvent& event) {
    acoustic_percepts_t message{};
    if (!decode(event, message)) return false;
    for (const auto& percept : message.percepts) {
      const auto truth = std::find_if(record_.truth.begin(), record_.truth.end(),
                                      [&](const TruthObject& o) { return o.id == percept.object_id; });
      if (truth == record_.truth.end()) continue;
      record_.heard[percept.object_id] = {seconds(message.utime), percept.est_x, percept.est_y, truth->x, truth->y};
    }
    return true;
  }

  bool addRobotState(const wire::LogEvent& event) {
    robot_state_t state{};
    if (!decode(event, state)) return false;
    RobotSample sample;
    sample.t = seconds(state.utime);
    sample.tick = state.tick;
    sample.x = state.x;
    sample.y = state.y;
    sample.yaw = state.yaw;
    sample.head_yaw = state.head_yaw;
    sample.path_length = state.path_length;
    sample.collisions = state.collisions;
    record_.robot.push_back(sample);
    record_.robot_radius = state.radius;
    return true;
  }

  // A keyframe: the whole list of its tick.
  bool addHypotheses(const wire::LogEvent& event) {
    hypotheses_t message{};
    if (!decode(event, message)) return false;
    addHypothesesSample(message);
    keyframe_ = std::move(message);
    return true;
  }

  // The changes of a tick since the last keyframe (wire/hypothesis_changes.hpp);
  // those of the keyframe's own tick add nothing to it.
  bool addHypothesisChanges(const wire::LogEvent& event) {
    hypothesis_changes_t message{};
    if (!decode(event, message)) return false;
    if (!keyframe_ || message.keyframe_tick == message.tick) return true;
    hypotheses_t whole{};
    if (!wire::applyChanges(*keyframe_, message, whole)) return false;
    addHypothesesSample(whole);
    return true;
  }

  void addHypothesesSample(const hypotheses_t& message) {
    HypothesesSample sample;
    sample.t = seconds(message.utime);
    sample.tick = message.tick;
    for (const auto& h : message.hypotheses) {
      HypothesisState state;
      state.object_id = h.object_id;
      state.x = h.x;
      state.y = h.y;
      placeOf(state, sample);
      state.best_category = h.best_category;
      state.confidence = h.confidence;
      state.seen = h.seen;
      state.heard = h.heard;
      state.verified = h.verified;
      state.falsified = h.falsified;
      state.seen_as = h.seen_as;
      state.heard_as = h.heard_as;
      state.first_heard_s = secondsOrNever(h.first_heard_utime);
      state.first_seen_s = secondsOrNever(h.first_seen_utime);
      state.settled_s = secondsOrNever(h.settled_utime);
      sample.hypotheses.push_back(std::move(state));
    }
    record_.hypotheses.push_back(std::move(sample));
  }

  // When the estimate took its present position: the first sample that had it.
  void placeOf(HypothesisState& state, const HypothesesSample& sample) {
    const auto [placed, added] = placed_.try_emplace(state.object_id, state);
    HypothesisState& last = placed->second;
    if (added || last.x != state.x || last.y != state.y) {
      last.x = state.x;
      last.y = state.y;
      last.placed_tick = sample.tick;
      last.placed_s = sample.t;
    }
    state.placed_tick = last.placed_tick;
    state.placed_s = last.placed_s;
  }

  bool addWeights(const wire::LogEvent& event) {
    dynamic_weights_t message{};
    if (!decode(event, message)) return false;
    WeightSample sample;
    sample.t = seconds(message.utime);
    sample.viewing_direction = message.viewing_direction;
    sample.current_task = message.current_task;
    sample.attended_object = message.attended_object;
    for (const auto& w : message.weights) sample.weights[w.object_id] = w.weight;
    record_.weights.push_back(std::move(sample));
    return true;
  }

  bool addTaskStack(const wire::LogEvent& event) {
    task_stack_t message{};
    if (!decode(event, message)) return false;
    TaskSample sample;
    sample.t = seconds(message.utime);
    if (!message.tasks.empty()) {
      const auto& top = message.tasks.front();
      sample.top = top.kind + (top.object_id.empty() ? "" : " " + top.object_id);
    }
    record_.tasks.push_back(std::move(sample));
    return true;
  }

  // The map is made once, at the end: the last keyframe with the last changes.
  bool addObstacleMap(const wire::LogEvent& event) {
    obstacle_map_t message{};
    if (!decode(event, message)) return false;
    const int64_t tick = message.tick;
    map_keyframes_[tick] = std::move(message);
    if (map_keyframes_.size() > 4) map_keyframes_.erase(map_keyframes_.begin());
    return true;
  }
  bool addObstacleMapChanges(const wire::LogEvent& event) {
    obstacle_map_changes_t message{};
    if (!decode(event, message)) return false;
    last_map_changes_ = std::move(message);
    return true;
  }
  void finishObstacleMap() {
    if (map_keyframes_.empty()) return;
    const obstacle_map_t& newest = map_keyframes_.rbegin()->second;
    try {
      const auto keyframe = last_map_changes_ ? map_keyframes_.find(last_map_changes_->keyframe_tick)
                                              : map_keyframes_.end();
      if (keyframe != map_keyframes_.end() && last_map_changes_->tick >= newest.tick)
        record_.obstacle_map = *planners::ObstacleMapAssembler().mapOf(keyframe->second, &*last_map_changes_);
      else
        record_.obstacle_map = planners::decodeObstacleMap(newest);
    } catch (const planners::ObstacleMapError&) {
      ++record_.rejected[channels::kObstacleMap.name];
    }
  }

  bool addStatus(const wire::LogEvent& event, std::string& into) {
    run_status_t status{};
    if (!decode(event, status)) return false;
    into = status.message;
    return true;
  }

  // Each process instance's last account (a restarted process counts anew).
  bool addRejects(const wire::LogEvent& event) {
    process_rejects_t account{};
    if (!decode(event, account)) return false;
    last_rejects_[{account.host, account.pid, account.process}] = account;
    return true;
  }
  void finishRejects() {
    for (const auto& [instance, account] : last_rejects_) {
      ProcessRejects& total = record_.process_rejects[account.process];
      total.unauthenticated += account.unauthenticated;
      total.other_run += account.other_run;
      total.malformed += account.malformed;
    }
  }

  RunRecord& record_;
  std::map<std::tuple<std::string, int32_t, std::string>, process_rejects_t> last_rejects_;  // by host, pid, name
  std::optional<hypotheses_t> keyframe_;  // the last HYPOTHESES
  std::map<std::string, HypothesisState> placed_;  // by object id: its position and when it took it
  std::map<int64_t, obstacle_map_t> map_keyframes_;  // the last OBSTACLE_MAPs by tick
  std::optional<obstacle_map_changes_t> last_map_changes_;
};

}  // namespace

RunRecord readRunLog(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw ReportError(path + ": is a folder, not an LCM log file");
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe) throw ReportError(path + ": cannot open the log file");
  }
  RunRecord record;
  record.log_path = path;
  try {
    // The run of BEFT_RUN_ID (beft run sets it), else the arbiter's in the log.
    const int64_t run = wire::runId() != 0 ? wire::runId() : wire::runOfLog(path);
    wire::LogReader log(path);
    RecordBuilder builder(record);
    wire::LogEvent event;
    while (log.nextOfRun(event, run)) builder.add(event);
    builder.finish();
    record.log_damage = log.damage().summary();
    record.other_run_messages = static_cast<int64_t>(log.otherRunEvents());
  } catch (const std::runtime_error& error) {
    throw ReportError(error.what());
  }
  if (record.events == 0) throw ReportError(path + ": the log holds no event (not an LCM log, or empty)");
  return record;
}

}  // namespace beft::report
