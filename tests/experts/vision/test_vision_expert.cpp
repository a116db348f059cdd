// The vision expert class (without LCM): fires on the inputs of its tick and
// resumes the obstacle map a previous run left on the blackboard.
#include <gtest/gtest.h>

#include <optional>

#include <beft/obstacle_map_t.hpp>
#include <beft/contact_t.hpp>
#include <beft/felt_contacts_t.hpp>
#include <beft/visual_percepts_t.hpp>

#include "lib/camera/camera_messages.hpp"
#include "lib/common/channels.hpp"
#include "experts/vision/depth_rays.hpp"
#include "experts/vision/obstacle_mapper.hpp"
#include "lib/camera/frame_compressor.hpp"
#include "lib/wire/reject_counter.hpp"
#include "lib/wire/obstacle_map_codec.hpp"
#include "lib/scene/ray_caster.hpp"
#include "tests/experts/support/scene_builders.hpp"
#include "lib/scene/scene_geometry.hpp"
#include "lib/wire/obstacle_map_changes.hpp"
#include "experts/vision/vision_expert.hpp"

using namespace beft;

namespace {

struct Collected : expert::Output {
  std::map<std::string, std::vector<uint8_t>> latest;
  std::optional<obstacle_map_t> keyframe;  // the last whole map published
  void publishEncoded(const std::string& channel, const std::vector<uint8_t>& bytes) override {
    latest[channel] = bytes;
    if (channel == channels::kObstacleMap) keyframe = get<obstacle_map_t>(channel);
  }
  template <typename Message>
  Message get(const std::string& channel) const {
    Message m{};
    const auto& bytes = latest.at(channel);
    EXPECT_TRUE(expert::decodeMessage(channel, bytes.data(), static_cast<int>(bytes.size()), m));
    return m;
  }
};

// The map of the tick last fired: the last keyframe published (or, when the
// expert resumed, the one it resumed from) with the changes of the tick.
planners::ObstacleCells publishedMap(const Collected& out, const obstacle_map_t* resumed_from = nullptr) {
  const auto changes = out.get<obstacle_map_changes_t>(channels::kObstacleMapChanges);
  const obstacle_map_t* keyframe = out.keyframe ? &*out.keyframe : resumed_from;
  if (keyframe == nullptr || keyframe->tick != changes.keyframe_tick)
    throw std::runtime_error("no keyframe of tick " + std::to_string(changes.keyframe_tick));
  return *planners::ObstacleMapAssembler().mapOf(*keyframe, &changes);
}

template <typename Message>
bool feed(expert::Expert& e, const std::string& channel, const Message& m) {
  std::vector<uint8_t> bytes(m.getEncodedSize());
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return e.onMessage(channel, bytes.data(), static_cast<int>(bytes.size()));
}

// One tick of the world `s` seen by a camera at (2, 5) looking along +x,
// frames raw or compressed as the world publishes them; the platform touched
// something at `contact` when one is given.
void feedScene(expert::Expert& e, const scene_objects_t& s, bool compressed = false,
               std::optional<std::pair<double, double>> contact = std::nullopt) {
  camera::Camera cam;
  cam.pose = {2, 5, 1.6, 0, 0};
  camera::CameraMessages frames;
  camera::encodeCameraMessages(camera::renderFrame(camera::SceneGeometry::fromMessage(s), cam), s.utime, s.tick,
                               {"victim"}, frames);
  if (compressed) {
    camera::CameraMessages packed;
    camera::FrameCompressor().compress(frames, packed);
    ASSERT_NE(packed.depth.compression, camera_frame_t::COMPRESSION_NONE);
    frames = packed;
  }
  ASSERT_TRUE(feed(e, channels::kGroundTruth, s));
  ASSERT_TRUE(feed(e, channels::kCameraDepth, frames.depth));
  ASSERT_TRUE(feed(e, channels::kCameraInstance, frames.instance));
  contact_t bumper{};
  bumper.utime = s.utime;
  bumper.tick = s.tick;
  bumper.touching = contact.has_value();
  bumper.x = contact ? contact->first : 0;
  bumper.y = contact ? contact->second : 0;
  bumper.heading = 0;  // moving along +x
  ASSERT_TRUE(feed(e, channels::kContact, bumper));
}

// A person 4 m in front of the camera at (6, 5), or further right as the
// tick grows (moving).
void feedTick(expert::Expert& e, int64_t tick, bool moving = false, bool compressed = false,
              std::optional<std::pair<double, double>> contact = std::nullopt) {
  const double y = moving ? 5 - 0.2 * static_cast<double>(tick) : 5;
  feedScene(e, test::scene({test::cylinderObject("victim", "person", 6, y, 0.3, 1.8)}, tick, 20, 10), compressed,
            contact);
}

expert::Firing firingFor(int64_t tick, int64_t id) {
  expert::Firing f;
  f.expert = "vision";
  f.tick = tick;
  f.utime = tick * 100000;
  f.firing_id = id;
  return f;
}

}  // namespace

