// The vision expert as a process (low level): stores GT_OBJECTS and the
// depth and instance images, and on FIRE for tick k publishes VISION (O_v of
// every object with a visual) and OBSTACLE_MAP (M_O, accumulated). It also
// reads OBSTACLE_MAP: a restarted vision expert resumes from the last map on
// the blackboard instead of forgetting every obstacle seen so far (its own
// maps, heard back while it runs, are ignored).
#pragma once

#include <memory>
#include <optional>

#include <beft/camera_frame_t.hpp>
#include <beft/obstacle_map_t.hpp>
#include <beft/contact_t.hpp>
#include <beft/felt_contacts_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "lib/expert/expert.hpp"
#include "lib/expert/scene_input.hpp"
#include "lib/expert/helper_task.hpp"
#include "lib/expert/id_index.hpp"
#include "experts/vision/visual_occlusion.hpp"
#include "experts/vision/obstacle_mapper.hpp"
#include "lib/scene/ray_caster.hpp"
#include "lib/scene/scene_solids.hpp"

namespace beft::vision {

class VisionExpert : public expert::Expert {
 public:
  std::string name() const override { return "vision"; }
  std::string description() const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;

 private:
  void updateMap(const scene_objects_t& scene, const camera_frame_t& depth, const contact_t* contact, int64_t tick);
  void resumeMap(int64_t first_tick);
  // Marks a contact on the map and remembers it for OBSTACLE_MAP_FELT.
  void markContact(double x, double y, double heading, double width, double radius);
  // Same camera pose and intrinsics (the pixels aside).
  static bool samePose(const camera_frame_t& a, const camera_frame_t& b);
  // The frame's header, without its pixels: what samePose compares.
  static camera_frame_t poseOf(const camera_frame_t& frame);
  // The same pose and the same pixels.
  static bool sameView(const camera_frame_t& a, const camera_frame_t& b);
  static bool unpackFrame(camera_frame_t& frame, std::string* why);

  ObstacleMapConfig map_config_;
  double contact_radius_ = 0.15;  // a contact marks the cells this close to ... [m]
  double contact_width_ = 0.5;    // ... a segment this wide across the motion, where the platform touched [m]
  std::unique_ptr<ObstacleMapper> mapper_;
  double mapped_world_width_ = 0, mapped_world_height_ = 0;
  int64_t last_mapped_tick_ = -1;
  // Published before this process started: the last keyframe, changes and contacts.
  std::optional<obstacle_map_t> resume_map_;
  std::optional<obstacle_map_changes_t> resume_changes_;
  std::optional<felt_contacts_t> resume_felt_;
  felt_contacts_t felt_{};  // every contact marked so far
  camera_frame_t last_depth_{};        // the depth frame last added to the map
  int64_t map_keyframe_ticks_ = 100;   // OBSTACLE_MAP at multiples of this, OBSTACLE_MAP_CHANGES every tick
  std::optional<obstacle_map_t> map_keyframe_;  // the whole map last published
  obstacle_map_changes_t changes_message_{};    // the changes as last encoded
  uint64_t changes_message_version_ = 0;        // mapper version they encode (0: none yet)
  camera::RayCaster ray_caster_;
  std::vector<int> expected_;          // expected pixels per object for the pose below and solids_
  camera_frame_t expected_pose_{};     // header only: the pixels do not matter to it
  camera::SceneSolids solids_;         // of the scene last fired
  expert::IdPositions<scene_object_t> scene_positions_;  // where each of its objects is in the list
  expert::SceneInput scene_{*this};
  // Frames arrive compressed: unpacked (or refused, and counted) as they are kept.
  expert::TickInput<camera_frame_t> depth_{*this, channels::kCameraDepth, 4, unpackFrame};
  expert::TickInput<camera_frame_t> instance_{*this, channels::kCameraInstance, 4, unpackFrame};
  // The bumper. A world that publishes CONTACT does so every tick: once one
  // was heard, each firing waits for its tick's (logs from before have none).
  expert::TickInput<contact_t> contact_{*this, channels::kContact, 16, {}, /*optional_until_heard=*/true};
  expert::HelperTask percepting_;  // last: its thread ends before the state it works on goes
  // To resume after a restart; its own map heard back is not decoded.
  expert::HandledInput<obstacle_map_t> previous_map_{
      *this, channels::kObstacleMap, [this](obstacle_map_t&& map) { resume_map_ = std::move(map); },
      [this] { return mapper_ == nullptr; }};
  expert::HandledInput<obstacle_map_changes_t> previous_changes_{
      *this, channels::kObstacleMapChanges,
      [this](obstacle_map_changes_t&& changes) { resume_changes_ = std::move(changes); },
      [this] { return mapper_ == nullptr; }};
  expert::HandledInput<felt_contacts_t> previous_felt_{
      *this, channels::kObstacleMapFelt, [this](felt_contacts_t&& felt) { resume_felt_ = std::move(felt); },
      [this] { return mapper_ == nullptr; }};
  expert::OutputPort<visual_percepts_t> vision_out_{*this, channels::kVision};
  expert::OutputPort<obstacle_map_t> obstacle_map_out_{*this, channels::kObstacleMap};
  expert::OutputPort<obstacle_map_changes_t> map_changes_out_{*this, channels::kObstacleMapChanges};
  expert::OutputPort<felt_contacts_t> felt_out_{*this, channels::kObstacleMapFelt};

  void publishMap(const scene_objects_t& scene, int64_t tick, expert::Output& out);
};

}  // namespace beft::vision
