// Vision expert logic, part 1: visual occlusion O_v from instance images.
#include <gtest/gtest.h>

#include "lib/camera/camera_messages.hpp"
#include "lib/scene/ray_caster.hpp"
#include "tests/experts/support/scene_builders.hpp"
#include "lib/scene/scene_geometry.hpp"
#include "experts/vision/visual_occlusion.hpp"

using namespace beft;

namespace {

camera_frame_t instanceFrame(int width, int height, const std::vector<std::string>& ids,
                             const std::vector<uint16_t>& values) {
  camera_frame_t f{};
  f.encoding = camera_frame_t::ENCODING_INSTANCE16;
  f.width = width;
  f.height = height;
  f.instance_ids = ids;
  f.num_ids = static_cast<int32_t>(ids.size());
  for (uint16_t v : values) {
    f.data.push_back(static_cast<uint8_t>(v & 0xff));
    f.data.push_back(static_cast<uint8_t>(v >> 8));
  }
  f.data_size = static_cast<int32_t>(f.data.size());
  return f;
}

const visual_percept_t* find(const visual_percepts_t& out, const std::string& id) {
  for (const auto& p : out.percepts)
    if (p.object_id == id) return &p;
  return nullptr;
}

}  // namespace

TEST(VisualOcclusion, CountsPixelsOfATinyInstanceImageThroughItsIds) {
  const auto s = test::scene({test::cylinderObject("victim", "person", 5, 5, 0.3, 1.8),
                              test::boxObject("wall", "wall", 4, 5, 0, 0.2, 3, 2)});
  // 4 x 2 image listing the ids in another order than the scene: 1 = wall, 2 = victim.
  const auto frame = instanceFrame(4, 2, {"wall", "victim"}, {0, 2, 2, 1,  //
                                                              0, 2, 1, 0});
  const std::vector<int> visible = vision::countVisiblePixels(frame, s);
  ASSERT_EQ(visible.size(), 2u);
  EXPECT_EQ(visible[0], 3);  // victim
  EXPECT_EQ(visible[1], 2);  // wall
}

TEST(VisualOcclusion, HalfVisibleIsFiftyPercentAndOutOfViewHasNoEntry) {
  auto s = test::scene({test::cylinderObject("victim", "person", 5, 5, 0.3, 1.8),
                        test::boxObject("wall", "wall", 4, 5, 0, 0.2, 3, 2), test::pointObject("radio", "siren", 1, 1),
                        test::boxObject("car", "car", 20, 5, 0, 4, 2, 1.5)});
  const auto out = vision::estimateVisualOcclusion(s, {3, 2, 0, 0}, {6, 2, 0, 0});
  ASSERT_EQ(out.num_percepts, 2);
  EXPECT_EQ(find(out, "radio"), nullptr);  // no visual
  EXPECT_DOUBLE_EQ(find(out, "victim")->occlusion, 50.0);
  EXPECT_EQ(find(out, "victim")->visible_pixels, 3);
  EXPECT_EQ(find(out, "victim")->expected_pixels, 6);
  EXPECT_DOUBLE_EQ(find(out, "wall")->occlusion, 0.0);
  EXPECT_EQ(find(out, "car"), nullptr);  // expected 0: out of view, O_v 100 by its absence
  // In view but hidden: kept, at 100.
  const auto hidden = vision::estimateVisualOcclusion(s, {3, 2, 0, 0}, {6, 2, 0, 5});
  ASSERT_NE(find(hidden, "car"), nullptr);
  EXPECT_DOUBLE_EQ(find(hidden, "car")->occlusion, 100.0);
}

TEST(VisualOcclusion, RefusesMalformedFrames) {
  const auto s = test::scene({test::cylinderObject("victim", "person", 5, 5, 0.3, 1.8)});
  auto wrong_size = instanceFrame(4, 2, {"victim"}, {0, 1, 1});
  EXPECT_THROW(vision::countVisiblePixels(wrong_size, s), std::invalid_argument);
  auto wrong_value = instanceFrame(2, 1, {"victim"}, {0, 7});
  EXPECT_THROW(vision::countVisiblePixels(wrong_value, s), std::invalid_argument);
  auto wrong_encoding = instanceFrame(2, 1, {"victim"}, {0, 1});
  wrong_encoding.encoding = camera_frame_t::ENCODING_DEPTH_MM16;
  EXPECT_THROW(vision::countVisiblePixels(wrong_encoding, s), std::invalid_argument);
  // Ids the scene does not know are ignored, not counted for anyone.
  const auto unknown = instanceFrame(2, 1, {"ghost"}, {1, 1});
  EXPECT_EQ(vision::countVisiblePixels(unknown, s), std::vector<int>{0});
}