TEST(VisionExpert, FiresOnlyWithTheInputsOfItsTick) {
  vision::VisionExpert vision;
  vision.startUp();
  feedTick(vision, 0);
  EXPECT_TRUE(vision.inputsReady(firingFor(0, 1)));
  EXPECT_FALSE(vision.inputsReady(firingFor(1, 2)));
  Collected out;
  EXPECT_FALSE(vision.fire(firingFor(1, 2), out).ok);
  EXPECT_TRUE(out.latest.empty());
  ASSERT_TRUE(vision.fire(firingFor(0, 1), out).ok);
  const auto percepts = out.get<visual_percepts_t>(channels::kVision);
  ASSERT_EQ(percepts.num_percepts, 1);
  EXPECT_DOUBLE_EQ(percepts.percepts[0].occlusion, 0.0);
  const auto map = publishedMap(out);
  EXPECT_EQ(map.width, 200);
  EXPECT_EQ(map.height, 100);
}

// The expected pixels follow the scene's objects, not only the camera: a
// person that grows, then moves, before a still camera is counted anew
// each time (the solids are kept while the objects stay the same).
TEST(VisionExpert, ExpectedPixelsFollowTheObjectsOfEachTick) {
  vision::VisionExpert vision;
  vision.startUp();
  const std::vector<std::pair<double, double>> radius_and_y = {{0.3, 5}, {0.3, 5}, {0.6, 5}, {0.6, 4.2}};
  std::vector<int> expected;
  for (int64_t tick = 0; tick < static_cast<int64_t>(radius_and_y.size()); ++tick) {
    const auto [radius, y] = radius_and_y[static_cast<size_t>(tick)];
    feedScene(vision, test::scene({test::cylinderObject("victim", "person", 6, y, radius, 1.8)}, tick, 20, 10));
    Collected out;
    ASSERT_TRUE(vision.fire(firingFor(tick, tick + 1), out).ok) << "tick " << tick;
    const auto percepts = out.get<visual_percepts_t>(channels::kVision);
    ASSERT_EQ(percepts.num_percepts, 1);
    // Nothing hides it: all it is expected to show is shown.
    EXPECT_GT(percepts.percepts[0].visible_pixels, 0);
    EXPECT_EQ(percepts.percepts[0].expected_pixels, percepts.percepts[0].visible_pixels) << "tick " << tick;
    expected.push_back(percepts.percepts[0].expected_pixels);
  }
  EXPECT_EQ(expected[1], expected[0]);  // nothing changed
  EXPECT_GT(expected[2], expected[1]);  // grown
  EXPECT_NE(expected[3], expected[2]);  // moved nearer the image's edge and farther
}

