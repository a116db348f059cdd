// The scenarios and sounds shipped in scenarios/ load cleanly and stage what
// their comments promise: who is visible from the start, who is hidden behind
// a wall, and that the robot can drive to a place from which it sees them.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <queue>
#include <set>

#include <gtest/gtest.h>

#include "lib/scenario/footprint.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/scenario/wav_info.hpp"

namespace beft::scenario {
namespace {

namespace fs = std::filesystem;

const fs::path kScenarios = BEFT_SCENARIOS_DIR;

Scenario loadShipped(const std::string& name) { return loadScenario((kScenarios / name).string(), nullptr); }

const Object& object(const Scenario& s, const std::string& id) {
  const Object* found = s.findObject(id);
  if (found == nullptr) throw std::runtime_error("no object '" + id + "' in " + s.file);
  return *found;
}

double topOf(const Object& o) {
  return o.z + (o.visual->shape == Visual::Shape::Box ? o.visual->size_z : o.visual->height);
}

// Does the 2-D segment a-b cross the object's ground footprint?
bool segmentCrossesFootprint(const Object& o, double ax, double ay, double bx, double by) {
  if (o.visual->shape == Visual::Shape::Cylinder) {
    const double dx = bx - ax, dy = by - ay;
    const double length2 = dx * dx + dy * dy;
    const double t = length2 > 0 ? std::clamp(((o.x - ax) * dx + (o.y - ay) * dy) / length2, 0.0, 1.0) : 0.0;
    return std::hypot(ax + t * dx - o.x, ay + t * dy - o.y) <= o.visual->radius;
  }
  // Into the box's frame, then clip the segment against the rectangle (Liang-Barsky).
  const double yaw = o.yaw * M_PI / 180.0, c = std::cos(yaw), s = std::sin(yaw);
  const double p0x = c * (ax - o.x) + s * (ay - o.y), p0y = -s * (ax - o.x) + c * (ay - o.y);
  const double p1x = c * (bx - o.x) + s * (by - o.y), p1y = -s * (bx - o.x) + c * (by - o.y);
  const double hx = o.visual->size_x / 2, hy = o.visual->size_y / 2;
  double t0 = 0, t1 = 1;
  const double d[2] = {p1x - p0x, p1y - p0y}, p[2] = {p0x, p0y}, h[2] = {hx, hy};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::abs(d[axis]) < 1e-12) {
      if (std::abs(p[axis]) > h[axis]) return false;
      continue;
    }
    double enter = (-h[axis] - p[axis]) / d[axis], leave = (h[axis] - p[axis]) / d[axis];
    if (enter > leave) std::swap(enter, leave);
    t0 = std::max(t0, enter);
    t1 = std::min(t1, leave);
    if (t0 > t1) return false;
  }
  return true;
}

TEST(SegmentCrossesFootprint, BoxesAndCylinders) {
  Object wall;
  wall.x = 10;
  wall.y = 5;
  wall.yaw = 90;
  wall.visual = Visual{};
  wall.visual->size_x = 4;  // along y once rotated: y in [3, 7]
  wall.visual->size_y = 0.2;
  EXPECT_TRUE(segmentCrossesFootprint(wall, 0, 5, 20, 5));
  EXPECT_TRUE(segmentCrossesFootprint(wall, 0, 0, 20, 10));
  EXPECT_FALSE(segmentCrossesFootprint(wall, 0, 8, 20, 8));
  EXPECT_FALSE(segmentCrossesFootprint(wall, 0, 5, 9.8, 5));  // stops short
  Object pole;
  pole.visual = Visual{};
  pole.visual->shape = Visual::Shape::Cylinder;
  pole.visual->radius = 1;
  EXPECT_TRUE(segmentCrossesFootprint(pole, -5, 0.9, 5, 0.9));
  EXPECT_FALSE(segmentCrossesFootprint(pole, -5, 1.1, 5, 1.1));
}

// An object hides what is behind it from the camera if it stands across the
// camera's height.
bool blocksCamera(const Object& o, double camera_height) {
  return o.visual && o.z <= camera_height && topOf(o) > camera_height;
}

