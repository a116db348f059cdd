#include <gtest/gtest.h>

#include <tinyxml2.h>

#include "services/ssr_bridge/scene_mirror.hpp"

using namespace beft::ssr_bridge;

namespace {

beft::scene_object_t acoustic(const std::string& id, const std::string& sound, double x, double y, bool active,
                              double level = 1.0) {
  beft::scene_object_t o{};
  o.id = id;
  o.x = x;
  o.y = y;
  o.has_acoustic = true;
  o.sound_active = active;
  o.sound = sound;
  o.level = level;
  return o;
}

beft::scene_object_t wall(const std::string& id) {
  beft::scene_object_t o{};
  o.id = id;
  o.label = "wall";
  return o;
}

beft::scene_objects_t scene(std::vector<beft::scene_object_t> objects) {
  beft::scene_objects_t s{};
  s.objects = std::move(objects);
  s.num_objects = static_cast<int32_t>(s.objects.size());
  return s;
}

beft::robot_state_t robot(double x, double y, double yaw, double head_yaw) {
  beft::robot_state_t r{};
  r.x = x;
  r.y = y;
  r.yaw = yaw;
  r.head_yaw = head_yaw;
  return r;
}

// Each request parsed: root <request>, its first child.
struct Request {
  std::string element;                      // source, reference, scene
  std::map<std::string, std::string> attributes;
  std::map<std::string, std::string> position, orientation;
};
std::vector<Request> parsed(const std::vector<std::string>& requests) {
  std::vector<Request> out;
  for (const auto& text : requests) {
    tinyxml2::XMLDocument doc;
    EXPECT_EQ(doc.Parse(text.c_str()), tinyxml2::XML_SUCCESS) << text;
    const auto* root = doc.RootElement();
    EXPECT_STREQ(root->Name(), "request");
    const auto* e = root->FirstChildElement();
    Request r;
    r.element = e->Name();
    for (auto* a = e->FirstAttribute(); a; a = a->Next()) r.attributes[a->Name()] = a->Value();
    if (const auto* p = e->FirstChildElement("position"))
      for (auto* a = p->FirstAttribute(); a; a = a->Next()) r.position[a->Name()] = a->Value();
    if (const auto* o = e->FirstChildElement("orientation"))
      for (auto* a = o->FirstAttribute(); a; a = a->Next()) r.orientation[a->Name()] = a->Value();
    out.push_back(r);
  }
  return out;
}

}  // namespace

TEST(SceneMirror, FirstClearsThenPlacesTheListenerThenMakesOneSourcePerSound) {
  SceneMirror mirror("/scenarios");
  mirror.setObjects(scene({acoustic("victim", "sounds/help.wav", 21, 12, true), wall("w1"),
                           acoustic("car1", "sounds/engine.wav", 12, 15, false, 0.5)}));
  mirror.setRobot(robot(2, 3, 90, 30));
  const auto requests = parsed(mirror.requests());
  ASSERT_EQ(requests.size(), 4u);
  EXPECT_EQ(requests[0].element, "scene");
  EXPECT_EQ(requests[0].attributes.at("clear"), "true");
  EXPECT_EQ(requests[1].element, "reference");
  EXPECT_EQ(requests[1].position.at("x"), "2.000");
  EXPECT_EQ(requests[1].orientation.at("azimuth"), "120.00");
  EXPECT_EQ(requests[2].attributes.at("new"), "true");
  EXPECT_EQ(requests[2].attributes.at("name"), "victim");
  EXPECT_EQ(requests[2].attributes.at("file"), "/scenarios/sounds/help.wav");
  EXPECT_EQ(requests[2].attributes.at("mute"), "false");
  EXPECT_EQ(requests[2].position.at("x"), "21.000");
  EXPECT_EQ(requests[3].attributes.at("name"), "car1");
  EXPECT_EQ(requests[3].attributes.at("mute"), "true");  // not sounding now
  EXPECT_EQ(requests[3].attributes.at("volume"), "-6.02");
  EXPECT_EQ(mirror.sourceCount(), 2u);
}

TEST(SceneMirror, SendsOnlyWhatChangedByNumber) {
  SceneMirror mirror("/s");
  mirror.setObjects(scene({acoustic("a", "a.wav", 1, 1, true), acoustic("b", "b.wav", 2, 2, true)}));
  mirror.setRobot(robot(0, 0, 0, 0));
  mirror.requests();
  EXPECT_TRUE(mirror.requests().empty());  // nothing new
  mirror.setObjects(scene({acoustic("a", "a.wav", 1, 1, true), acoustic("b", "b.wav", 2.5, 2, false)}));
  mirror.setRobot(robot(0, 0, 0, 0.001));  // below the hundredth of a degree written: not sent
  auto requests = parsed(mirror.requests());
  ASSERT_EQ(requests.size(), 1u);
  EXPECT_EQ(requests[0].attributes.at("id"), "2");  // b was made second
  EXPECT_EQ(requests[0].attributes.at("mute"), "true");
  EXPECT_EQ(requests[0].position.at("x"), "2.500");
  EXPECT_FALSE(requests[0].attributes.count("volume"));
  mirror.setRobot(robot(0, 0, 10, -40));
  requests = parsed(mirror.requests());
  ASSERT_EQ(requests.size(), 1u);
  EXPECT_EQ(requests[0].element, "reference");
  EXPECT_TRUE(requests[0].position.empty());
  EXPECT_EQ(requests[0].orientation.at("azimuth"), "330.00");
}