TEST(VisionExpert, ResumesTheMapOfAPreviousRunAndIgnoresItsOwnEcho) {
  // A map from before a restart: an obstacle seen earlier at (15, 2), out of view now.
  planners::ObstacleCells before;
  before.width = 200;
  before.height = 100;
  before.resolution = 0.1;
  before.cells.assign(200 * 100, obstacle_map_t::CELL_UNKNOWN);
  before.cells[20 * 200 + 150] = obstacle_map_t::CELL_OCCUPIED;
  const auto previous = planners::makeObstacleMap(before, obstacle_map_t::ENCODING_RLE, 0, 41);

  vision::VisionExpert vision;
  vision.startUp();
  ASSERT_TRUE(feed(vision, channels::kObstacleMap, previous));
  feedTick(vision, 42);
  Collected out;
  ASSERT_TRUE(vision.fire(firingFor(42, 1), out).ok);
  EXPECT_EQ(out.latest.count(channels::kObstacleMap), 0u);  // the resumed keyframe still holds
  auto map = publishedMap(out, &previous);
  EXPECT_EQ(map.at(150, 20), obstacle_map_t::CELL_OCCUPIED);  // remembered
  int person_cells = 0;  // its near side, x = 5.7
  for (int row = 47; row <= 53; ++row) person_cells += map.at(57, row) == obstacle_map_t::CELL_OCCUPIED;
  EXPECT_GT(person_cells, 2);  // the person seen now

  // Once running, a map heard on the channel (its own) changes nothing.
  before.cells.assign(200 * 100, obstacle_map_t::CELL_OCCUPIED);
  ASSERT_TRUE(feed(vision, channels::kObstacleMap, planners::makeObstacleMap(before, obstacle_map_t::ENCODING_RLE)));
  feedTick(vision, 43);
  ASSERT_TRUE(vision.fire(firingFor(43, 2), out).ok);
  map = publishedMap(out, &previous);
  EXPECT_EQ(map.at(10, 90), obstacle_map_t::CELL_UNKNOWN);
}

TEST(VisionExpert, AMapFromAnEarlierRunIsNotResumed) {
  // The blackboard still holds the last map of a run that reached tick 900;
  // this run starts at tick 0.
  planners::ObstacleCells stale;
  stale.width = 200;
  stale.height = 100;
  stale.resolution = 0.1;
  stale.cells.assign(200 * 100, obstacle_map_t::CELL_OCCUPIED);
  vision::VisionExpert vision;
  vision.startUp();
  ASSERT_TRUE(feed(vision, channels::kObstacleMap, planners::makeObstacleMap(stale, obstacle_map_t::ENCODING_RLE, 0, 900)));
  feedTick(vision, 0);
  Collected out;
  ASSERT_TRUE(vision.fire(firingFor(0, 1), out).ok);
  const auto map = publishedMap(out);
  EXPECT_EQ(map.at(10, 90), obstacle_map_t::CELL_UNKNOWN);
}

TEST(VisionExpert, AMapForAnotherGridIsNotResumed) {
  planners::ObstacleCells other;
  other.width = 50;
  other.height = 50;
  other.resolution = 0.2;
  other.cells.assign(50 * 50, obstacle_map_t::CELL_OCCUPIED);
  vision::VisionExpert vision;
  vision.startUp();
  ASSERT_TRUE(feed(vision, channels::kObstacleMap, planners::makeObstacleMap(other, obstacle_map_t::ENCODING_RLE, 0, 4)));
  feedTick(vision, 5);
  Collected out;
  ASSERT_TRUE(vision.fire(firingFor(5, 1), out).ok);
  const auto map = publishedMap(out);
  EXPECT_EQ(map.width, 200);
  EXPECT_EQ(map.at(10, 90), obstacle_map_t::CELL_UNKNOWN);
}

TEST(VisionExpert, ABadDepthFrameFailsTheFiringAndTheNextTickWorks) {
  // The map is built beside the percepts: its error must still reach the outcome.
  vision::VisionExpert vision;
  vision.startUp();
  feedTick(vision, 0);
  camera_frame_t broken{};
  broken.tick = 0;
  broken.utime = 0;
  broken.encoding = camera_frame_t::ENCODING_RGB8;
  broken.width = 4;
  broken.height = 2;
  broken.data.assign(24, 0);
  broken.data_size = 24;
  ASSERT_TRUE(feed(vision, channels::kCameraDepth, broken));
  Collected out;
  const expert::Outcome failed = vision.fire(firingFor(0, 1), out);
  EXPECT_FALSE(failed.ok);
  EXPECT_NE(failed.message.find("DEPTH_MM16"), std::string::npos) << failed.message;
  EXPECT_TRUE(out.latest.empty()) << "published after a failure";
  feedTick(vision, 1);
  ASSERT_TRUE(vision.fire(firingFor(1, 2), out).ok);
  EXPECT_EQ(out.get<visual_percepts_t>(channels::kVision).num_percepts, 1);
  EXPECT_EQ(publishedMap(out).width, 200);
}