bool sightBlocked(const Scenario& s, double x, double y, double tx, double ty, const std::string& target) {
  for (const Object& o : s.objects) {
    if (o.id != target && blocksCamera(o, s.robot.camera.height_above_ground) &&
        segmentCrossesFootprint(o, x, y, tx, ty)) {
      return true;
    }
  }
  return false;
}

double halfWidth(const Object& o) {
  return o.visual->shape == Visual::Shape::Cylinder ? o.visual->radius
                                                     : std::min(o.visual->size_x, o.visual->size_y) / 2;
}

// Hidden: the lines to the target's centre and to both of its sides are blocked.
bool hiddenFrom(const Scenario& s, double x, double y, const Object& target) {
  const double d = std::hypot(target.x - x, target.y - y);
  const double nx = -(target.y - y) / d * halfWidth(target), ny = (target.x - x) / d * halfWidth(target);
  return sightBlocked(s, x, y, target.x, target.y, target.id) &&
         sightBlocked(s, x, y, target.x + nx, target.y + ny, target.id) &&
         sightBlocked(s, x, y, target.x - nx, target.y - ny, target.id);
}

// Seen from the robot's start pose: in range, inside the field of view with the
// head straight, and the line to its centre is clear.
bool visibleFromStart(const Scenario& s, const Object& target) {
  const Robot& r = s.robot;
  const double bearing = std::atan2(target.y - r.y, target.x - r.x) * 180 / M_PI - r.yaw;
  const double relative = std::remainder(bearing, 360.0);
  return std::hypot(target.x - r.x, target.y - r.y) <= r.camera.range && std::abs(relative) < r.camera.fov / 2 &&
         !sightBlocked(s, r.x, r.y, target.x, target.y, target.id);
}

// Cells (at the world's resolution) the robot's centre can reach from the
// start while keeping `clearance` from every obstacle footprint and the world's
// edge. With clearance 0.75 m every passage used is at least 1.5 m wide.
class Reachable {
 public:
  Reachable(const Scenario& s, double clearance) : s_(s) {
    step_ = s.world.resolution;
    nx_ = static_cast<int>(s.world.width / step_);
    ny_ = static_cast<int>(s.world.height / step_);
    reached_.assign(static_cast<size_t>(nx_ * ny_), false);
    std::vector<bool> free(reached_.size());
    for (int j = 0; j < ny_; ++j) {
      for (int i = 0; i < nx_; ++i) free[index(i, j)] = isFree(x(i), y(j), clearance);
    }
    const int si = static_cast<int>(s.robot.x / step_), sj = static_cast<int>(s.robot.y / step_);
    if (!free[index(si, sj)]) return;
    std::queue<std::pair<int, int>> frontier;
    frontier.push({si, sj});
    reached_[index(si, sj)] = true;
    while (!frontier.empty()) {
      const auto [i, j] = frontier.front();
      frontier.pop();
      const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
      for (int k = 0; k < 4; ++k) {
        const int a = i + di[k], b = j + dj[k];
        if (a < 0 || b < 0 || a >= nx_ || b >= ny_ || !free[index(a, b)] || reached_[index(a, b)]) continue;
        reached_[index(a, b)] = true;
        frontier.push({a, b});
      }
    }
  }

  bool startIsFree() const { return reached_[index(static_cast<int>(s_.robot.x / step_), static_cast<int>(s_.robot.y / step_))]; }

  // Is there a reachable cell from which the target is in camera range and
  // the line to its centre is clear?
  bool canSee(const Object& target) const {
    for (int j = 0; j < ny_; ++j) {
      for (int i = 0; i < nx_; ++i) {
        if (!reached_[index(i, j)]) continue;
        if (std::hypot(target.x - x(i), target.y - y(j)) > s_.robot.camera.range) continue;
        if (!sightBlocked(s_, x(i), y(j), target.x, target.y, target.id)) return true;
      }
    }
    return false;
  }