TEST(SceneMirror, AnObjectThatLeavesOrFallsSilentIsMutedNotDeleted) {
  SceneMirror mirror("/s");
  mirror.setObjects(scene({acoustic("a", "a.wav", 1, 1, true), acoustic("b", "b.wav", 2, 2, true)}));
  mirror.requests();
  auto quiet_b = acoustic("b", "b.wav", 2, 2, true);
  quiet_b.has_acoustic = false;
  mirror.setObjects(scene({quiet_b}));  // a gone, b no longer acoustic
  const auto requests = parsed(mirror.requests());
  ASSERT_EQ(requests.size(), 2u);
  EXPECT_EQ(requests[0].attributes.at("id"), "1");
  EXPECT_EQ(requests[0].attributes.at("mute"), "true");
  EXPECT_EQ(requests[1].attributes.at("id"), "2");
  EXPECT_EQ(requests[1].attributes.at("mute"), "true");
}

TEST(SceneMirror, ANewSoundOfAnObjectIsANewSourceAndTheOldOneFallsSilent) {
  SceneMirror mirror("/s");
  mirror.setObjects(scene({acoustic("walker", "talk.wav", 1, 1, true)}));
  mirror.requests();
  mirror.setObjects(scene({acoustic("walker", "help.wav", 1, 2, true)}));
  const auto requests = parsed(mirror.requests());
  ASSERT_EQ(requests.size(), 2u);
  EXPECT_EQ(requests[0].attributes.at("id"), "1");
  EXPECT_EQ(requests[0].attributes.at("mute"), "true");
  EXPECT_EQ(requests[1].attributes.at("new"), "true");
  EXPECT_EQ(requests[1].attributes.at("name"), "walker [help.wav]");
  EXPECT_EQ(requests[1].attributes.at("file"), "/s/help.wav");
}

TEST(SceneMirror, ARestartClearsAndMakesEverySourceAgain) {
  SceneMirror mirror("/s");
  mirror.setObjects(scene({acoustic("a", "a.wav", 1, 1, true), acoustic("b", "/abs/b.wav", 2, 2, false)}));
  mirror.setRobot(robot(5, 5, 0, 0));
  mirror.requests();
  mirror.restart();
  const auto requests = parsed(mirror.requests());
  ASSERT_EQ(requests.size(), 4u);
  EXPECT_EQ(requests[0].element, "scene");
  EXPECT_EQ(requests[1].element, "reference");
  EXPECT_EQ(requests[2].attributes.at("name"), "a");
  EXPECT_EQ(requests[3].attributes.at("file"), "/abs/b.wav");
  EXPECT_EQ(requests[3].attributes.at("mute"), "true");
}

TEST(SceneMirror, SsrsReportOfANumberCorrectsIt) {
  SceneMirror mirror("/s");
  mirror.setObjects(scene({acoustic("a", "a.wav", 1, 1, true), acoustic("b", "b.wav", 2, 2, true)}));
  mirror.requests();
  EXPECT_EQ(mirror.sourceNamed(1, "a"), "");  // as expected
  EXPECT_EQ(mirror.sourceNamed(5, "somebody else's"), "");
  // SSR refused to make a: b became number 1.
  const std::string warning = mirror.sourceNamed(1, "b");
  EXPECT_NE(warning.find("'b' 1, not 2"), std::string::npos) << warning;
  const auto requests = parsed(mirror.requests());  // b's whole state again, to its real number
  ASSERT_EQ(requests.size(), 1u);
  EXPECT_EQ(requests[0].attributes.at("id"), "1");
  EXPECT_EQ(requests[0].attributes.at("mute"), "false");
  EXPECT_EQ(requests[0].position.at("x"), "2.000");
  mirror.setObjects(scene({acoustic("a", "a.wav", 9, 9, true), acoustic("b", "b.wav", 2, 2, true)}));
  EXPECT_TRUE(mirror.requests().empty());  // a's number is unknown now: nothing reaches it
}

TEST(SceneMirror, UnprintableIdsAndPathsAreLeftOutWithOneWarning) {
  SceneMirror mirror("/s");
  const auto bad = acoustic(std::string("bad\x01id"), "x.wav", 0, 0, true);
  const auto no_file = acoustic("silent", "", 0, 0, true);
  mirror.setObjects(scene({bad, no_file, acoustic("ok", "ok.wav", 0, 0, true)}));
  mirror.setObjects(scene({bad, no_file, acoustic("ok", "ok.wav", 0, 0, true)}));
  EXPECT_EQ(mirror.takeWarnings().size(), 2u);
  EXPECT_TRUE(mirror.takeWarnings().empty());
  EXPECT_EQ(mirror.sourceCount(), 1u);
}

TEST(SceneMirror, ASceneCannotAskForEndlesslyManySources) {
  SceneMirror mirror("/s");
  for (int tick = 0; tick < 3; ++tick) {
    std::vector<beft::scene_object_t> many;
    for (int i = 0; i < 200; ++i)
      many.push_back(acoustic("o" + std::to_string(tick) + "_" + std::to_string(i), "x.wav", 0, 0, true));
    mirror.setObjects(scene(many));
  }
  EXPECT_EQ(mirror.sourceCount(), 256u);
  EXPECT_EQ(mirror.takeWarnings().size(), 1u);
}
