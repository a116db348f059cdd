#include "sim/world/scene_timeline.hpp"

#include <cmath>
#include <cstdio>

namespace beft::world {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

std::string formatTime(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "t=%.2f s", t);
  return buffer;
}

std::string formatNumber(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%g", value);
  return buffer;
}

int indexOf(const std::vector<scenario::Object>& objects, const std::string& id) {
  for (size_t i = 0; i < objects.size(); ++i)
    if (objects[i].id == id) return static_cast<int>(i);
  return -1;
}

}  // namespace

PathPoint pathPointAt(const scenario::Path& path, double t) {
  const std::vector<scenario::Waypoint>& points = path.waypoints;
  PathPoint result;
  if (points.empty()) return result;
  result.x = points[0].x;
  result.y = points[0].y;
  // Legs: consecutive waypoints, plus last -> first when looping.
  const size_t legs = points.size() - 1 + (path.loop ? 1 : 0);
  double total = 0;
  for (size_t i = 0; i < legs; ++i) {
    const auto& a = points[i];
    const auto& b = points[(i + 1) % points.size()];
    total += std::hypot(b.x - a.x, b.y - a.y);
  }
  // Initial heading: that of the first leg with a length.
  for (size_t i = 0; i < legs; ++i) {
    const auto& a = points[i];
    const auto& b = points[(i + 1) % points.size()];
    if (b.x != a.x || b.y != a.y) {
      result.yaw = std::atan2(b.y - a.y, b.x - a.x) * kRadToDeg;
      break;
    }
  }
  if (total <= 0 || !(path.speed > 0) || !(t > 0)) return result;
  double along = path.speed * t;
  along = path.loop ? std::fmod(along, total) : std::min(along, total);
  for (size_t i = 0; i < legs; ++i) {
    const auto& a = points[i];
    const auto& b = points[(i + 1) % points.size()];
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    if (length == 0) continue;
    result.yaw = std::atan2(b.y - a.y, b.x - a.x) * kRadToDeg;
    if (along <= length || i + 1 == legs) {
      const double s = std::min(along / length, 1.0);
      result.x = a.x + s * (b.x - a.x);
      result.y = a.y + s * (b.y - a.y);
      return result;
    }
    along -= length;
  }
  return result;
}

int64_t eventTick(double t, double dt) {
  if (!(t > 0)) return 0;
  return static_cast<int64_t>(std::ceil(t / dt - 1e-9));
}

SceneTimeline::SceneTimeline(const scenario::Scenario& scenario)
    : scenario_(scenario), objects_(scenario.objects) {
  std::vector<bool> on_path(objects_.size(), false);
  for (const scenario::Path& path : scenario.paths) {
    const int object = indexOf(objects_, path.object);
    path_object_.push_back(object);
    if (object < 0) {
      startup_notes_.push_back("path names unknown object '" + path.object + "'; ignored");
      continue;
    }
    on_path[object] = true;
    const PathPoint start = pathPointAt(path, 0);
    const scenario::Object& o = objects_[object];
    if (std::hypot(o.x - start.x, o.y - start.y) > 0.01) {
      startup_notes_.push_back("object '" + o.id + "' is at (" + formatNumber(o.x) + ", " + formatNumber(o.y) +
                               ") but its path starts at (" + formatNumber(start.x) + ", " +
                               formatNumber(start.y) + "); it starts on the path");
    }
  }
  for (const scenario::Event& event : scenario.events) {
    const int object = indexOf(objects_, event.object);
    event_object_.push_back(object);
    if (object < 0) {
      startup_notes_.push_back("event at " + formatTime(event.t) + " names unknown object '" + event.object +
                               "'; ignored");
    } else if (on_path[object] && (event.x || event.y || event.yaw)) {
      startup_notes_.push_back("event at " + formatTime(event.t) + " moves '" + event.object +
                               "', which follows a path: the path sets its position again at the next tick");
    } else if (event.active && !objects_[object].acoustic && !event.sound) {
      startup_notes_.push_back("event at " + formatTime(event.t) + " sets active on '" + event.object +
                               "', which has no sound; ignored");
    }
  }
  movePaths();
  applyDueEvents();
}

bool SceneTimeline::advance() {
  ++tick_;
  changes_.clear();
  const bool moved_on_paths = movePaths();
  const size_t events_before = next_event_;
  const bool moved_by_events = applyDueEvents();
  if (moved_on_paths || next_event_ != events_before) last_change_tick_ = tick_;
  return moved_on_paths || moved_by_events;
}

bool SceneTimeline::movePaths() {
  bool moved = false;
  const double t = tick_ * scenario_.dt;
  for (size_t p = 0; p < scenario_.paths.size(); ++p) {
    const int index = path_object_[p];
    if (index < 0) continue;
    scenario::Object& object = objects_[index];
    const PathPoint point = pathPointAt(scenario_.paths[p], t);
    if (point.x != object.x || point.y != object.y || point.yaw != object.yaw) moved = true;
    object.x = point.x;
    object.y = point.y;
    object.yaw = point.yaw;
  }
  return moved;
}

bool SceneTimeline::applyDueEvents() {
  bool moved = false;
  const auto& events = scenario_.events;
  while (next_event_ < events.size() && eventTick(events[next_event_].t, scenario_.dt) <= tick_) {
    const scenario::Event& event = events[next_event_];
    const int index = event_object_[next_event_];
    ++next_event_;
    if (index < 0) continue;
    scenario::Object& object = objects_[index];
    std::string what;
    const auto note = [&what](const std::string& text) { what += (what.empty() ? "" : ", ") + text; };
    if (event.activity) {
      object.activity = *event.activity;
      note("activity " + object.activity);
    }
    if (event.label) {
      object.label = *event.label;
      note("label " + object.label);
    }
    if (event.sound) {
      if (!object.acoustic) {
        object.acoustic = scenario::Acoustic{};
        object.acoustic->line = event.line;
      }
      object.acoustic->sound = *event.sound;
      object.acoustic->sound_path = event.sound_path ? *event.sound_path : *event.sound;
      note("sound " + *event.sound);
    }
    if (event.active && object.acoustic) {
      object.acoustic->active = *event.active;
      note(std::string("active ") + (*event.active ? "1" : "0"));
    }
    if (event.x) object.x = *event.x;
    if (event.y) object.y = *event.y;
    if (event.yaw) object.yaw = *event.yaw;
    if (event.x || event.y || event.yaw) {
      moved = true;
      note("pose (" + formatNumber(object.x) + ", " + formatNumber(object.y) + ", " + formatNumber(object.yaw) +
           ")");
    }
    changes_.push_back("event " + formatTime(event.t) + " (tick " + std::to_string(tick_) + "): " + object.id +
                       (what.empty() ? " unchanged" : " " + what));
  }
  return moved;
}

}  // namespace beft::world
