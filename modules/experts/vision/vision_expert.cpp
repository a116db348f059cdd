#include "experts/vision/vision_expert.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "lib/scene/camera_model.hpp"
#include "lib/common/channels.hpp"
#include "experts/vision/depth_rays.hpp"
#include "lib/camera/frame_decoding.hpp"
#include "lib/common/log.hpp"
#include "lib/wire/obstacle_map_codec.hpp"
#include "lib/scene/scene_geometry.hpp"
#include "experts/vision/visual_occlusion.hpp"

namespace beft::vision {

std::string VisionExpert::description() const {
  return "Low-level vision expert: the visual occlusion O_v = 100 (1 - visible / expected) of "
         "every object with a visual (visible: its pixels in the instance image; expected: the "
         "pixels it would cover if nothing were in front; out of view = 100), and the obstacle "
         "map M_O: depth pixels back-projected into the world; returns above "
         "obstacle_min_height mark OCCUPIED cells, cells the rays crossed become FREE, and an "
         "occupied cell is cleared only when a ray crosses it below obstacle_min_height (so a "
         "person who walked away stops blocking the map). The map covers the world of "
         "GT_OBJECTS at --param resolution and accumulates over the run. Reads GT_OBJECTS, "
         "CAMERA_DEPTH, CAMERA_INSTANCE and CONTACT of the fired tick, writes VISION, OBSTACLE_MAP "
         "(the whole map at keyframes), OBSTACLE_MAP_CHANGES (every tick) and OBSTACLE_MAP_FELT (every "
         "contact marked so far, every tick). When (re)started during a run it resumes from the last "
         "of these on the blackboard. A contact of the platform (CONTACT touching, at x/y) marks the "
         "cells within contact_radius of a contact_width segment across the motion OCCUPIED for good, like a bumper: what the camera could not map is "
         "not driven into twice. To run it alone: start beft-world and feed FIRE tokens for 'vision' (or run "
         "the arbiter), and watch VISION with lcm-spy.";
}

void VisionExpert::declareParameters(DeclaredParameters& parameters) {
  parameters.declare("resolution", map_config_.resolution, 0, DeclaredParameters::kNoLimit, "obstacle map cell edge [m]", true);
  parameters.declare("obstacle_min_height", map_config_.obstacle_min_height, 0, DeclaredParameters::kNoLimit,
                     "depth returns above this height are obstacles [m]");
  parameters.declare("map_keyframe_ticks", map_keyframe_ticks_, 1, 1000000,
                     "OBSTACLE_MAP (the whole map) is published at ticks that are multiples of this (1: every "
                     "tick); OBSTACLE_MAP_CHANGES every tick carries the rectangle changed since");
  parameters.declare("contact_radius", contact_radius_, 0, 2,
                     "a contact of the platform marks the map's cells within this of the touching segment [m]");
  parameters.declare("contact_width", contact_width_, 0, 5,
                     "width of the touching segment, across the stopped motion, centred where the platform touched [m]");
}

bool VisionExpert::samePose(const camera_frame_t& a, const camera_frame_t& b) {
  return a.encoding == b.encoding && a.width == b.width && a.height == b.height && a.fov == b.fov &&
         a.range == b.range && a.cam_x == b.cam_x && a.cam_y == b.cam_y && a.cam_z == b.cam_z &&
         a.cam_yaw == b.cam_yaw && a.cam_pitch == b.cam_pitch;
}

camera_frame_t VisionExpert::poseOf(const camera_frame_t& frame) {
  camera_frame_t pose{};
  pose.encoding = frame.encoding;
  pose.width = frame.width;
  pose.height = frame.height;
  pose.fov = frame.fov;
  pose.range = frame.range;
  pose.cam_x = frame.cam_x;
  pose.cam_y = frame.cam_y;
  pose.cam_z = frame.cam_z;
  pose.cam_yaw = frame.cam_yaw;
  pose.cam_pitch = frame.cam_pitch;
  return pose;
}

bool VisionExpert::sameView(const camera_frame_t& a, const camera_frame_t& b) {
  return samePose(a, b) && a.data == b.data;
}

bool VisionExpert::unpackFrame(camera_frame_t& frame, std::string* why) {
  return camera::decodeCameraFrame(frame, why);
}

expert::Outcome VisionExpert::fire(const expert::Firing& firing, expert::Output& out) {
  const auto* scene = scene_.ofTick(firing.tick);
  const auto* depth = depth_.ofTick(firing.tick);
  const auto* instance = instance_.ofTick(firing.tick);
  const auto* contact = contact_.ofTick(firing.tick);
  if (scene == nullptr || depth == nullptr || instance == nullptr)
    return expert::Outcome::failure(
        std::string("no ") + (scene == nullptr ? "GT_OBJECTS" : depth == nullptr ? "CAMERA_DEPTH" : "CAMERA_INSTANCE") +
        " for tick " + std::to_string(firing.tick));
  try {
    // The map and the percepts need nothing of each other: the percepts are
    // counted on the helper thread meanwhile (they touch only their own
    // state). The map stays here: it starts at once, while the helper takes
    // a wake-up to start. Expected pixels, the longest part, are counted by
    // both threads: the helper starts on them, this thread takes the solids
    // left when its map is done.
    // Expected pixels only change with the camera or the objects' shapes and poses.
    // The solids are made again only when the scene's objects change (rarely:
    // hundreds of objects were turned into solids at every tick of a drive).
    const bool scene_changed = solids_.update(*scene);
    const auto& scene_index = scene_positions_.of(scene->objects, &scene_object_t::id);
    const bool recount = scene_changed || expected_pose_.width == 0 || !samePose(*instance, expected_pose_);
    const camera::SceneGeometry* solids = &solids_.solids();
    if (recount) {
      // Objects the real image cannot show at all are out of view: 0
      // expected, O_v = 100, not counted.
      ray_caster_.prepareExpectedInView(camera::cameraOfFrame(*instance));
    }
    std::atomic<size_t> next_solid{0};
    std::vector<int> helper_counts, own_counts;
    std::vector<int> visible;
    percepting_.start([&] {
      if (recount) ray_caster_.countExpected(*solids, next_solid, helper_counts);
      visible = countVisiblePixels(*instance, scene_index, scene->objects.size());
    });
    expert::WaitOnExit perceived(percepting_);  // also when the map throws
    updateMap(*scene, *depth, contact, firing.tick);
    if (recount) ray_caster_.countExpected(*solids, next_solid, own_counts);
    percepting_.wait();  // an error of the percepts ends up below
    if (recount) {
      expected_ = std::move(own_counts);
      for (size_t i = 0; i < expected_.size() && i < helper_counts.size(); ++i) expected_[i] += helper_counts[i];
      expected_pose_ = poseOf(*instance);
    }
    const visual_percepts_t percepts = estimateVisualOcclusion(*scene, visible, expected_);
    // Both at the end: a publish wakes the readers, who would take the cores from the work.
    vision_out_.publish(out, percepts);
    publishMap(*scene, firing.tick, out);
  } catch (const std::exception& e) {
    return expert::Outcome::failure("tick " + std::to_string(firing.tick) + ": " + e.what());
  }
  return expert::Outcome::success();
}

// The whole map at keyframe ticks (and when none was published yet), and at
// every tick the rectangle changed since the keyframe, re-encoded only when a
// cell changed (a robot standing still sees no change).
void VisionExpert::publishMap(const scene_objects_t& scene, int64_t tick, expert::Output& out) {
  const bool keyframe_due = tick % map_keyframe_ticks_ == 0 || !map_keyframe_ || map_keyframe_->tick > tick;
  if (keyframe_due && !(map_keyframe_ && map_keyframe_->tick == tick)) {
    map_keyframe_ = mapper_->toMessage(scene.utime, tick);
    mapper_->markKeyframe();
    changes_message_version_ = 0;
  }
  if (map_keyframe_->tick == tick) obstacle_map_out_.publish(out, *map_keyframe_);
  if (changes_message_version_ == 0 || mapper_->version() != changes_message_version_) {
    changes_message_ = mapper_->changesMessage(map_keyframe_->tick, scene.utime, tick);
    changes_message_version_ = mapper_->version();
  }
  changes_message_.utime = scene.utime;
  changes_message_.tick = tick;
  map_changes_out_.publish(out, changes_message_);
  felt_.utime = scene.utime;
  felt_.tick = tick;
  felt_.width = felt_.num_contacts > 0 ? felt_.width : contact_width_;
  felt_.radius = felt_.num_contacts > 0 ? felt_.radius : contact_radius_;
  felt_out_.publish(out, felt_);
}

// Starts from the map this expert published before a restart, if it covers
// the same grid. A map of a later tick than the first one fired belongs to an
// earlier run (the blackboard outlived it), not to this one.
void VisionExpert::resumeMap(int64_t first_tick) {
  std::optional<obstacle_map_changes_t> changes = std::move(resume_changes_);
  resume_changes_.reset();
  std::optional<felt_contacts_t> felt = std::move(resume_felt_);
  resume_felt_.reset();
  if (!resume_map_) return;
  const obstacle_map_t map = std::move(*resume_map_);
  resume_map_.reset();
  if (map.tick >= first_tick) {
    log::info("obstacle map of tick ", map.tick, " on the blackboard is from another run: starting empty");
    return;
  }
  if (map.width != mapper_->width() || map.height != mapper_->height() ||
      std::abs(map.resolution - mapper_->resolution()) > 1e-9 || map.origin_x != 0 || map.origin_y != 0) {
    log::warn("obstacle map of tick ", map.tick, " on the blackboard is for another grid: starting empty");
    return;
  }
  try {
    planners::ObstacleCells cells = planners::decodeObstacleMap(map);
    // The changes since that keyframe, when they belong to it and to this run.
    const bool with_changes = changes && changes->keyframe_tick == map.tick && changes->tick < first_tick;
    if (with_changes) planners::applyMapChanges(*changes, cells);
    mapper_->restoreCells(cells.cells);
    // The contacts marked before: their cells stay safe from being cleared.
    // Marked already in the map, they change no cell.
    if (felt && felt->tick < first_tick) {
      const size_t count = std::min({felt->x.size(), felt->y.size(), felt->heading.size()});
      for (size_t i = 0; i < count; ++i) markContact(felt->x[i], felt->y[i], felt->heading[i], felt->width, felt->radius);
    }
    if (with_changes) mapper_->restoreChanged({changes->x0, changes->y0, changes->width, changes->height});
    map_keyframe_ = map;
    log::info("resumed the obstacle map of tick ", with_changes ? changes->tick : map.tick, " from the blackboard, ",
              felt_.num_contacts, " contacts marked");
  } catch (const std::exception& e) {
    log::warn("obstacle map of tick ", map.tick, " on the blackboard is unusable (", e.what(), "): starting empty");
  }
}

void VisionExpert::markContact(double x, double y, double heading, double width, double radius) {
  mapper_->markContact(x, y, heading, width, radius);
  felt_.width = width;
  felt_.radius = radius;
  felt_.x.push_back(x);
  felt_.y.push_back(y);
  felt_.heading.push_back(heading);
  felt_.num_contacts = static_cast<int32_t>(felt_.x.size());
}

void VisionExpert::updateMap(const scene_objects_t& scene, const camera_frame_t& depth, const contact_t* contact,
                             int64_t tick) {
  if (!mapper_ || scene.world_width != mapped_world_width_ || scene.world_height != mapped_world_height_) {
    if (mapper_) log::warn("world size changed: obstacle map restarted");
    mapper_ = std::make_unique<ObstacleMapper>(scene.world_width, scene.world_height, map_config_);
    map_keyframe_.reset();
    changes_message_version_ = 0;
    felt_ = felt_contacts_t{};
    resumeMap(tick);
    mapped_world_width_ = scene.world_width;
    mapped_world_height_ = scene.world_height;
    last_mapped_tick_ = -1;
    last_depth_ = camera_frame_t{};
  }
  if (tick == last_mapped_tick_) return;  // a re-sent FIRE: this frame is in the map already
  last_mapped_tick_ = tick;
  if (contact != nullptr && contact->touching && contact_radius_ > 0)
    markContact(contact->x, contact->y, contact->heading, contact_width_, contact_radius_);
  // The same image from the same pose adds nothing (integrating is
  // idempotent): a robot standing in a still scene costs no mapping.
  if (sameView(depth, last_depth_)) return;
  mapper_->integrate(DepthFrameRays(depth));
  last_depth_ = depth;
}

}  // namespace beft::vision
