// Looking closely at the ground, once no frontier is left.
//
// Depth maps the ground from farther away, and from other angles, than
// vision can tell what lies on it: a house's floor is mapped through its
// open side from the road, a person lying on it is perceived only once it
// is inside the camera's field of view, in line of sight and near enough
// (v_P = v_d * v_o, eq. 1). A map with no frontier left is no proof that
// nobody silent lies somewhere, so the robot then visits the known free
// ground the camera has not yet looked at closely.
//
// Coverage is kept on a coarse grid anchored at the map's origin. A cell is
// looked at closely once its centre was within range_m of the camera and
// inside its horizontal field of view, known free on the map, with no
// occupied cell on the line between. Patches of free cells never looked at
// closely (8-connected, at least min_cells) are the goals. The robot drives
// into the patch, to the cell near the one it reaches soonest (within
// inward_m) that has the most of the patch within range_m, faces the patch,
// and turns a quarter at a time towards the rest of it that lies around.
// What stayed unseen from a goal the robot went to is not asked for again:
// the cells within visited_radius_m of it, and those within range_m that no
// clear line reaches from it whose view is blocked farther than
// hidden_near_goal_m from the goal. By default (100 m) none of the latter:
// ground hidden from one goal is looked at from another. The floor of a
// house open on one side, hidden from a goal beside its wall, is looked at
// from the open side later; given up, a radio on such a floor was never
// seen in a generated district. This costs time: generated 80 x 60 m
// missions took 150-280 s longer than with 0 (all hidden cells given up),
// the last close looks going 30-40 m to patches of 1.5 m2. 3 m still gave a
// house's floor up from goals farther off. The search ends either way: each
// goal is a cell of its patch, given up if not looked at, and a patch with
// no cell the robot can stand on has no goal.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "experts/exploration/known_map.hpp"
#include "experts/exploration/viewpoints.hpp"

namespace beft::exploration {

struct CloseLookParameters {
  bool enabled = true;            // search the ground not looked at closely once no frontier is left
  // Ground this close to the camera, in view, is looked at closely [m]. At
  // 10 m a person's v_d is 0.5 (eq. 1): seen when unoccluded, and any
  // visible pixel of it makes a glimpsed hypothesis, which is inspected.
  double range_m = 10.0;
  double fov_deg = 90.0;          // the camera's horizontal field of view [deg]
  double cell_m = 0.5;            // pitch of the coverage grid [m]
  int min_cells = 6;              // smaller patches are ignored [cells]
  double inward_m = 3.0;          // the goal lies this close to the patch's nearest cell [m]
  double visited_radius_m = 2.0;  // ground this close to a goal gone to is not asked for again [m]
  double hidden_near_goal_m = 100;  // ground hidden from a goal by what stands this near it stays open [m]
  double pose_step_m = 0.25;      // the view is marked again after the camera moved this far [m]
  double gaze_step_deg = 10.0;    // or turned this far [deg]
};

struct CloseLookGoal {
  double x = 0, y = 0;    // a standable, reachable cell of the patch [m]
  double yaw = 0;         // facing the patch's cells within range_m [deg]
  std::vector<double> turns;  // then turned to these headings, in order [deg]
  double travel_m = 0;    // [m]
  int size = 0;           // cells of the patch
};

class CloseLookCoverage {
 public:
  explicit CloseLookCoverage(CloseLookParameters parameters = {}) : parameters_(parameters) {}
  const CloseLookParameters& parameters() const { return parameters_; }

  // Marks what the camera at (x, y) gazing along gaze_deg (CCW from +x)
  // looks at closely, when it moved or turned enough since the last mark.
  void look(const KnownMap& map, double x, double y, double gaze_deg);
  // The robot went to (or gave up going to) this goal: what it could not
  // look at closely from there is not asked for again (see above).
  void visited(const KnownMap& map, Point goal);

  // Whether the ground at (x, y) is still to be looked at closely (not looked
  // at, not given up).
  bool open(double x, double y) const;
  // Ground cells still to be looked at closely within radius of (x, y).
  int openGroundNear(const KnownMap& map, double x, double y, double radius) const;
  // Cells looked at closely so far.
  int lookedAtCells() const { return looked_at_; }

  // The patch the robot reaches soonest (the first found of equals), if any.
  std::optional<CloseLookGoal> cheapestPatch(const KnownMap& map, const TravelField& travel, Point robot);

 private:
  enum : uint8_t { kNotLooked = 0, kLooked = 1, kGivenUp = 2 };
  // Follows the map's extent; a map of another extent starts afresh.
  void fit(const KnownMap& map);
  bool cellOf(double wx, double wy, Cell& cell) const;
  double centreX(int x) const { return origin_x_ + (x + 0.5) * parameters_.cell_m; }
  double centreY(int y) const { return origin_y_ + (y + 0.5) * parameters_.cell_m; }
  size_t index(int x, int y) const { return static_cast<size_t>(y) * width_ + x; }
  // Known free on the map at the cell's centre.
  bool ground(const KnownMap& map, int x, int y) const;
  std::vector<std::vector<Cell>> openPatches(const KnownMap& map) const;
  // The goal for a patch whose cell `nearest` the robot reaches soonest.
  CloseLookGoal goalIn(const KnownMap& map, const TravelField& travel, const std::vector<Cell>& patch,
                       const Cell& nearest, double nearest_travel, Point robot) const;

  CloseLookParameters parameters_;
  int width_ = 0, height_ = 0;
  double origin_x_ = 0, origin_y_ = 0, map_width_m_ = -1, map_height_m_ = -1;
  std::vector<uint8_t> state_;
  int looked_at_ = 0;
  std::optional<Point> last_camera_;
  double last_gaze_deg_ = 0;
};

}  // namespace beft::exploration
