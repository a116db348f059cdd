// Whether the robot could ever see an object, on the ground truth: some place
// its footprint can reach (reachability.hpp), within the exploration's
// viewing distances of the object, from which a straight line from the
// camera (at its height) to the object's body passes through no other
// object's solid (a box or a cylinder in 3-D: a camera at 1.6 m sees over
// rubble 1 m high). Used by the scene generator, which refuses a layout with
// an object nobody could see, and by the report, which says why an object
// was left unsettled.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lib/scenario/reachability.hpp"
#include "lib/scenario/scenario.hpp"

namespace beft::scenario {

struct SightOptions {
  double min_distance = 1.5;  // closest place to look from, from the object's centre [m]
  double max_distance = 6.0;  // farthest [m]
  double spacing = 0.5;       // places are tried on a grid of this pitch [m]
  double eye_height = 1.6;    // the camera above the ground [m]
};

struct Place {
  double x = 0, y = 0;  // [m]
};

// Does the segment from a to b (3-D) cross the object's solid? An object
// without a visual has none.
bool segmentHitsSolid(const Object& object, const double a[3], const double b[3]);

class SightLines {
 public:
  SightLines(const Scenario& scenario, const ReachabilityOptions& reach = {}, const SightOptions& sight = {});

  // A reachable place from which the object is seen; none when there is no such place.
  std::optional<Place> placeThatSees(const Object& object) const;
  const ReachableSpace& reachable() const { return space_; }

 private:
  const Scenario& scenario_;
  ReachableSpace space_;
  SightOptions sight_;
};

// Whether the mission must settle objects of this label (walls need not be seen).
bool mustBeSeen(const Object& object);

// Ids of the objects the mission must settle that no reachable place sees, in file order.
std::vector<std::string> unseeableObjects(const Scenario& scenario, const ReachabilityOptions& reach = {},
                                          const SightOptions& sight = {});

}  // namespace beft::scenario