// A contact of the platform enters the map like a bumper: the touched cells
// are OCCUPIED at once, and stay so when the camera later sees the floor
// there (what was touched may be too low or thin to map), while an occupied
// cell that was only seen is cleared by the same view.
TEST(VisionExpert, AContactEntersTheMapAndNoViewClearsIt) {
  vision::VisionExpert vision;
  vision.startUp();
  feedTick(vision, 0, false, false, std::make_pair(4.0, 5.0));
  Collected out;
  ASSERT_TRUE(vision.fire(firingFor(0, 1), out).ok);
  auto map = publishedMap(out);
  EXPECT_EQ(map.at(40, 50), obstacle_map_t::CELL_OCCUPIED);  // (4.05, 5.05): touched
  // Ticks later, no contact, the same floor in view: still occupied.
  for (int64_t tick = 1; tick <= 3; ++tick) {
    feedTick(vision, tick);
    ASSERT_TRUE(vision.fire(firingFor(tick, tick + 1), out).ok);
  }
  map = publishedMap(out);
  EXPECT_EQ(map.at(40, 50), obstacle_map_t::CELL_OCCUPIED);
  EXPECT_EQ(map.at(39, 49), obstacle_map_t::CELL_OCCUPIED);  // (3.95, 4.95): within 0.15 m too
  EXPECT_EQ(map.at(40, 52), obstacle_map_t::CELL_OCCUPIED);  // (4.05, 5.25): across the motion, within 0.25 m
  EXPECT_NE(map.at(43, 50), obstacle_map_t::CELL_OCCUPIED);  // ahead, beyond the contact's 0.15 m
  EXPECT_NE(map.at(40, 55), obstacle_map_t::CELL_OCCUPIED);  // across, beyond 0.25 + 0.15 m
}

// Killed after a contact and restarted from the blackboard, the expert marks
// the contacts of OBSTACLE_MAP_FELT again: the touched cells stay safe from
// the views that follow, and it publishes what it would have published.
TEST(VisionExpert, ARestartAfterAContactKeepsTheTouchedCellsSafe) {
  vision::VisionExpert uninterrupted, restarted, forgetful;
  for (auto* e : {&uninterrupted, &restarted, &forgetful}) e->startUp({{"map_keyframe_ticks", "4"}});
  Collected out, after_restart, forgot;
  for (int64_t tick = 0; tick < 10; ++tick) {
    const auto contact = tick == 1 ? std::optional<std::pair<double, double>>(std::make_pair(4.0, 5.0)) : std::nullopt;
    feedTick(uninterrupted, tick, false, false, contact);
    out.latest.clear();
    ASSERT_TRUE(uninterrupted.fire(firingFor(tick, tick + 1), out).ok);
    const auto felt = out.get<felt_contacts_t>(channels::kObstacleMapFelt);
    EXPECT_EQ(felt.num_contacts, tick >= 1 ? 1 : 0) << "tick " << tick;
    if (tick == 6) {
      // Killed after tick 6: the blackboard holds the keyframe of tick 4 and tick 6's changes and contacts.
      for (auto* e : {&restarted, &forgetful}) {
        ASSERT_TRUE(feed(*e, channels::kObstacleMap, *out.keyframe));
        ASSERT_TRUE(feed(*e, channels::kObstacleMapChanges, out.get<obstacle_map_changes_t>(channels::kObstacleMapChanges)));
      }
      ASSERT_TRUE(feed(restarted, channels::kObstacleMapFelt, felt));
    }
    if (tick > 6) {
      feedTick(restarted, tick);
      feedTick(forgetful, tick);
      after_restart.latest.clear();
      ASSERT_TRUE(restarted.fire(firingFor(tick, tick + 1), after_restart).ok);
      ASSERT_TRUE(forgetful.fire(firingFor(tick, tick + 1), forgot).ok);
      for (const auto& channel : {channels::kObstacleMapChanges.name, channels::kObstacleMapFelt.name, channels::kVision.name})
        EXPECT_EQ(after_restart.latest.at(channel), out.latest.at(channel)) << channel << ", tick " << tick;
    }
  }
  const obstacle_map_t resumed_from = *out.keyframe;
  EXPECT_EQ(publishedMap(after_restart, &resumed_from).at(40, 50), obstacle_map_t::CELL_OCCUPIED);
  // Without the contacts, the floor seen there clears what was touched.
  EXPECT_NE(publishedMap(forgot, &resumed_from).at(40, 50), obstacle_map_t::CELL_OCCUPIED);
}

