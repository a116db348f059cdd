// How the scene's objects change over simulated time: paths and events.
//
// Paths: the object moves along its waypoints at the path's speed, starting
// at the first waypoint at t = 0, so its position at time t is the point at
// arc length speed * t. A looping path continues from the last waypoint back
// to the first; otherwise the object stops at the last one. While it moves it
// faces its direction of travel (yaw = heading of the current segment).
// Paths set x, y and yaw at every tick, so an event's x, y or yaw for an
// object on a path lasts only until the next tick (warned at start).
//
// Events: an event at time t applies at the first tick whose time k * dt is
// >= t (within 1e-9 of a tick), events of one tick in time order and equal
// times in file order, after the paths have moved. Attributes present in the
// event change; a `sound` on an object without <acoustic> gives it one
// (active unless the event says otherwise, level 1).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "lib/scenario/scenario.hpp"

namespace beft::world {

// Position along a path at time t [s]: x, y [m] and heading [deg].
struct PathPoint {
  double x = 0, y = 0, yaw = 0;
};
PathPoint pathPointAt(const scenario::Path& path, double t);

// The tick at which an event at time t applies.
int64_t eventTick(double t, double dt);

class SceneTimeline {
 public:
  // The objects at tick 0: paths at their start, events at t = 0 applied.
  // Notes about questionable input (see above) go to startup_notes.
  explicit SceneTimeline(const scenario::Scenario& scenario);

  // Moves to the next tick. Returns true if any object moved or changed shape
  // position (the geometry must be rebuilt).
  bool advance();

  int64_t tick() const { return tick_; }
  // The last tick at which an object moved or an event applied (0 at the start).
  int64_t lastChangeTick() const { return last_change_tick_; }
  const std::vector<scenario::Object>& objects() const { return objects_; }
  // Lines describing what the last tick changed ("t=12.0 s: walker activity -> yelling").
  const std::vector<std::string>& changes() const { return changes_; }
  const std::vector<std::string>& startupNotes() const { return startup_notes_; }

 private:
  // Moves path objects to tick_'s time; true if a position changed.
  bool movePaths();
  // Applies the events due at tick_; true if a position changed.
  bool applyDueEvents();

  const scenario::Scenario& scenario_;
  std::vector<scenario::Object> objects_;
  std::vector<int> path_object_;  // object index of each path
  std::vector<int> event_object_; // object index of each event
  size_t next_event_ = 0;
  int64_t tick_ = 0;
  int64_t last_change_tick_ = 0;
  std::vector<std::string> changes_, startup_notes_;
};

}  // namespace beft::world
