// The scenario data model: what a scenario XML file describes
// (../shared/spec/scenario-format.md). Loaded by load_scenario.hpp.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace beft::scenario {

struct Visual {
  enum class Shape { Box, Cylinder };
  Shape shape = Shape::Box;
  double size_x = 0, size_y = 0, size_z = 0;  // box full extents [m]
  double radius = 0, height = 0;              // cylinder [m]
  uint32_t color_rgb = 0x808080;              // 0xRRGGBB
  // Share of sound energy its surfaces absorb, [0, 1]; none: the
  // scenario's <acoustics absorption> (rendered hearing only).
  std::optional<double> absorption;
  int line = 0;
};

// Room acoustics of the rendered ear signals (<acoustics>); without the
// element the free field, direct sound only. Neither the paper's
// degradation functions nor the ground-truth acoustic expert use it.
struct Acoustics {
  double reverberation = 0;  // T60 of the diffuse late tail [s]; 0: no tail
  int reflection_order = 0;  // image sources off the objects' surfaces up to this order, 0..4
  double absorption = 0.2;   // share of sound energy a surface without its own absorbs [-]
  bool ground = true;        // the ground z = 0 reflects
  int line = 0;
};

struct Acoustic {
  std::string sound;       // as written in the file (relative to the scenario)
  std::string sound_path;  // resolved path of the WAV file
  bool active = true;      // activity flag f_i
  double level = 1.0;      // linear gain
  std::string label;       // acoustic label (what it sounds like); empty = object's label
  int line = 0;
};

struct Object {
  std::string id, label, activity = "idle";
  double x = 0, y = 0, z = 0, yaw = 0;  // [m], yaw [deg]
  std::optional<Visual> visual;          // none: can be heard, never seen
  std::optional<Acoustic> acoustic;      // none: silent
  int line = 0;
  // The label its sound suggests: <acoustic label=...> or else its category.
  const std::string& acousticLabel() const {
    return acoustic && !acoustic->label.empty() ? acoustic->label : label;
  }
};

struct Waypoint {
  double x = 0, y = 0;
  int line = 0;
};

struct Path {
  std::string object;
  double speed = 0;  // [m/s]
  bool loop = false;
  std::vector<Waypoint> waypoints;
  int line = 0;
};

// A change at time t; only the attributes present change.
struct Event {
  double t = 0;  // [s]
  std::string object;
  std::optional<std::string> activity, sound, sound_path, label;
  std::optional<bool> active;
  std::optional<double> x, y, yaw;
  int line = 0;
};

struct RobotLimits {
  double max_speed = 1.0;          // [m/s]
  double max_turn_rate = 90;       // [deg/s]
  double head_yaw_range = 170;     // total pan span, centred on the nose [deg]
  double head_pitch_range = 30;    // total tilt span, centred on level [deg]
  double head_turn_rate = 180;     // head pan/tilt rate limit [deg/s] (extension)
};

struct Camera {
  double fov = 90;                 // horizontal field of view [deg]
  int width = 160, height = 120;   // [px]
  double range = 20;               // [m]
  double height_above_ground = 1.6;// [m]
};

struct Robot {
  double x = 0, y = 0, yaw = 0, head_yaw = 0, head_pitch = 0;
  double radius = 0.35;            // platform footprint radius [m] (extension)
  RobotLimits limits;
  Camera camera;
  int line = 0;
};

struct World {
  double width = 0, height = 0;    // [m]
  double resolution = 0.1;         // obstacle-map cell edge [m]
};

struct Scenario {
  std::string file;                // path it was loaded from
  std::string name;
  int version = 1;
  double dt = 0.1;                 // [s per tick]
  double duration = 120;           // [s]
  uint64_t seed = 0;
  World world;
  std::vector<std::string> categories;  // default person car siren wall fire
  Robot robot;
  std::vector<Object> objects;          // file order
  std::vector<Path> paths;
  std::vector<Event> events;            // sorted by t; equal t keep file order
  std::map<std::pair<std::string, std::string>, double> congruency;  // (label, activity) -> c
  std::optional<Acoustics> acoustics;   // none: the free field
  std::vector<std::string> warnings;    // "FILE:LINE: warning: ..." found while loading

  const Object* findObject(const std::string& id) const;
  // c for (label, activity); pairs not in the table give default_value.
  double congruencyOf(const std::string& label, const std::string& activity,
                      double default_value = 0.5) const;
};

// A refusal: file, line and what is wrong. what() is "FILE:LINE: message".
class ScenarioError : public std::runtime_error {
 public:
  ScenarioError(std::string file, int line, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  std::string message_;
};

}  // namespace beft::scenario