TEST(VisionExpert, AnOccupiedCellOnlySeenIsClearedByTheSameView) {
  vision::ObstacleMapper mapper(20, 10, vision::ObstacleMapConfig{});
  std::vector<uint8_t> cells(mapper.cells().size(), obstacle_map_t::CELL_UNKNOWN);
  cells[50 * 200 + 40] = obstacle_map_t::CELL_OCCUPIED;
  mapper.restoreCells(cells);
  const auto s = test::scene({test::cylinderObject("victim", "person", 6, 5, 0.3, 1.8)}, 0, 20, 10);
  camera::Camera cam;
  cam.pose = {2, 5, 1.6, 0, 0};
  camera::CameraMessages frames;
  camera::encodeCameraMessages(camera::renderFrame(camera::SceneGeometry::fromMessage(s), cam), s.utime, 0,
                               {"victim"}, frames);
  mapper.integrate(vision::DepthFrameRays(frames.depth));
  EXPECT_EQ(mapper.cell(40, 50), obstacle_map_t::CELL_FREE);
  mapper.markContact(4.05, 5.05, 0.0, 0.0, 0.15);
  EXPECT_EQ(mapper.cell(40, 50), obstacle_map_t::CELL_OCCUPIED);
  mapper.integrate(vision::DepthFrameRays(frames.depth));
  EXPECT_EQ(mapper.cell(40, 50), obstacle_map_t::CELL_OCCUPIED);
}

TEST(VisionExpert, CompressedFramesGiveTheOutputsOfRawOnes) {
  vision::VisionExpert from_raw, from_compressed;
  from_raw.startUp();
  from_compressed.startUp();
  for (int64_t tick = 0; tick < 6; ++tick) {
    feedTick(from_raw, tick, true, false);
    feedTick(from_compressed, tick, true, true);
    Collected raw_out, compressed_out;
    ASSERT_TRUE(from_raw.fire(firingFor(tick, tick + 1), raw_out).ok);
    ASSERT_TRUE(from_compressed.fire(firingFor(tick, tick + 1), compressed_out).ok);
    ASSERT_EQ(raw_out.latest.size(), tick == 0 ? 4u : 3u);  // VISION, changes, contacts, and the whole map at tick 0
    EXPECT_EQ(compressed_out.latest, raw_out.latest) << "tick " << tick;
  }
}

