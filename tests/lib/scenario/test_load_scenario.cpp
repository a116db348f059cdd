// Valid scenario files load with every default filled in, every attribute
// read, events in time order, and warnings for what the loader does not know.
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "lib/scenario/load_scenario.hpp"
#include "tests/lib/scenario/scenario_test_dir.hpp"

namespace beft::scenario {
namespace {

using LoadScenario = testing::ScenarioTestDir;

const char* kMinimal = R"(<?xml version="1.0"?>
<scenario name="minimal">
  <world width="30" height="20"/>
  <robot x="2" y="3"/>
  <object id="w" label="wall" x="10" y="10">
    <visual shape="box" size="4 0.2 2.5"/>
  </object>
  <object id="p" label="person" x="12" y="8">
    <acoustic sound="sounds/beep.wav"/>
  </object>
  <path object="p" speed="0.5">
    <waypoint x="12" y="8"/>
    <waypoint x="14" y="8"/>
  </path>
</scenario>
)";

TEST_F(LoadScenario, FillsEveryDefault) {
  const Scenario s = loadScenario(write(kMinimal), nullptr);
  EXPECT_EQ(s.name, "minimal");
  EXPECT_EQ(s.version, 1);
  EXPECT_DOUBLE_EQ(s.dt, 0.1);
  EXPECT_DOUBLE_EQ(s.duration, 120);
  EXPECT_EQ(s.seed, 0u);
  EXPECT_DOUBLE_EQ(s.world.width, 30);
  EXPECT_DOUBLE_EQ(s.world.height, 20);
  EXPECT_DOUBLE_EQ(s.world.resolution, 0.1);
  EXPECT_EQ(s.categories, (std::vector<std::string>{"person", "car", "siren", "wall", "fire"}));

  EXPECT_DOUBLE_EQ(s.robot.x, 2);
  EXPECT_DOUBLE_EQ(s.robot.y, 3);
  EXPECT_DOUBLE_EQ(s.robot.yaw, 0);
  EXPECT_DOUBLE_EQ(s.robot.head_yaw, 0);
  EXPECT_DOUBLE_EQ(s.robot.head_pitch, 0);
  EXPECT_DOUBLE_EQ(s.robot.radius, 0.35);
  EXPECT_EQ(s.robot.line, 4);
  EXPECT_DOUBLE_EQ(s.robot.limits.max_speed, 1.0);
  EXPECT_DOUBLE_EQ(s.robot.limits.max_turn_rate, 90);
  EXPECT_DOUBLE_EQ(s.robot.limits.head_yaw_range, 170);
  EXPECT_DOUBLE_EQ(s.robot.limits.head_pitch_range, 30);
  EXPECT_DOUBLE_EQ(s.robot.limits.head_turn_rate, 180);
  EXPECT_DOUBLE_EQ(s.robot.camera.fov, 90);
  EXPECT_EQ(s.robot.camera.width, 160);
  EXPECT_EQ(s.robot.camera.height, 120);
  EXPECT_DOUBLE_EQ(s.robot.camera.range, 20);
  EXPECT_DOUBLE_EQ(s.robot.camera.height_above_ground, 1.6);

  ASSERT_EQ(s.objects.size(), 2u);
  const Object& wall = s.objects[0];
  EXPECT_EQ(wall.id, "w");
  EXPECT_EQ(wall.activity, "idle");
  EXPECT_DOUBLE_EQ(wall.z, 0);
  EXPECT_DOUBLE_EQ(wall.yaw, 0);
  EXPECT_EQ(wall.line, 5);
  ASSERT_TRUE(wall.visual.has_value());
  EXPECT_EQ(wall.visual->shape, Visual::Shape::Box);
  EXPECT_DOUBLE_EQ(wall.visual->size_x, 4);
  EXPECT_DOUBLE_EQ(wall.visual->size_y, 0.2);
  EXPECT_DOUBLE_EQ(wall.visual->size_z, 2.5);
  EXPECT_EQ(wall.visual->color_rgb, 0x808080u);
  EXPECT_FALSE(wall.acoustic.has_value());

  const Object& person = s.objects[1];
  EXPECT_FALSE(person.visual.has_value());
  ASSERT_TRUE(person.acoustic.has_value());
  EXPECT_TRUE(person.acoustic->active);
  EXPECT_DOUBLE_EQ(person.acoustic->level, 1.0);
  EXPECT_EQ(person.acoustic->label, "");
  EXPECT_EQ(person.acousticLabel(), "person");
  EXPECT_EQ(person.acoustic->sound, "sounds/beep.wav");
  EXPECT_TRUE(std::filesystem::path(person.acoustic->sound_path).is_absolute());
  EXPECT_TRUE(std::filesystem::equivalent(person.acoustic->sound_path, dir_ / "sounds" / "beep.wav"));

  ASSERT_EQ(s.paths.size(), 1u);
  EXPECT_FALSE(s.paths[0].loop);
  EXPECT_TRUE(s.events.empty());

  // The seven pairs of the format's default table.
  EXPECT_EQ(s.congruency.size(), 7u);
  EXPECT_DOUBLE_EQ(s.congruencyOf("person", "walking"), 0.25);
  EXPECT_DOUBLE_EQ(s.congruencyOf("person", "idle"), 0.25);
  EXPECT_DOUBLE_EQ(s.congruencyOf("person", "yelling"), 0.75);
  EXPECT_DOUBLE_EQ(s.congruencyOf("fire", "burning"), 0.5);
  EXPECT_DOUBLE_EQ(s.congruencyOf("fire", "spreading"), 0.75);
  EXPECT_DOUBLE_EQ(s.congruencyOf("siren", "ringing"), 0.5);
  EXPECT_DOUBLE_EQ(s.congruencyOf("car", "idle"), 0.25);
  EXPECT_DOUBLE_EQ(s.congruencyOf("car", "burning"), 0.5);
  EXPECT_DOUBLE_EQ(s.congruencyOf("car", "burning", 0.3), 0.3);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

TEST_F(LoadScenario, FindObjectByIdOrNothing) {
  const Scenario s = loadScenario(write(kMinimal), nullptr);
  ASSERT_NE(s.findObject("p"), nullptr);
  EXPECT_EQ(s.findObject("p")->label, "person");
  EXPECT_EQ(s.findObject("nobody"), nullptr);
}

TEST_F(LoadScenario, EventsApplyInTimeOrderAndEqualTimesInFileOrder) {
  const std::string path = write(R"(<?xml version="1.0"?>
<scenario name="events" duration="60">
  <world width="30" height="20"/>
  <robot x="2" y="2"/>
  <object id="a" label="person" x="10" y="10"/>
  <events>
    <event t="5" object="a" activity="first_at_5"/>
    <event t="1" object="a" activity="first_at_1"/>
    <event t="5" object="a" activity="second_at_5"/>
    <event t="0" object="a" activity="at_0"/>
  </events>
  <events>
    <event t="1" object="a" activity="second_at_1"/>
    <event t="5" object="a" activity="third_at_5"/>
  </events>
</scenario>
)");
  const Scenario s = loadScenario(path, nullptr);
  std::vector<std::string> order;
  for (const Event& event : s.events) order.push_back(*event.activity);
  EXPECT_EQ(order, (std::vector<std::string>{"at_0", "first_at_1", "second_at_1", "first_at_5", "second_at_5",
                                             "third_at_5"}));
  EXPECT_EQ(s.events[0].line, 10);
}

TEST_F(LoadScenario, ReadsEveryFeature) {
  const std::filesystem::path nested = dir_ / "scenarios";
  std::filesystem::create_directories(nested);
  const std::string path = write(R"(<?xml version="1.0" encoding="UTF-8"?>
<scenario name="everything" version="1" dt="0.05" duration="90" seed="12345678901">
  <world width="40" height="25" resolution="0.2"/>
  <categories>person car siren wall fire debris</categories>
  <robot x="3" y="4" yaw="45" head_yaw="-30" head_pitch="10" radius="0.4">
    <limits max_speed="1.5" max_turn_rate="120" head_yaw_range="160" head_pitch_range="40" head_turn_rate="90"/>
    <camera fov="70" width="320" height="240" range="25" height_above_ground="1.4"/>
  </robot>
  <object id="victim" label="person" x="12" y="8" z="0.1" yaw="90" activity="yelling">
    <visual shape="cylinder" radius="0.3" height="1.8" color="#D04040"/>
    <acoustic sound="../sounds/beep.wav" active="1" level="0.8"/>
  </object>
  <object id="rubble" label="debris" x="20" y="10" yaw="30">
    <visual shape="box" size="1.5 1 0.6" color="#554433"/>
  </object>
  <object id="radio" label="siren" x="30" y="20" activity="idle">
    <acoustic sound="../sounds/beep.wav" active="0" level="2" label="person"/>
  </object>
  <path object="victim" speed="0.8" loop="1">
    <waypoint x="12" y="8"/>
    <waypoint x="16" y="8"/>
    <waypoint x="16" y="12"/>
  </path>
  <events>
    <event t="30" object="radio" active="1" sound="../sounds/beep.wav" activity="talking"/>
    <event t="12.5" object="victim" x="14" y="9" yaw="180" label="person" active="0"/>
  </events>
  <congruency>
    <c label="person" activity="walking" value="0.3"/>
    <c label="car" activity="driving" value="0.5"/>
  </congruency>
</scenario>
)", "scenarios/everything.xml");
  const Scenario s = loadScenario(path, nullptr);
  EXPECT_EQ(s.file, path);
  EXPECT_EQ(s.name, "everything");
  EXPECT_DOUBLE_EQ(s.dt, 0.05);
  EXPECT_DOUBLE_EQ(s.duration, 90);
  EXPECT_EQ(s.seed, 12345678901u);
  EXPECT_DOUBLE_EQ(s.world.width, 40);
  EXPECT_DOUBLE_EQ(s.world.height, 25);
  EXPECT_DOUBLE_EQ(s.world.resolution, 0.2);
  EXPECT_EQ(s.categories.size(), 6u);
  EXPECT_EQ(s.categories.back(), "debris");

  EXPECT_DOUBLE_EQ(s.robot.yaw, 45);
  EXPECT_DOUBLE_EQ(s.robot.head_yaw, -30);
  EXPECT_DOUBLE_EQ(s.robot.head_pitch, 10);
  EXPECT_DOUBLE_EQ(s.robot.radius, 0.4);
  EXPECT_DOUBLE_EQ(s.robot.limits.max_speed, 1.5);
  EXPECT_DOUBLE_EQ(s.robot.limits.max_turn_rate, 120);
  EXPECT_DOUBLE_EQ(s.robot.limits.head_yaw_range, 160);
  EXPECT_DOUBLE_EQ(s.robot.limits.head_pitch_range, 40);
  EXPECT_DOUBLE_EQ(s.robot.limits.head_turn_rate, 90);
  EXPECT_DOUBLE_EQ(s.robot.camera.fov, 70);
  EXPECT_EQ(s.robot.camera.width, 320);
  EXPECT_EQ(s.robot.camera.height, 240);
  EXPECT_DOUBLE_EQ(s.robot.camera.range, 25);
  EXPECT_DOUBLE_EQ(s.robot.camera.height_above_ground, 1.4);

  const Object* victim = s.findObject("victim");
  ASSERT_NE(victim, nullptr);
  EXPECT_DOUBLE_EQ(victim->z, 0.1);
  EXPECT_DOUBLE_EQ(victim->yaw, 90);
  EXPECT_EQ(victim->activity, "yelling");
  EXPECT_EQ(victim->visual->shape, Visual::Shape::Cylinder);
  EXPECT_DOUBLE_EQ(victim->visual->radius, 0.3);
  EXPECT_DOUBLE_EQ(victim->visual->height, 1.8);
  EXPECT_EQ(victim->visual->color_rgb, 0xD04040u);
  EXPECT_DOUBLE_EQ(victim->acoustic->level, 0.8);
  // Sound paths are relative to the scenario file, not to the working folder.
  EXPECT_TRUE(std::filesystem::equivalent(victim->acoustic->sound_path, dir_ / "sounds" / "beep.wav"));

  const Object* rubble = s.findObject("rubble");
  ASSERT_NE(rubble, nullptr);
  EXPECT_EQ(rubble->label, "debris");
  EXPECT_EQ(rubble->visual->color_rgb, 0x554433u);

  const Object* radio = s.findObject("radio");
  ASSERT_NE(radio, nullptr);
  EXPECT_FALSE(radio->visual.has_value());
  EXPECT_FALSE(radio->acoustic->active);
  EXPECT_DOUBLE_EQ(radio->acoustic->level, 2);
  EXPECT_EQ(radio->acousticLabel(), "person");

  ASSERT_EQ(s.paths.size(), 1u);
  EXPECT_TRUE(s.paths[0].loop);
  EXPECT_DOUBLE_EQ(s.paths[0].speed, 0.8);
  ASSERT_EQ(s.paths[0].waypoints.size(), 3u);
  EXPECT_DOUBLE_EQ(s.paths[0].waypoints[2].y, 12);

  ASSERT_EQ(s.events.size(), 2u);
  const Event& move = s.events[0];
  EXPECT_DOUBLE_EQ(move.t, 12.5);
  EXPECT_EQ(move.object, "victim");
  EXPECT_DOUBLE_EQ(*move.x, 14);
  EXPECT_DOUBLE_EQ(*move.y, 9);
  EXPECT_DOUBLE_EQ(*move.yaw, 180);
  EXPECT_EQ(*move.label, "person");
  EXPECT_FALSE(*move.active);
  EXPECT_FALSE(move.activity.has_value());
  EXPECT_FALSE(move.sound.has_value());
  const Event& radio_on = s.events[1];
  EXPECT_TRUE(*radio_on.active);
  EXPECT_EQ(*radio_on.activity, "talking");
  EXPECT_EQ(*radio_on.sound, "../sounds/beep.wav");
  EXPECT_TRUE(std::filesystem::equivalent(*radio_on.sound_path, dir_ / "sounds" / "beep.wav"));

  // Overridden and added pairs; the other defaults stay.
  EXPECT_EQ(s.congruency.size(), 8u);
  EXPECT_DOUBLE_EQ(s.congruencyOf("person", "walking"), 0.3);
  EXPECT_DOUBLE_EQ(s.congruencyOf("car", "driving"), 0.5);
  EXPECT_DOUBLE_EQ(s.congruencyOf("person", "yelling"), 0.75);
}

TEST_F(LoadScenario, UnknownAttributesAndElementsAreWarnedAboutWithTheirLine) {
  const std::string path = write(R"(<?xml version="1.0"?>
<scenario name="extended">
  <world width="30" height="20" floor="concrete"/>
  <robot x="2" y="2"/>
  <object id="a" label="car" x="10" y="10" speed="3">
    <smell strength="2"/>
  </object>
  <weather rain="1"/>
</scenario>
)");
  std::ostringstream stream;
  const Scenario s = loadScenario(path, &stream);
  const std::vector<std::string> expected = {
      path + ":3: warning: unknown attribute 'floor' on <world>",
      path + ":5: warning: unknown attribute 'speed' on <object>",
      path + ":6: warning: unknown element <smell> in <object>",
      path + ":8: warning: unknown element <weather> in <scenario>",
  };
  EXPECT_EQ(s.warnings, expected);
  std::string expected_text;
  for (const std::string& line : expected) expected_text += line + "\n";
  EXPECT_EQ(stream.str(), expected_text);
  EXPECT_NE(s.findObject("a"), nullptr);  // a warning does not stop the load
}

TEST_F(LoadScenario, AttributeOfTheOtherShapeIsWarnedAbout) {
  const Scenario s = loadScenario(write(R"(<?xml version="1.0"?>
<scenario name="t">
  <world width="30" height="20"/>
  <robot x="2" y="2"/>
  <object id="w" label="wall" x="10" y="10">
    <visual shape="box" size="1 1 1" radius="3"/>
  </object>
</scenario>
)"),
                                  nullptr);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find(":6: warning: unknown attribute 'radius' on <visual>"), std::string::npos);
}

TEST_F(LoadScenario, WarnsAboutEventsAfterTheEndAndAudibleActivitiesWithoutCongruency) {
  const Scenario s = loadScenario(write(R"(<?xml version="1.0"?>
<scenario name="t" duration="30">
  <world width="30" height="20"/>
  <robot x="2" y="2"/>
  <object id="p" label="person" x="10" y="10" activity="yeling">
    <acoustic sound="sounds/beep.wav"/>
  </object>
  <events>
    <event t="45" object="p" activity="yelling"/>
    <event t="5" object="p"/>
  </events>
</scenario>
)"),
                                  nullptr);
  ASSERT_EQ(s.warnings.size(), 3u);
  EXPECT_NE(s.warnings[0].find(":9: warning: event at t=45 s comes after the end"), std::string::npos) << s.warnings[0];
  EXPECT_NE(s.warnings[1].find(":10: warning: event changes nothing"), std::string::npos) << s.warnings[1];
  EXPECT_NE(s.warnings[2].find(":5: warning: no congruency for (person, yeling)"), std::string::npos)
      << s.warnings[2];
}

TEST_F(LoadScenario, WorksFromAnotherWorkingFolder) {
  const std::string path = write(kMinimal);
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::temp_directory_path());
  const Scenario s = loadScenario(path, nullptr);
  std::filesystem::current_path(previous);
  EXPECT_TRUE(std::filesystem::exists(s.objects[1].acoustic->sound_path));
}

