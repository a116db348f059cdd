#include "tools/check/scenario_summary.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "lib/scenario/wav_info.hpp"

namespace beft::scenario {

namespace {

// Shortest readable form: 2, 0.35, 12.5.
std::string num(double value) {
  std::ostringstream out;
  out << std::setprecision(6) << value;
  return out.str();
}

std::string point(double x, double y) { return "(" + num(x) + ", " + num(y) + ")"; }

std::string describeVisual(const Object& object) {
  if (!object.visual) return "no visual";
  const Visual& v = *object.visual;
  if (v.shape == Visual::Shape::Cylinder) return "cylinder r " + num(v.radius) + " h " + num(v.height);
  return "box " + num(v.size_x) + " x " + num(v.size_y) + " x " + num(v.size_z);
}

std::string describeSound(const std::string& path) {
  try {
    const WavInfo info = readWavInfo(path);
    std::ostringstream out;
    out << std::fixed << std::setprecision(2) << info.duration << " s, " << info.sample_rate << " Hz, "
        << (info.channels == 1 ? std::string("mono") : std::to_string(info.channels) + " channels");
    return out.str();
  } catch (const WavError& error) {
    return std::string("unreadable: ") + error.what();
  }
}

double pathLength(const Path& path) {
  double length = 0;
  for (size_t i = 1; i < path.waypoints.size(); ++i) {
    length += std::hypot(path.waypoints[i].x - path.waypoints[i - 1].x, path.waypoints[i].y - path.waypoints[i - 1].y);
  }
  if (path.loop) {
    length += std::hypot(path.waypoints.front().x - path.waypoints.back().x,
                         path.waypoints.front().y - path.waypoints.back().y);
  }
  return length;
}

std::string describeEvent(const Event& event) {
  std::string text;
  auto add = [&text](const std::string& part) { text += (text.empty() ? "" : " ") + part; };
  if (event.activity) add("activity=" + *event.activity);
  if (event.active) add(std::string("active=") + (*event.active ? "1" : "0"));
  if (event.sound) add("sound=" + *event.sound);
  if (event.x || event.y) add("moves to x=" + (event.x ? num(*event.x) : "-") + " y=" + (event.y ? num(*event.y) : "-"));
  if (event.yaw) add("yaw=" + num(*event.yaw));
  if (event.label) add("label=" + *event.label);
  return text.empty() ? "(no change)" : text;
}

}  // namespace

void printSummary(const Scenario& s, std::ostream& out) {
  const World& world = s.world;
  const Robot& robot = s.robot;
  const auto cells_x = static_cast<long>(std::ceil(world.width / world.resolution - 1e-9));
  const auto cells_y = static_cast<long>(std::ceil(world.height / world.resolution - 1e-9));

  out << "scenario   " << s.name << "  (" << s.file << ", version " << s.version << ")\n";
  out << "world      " << num(world.width) << " x " << num(world.height) << " m, resolution " << num(world.resolution)
      << " m (" << cells_x << " x " << cells_y << " cells)\n";
  out << "time       dt " << num(s.dt) << " s, duration " << num(s.duration) << " s ("
      << static_cast<long>(std::llround(s.duration / s.dt)) << " ticks), seed " << s.seed << "\n";
  out << "robot      start " << point(robot.x, robot.y) << " yaw " << num(robot.yaw) << " deg, head pan "
      << num(robot.head_yaw) << " tilt " << num(robot.head_pitch) << " deg, radius " << num(robot.radius) << " m\n";
  out << "           limits " << num(robot.limits.max_speed) << " m/s, " << num(robot.limits.max_turn_rate)
      << " deg/s; head pan range " << num(robot.limits.head_yaw_range) << ", tilt range "
      << num(robot.limits.head_pitch_range) << " deg, " << num(robot.limits.head_turn_rate) << " deg/s\n";
  out << "           camera fov " << num(robot.camera.fov) << " deg, " << robot.camera.width << " x "
      << robot.camera.height << " px, range " << num(robot.camera.range) << " m, at "
      << num(robot.camera.height_above_ground) << " m\n";

  out << "objects    " << s.objects.size() << "\n";
  for (const std::string& category : s.categories) {
    std::string ids;
    int count = 0;
    for (const Object& object : s.objects) {
      if (object.label != category) continue;
      ids += " " + object.id;
      ++count;
    }
    out << "  " << std::left << std::setw(9) << category << std::right << std::setw(2) << count
        << (count > 0 ? ":" : "") << ids << "\n";
  }

  int sound_count = 0;
  for (const Object& object : s.objects) sound_count += object.acoustic.has_value();
  out << "sounds     " << sound_count << "\n";
  for (const Object& object : s.objects) {
    if (!object.acoustic) continue;
    const Acoustic& a = *object.acoustic;
    out << "  " << object.id << ": " << a.sound << " (" << describeSound(a.sound_path) << "), "
        << (a.active ? "active" : "silent") << ", level " << num(a.level) << ", sounds like "
        << object.acousticLabel() << ", " << object.activity << ", " << describeVisual(object) << "\n";
  }

  out << "paths      " << s.paths.size() << "\n";
  for (const Path& path : s.paths) {
    out << "  " << path.object << ": " << path.waypoints.size() << " waypoints, " << num(pathLength(path)) << " m at "
        << num(path.speed) << " m/s, " << (path.loop ? "looping" : "once") << ":";
    for (const Waypoint& waypoint : path.waypoints) out << " " << point(waypoint.x, waypoint.y);
    out << "\n";
  }

  out << "events     " << s.events.size() << "\n";
  for (const Event& event : s.events) {
    out << "  t=" << std::fixed << std::setprecision(1) << std::setw(6) << event.t << std::defaultfloat << " s  "
        << event.object << ": " << describeEvent(event) << "\n";
  }

  out << "congruency " << s.congruency.size() << " pairs\n";
  std::string current_label;
  for (const auto& [key, value] : s.congruency) {
    if (key.first != current_label) {
      if (!current_label.empty()) out << "\n";
      current_label = key.first;
      out << "  " << std::left << std::setw(9) << current_label << std::right;
    }
    out << " " << key.second << " " << num(value);
  }
  if (!current_label.empty()) out << "\n";
  if (!s.warnings.empty()) out << "warnings   " << s.warnings.size() << " (printed above)\n";
}

}  // namespace beft::scenario