TEST(VisionExpert, ADamagedCompressedFrameIsRefusedAndCountedAndTheTickWaits) {
  vision::VisionExpert vision;
  vision.startUp();
  const auto s = test::scene({test::cylinderObject("victim", "person", 6, 5, 0.3, 1.8)}, 3, 20, 10);
  camera::Camera cam;
  cam.pose = {2, 5, 1.6, 0, 0};
  camera::CameraMessages frames, packed;
  camera::encodeCameraMessages(camera::renderFrame(camera::SceneGeometry::fromMessage(s), cam), s.utime, 3,
                               {"victim"}, frames);
  camera::FrameCompressor().compress(frames, packed);
  camera_frame_t damaged = packed.depth;
  damaged.data[damaged.data.size() / 2] ^= 0x01;
  camera_frame_t lying = packed.instance;
  lying.height = 60;  // the payload holds 120 rows

  const auto before = wire::processRejects().totals();
  const auto count = [](const std::map<std::string, uint64_t>& totals, const std::string& channel) {
    auto it = totals.find(channel);
    return it == totals.end() ? uint64_t{0} : it->second;
  };
  ASSERT_TRUE(feed(vision, channels::kGroundTruth, s));
  EXPECT_FALSE(feed(vision, channels::kCameraDepth, damaged));
  EXPECT_FALSE(feed(vision, channels::kCameraInstance, lying));
  const auto after = wire::processRejects().totals();
  EXPECT_EQ(count(after, channels::kCameraDepth), count(before, channels::kCameraDepth) + 1);
  EXPECT_EQ(count(after, channels::kCameraInstance), count(before, channels::kCameraInstance) + 1);
  EXPECT_FALSE(vision.inputsReady(firingFor(3, 1)));
  EXPECT_EQ(vision.inputsLacking(firingFor(3, 1)),
            (std::vector<std::string>{channels::kCameraDepth, channels::kCameraInstance}));
  // The intact frames, arriving after, are taken.
  ASSERT_TRUE(feed(vision, channels::kCameraDepth, packed.depth));
  ASSERT_TRUE(feed(vision, channels::kCameraInstance, packed.instance));
  EXPECT_TRUE(vision.inputsReady(firingFor(3, 1)));
  Collected out;
  ASSERT_TRUE(vision.fire(firingFor(3, 1), out).ok);
  EXPECT_EQ(out.get<visual_percepts_t>(channels::kVision).num_percepts, 1);
}

// The whole map at keyframe ticks, at every tick the rectangle changed since;
// the two give, at every tick, the map an expert sending the whole map every
// tick sends. A restart from the keyframe and the changes goes on as if
// nothing had happened.
TEST(VisionExpert, KeyframesAndChangesGiveTheMapOfEveryTick) {
  vision::VisionExpert every_tick, keyframes, restarted;
  every_tick.startUp({{"map_keyframe_ticks", "1"}});
  keyframes.startUp({{"map_keyframe_ticks", "4"}});
  restarted.startUp({{"map_keyframe_ticks", "4"}});
  Collected whole, changed, after_restart;
  for (int64_t tick = 0; tick < 11; ++tick) {
    feedTick(every_tick, tick, true);
    feedTick(keyframes, tick, true);
    whole.latest.clear();
    changed.latest.clear();
    ASSERT_TRUE(every_tick.fire(firingFor(tick, tick + 1), whole).ok);
    ASSERT_TRUE(keyframes.fire(firingFor(tick, tick + 1), changed).ok);
    EXPECT_EQ(changed.latest.count(channels::kObstacleMap), tick % 4 == 0 ? 1u : 0u) << tick;
    const auto changes = changed.get<obstacle_map_changes_t>(channels::kObstacleMapChanges);
    EXPECT_EQ(changes.keyframe_tick, tick - tick % 4);
    if (tick % 4 == 0) {
      EXPECT_EQ(changes.width, 0);  // nothing changed since its own keyframe
    }
    EXPECT_EQ(publishedMap(changed).cells, publishedMap(whole).cells) << "tick " << tick;
    if (tick == 6) {
      // Killed after tick 6: restarted from the blackboard's keyframe (tick 4) and changes (tick 6).
      ASSERT_TRUE(feed(restarted, channels::kObstacleMap, *changed.keyframe));
      ASSERT_TRUE(feed(restarted, channels::kObstacleMapChanges, changes));
    }
    if (tick > 6) {
      feedTick(restarted, tick, true);
      after_restart.latest.clear();
      ASSERT_TRUE(restarted.fire(firingFor(tick, tick + 1), after_restart).ok);
      EXPECT_EQ(after_restart.latest.at(channels::kObstacleMapChanges),
                changed.latest.at(channels::kObstacleMapChanges)) << "tick " << tick;
      if (tick % 4 == 0) {
        EXPECT_EQ(after_restart.latest.at(channels::kObstacleMap), changed.latest.at(channels::kObstacleMap));
      }
    }
  }
}