TEST_F(LoadScenario, AcousticsAbsentMeansTheFreeField) {
  const Scenario s = loadScenario(write(kMinimal), nullptr);
  EXPECT_FALSE(s.acoustics.has_value());
  EXPECT_FALSE(s.objects[0].visual->absorption.has_value());
}

TEST_F(LoadScenario, AcousticsDefaultsAndValues) {
  std::string text = kMinimal;
  text.replace(text.find("</scenario>"), 0, "  <acoustics/>\n");
  const Scenario defaults = loadScenario(write(text), nullptr);
  ASSERT_TRUE(defaults.acoustics.has_value());
  EXPECT_DOUBLE_EQ(defaults.acoustics->reverberation, 0);
  EXPECT_EQ(defaults.acoustics->reflection_order, 0);
  EXPECT_DOUBLE_EQ(defaults.acoustics->absorption, 0.2);
  EXPECT_TRUE(defaults.acoustics->ground);
  EXPECT_EQ(defaults.acoustics->line, 15);

  std::string full = kMinimal;
  full.replace(full.find("</scenario>"), 0,
               "  <acoustics reverberation=\"0.6\" reflection_order=\"2\" absorption=\"0.35\" ground=\"0\"/>\n");
  full.replace(full.find("size=\"4 0.2 2.5\""), 0, "absorption=\"0.05\" ");
  std::ostringstream warnings;
  const Scenario s = loadScenario(write(full), &warnings);
  EXPECT_EQ(warnings.str(), "");
  ASSERT_TRUE(s.acoustics.has_value());
  EXPECT_DOUBLE_EQ(s.acoustics->reverberation, 0.6);
  EXPECT_EQ(s.acoustics->reflection_order, 2);
  EXPECT_DOUBLE_EQ(s.acoustics->absorption, 0.35);
  EXPECT_FALSE(s.acoustics->ground);
  EXPECT_DOUBLE_EQ(*s.objects[0].visual->absorption, 0.05);
}

TEST_F(LoadScenario, AcousticsEdgesOfTheRangesLoad) {
  for (const char* attributes : {"reverberation=\"10\" reflection_order=\"4\" absorption=\"1\" ground=\"1\"",
                                 "reverberation=\"0\" reflection_order=\"0\" absorption=\"0\" ground=\"0\""}) {
    std::string text = kMinimal;
    text.replace(text.find("</scenario>"), 0, std::string("  <acoustics ") + attributes + "/>\n");
    EXPECT_NO_THROW(loadScenario(write(text), nullptr)) << attributes;
  }
}

}  // namespace
}  // namespace beft::scenario