TEST(VisualOcclusion, PersonHalfBehindABoxInARenderedFrame) {
  // Camera at (0, 5) looking along +x; a person 10 m ahead; a box covering
  // exactly the left half (y > 5) of the line of sight, taller than the view
  // of the person.
  const auto s = test::scene({test::cylinderObject("victim", "person", 10, 5, 0.5, 1.8),
                              test::boxObject("box", "car", 5, 6, 0, 0.5, 2, 2.5)});
  const auto solids = camera::SceneGeometry::fromMessage(s);
  camera::Camera cam;
  cam.pose = {0, 5, 1.6, 0, 0};
  const auto rendered = camera::renderFrame(solids, cam);
  camera::CameraMessages messages;
  camera::encodeCameraMessages(rendered, s.utime, s.tick, {"victim", "box"}, messages);
  const auto expected = camera::expectedPixelsPerObject(solids, camera::cameraOfFrame(messages.instance));
  const auto out =
      vision::estimateVisualOcclusion(s, vision::countVisiblePixels(messages.instance, s), expected);
  const auto* victim = find(out, "victim");
  ASSERT_NE(victim, nullptr);
  EXPECT_GT(victim->expected_pixels, 100);
  EXPECT_NEAR(victim->occlusion, 50.0, 3.0);
  EXPECT_DOUBLE_EQ(find(out, "box")->occlusion, 0.0);

  // Without the box: fully visible.
  const auto alone = test::scene({test::cylinderObject("victim", "person", 10, 5, 0.5, 1.8)});
  const auto alone_solids = camera::SceneGeometry::fromMessage(alone);
  camera::encodeCameraMessages(camera::renderFrame(alone_solids, cam), 0, 0, {"victim"}, messages);
  const auto clear = vision::estimateVisualOcclusion(
      alone, vision::countVisiblePixels(messages.instance, alone),
      camera::expectedPixelsPerObject(alone_solids, camera::cameraOfFrame(messages.instance)));
  EXPECT_DOUBLE_EQ(find(clear, "victim")->occlusion, 0.0);
}

// spec/model.md: the part of an object outside the field of view counts as
// occluded. A person whose axis lies on the image's left border (45 degrees
// off the axis of a 90 degree camera) is half out of view.
TEST(VisualOcclusion, AnObjectAcrossTheImageBorderIsPartlyOccluded) {
  const auto s = test::scene({test::cylinderObject("edge", "person", 10, 15, 0.5, 1.8),
                              test::cylinderObject("inside", "person", 10, 5, 0.5, 1.8),
                              test::cylinderObject("outside", "person", 5, 15, 0.5, 1.8)});
  const auto solids = camera::SceneGeometry::fromMessage(s);
  camera::Camera cam;
  cam.pose = {0, 5, 1.6, 0, 0};
  camera::CameraMessages messages;
  camera::encodeCameraMessages(camera::renderFrame(solids, cam), 0, 0, {"edge", "inside", "outside"}, messages);
  const auto out = vision::estimateVisualOcclusion(
      s, vision::countVisiblePixels(messages.instance, s),
      camera::expectedPixelsPerObject(solids, camera::withoutViewLimits(camera::cameraOfFrame(messages.instance))));
  const auto* edge = find(out, "edge");
  ASSERT_NE(edge, nullptr);
  EXPECT_GT(edge->visible_pixels, 0);
  EXPECT_NEAR(edge->occlusion, 50.0, 8.0) << edge->visible_pixels << " of " << edge->expected_pixels;
  EXPECT_DOUBLE_EQ(find(out, "inside")->occlusion, 0.0);
  // Wholly out of view: counted in the wider view, seen nowhere.
  EXPECT_GT(find(out, "outside")->expected_pixels, 0);
  EXPECT_DOUBLE_EQ(find(out, "outside")->occlusion, 100.0);
  // Counted within the image only (as before), the edge person would pass as unoccluded.
  const auto clipped = vision::estimateVisualOcclusion(
      s, vision::countVisiblePixels(messages.instance, s),
      camera::expectedPixelsPerObject(solids, camera::cameraOfFrame(messages.instance)));
  EXPECT_LT(find(clipped, "edge")->occlusion, 1.0);
}

TEST(VisualOcclusion, TheWiderViewKeepsEveryPixelRayOfTheImage) {
  camera::Camera cam;
  cam.pose = {1, 2, 1.6, 30, -5};
  const camera::Camera wide = camera::withoutViewLimits(cam);
  EXPECT_EQ(wide.intrinsics.width, 3 * cam.intrinsics.width);
  EXPECT_EQ(wide.intrinsics.height, 3 * cam.intrinsics.height);
  // Pixel (u, v) of the image is pixel (u + w, v + h) of the wider one: the same ray.
  for (const auto& [u, v] : {std::pair{0, 0}, {17, 93}, {159, 119}}) {
    const Eigen::Vector3d a = camera::pixelRay(cam, u, v);
    const Eigen::Vector3d b = camera::pixelRay(wide, u + cam.intrinsics.width, v + cam.intrinsics.height);
    EXPECT_LT((a.normalized() - b.normalized()).norm(), 1e-12) << u << ", " << v;
  }
}

