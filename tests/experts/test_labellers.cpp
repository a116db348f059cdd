// Mid-level labelling logic: eqs. 1-3 for the geometry of the low-level
// percepts, against hand-computed numbers and the model library.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "experts/acoustic_labels/acoustic_labeller.hpp"
#include "lib/model/model.hpp"
#include "tests/experts/support/scene_builders.hpp"
#include "experts/visual_labels/visual_labeller.hpp"

using namespace beft;

namespace {

geometry_percepts_t geometryOf(const std::vector<std::tuple<std::string, double, double>>& rows) {
  geometry_percepts_t g{};
  for (const auto& [id, distance, azimuth] : rows) {
    geometry_percept_t p{};
    p.object_id = id;
    p.distance = distance;
    p.azimuth = azimuth;
    g.percepts.push_back(p);
  }
  g.num_percepts = static_cast<int32_t>(g.percepts.size());
  return g;
}

visual_percept_t visualPercept(const std::string& id, double occlusion) {
  visual_percept_t p{};
  p.object_id = id;
  p.occlusion = occlusion;
  p.visible_pixels = 10;
  p.expected_pixels = 20;
  return p;
}

acoustic_percept_t acousticPercept(const std::string& id, double occlusion, const std::string& label) {
  acoustic_percept_t p{};
  p.object_id = id;
  p.occlusion = occlusion;
  p.acoustic_label = label;
  p.activity = "yelling";
  return p;
}

double confidenceOf(const object_labels_t& entry, const std::string& category) {
  for (int j = 0; j < entry.num_categories; ++j)
    if (entry.categories[j] == category) return entry.confidence[j];
  throw std::runtime_error("no category " + category);
}

}  // namespace

TEST(VisualLabeller, HandComputedValuesAtTenMetres) {
  const auto s = test::scene({test::cylinderObject("victim", "person", 0, 0, 0.3, 1.8),
                              test::boxObject("wall", "wall", 1, 1, 0, 1, 1, 1)});
  visual_percepts_t vision{};
  vision.tick = 3;
  vision.utime = 300000;
  vision.percepts = {visualPercept("victim", 0), visualPercept("wall", 50)};
  vision.num_percepts = 2;
  const auto result =
      visual_labels::labelVisually(s, geometryOf({{"victim", 10, 0}, {"wall", 10, 0}}), vision, model::Parameters{});
  ASSERT_TRUE(result.skipped.empty());
  ASSERT_EQ(result.labels.num_objects, 2);
  EXPECT_EQ(result.labels.modality, labels_t::MODALITY_VISUAL);
  EXPECT_EQ(result.labels.tick, 3);
  const auto& victim = result.labels.objects[0];
  // g_d(10) = 0.5, v_o(0) = 1: v_P = 0.5, and eq. 3 gives 0.5 +- 0.5 * 0.5.
  EXPECT_NEAR(victim.perceptibility, 0.5, 1e-12);
  EXPECT_NEAR(confidenceOf(victim, "person"), 0.75, 1e-12);
  EXPECT_NEAR(confidenceOf(victim, "wall"), 0.25, 1e-12);
  ASSERT_EQ(victim.num_categories, 5);
  // Half occluded: v_P = 0.25; L = 0.5 +- 0.5 / (1 + e^5).
  const auto& wall = result.labels.objects[1];
  EXPECT_NEAR(wall.perceptibility, 0.25, 1e-12);
  EXPECT_NEAR(confidenceOf(wall, "wall"), 0.5 + 0.5 / (1 + std::exp(5.0)), 1e-12);
  EXPECT_NEAR(confidenceOf(wall, "person"), 0.5 - 0.5 / (1 + std::exp(5.0)), 1e-12);
}

TEST(VisualLabeller, EqualsTheModelLibraryForAnyGeometryAndBothForms) {
  const auto s = test::scene({test::boxObject("car1", "car", 0, 0, 0, 4, 2, 1.5)});
  model::Parameters printed;
  model::setParameter(printed, "label_form", "printed");
  for (const auto& parameters : {model::Parameters{}, printed}) {
    for (double d : {0.5, 4.0, 9.0, 17.0}) {
      for (double occlusion : {0.0, 30.0, 100.0}) {
        visual_percepts_t vision{};
        vision.percepts = {visualPercept("car1", occlusion)};
        vision.num_percepts = 1;
        const auto result = visual_labels::labelVisually(s, geometryOf({{"car1", d, 33}}), vision, parameters);
        ASSERT_EQ(result.labels.num_objects, 1);
        const double v_p = model::visualPerceptibility(d, occlusion);
        EXPECT_DOUBLE_EQ(result.labels.objects[0].perceptibility, v_p);
        EXPECT_EQ(result.labels.objects[0].confidence, model::labelConfidences(s.categories, "car", v_p, parameters));
      }
    }
  }
}

