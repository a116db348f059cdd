// The ears process's block of a tick: which samples, which sources, and the
// 16-bit message that carries them.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "lib/scenario/load_scenario.hpp"
#include "sim/ears/ear_signals.hpp"

using namespace beft;

namespace {

scene_object_t caller(const std::string& id, double x, double y, const std::string& sound, double level = 1) {
  scene_object_t o{};
  o.id = id;
  o.label = "person";
  o.activity = "yelling";
  o.x = x;
  o.y = y;
  o.shape = scene_object_t::SHAPE_NONE;
  o.has_acoustic = true;
  o.sound_active = true;
  o.sound = sound;
  o.level = level;
  return o;
}

robot_state_t robotAt(int64_t tick, double yaw = 0) {
  robot_state_t r{};
  r.tick = tick;
  r.utime = tick * 100000;
  r.yaw = yaw;
  r.camera_height = 1.2;
  r.radius = 0.35;
  return r;
}

struct Scene {
  scene_objects_t message{};
  camera::SceneGeometry solids;
  explicit Scene(std::vector<scene_object_t> objects) {
    message.objects = std::move(objects);
    message.num_objects = static_cast<int32_t>(message.objects.size());
    solids = camera::SceneGeometry::fromMessage(message);
  }
};

std::vector<std::string> warnings;
hearing::SoundBank bank() {
  return hearing::SoundBank(std::string(BEFT_SOURCE_DIR) + "/scenarios", 44100,
                            [](const std::string& text) { warnings.push_back(text); });
}

}  // namespace

TEST(EarSignals, ABlockSpansFromThePreviousTicksTimeToThisOnes) {
  Scene scene({caller("a", 3, 0, "sounds/help.wav")});
  auto sounds = bank();
  const robot_state_t before = robotAt(4), now = robotAt(5, 30);
  const auto request = ears::blockRequest(scene.message, scene.solids, now, &before, sounds, 44100, {});
  EXPECT_EQ(request.first_sample, 4 * 4410);
  EXPECT_EQ(request.num_samples, 4410);
  EXPECT_NEAR(request.previous.yaw_deg, 0, 1e-9);
  EXPECT_NEAR(request.current.yaw_deg, 30, 1e-9);
  EXPECT_NEAR(request.current.centre.z(), 1.2, 1e-9);
  ASSERT_EQ(request.sources.size(), 1u);
  EXPECT_GT(request.sources[0].signal->samples.size(), 44100u) << "2.1 s of 16 kHz resampled to 44.1 kHz";
  // The first tick has no previous one: first_block_s before it, not before 0.
  const auto first = ears::blockRequest(scene.message, scene.solids, robotAt(0), nullptr, sounds, 44100, {});
  EXPECT_EQ(first.first_sample, 0);
  EXPECT_EQ(first.num_samples, 0);
  const auto alone = ears::blockRequest(scene.message, scene.solids, now, nullptr, sounds, 44100, {});
  EXPECT_EQ(alone.first_sample, 4 * 4410);
  EXPECT_EQ(alone.num_samples, 4410);
  EXPECT_NEAR(alone.previous.yaw_deg, 30, 1e-9) << "no previous pose: nothing to cross-fade from";
}

TEST(EarSignals, RendersOnlyTheLoudestSoundingSourcesWhoseSoundsCanBeRead) {
  auto silent = caller("silent", 1, 0, "sounds/help.wav");
  silent.sound_active = false;
  Scene scene({caller("far", 20, 0, "sounds/siren.wav", 1), caller("near", 2, 0, "sounds/engine.wav", 0.5),
               caller("loud_far", 10, 0, "sounds/fire.wav", 4), silent,
               caller("missing", 1, 1, "sounds/no_such_file.wav")});
  auto sounds = bank();
  warnings.clear();
  ears::EarsConfig config;
  config.max_sources = 2;
  const auto request = ears::blockRequest(scene.message, scene.solids, robotAt(3), nullptr, sounds, 44100, config);
  ASSERT_EQ(request.sources.size(), 2u);
  EXPECT_NEAR(request.sources[0].position.x(), 10, 1e-9) << "level 4 at 10 m is louder than level 0.5 at 2 m";
  EXPECT_NEAR(request.sources[1].position.x(), 2, 1e-9);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("no_such_file.wav"), std::string::npos) << warnings[0];
}