 private:
  size_t index(int i, int j) const { return static_cast<size_t>(j * nx_ + i); }
  double x(int i) const { return (i + 0.5) * step_; }
  double y(int j) const { return (j + 0.5) * step_; }
  bool isFree(double px, double py, double clearance) const {
    if (px < clearance || py < clearance || px > s_.world.width - clearance || py > s_.world.height - clearance) {
      return false;
    }
    for (const Object& o : s_.objects) {
      // Anything standing at body height is an obstacle; a siren head on a pole is not (its pole is).
      if (o.visual && o.z < s_.robot.camera.height_above_ground && distanceToFootprint(o, px, py) < clearance) {
        return false;
      }
    }
    return true;
  }

  const Scenario& s_;
  double step_ = 0.1;
  int nx_ = 0, ny_ = 0;
  std::vector<bool> reached_;
};

constexpr double kCorridorClearance = 0.75;  // half of the 1.5 m minimum corridor

std::vector<fs::path> shippedScenarios() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(kScenarios)) {
    if (entry.path().extension() == ".xml") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(ShippedScenarios, AllLoadWithoutWarningsAndDescribeThemselves) {
  const std::vector<fs::path> files = shippedScenarios();
  std::set<std::string> names;
  for (const fs::path& file : files) names.insert(file.filename().string());
  for (const char* expected : {"yard.xml", "fig4_dw.xml", "peek.xml", "decoy.xml"}) {
    EXPECT_EQ(names.count(expected), 1u) << expected << " is missing from scenarios/";
  }
  for (const fs::path& file : files) {
    SCOPED_TRACE(file.filename().string());
    const Scenario s = loadScenario(file.string(), nullptr);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    EXPECT_EQ(s.name + ".xml", file.filename().string());
    EXPECT_DOUBLE_EQ(s.robot.radius, 0.35);
    EXPECT_DOUBLE_EQ(s.robot.camera.height_above_ground, 1.6);
    std::ifstream in(file);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_LT(text.find("<!--"), text.find("<scenario")) << "no comment describing the scenario before <scenario>";
    Reachable reachable(s, kCorridorClearance);
    EXPECT_TRUE(reachable.startIsFree()) << "the start is closer than 0.75 m to an obstacle";
  }
}

// An XML comment may not hold "--" (XML 1.0, section 2.5): tinyxml2 reads
// such a file, but Python's, libxml2's and most other parsers refuse it.
TEST(ShippedScenarios, EveryXmlFileHasWellFormedComments) {
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(kScenarios)) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".xml" && extension != ".pnml") continue;
    ++files;
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (auto open = text.find("<!--"); open != std::string::npos; open = text.find("<!--", open + 4)) {
      const auto close = text.find("-->", open + 4);
      ASSERT_NE(close, std::string::npos) << entry.path().filename() << ": a comment is not closed";
      EXPECT_EQ(text.substr(open + 4, close - open - 4).find("--"), std::string::npos)
          << entry.path().filename() << ": \"--\" inside a comment, at byte " << open;
    }
  }
  EXPECT_GE(files, 8);
}

TEST(ShippedSounds, AreShortMono16kHz16BitWavFiles) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(kScenarios / "sounds")) {
    if (entry.path().extension() != ".wav") continue;
    SCOPED_TRACE(entry.path().filename().string());
    ++count;
    const WavInfo info = readWavInfo(entry.path().string());
    EXPECT_EQ(info.sample_rate, 16000);
    EXPECT_EQ(info.channels, 1);
    EXPECT_GE(info.duration, 1.0);
    EXPECT_LE(info.duration, 3.0);
    const auto bytes = fs::file_size(entry.path());
    EXPECT_LT(bytes, 100u * 1024u);
    EXPECT_NEAR(static_cast<double>(bytes), 44.0 + 2.0 * info.frames, 200) << "not 16-bit PCM";
  }
  EXPECT_EQ(count, 6);
}

