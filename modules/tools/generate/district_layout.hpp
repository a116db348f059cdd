// A generated search-and-rescue district: a street grid of blocks holding
// ruined buildings open on one side (a person, a radio or rubble inside),
// and rubble, parked cars, sirens on poles, fires and persons in the open.
// Everything is axis-aligned and placed by a seeded generator, so a seed
// and the parameters fix the file.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace beft::generate {

struct DistrictParameters {
  double width = 80, height = 60;  // world [m]
  int objects = 110;               // objects to place (walls count one each) [-]
  uint64_t seed = 1;
  std::string sounds_dir = "sounds";  // as written in the file, relative to it
};

struct PlacedSound {
  std::string file;       // e.g. help.wav
  bool active = true;
  double level = 1.0;
  std::string label;      // acoustic label; empty: the object's own
};

struct PlacedObject {
  std::string id, label, activity = "idle";
  double x = 0, y = 0, z = 0, yaw = 0;
  bool cylinder = false;
  double size_x = 0, size_y = 0, size_z = 0;  // box full extents [m]
  double radius = 0, height = 0;              // cylinder [m]
  uint32_t color = 0x808080;
  std::optional<PlacedSound> sound;
};

struct PlacedEvent {
  double t = 0;
  std::string object, activity;
  std::optional<bool> active;
};

struct District {
  DistrictParameters parameters;
  double robot_x = 0, robot_y = 0, robot_yaw = 0;
  double duration = 0;  // [s]
  std::vector<PlacedObject> objects;
  std::vector<PlacedEvent> events;  // by time
  int buildings = 0, persons = 0, calling_persons = 0, radios = 0;
};

// Lays out a district; throws std::invalid_argument when the parameters
// cannot make one (world too small for a block, more objects than fit).
// `attempt` varies the layout for the same seed (used when a layout fails
// its reachability check).
District layDistrict(const DistrictParameters& parameters, int attempt = 0);

}  // namespace beft::generate