TEST(EarSignals, TheMessageCarriesTheSamplesTo16BitsOfTheBlocksPeak) {
  hearing::StereoBlock block;
  for (int i = 0; i < 441; ++i) {
    block.left.push_back(static_cast<float>(0.02 * std::sin(i * 0.1)));
    block.right.push_back(static_cast<float>(-0.05 * std::cos(i * 0.07)));
  }
  hearing::BlockRequest request;
  request.first_sample = 8820;
  request.current.centre = {1, 2, 1.2};
  request.current.yaw_deg = 45;
  const auto message = ears::blockMessage(block, request, robotAt(2), 44100);
  EXPECT_EQ(message.tick, 2);
  EXPECT_EQ(message.first_sample, 8820);
  EXPECT_EQ(message.num_samples, 441);
  EXPECT_EQ(message.sample_rate, 44100);
  EXPECT_NEAR(message.head_yaw, 45, 1e-12);
  EXPECT_NEAR(message.full_scale, 0.05, 1e-4);
  int16_t largest = 0;
  for (int i = 0; i < 441; ++i) {
    EXPECT_NEAR(message.left[i] * message.full_scale / 32767, block.left[i], message.full_scale / 32767);
    EXPECT_NEAR(message.right[i] * message.full_scale / 32767, block.right[i], message.full_scale / 32767);
    largest = std::max<int16_t>(largest, static_cast<int16_t>(std::abs(message.right[i])));
  }
  EXPECT_EQ(largest, 32767);
  // Silence keeps a usable scale.
  hearing::StereoBlock quiet;
  quiet.left.assign(10, 0.0f);
  quiet.right.assign(10, 0.0f);
  EXPECT_EQ(ears::blockMessage(quiet, request, robotAt(2), 44100).full_scale, 1.0);
}

namespace {

// A scenario with a caller behind a wall, a second wall beside them, and
// `acoustics` (an <acoustics .../> element, or nothing), written to a
// temporary file; its path.
std::string roomScenario(const std::string& acoustics) {
  static int count = 0;
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("beft_ears_room_" + std::to_string(getpid()) + "_" + std::to_string(count++) + ".xml"))
                               .string();
  std::ofstream(path) << "<?xml version=\"1.0\"?>\n<scenario name=\"room\" seed=\"3\">\n"
                         "  <world width=\"20\" height=\"12\"/>\n  <robot x=\"2\" y=\"5\"/>\n"
                         "  <object id=\"wall\" label=\"wall\" x=\"5\" y=\"5\" yaw=\"90\">\n"
                         "    <visual shape=\"box\" size=\"4 0.2 2.5\"/>\n  </object>\n"
                         "  <object id=\"side\" label=\"wall\" x=\"5\" y=\"9.1\">\n"
                         "    <visual shape=\"box\" size=\"12 0.2 3\" absorption=\"0.05\"/>\n  </object>\n"
                         "  <object id=\"caller\" label=\"person\" x=\"8\" y=\"5\" activity=\"yelling\">\n"
                         "    <visual shape=\"cylinder\" radius=\"0.3\" height=\"1.8\"/>\n"
                         "    <acoustic sound=\"" BEFT_SOURCE_DIR "/scenarios/sounds/help.wav\"/>\n  </object>\n" +
                             acoustics + "\n</scenario>\n";
  return path;
}

struct RenderedTick {
  hearing::StereoBlock block;
  std::optional<ears::EarsRoom> room;
};