TEST(ShippedScenarios, YardHidesTheYellingVictimBehindAWallAndShowsTheOther) {
  const Scenario s = loadShipped("yard.xml");
  EXPECT_DOUBLE_EQ(s.world.width, 30);
  EXPECT_DOUBLE_EQ(s.world.height, 20);
  EXPECT_DOUBLE_EQ(s.dt, 0.1);
  EXPECT_DOUBLE_EQ(s.duration, 120);
  const double camera = s.robot.camera.height_above_ground;

  const Object& hidden = object(s, "victim_hidden");
  EXPECT_EQ(hidden.label, "person");
  EXPECT_EQ(hidden.activity, "yelling");
  ASSERT_TRUE(hidden.acoustic && hidden.acoustic->active);
  EXPECT_EQ(fs::path(hidden.acoustic->sound).filename(), "help.wav");

  // The straight line from the start to the yelling victim crosses a wall
  // taller than the camera.
  bool crosses_tall_wall = false;
  for (const Object& o : s.objects) {
    if (o.label == "wall" && o.visual && topOf(o) > camera &&
        segmentCrossesFootprint(o, s.robot.x, s.robot.y, hidden.x, hidden.y)) {
      crosses_tall_wall = true;
    }
  }
  EXPECT_TRUE(crosses_tall_wall);

  // Hidden from everywhere within 3 m of the start, yet the robot can drive
  // (through passages >= 1.5 m wide) to a place from which it sees the victim.
  for (double dx = -3; dx <= 3; dx += 0.25) {
    for (double dy = -3; dy <= 3; dy += 0.25) {
      const double px = s.robot.x + dx, py = s.robot.y + dy;
      if (std::hypot(dx, dy) > 3 || px < 0 || py < 0 || px > s.world.width || py > s.world.height) continue;
      EXPECT_TRUE(hiddenFrom(s, px, py, hidden)) << "victim_hidden is visible from (" << px << ", " << py << ")";
    }
  }
  const Reachable reachable(s, kCorridorClearance);
  EXPECT_TRUE(reachable.canSee(hidden));

  // Another victim is in view from the start.
  const Object& seen = object(s, "victim_seen");
  EXPECT_EQ(seen.label, "person");
  EXPECT_TRUE(visibleFromStart(s, seen));
  EXPECT_FALSE(visibleFromStart(s, hidden));

  // A car of about 4.2 x 1.8 x 1.5 m, idle, and a ringing siren.
  const Object& car = object(s, "car1");
  EXPECT_EQ(car.label, "car");
  EXPECT_EQ(car.activity, "idle");
  EXPECT_NEAR(car.visual->size_x, 4.2, 0.3);
  EXPECT_NEAR(car.visual->size_y, 1.8, 0.2);
  EXPECT_NEAR(car.visual->size_z, 1.5, 0.2);
  const Object& siren = object(s, "siren1");
  EXPECT_EQ(siren.label, "siren");
  EXPECT_EQ(siren.activity, "ringing");
  EXPECT_TRUE(siren.acoustic && siren.acoustic->active);
  EXPECT_DOUBLE_EQ(s.congruencyOf(hidden.label, hidden.activity), 0.75);
}