TEST(VisualLabeller, SkipsPerceptsWithoutGeometry) {
  const auto s = test::scene({test::boxObject("car1", "car", 0, 0, 0, 4, 2, 1.5)});
  visual_percepts_t vision{};
  vision.percepts = {visualPercept("car1", 0), visualPercept("ghost", 0)};
  vision.num_percepts = 2;
  const auto result = visual_labels::labelVisually(s, geometryOf({{"car1", 3, 0}}), vision, model::Parameters{});
  EXPECT_EQ(result.labels.num_objects, 1);
  ASSERT_EQ(result.skipped.size(), 1u);
  EXPECT_NE(result.skipped[0].find("ghost"), std::string::npos);
}

TEST(VisualLabeller, LabelsOnlyWhatTheCameraShows) {
  const auto s = test::scene({test::boxObject("car1", "car", 0, 0, 0, 4, 2, 1.5),
                              test::cylinderObject("behind", "person", 5, 0, 0.3, 1.8)});
  visual_percepts_t vision{};
  visual_percept_t hidden = visualPercept("behind", 100);
  hidden.visible_pixels = 0;
  vision.percepts = {visualPercept("car1", 0), hidden};
  vision.num_percepts = 2;
  const auto result = visual_labels::labelVisually(s, geometryOf({{"car1", 3, 0}, {"behind", 6, 0}}), vision,
                                                   model::Parameters{});
  ASSERT_EQ(result.labels.num_objects, 1);
  EXPECT_EQ(result.labels.objects[0].object_id, "car1");
  EXPECT_TRUE(result.skipped.empty());  // an unseen object is no error
}

TEST(AcousticLabeller, HandComputedValuesUseTheAcousticLabel) {
  // A radio (a siren) that plays a voice: it sounds like a person.
  const auto s = test::scene({test::sounding(test::boxObject("radio", "siren", 0, 0, 0, 0.3, 0.2, 0.2), "playing",
                                             "person")});
  acoustic_percepts_t audio{};
  audio.tick = 7;
  audio.percepts = {acousticPercept("radio", 50, "person")};
  audio.num_percepts = 1;
  const auto result =
      acoustic_labels::labelAcoustically(s, geometryOf({{"radio", 10, 90}}), audio, model::Parameters{});
  ASSERT_EQ(result.labels.num_objects, 1);
  EXPECT_EQ(result.labels.modality, labels_t::MODALITY_ACOUSTIC);
  EXPECT_EQ(result.labels.tick, 7);
  // a_d(10) = 0.5, a_o(50) = 0.6, a_w(90) = exp(-0.5) with s = 8100: a_P = 0.3 e^-0.5.
  const double a_p = 0.3 * std::exp(-0.5);
  const auto& entry = result.labels.objects[0];
  EXPECT_NEAR(entry.perceptibility, a_p, 1e-12);
  const double spread = 0.5 / (1 + std::exp(-20 * (a_p - 0.5)));
  EXPECT_NEAR(confidenceOf(entry, "person"), 0.5 + spread, 1e-12);
  EXPECT_NEAR(confidenceOf(entry, "siren"), 0.5 - spread, 1e-12);
}