// Tick 10 of the scenario as beft-ears renders it (spherical head).
RenderedTick renderTick(const std::string& acoustics) {
  const scenario::Scenario scenario = scenario::loadScenario(roomScenario(acoustics), nullptr);
  scene_objects_t message{};
  for (const scenario::Object& object : scenario.objects) {
    scene_object_t o = caller(object.id, object.x, object.y, object.acoustic ? object.acoustic->sound_path : "");
    o.has_acoustic = o.sound_active = object.acoustic.has_value();
    o.yaw = object.yaw;
    o.shape = object.visual->shape == scenario::Visual::Shape::Box ? scene_object_t::SHAPE_BOX : scene_object_t::SHAPE_CYLINDER;
    o.size_x = object.visual->shape == scenario::Visual::Shape::Box ? object.visual->size_x : 2 * object.visual->radius;
    o.size_y = object.visual->shape == scenario::Visual::Shape::Box ? object.visual->size_y : 2 * object.visual->radius;
    o.size_z = object.visual->shape == scenario::Visual::Shape::Box ? object.visual->size_z : object.visual->height;
    o.radius = object.visual->radius;
    message.objects.push_back(o);
  }
  message.num_objects = static_cast<int32_t>(message.objects.size());
  const camera::SceneGeometry solids = camera::SceneGeometry::fromMessage(message);
  static const hearing::BinauralRenderer renderer(hearing::HrirSet::sphericalHead(), 44100);
  hearing::SoundBank sounds("/", 44100, [](const std::string&) {});
  robot_state_t robot = robotAt(10), before = robotAt(9);
  robot.x = before.x = 2;
  robot.y = before.y = 5;
  hearing::BlockRequest request = ears::blockRequest(message, solids, robot, &before, sounds, 44100, {});
  RenderedTick tick;
  tick.room = ears::roomOfScenario(scenario, renderer.hrirs(), 44100);
  std::optional<hearing::RoomModel> room;
  if (tick.room) {
    room.emplace(ears::roomOfTick(*tick.room, message, solids));
    request.room = &*room;
  }
  tick.block = renderer.render(request);
  return tick;
}

double energy(const hearing::StereoBlock& block) {
  double sum = 0;
  for (float s : block.left) sum += static_cast<double>(s) * s;
  for (float s : block.right) sum += static_cast<double>(s) * s;
  return sum;
}

}  // namespace

TEST(EarsRoom, WithoutAcousticsTheFreeFieldBitForBit) {
  const RenderedTick free_field = renderTick("");
  EXPECT_FALSE(free_field.room.has_value());
  // An <acoustics> that asks for nothing (no reflections, no tail, no ground) changes no sample.
  const RenderedTick nothing = renderTick("<acoustics reflection_order=\"0\" reverberation=\"0\" ground=\"0\"/>");
  ASSERT_TRUE(nothing.room.has_value());
  EXPECT_EQ(free_field.block.left, nothing.block.left);
  EXPECT_EQ(free_field.block.right, nothing.block.right);
  EXPECT_GT(energy(free_field.block), 0);
}

TEST(EarsRoom, TheScenariosAcousticsReachTheEars) {
  const RenderedTick free_field = renderTick("");
  const RenderedTick room = renderTick("<acoustics reflection_order=\"2\" reverberation=\"0.6\" absorption=\"0.3\"/>");
  ASSERT_TRUE(room.room.has_value());
  EXPECT_EQ(room.room->base.settings().reflection_order, 2);
  EXPECT_DOUBLE_EQ(room.room->base.settings().t60_s, 0.6);
  EXPECT_DOUBLE_EQ(room.room->absorption.at("side"), 0.05);
  EXPECT_DOUBLE_EQ(room.room->absorption.at("wall"), 0.3);
  // The caller behind the wall is heard louder through the side wall's reflections and the tail.
  EXPECT_GT(energy(room.block), 1.5 * energy(free_field.block));
}