TEST(ShippedScenarios, Fig4WalkerYellsThenCalmsDownAndTheFireSpreads) {
  const Scenario s = loadShipped("fig4_dw.xml");
  EXPECT_NEAR(s.duration, 45, 5);
  const Object& walker = object(s, "walker");
  EXPECT_EQ(walker.activity, "walking");
  EXPECT_EQ(fs::path(walker.acoustic->sound).filename(), "talk.wav");
  const Object& fire = object(s, "fire1");
  EXPECT_EQ(fire.label, "fire");
  EXPECT_EQ(fire.activity, "burning");
  EXPECT_EQ(fs::path(fire.acoustic->sound).filename(), "fire.wav");

  ASSERT_EQ(s.events.size(), 3u);
  EXPECT_EQ(s.events[0].object, "walker");
  EXPECT_NEAR(s.events[0].t, 10, 1);
  EXPECT_EQ(*s.events[0].activity, "yelling");
  EXPECT_EQ(fs::path(*s.events[0].sound).filename(), "help.wav");
  EXPECT_EQ(s.events[1].object, "walker");
  EXPECT_NEAR(s.events[1].t, 25, 1);
  EXPECT_EQ(*s.events[1].activity, "walking");
  EXPECT_EQ(s.events[2].object, "fire1");
  EXPECT_NEAR(s.events[2].t, 30, 1);
  EXPECT_EQ(*s.events[2].activity, "spreading");
  // The congruency changes the experiment is about.
  EXPECT_LT(s.congruencyOf("person", "walking"), s.congruencyOf("person", "yelling"));
  EXPECT_LT(s.congruencyOf("fire", "burning"), s.congruencyOf("fire", "spreading"));

  // Everything stays in view from the start: both objects, and every waypoint
  // of the walker's and the creeping fire's paths.
  EXPECT_TRUE(visibleFromStart(s, fire));
  ASSERT_EQ(s.paths.size(), 2u);
  EXPECT_EQ(s.paths[0].object, "walker");
  EXPECT_EQ(s.paths[1].object, "fire1");
  for (const auto& path : s.paths) {
    for (const Waypoint& waypoint : path.waypoints) {
      Object at = path.object == "walker" ? walker : fire;
      at.x = waypoint.x;
      at.y = waypoint.y;
      EXPECT_TRUE(visibleFromStart(s, at)) << path.object << " waypoint (" << waypoint.x << ", " << waypoint.y << ")";
    }
  }
  // Where the fire stops, at 30 s when it spreads, the whole of the walker's
  // path is within the 3 m danger radius: the walker is endangered from then on.
  const Waypoint& fire_end = s.paths[1].waypoints.back();
  for (const Waypoint& waypoint : s.paths[0].waypoints)
    EXPECT_LE(std::hypot(waypoint.x - fire_end.x, waypoint.y - fire_end.y), 3.0);
  double fire_path_m = 0;
  for (size_t i = 1; i < s.paths[1].waypoints.size(); ++i)
    fire_path_m += std::hypot(s.paths[1].waypoints[i].x - s.paths[1].waypoints[i - 1].x,
                              s.paths[1].waypoints[i].y - s.paths[1].waypoints[i - 1].y);
  EXPECT_LE(fire_path_m / s.paths[1].speed, 30.0) << "the fire is in place when it spreads";
}

TEST(ShippedScenarios, PeekNeedsADetourToSeeTheOnlyVictim) {
  const Scenario s = loadShipped("peek.xml");
  std::vector<const Object*> persons;
  for (const Object& o : s.objects) {
    if (o.label == "person") persons.push_back(&o);
  }
  ASSERT_EQ(persons.size(), 1u);
  const Object& victim = *persons[0];
  EXPECT_EQ(victim.activity, "yelling");
  EXPECT_TRUE(victim.acoustic && victim.acoustic->active);
  for (double dx = -3; dx <= 3; dx += 0.25) {
    for (double dy = -3; dy <= 3; dy += 0.25) {
      if (std::hypot(dx, dy) > 3) continue;
      EXPECT_TRUE(hiddenFrom(s, s.robot.x + dx, s.robot.y + dy, victim))
          << "visible from (" << s.robot.x + dx << ", " << s.robot.y + dy << ")";
    }
  }
  EXPECT_TRUE(Reachable(s, kCorridorClearance).canSee(victim));
}

TEST(ShippedScenarios, DecoyRadioSoundsLikeAPersonBehindAWall) {
  const Scenario s = loadShipped("decoy.xml");
  const Object& radio = object(s, "radio");
  EXPECT_EQ(radio.label, "siren");
  EXPECT_EQ(radio.acousticLabel(), "person");
  EXPECT_EQ(fs::path(radio.acoustic->sound).filename(), "voice_radio.wav");
  EXPECT_TRUE(radio.acoustic->active);
  EXPECT_TRUE(hiddenFrom(s, s.robot.x, s.robot.y, radio));
  const Object& victim = object(s, "victim");
  EXPECT_EQ(victim.label, "person");
  const Reachable reachable(s, kCorridorClearance);
  EXPECT_TRUE(reachable.canSee(radio));
  EXPECT_TRUE(reachable.canSee(victim));
  EXPECT_DOUBLE_EQ(s.congruencyOf("person", "talking"), 0.5);
}

}  // namespace
}  // namespace beft::scenario