TEST(AcousticLabeller, EqualsTheModelLibraryAndHonoursTheAzimuthVariance) {
  const auto s = test::scene({test::sounding(test::cylinderObject("v", "person", 0, 0, 0.3, 1.8), "yelling")});
  model::Parameters literal;
  model::setParameter(literal, "aw_variance_deg2", "90");
  for (const auto& parameters : {model::Parameters{}, literal}) {
    for (double alpha : {-170.0, -30.0, 0.0, 45.0, 180.0}) {
      acoustic_percepts_t audio{};
      audio.percepts = {acousticPercept("v", 25, "")};  // no label in AUDIO: falls back to GT
      audio.num_percepts = 1;
      const auto result = acoustic_labels::labelAcoustically(s, geometryOf({{"v", 6, alpha}}), audio, parameters);
      ASSERT_EQ(result.labels.num_objects, 1);
      const double a_p = model::acousticPerceptibility(6, 25, alpha, parameters);
      EXPECT_DOUBLE_EQ(result.labels.objects[0].perceptibility, a_p);
      EXPECT_EQ(result.labels.objects[0].confidence, model::labelConfidences(s.categories, "person", a_p, parameters));
    }
  }
  // The paper's printed s = 90 makes a_w(30 deg) tiny.
  EXPECT_NEAR(model::acousticPerceptibility(6, 0, 30, literal) / model::acousticPerceptibility(6, 0, 0, literal),
              std::exp(-5.0), 1e-12);
}

// A labeller used tick after tick writes over its earlier entries: each tick
// must give what labelling that tick alone gives, whether the lists grow or
// shrink, percepts lack geometry, or ids repeat (the last one counts).
TEST(Labellers, ReusedTickAfterTickEqualLabellingEachTickAlone) {
  std::mt19937 random(3);
  std::vector<scene_object_t> objects;
  for (int i = 0; i < 40; ++i) {
    scene_object_t o = test::sounding(test::boxObject("o" + std::to_string(i), i % 3 ? "person" : "car", i, 0, 0, 1, 1, 1),
                                      "yelling", i % 4 == 0 ? "" : (i % 2 ? "person" : "siren"));
    objects.push_back(o);
  }
  const auto s = test::scene(objects);
  acoustic_labels::AcousticLabeller acoustic;
  visual_labels::VisualLabeller visual;
  std::uniform_int_distribution<int> count(0, 45), pick(0, 44), pixels(-1, 3);
  std::uniform_real_distribution<double> value(0, 100);
  const auto bytes = [](const labels_t& labels) {
    std::vector<uint8_t> out(labels.getEncodedSize());
    labels.encode(out.data(), 0, static_cast<int>(out.size()));
    return out;
  };
  for (int tick = 0; tick < 60; ++tick) {
    std::vector<std::tuple<std::string, double, double>> rows;
    for (int n = count(random); n > 0; --n) rows.emplace_back("o" + std::to_string(pick(random)), value(random) / 5, value(random));
    const geometry_percepts_t geometry = geometryOf(rows);  // ids o40.. are in no scene; some repeat
    acoustic_percepts_t audio{};
    visual_percepts_t vision{};
    audio.tick = vision.tick = tick;
    for (int n = count(random); n > 0; --n) {
      audio.percepts.push_back(acousticPercept("o" + std::to_string(pick(random)), value(random), ""));
      if (n % 3 == 0) audio.percepts.back().acoustic_label = "person";
      visual_percept_t v = visualPercept("o" + std::to_string(pick(random)), value(random));
      v.visible_pixels = pixels(random);
      vision.percepts.push_back(v);
    }
    audio.num_percepts = static_cast<int32_t>(audio.percepts.size());
    vision.num_percepts = static_cast<int32_t>(vision.percepts.size());
    const auto& reused_acoustic = acoustic.label(s, geometry, audio, model::Parameters{});
    const auto alone_acoustic = acoustic_labels::labelAcoustically(s, geometry, audio, model::Parameters{});
    EXPECT_EQ(bytes(reused_acoustic.labels), bytes(alone_acoustic.labels)) << "tick " << tick;
    EXPECT_EQ(reused_acoustic.labels.objects.size(), alone_acoustic.labels.objects.size()) << "tick " << tick;
    EXPECT_EQ(reused_acoustic.skipped, alone_acoustic.skipped) << "tick " << tick;
    const auto& reused_visual = visual.label(s, geometry, vision, model::Parameters{});
    const auto alone_visual = visual_labels::labelVisually(s, geometry, vision, model::Parameters{});
    EXPECT_EQ(bytes(reused_visual.labels), bytes(alone_visual.labels)) << "tick " << tick;
    EXPECT_EQ(reused_visual.labels.objects.size(), alone_visual.labels.objects.size()) << "tick " << tick;
    EXPECT_EQ(reused_visual.skipped, alone_visual.skipped) << "tick " << tick;
  }
}
