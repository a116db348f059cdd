// The RGBD camera: geometry of single rays and frames, occlusion, field of
// view, the three render methods agreeing, and the frame messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "lib/camera/camera_messages.hpp"
#include "lib/scene/camera_model.hpp"
#include "lib/scene/ray_caster.hpp"
#include "lib/scene/row_workers.hpp"
#include "lib/scene/scene_geometry.hpp"
#include "lib/scene/scene_solids.hpp"

using namespace beft::camera;

namespace {

Camera levelCamera(double x, double y, double z, double yaw_deg, double pitch_deg = 0) {
  Camera camera;
  camera.pose = {x, y, z, yaw_deg, pitch_deg};
  camera.intrinsics = {90.0, 160, 120, 20.0};
  return camera;
}

int countPixelsOf(const RenderedFrame& frame, int object) {
  int count = 0;
  for (int32_t value : frame.object) count += value == object;
  return count;
}

}  // namespace

TEST(Camera, BoxStraightAheadGivesItsDistanceAtTheCentrePixel) {
  SceneGeometry scene;
  // Front face at x = 5.0: the box spans x in [5, 6], centred on the optical axis.
  scene.addBox(0, 5.5, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 0xff0000);
  scene.buildIndex();
  const Camera camera = levelCamera(0, 0, 1.5, 0);
  const RenderedFrame frame = renderFrame(scene, camera);
  const int centre = 60 * 160 + 80;
  EXPECT_NEAR(frame.depth[centre], 5.0, 1e-6);
  EXPECT_EQ(frame.object[centre], 0);

  CameraMessages messages;
  encodeCameraMessages(frame, 1000, 7, {"crate"}, messages);
  EXPECT_NEAR(depthAt(messages.depth, 80, 60), 5.0, 1e-9);
  EXPECT_EQ(instanceAt(messages.instance, 80, 60), 0);
  EXPECT_EQ(messages.instance.instance_ids.at(0), "crate");
  // A flat face square to the axis has the same z-depth at every pixel on it.
  EXPECT_NEAR(depthAt(messages.depth, 70, 55), 5.0, 1e-9);
}

TEST(Camera, YawedCameraAndRotatedBoxGiveTheExpectedDepth) {
  SceneGeometry scene;
  // A cube rotated 45 degrees: its nearest edge points at the camera.
  scene.addBox(0, 0.0, 10.0, 0.0, 45.0, 2.0, 2.0, 4.0);
  scene.buildIndex();
  const Camera camera = levelCamera(0, 0, 1.0, 90);  // looking along +y
  const RenderedFrame frame = renderFrame(scene, camera);
  // The edge is at depth 10 - sqrt(2). The centre pixel's ray runs half a
  // pixel to the right (x = delta * t), meeting the face x + (10 - y) = sqrt(2)
  // at t = (10 - sqrt(2)) / (1 - delta).
  const double delta = 0.5 / focalLengthPx(90, 160);
  EXPECT_NEAR(frame.depth[60 * 160 + 80], (10.0 - std::sqrt(2.0)) / (1.0 - delta), 1e-5);
}

TEST(Camera, ObjectBehindAnotherIsAbsentFromTheInstanceImage) {
  SceneGeometry scene;
  scene.addBox(0, 4.0, 0.0, 0.0, 0.0, 0.4, 4.0, 3.0);  // a wall in front
  scene.addCylinder(1, 8.0, 0.0, 0.0, 0.3, 1.8);       // a person behind it
  scene.buildIndex();
  const Camera camera = levelCamera(0, 0, 1.5, 0);
  const RenderedFrame frame = renderFrame(scene, camera);
  EXPECT_GT(countPixelsOf(frame, 0), 0);
  EXPECT_EQ(countPixelsOf(frame, 1), 0);
  // Without the wall it would be seen: the occlusion denominator says so.
  const std::vector<int> expected = expectedPixelsPerObject(scene, camera);
  ASSERT_EQ(expected.size(), 2u);
  EXPECT_EQ(expected[0], countPixelsOf(frame, 0));
  EXPECT_GT(expected[1], 50);

  // Move the person out from behind the wall: now visible, and every pixel
  // the unoccluded count promises is rendered.
  SceneGeometry moved;
  moved.addBox(0, 4.0, 0.0, 0.0, 0.0, 0.4, 4.0, 3.0);
  moved.addCylinder(1, 8.0, 5.0, 0.0, 0.3, 1.8);
  moved.buildIndex();
  const RenderedFrame moved_frame = renderFrame(moved, camera);
  EXPECT_EQ(countPixelsOf(moved_frame, 1), expectedPixelsPerObject(moved, camera)[1]);
  EXPECT_GT(countPixelsOf(moved_frame, 1), 0);
}

TEST(Camera, ObjectOutsideTheFieldOfViewIsAbsent) {
  SceneGeometry scene;
  scene.addCylinder(0, 5.0, 5.0 * std::tan(50 * M_PI / 180), 0.0, 0.3, 1.8);  // 50 deg left, fov 90
  scene.addCylinder(1, -5.0, 0.0, 0.0, 0.3, 1.8);                             // behind
  scene.addCylinder(2, 5.0, 5.0 * std::tan(30 * M_PI / 180), 0.0, 0.3, 1.8);  // 30 deg left: in view
  scene.addCylinder(3, 25.0, 0.0, 0.0, 0.3, 1.8);                             // beyond the 20 m range
  scene.buildIndex();
  const Camera camera = levelCamera(0, 0, 1.5, 0);
  const RenderedFrame frame = renderFrame(scene, camera);
  EXPECT_EQ(countPixelsOf(frame, 0), 0);
  EXPECT_EQ(countPixelsOf(frame, 1), 0);
  EXPECT_GT(countPixelsOf(frame, 2), 0);
  EXPECT_EQ(countPixelsOf(frame, 3), 0);
  const std::vector<int> expected = expectedPixelsPerObject(scene, camera);
  EXPECT_EQ(expected[0], 0);
  EXPECT_EQ(expected[1], 0);
  EXPECT_EQ(expected[3], 0);
  // Turned 50 degrees left, object 0 is straight ahead.
  const RenderedFrame turned = renderFrame(scene, levelCamera(0, 0, 1.5, 50));
  EXPECT_EQ(turned.object[60 * 160 + 80], 0);
}

// The unoccluded count of a solid alone is every pixel the renderer gives it,
// whatever the solid's size, pose, distance and place in the image: the
// count follows each row's run from its ends, the renderer tests every ray.
TEST(Camera, ExpectedPixelsOfASolidAloneAreItsRenderedPixels) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto between = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  int seen = 0, cut_by_the_edge = 0;
  for (int trial = 0; trial < 600; ++trial) {
    // Near (filling the view) to far, in front or to the side; some raised.
    const double distance = trial % 4 == 0 ? between(0.4, 2.0) : between(1.0, 18.0);
    const double bearing = between(-70.0, 70.0) * M_PI / 180.0;
    const double x = distance * std::cos(bearing), y = distance * std::sin(bearing);
    const double z = trial % 5 == 0 ? between(0.2, 1.5) : 0.0;
    SceneGeometry scene;
    if (trial % 3 == 0)
      scene.addCylinder(0, x, y, z, between(0.05, 1.5), between(0.1, 3.0));
    else
      scene.addBox(0, x, y, z, between(0.0, 360.0), between(0.05, 4.0), between(0.05, 4.0), between(0.05, 3.0));
    scene.buildIndex();
    const Camera camera = levelCamera(0, 0, between(0.3, 2.0), between(-20.0, 20.0), between(-35.0, 35.0));
    const RenderedFrame frame = renderFrame(scene, camera);
    const int rendered = countPixelsOf(frame, 0);
    ASSERT_EQ(expectedPixelsPerObject(scene, camera).at(0), rendered) << "trial " << trial;
    seen += rendered > 0;
    bool on_edge = false;
    for (int v = 0; v < 120 && !on_edge; ++v)
      on_edge = frame.object[v * 160] == 0 || frame.object[v * 160 + 159] == 0;
    cut_by_the_edge += on_edge;
  }
  // The trials cover solids in view and solids the image edge cuts.
  EXPECT_GT(seen, 300);
  EXPECT_GT(cut_by_the_edge, 60);
}

// Counted by two threads claiming solids from one counter: summed, the
// counts of one thread counting all.
TEST(Camera, ExpectedPixelsCountedByTwoThreadsSumToOnesCounts) {
  SceneGeometry scene;
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> along(1.0, 12.0), across(-8.0, 8.0);
  for (int i = 0; i < 120; ++i) {
    if (i % 2) scene.addCylinder(i, along(rng), across(rng), 0.0, 0.2 + 0.01 * (i % 30), 0.5 + 0.02 * (i % 50));
    else scene.addBox(i, along(rng), across(rng), 0.0, 0.3 * i, 0.4 + 0.01 * (i % 40), 0.2 + 0.02 * (i % 20), 1.2);
  }
  scene.buildIndex();
  const Camera real = levelCamera(0, 0, 1.5, 10);
  RayCaster alone;
  const std::vector<int> expected = alone.expectedPixelsInView(scene, real);
  for (int round = 0; round < 20; ++round) {
    RayCaster shared;
    shared.prepareExpectedInView(real);
    std::atomic<size_t> next_solid{0};
    std::vector<int> first, second;
    std::thread helper([&] { shared.countExpected(scene, next_solid, first); });
    shared.countExpected(scene, next_solid, second);
    helper.join();
    ASSERT_EQ(first.size(), expected.size());
    ASSERT_EQ(second.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) ASSERT_EQ(first[i] + second[i], expected[i]) << "object " << i;
  }
  EXPECT_GT(std::count_if(expected.begin(), expected.end(), [](int n) { return n > 0; }), 20);
}

// On the widened camera, restricted to the real image's pixels: an object
// the real image cannot show (50 deg left, behind) gets 0; one in view, or
// across the image's edge, keeps the whole count of the widened plane.
TEST(Camera, TheWidenedCountSkipsOnlyWhatTheRealImageCannotShow) {
  SceneGeometry scene;
  scene.addCylinder(0, 5.0, 5.0 * std::tan(50 * M_PI / 180), 0.0, 0.3, 1.8);  // 50 deg left, fov 90
  scene.addCylinder(1, -5.0, 0.0, 0.0, 0.3, 1.8);                             // behind
  scene.addCylinder(2, 5.0, 5.0 * std::tan(30 * M_PI / 180), 0.0, 0.3, 1.8);  // 30 deg left: in view
  scene.addCylinder(3, 5.0, 5.0 * std::tan(45 * M_PI / 180), 0.0, 0.3, 1.8);  // across the left edge
  scene.buildIndex();
  const Camera real = levelCamera(0, 0, 1.5, 0);
  const Camera wide = withoutViewLimits(real);
  RayCaster caster;
  const std::vector<int> all = caster.expectedPixelsPerObject(scene, wide);
  RayCaster::PixelRect image{160, 120, 319, 239};
  const std::vector<int> touching = caster.expectedPixelsPerObject(scene, wide, &image);
  EXPECT_GT(all[0], 0);
  EXPECT_EQ(touching[0], 0);
  EXPECT_EQ(touching[1], 0);
  EXPECT_GT(all[2], 0);
  EXPECT_EQ(touching[2], all[2]);
  EXPECT_GT(all[3], 0);
  EXPECT_EQ(touching[3], all[3]);
}

TEST(Camera, GroundGivesDepthButNoObjectAndSkyGivesNothing) {
  SceneGeometry scene;
  scene.buildIndex();
  // Pitched 20 degrees down from 1.6 m: the optical axis meets the ground at
  // depth 1.6 / sin(20 deg). The centre pixel is half a pixel below the axis.
  const Camera camera = levelCamera(3, 3, 1.6, 30, -20);
  const RenderedFrame frame = renderFrame(scene, camera);
  const CameraFrame axes(camera);
  const Eigen::Vector3d ray = pixelRay(axes, 80, 60);
  EXPECT_NEAR(frame.depth[60 * 160 + 80], -1.6 / ray.z(), 1e-5);
  // That ray points atan(0.5 / f) further down than the axis; its ground point
  // is 1.6 / sin(elevation) away along it, and depth is that times cos(offset).
  const double offset = std::atan(0.5 / focalLengthPx(90, 160));
  const double elevation = 20 * M_PI / 180 + offset;
  EXPECT_NEAR(frame.depth[60 * 160 + 80], 1.6 / std::sin(elevation) * std::cos(offset), 1e-5);
  EXPECT_EQ(frame.object[60 * 160 + 80], -1);
  EXPECT_EQ(frame.depth[0], 0.0f);  // top-left corner: sky
  EXPECT_EQ(frame.object[0], -1);
  // The sky is bluer than the ground.
  EXPECT_GT(frame.rgb[2], frame.rgb[0]);
}

TEST(Camera, BackProjectionInvertsTheRenderer) {
  const Camera camera = levelCamera(2.0, -1.0, 1.4, 123.0, 7.5);
  for (const auto& [u, v] : std::vector<std::pair<int, int>>{{0, 0}, {80, 60}, {159, 119}, {17, 101}}) {
    const Eigen::Vector3d point = backProject(camera, u, v, 6.25);
    const auto image = projectPoint(camera, point);
    ASSERT_TRUE(image.has_value());
    EXPECT_NEAR(image->x, u + 0.5, 1e-9);
    EXPECT_NEAR(image->y, v + 0.5, 1e-9);
    EXPECT_NEAR(image->depth, 6.25, 1e-9);
  }
  // Row 0 is the top: its rays point higher than the bottom row's.
  EXPECT_GT(pixelRay(camera, 80, 0).z(), pixelRay(camera, 80, 119).z());
  // Column 0 is the left: with yaw 0, left is +y.
  EXPECT_GT(pixelRay(levelCamera(0, 0, 1, 0), 0, 60).y(), 0);
}

// Random cylinders and boxes (some raised) over a 30 m yard, and random views of it.
struct RandomYard {
  std::mt19937 random;
  std::uniform_real_distribution<double> position{0.0, 30.0}, size{0.2, 3.0}, angle{0.0, 360.0};
  SceneGeometry scene;

  RandomYard(unsigned seed, int objects) : random(seed) {
    for (int i = 0; i < objects; ++i) {
      if (i % 3 == 0) {
        scene.addCylinder(i, position(random), position(random), 0.0, 0.5 * size(random), 2 * size(random));
      } else {
        scene.addBox(i, position(random), position(random), i % 7 == 0 ? 1.0 : 0.0, angle(random), size(random),
                     size(random), size(random));
      }
    }
    scene.buildIndex();
  }
  Camera view(double pitch_deg) {
    const double x = position(random), y = position(random);
    return levelCamera(x, y, 1.6, angle(random), pitch_deg);
  }
};

namespace {

// The same objects, depths and colours in every pixel.
void expectSameImage(const RenderedFrame& actual, const RenderedFrame& expected, const std::string& what) {
  EXPECT_EQ(actual.object, expected.object) << what;
  EXPECT_EQ(actual.depth, expected.depth) << what;
  EXPECT_EQ(actual.rgb, expected.rgb) << what;
}

}  // namespace

TEST(Camera, RenderMethodsGiveIdenticalImages) {
  RandomYard yard(42, 120);
  const SceneGeometry& scene = yard.scene;
  RayCaster caster;
  for (int view = 0; view < 6; ++view) {
    const Camera camera = yard.view(view * 5.0 - 12.0);
    RenderedFrame projection, grid, brute;
    caster.render(scene, camera, projection, RenderMethod::Projection);
    caster.render(scene, camera, grid, RenderMethod::GridTraversal);
    caster.render(scene, camera, brute, RenderMethod::BruteForce);
    expectSameImage(projection, brute, "projection, view " + std::to_string(view));
    expectSameImage(grid, brute, "grid, view " + std::to_string(view));
    // Rendered pixels never exceed the unoccluded count.
    const std::vector<int> expected = caster.expectedPixelsPerObject(scene, camera);
    for (int object = 0; object < scene.objectCount(); ++object) {
      EXPECT_LE(countPixelsOf(brute, object), expected[object]) << "object " << object;
    }
  }
}

TEST(Camera, ThreadCountDoesNotChangeTheImage) {
  RandomYard yard(7, 60);
  const SceneGeometry& scene = yard.scene;
  RayCaster one, two, three;
  two.setThreads(2);
  three.setThreads(3);
  EXPECT_EQ(one.threads(), 1);
  EXPECT_EQ(two.threads(), 2);
  for (int view = 0; view < 8; ++view) {
    Camera camera = yard.view(view * 4.0 - 14.0);
    if (view == 7) camera.intrinsics.height = 5;  // fewer rows than a band each would need: one thread
    RenderedFrame a, b, c, brute;
    one.render(scene, camera, a);
    two.render(scene, camera, b);
    three.render(scene, camera, c);
    one.render(scene, camera, brute, RenderMethod::BruteForce);
    expectSameImage(b, a, "two threads, view " + std::to_string(view));
    expectSameImage(c, a, "three threads, view " + std::to_string(view));
    expectSameImage(b, brute, "two threads against brute force, view " + std::to_string(view));
  }
}

TEST(SceneGeometry, SegmentsAreBlockedBySolidsTheyCross) {
  SceneGeometry scene;
  scene.setObjectCount(3);
  scene.addBox(0, 5.0, 0.0, 0.0, 90.0, 4.0, 0.2, 2.5);  // a wall across the x axis
  scene.addCylinder(2, 10.0, 3.0, 0.0, 0.3, 1.8);
  scene.buildIndex();
  const Eigen::Vector3d ear(0, 0, 1.6), source(8, 0, 1.0), high_source(8, 0, 4.0);
  EXPECT_TRUE(segmentBlocked(scene, ear, source));
  EXPECT_EQ(segmentHitsObject(scene, ear, source), 0);
  EXPECT_FALSE(segmentBlocked(scene, ear, source, 0));  // ignoring the wall
  // Over the wall: at x = 5 the segment to (8, 0, 4) is at z = 3.06 > 2.5.
  EXPECT_FALSE(segmentBlocked(scene, Eigen::Vector3d(0, 0, 2.6), high_source));
  // Past the end of the wall (it spans y in [-2, 2]).
  EXPECT_FALSE(segmentBlocked(scene, Eigen::Vector3d(0, 3, 1), Eigen::Vector3d(8, 3, 1)));
  // Through the person, unless it is the source itself.
  const Eigen::Vector3d person_centre(10, 3, 1);
  EXPECT_EQ(segmentHitsObject(scene, Eigen::Vector3d(12, 3, 1), Eigen::Vector3d(8, 3, 1)), 2);
  EXPECT_FALSE(segmentBlocked(scene, person_centre, Eigen::Vector3d(14, 3, 1.6), 2));
  // Object 1 has no solid; it never blocks.
  EXPECT_EQ(scene.solidOfObject(1), -1);
}

TEST(SceneGeometry, GridTraversalAgreesWithBruteForceForRandomRays) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> position(-5.0, 45.0), unit(-1.0, 1.0), size(0.1, 2.0);
  SceneGeometry scene;
  for (int i = 0; i < 300; ++i) scene.addBox(i, position(random), position(random), 0, 37.0 * i, size(random), size(random), size(random));
  scene.buildIndex(1.3);
  int hits = 0;
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector3d o(position(random), position(random), 1.0 + unit(random));
    const Eigen::Vector3d d(unit(random), unit(random), 0.2 * unit(random));
    const auto a = scene.firstHit(o, d, 0.0, 40.0);
    const auto b = scene.firstHitBruteForce(o, d, 0.0, 40.0);
    ASSERT_EQ(a.solid, b.solid) << "ray " << i;
    if (a.solid >= 0) {
      EXPECT_EQ(a.t, b.t);
      ++hits;
    }
  }
  EXPECT_GT(hits, 1000);
}

TEST(CameraMessages, FramesFitInOneUdpDatagramAndValidate) {
  SceneGeometry scene;
  scene.addBox(0, 5.5, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0);
  scene.buildIndex();
  const RenderedFrame frame = renderFrame(scene, levelCamera(0, 0, 1.5, 0));
  CameraMessages messages;
  std::vector<std::string> ids;
  for (int i = 0; i < 100; ++i) ids.push_back("object_" + std::to_string(i));
  encodeCameraMessages(frame, 0, 0, ids, messages);
  for (const beft::camera_frame_t* message : {&messages.color, &messages.depth, &messages.instance}) {
    std::string why;
    EXPECT_TRUE(validCameraFrame(*message, &why)) << why;
    EXPECT_LT(message->getEncodedSize(), 64 * 1024);
  }
  beft::camera_frame_t broken = messages.depth;
  broken.data.pop_back();
  std::string why;
  EXPECT_FALSE(validCameraFrame(broken, &why));
  EXPECT_NE(why.find("data_size"), std::string::npos);
}

TEST(CameraMessages, RenderingStraightIntoMessagesGivesTheEncodedFrame) {
  RandomYard yard(11, 60);
  std::vector<std::string> ids;
  for (int i = 0; i < 40; ++i) ids.push_back("object_" + std::to_string(i));  // objects 40.. have no id: instance 0
  RayCaster one, two;
  two.setThreads(2);
  int with_objects = 0;
  for (int view = 0; view < 6; ++view) {
    const Camera camera = yard.view(view * 4.0 - 10.0);
    RenderedFrame frame;
    one.render(yard.scene, camera, frame);
    CameraMessages encoded, direct, direct_two;
    encodeCameraMessages(frame, 5000, 3, ids, encoded);
    renderCameraMessages(one, yard.scene, camera, 5000, 3, ids, direct);
    renderCameraMessages(two, yard.scene, camera, 5000, 3, ids, direct_two);
    for (const CameraMessages* m : {&direct, &direct_two}) {
      const auto bytes = [](const beft::camera_frame_t& f) {
        std::vector<uint8_t> out(f.getEncodedSize());
        f.encode(out.data(), 0, static_cast<int>(out.size()));
        return out;
      };
      EXPECT_EQ(bytes(m->color), bytes(encoded.color)) << "view " << view;
      EXPECT_EQ(bytes(m->depth), bytes(encoded.depth)) << "view " << view;
      EXPECT_EQ(bytes(m->instance), bytes(encoded.instance)) << "view " << view;
    }
    for (int v = 0; v < frame.height; v += 7)
      for (int u = 0; u < frame.width; u += 7) with_objects += instanceAt(direct.instance, u, v) >= 0;
  }
  EXPECT_GT(with_objects, 0) << "no view saw an object with an id";
}

// The instance frame lists only the objects it shows, in the ground truth's
// order, and every pixel still names the object the renderer put there.
TEST(CameraMessages, InstanceFrameListsExactlyTheObjectsItShows) {
  RandomYard yard(5, 120);
  std::vector<std::string> ids;
  for (int i = 0; i < 100; ++i) ids.push_back("object_" + std::to_string(i));  // objects 100.. have no id
  RayCaster caster;
  int views_with_objects = 0;
  for (int view = 0; view < 12; ++view) {
    RenderedFrame frame;
    caster.render(yard.scene, yard.view(view * 3.0 - 15.0), frame);
    CameraMessages messages;
    encodeCameraMessages(frame, 0, view, ids, messages);
    std::string why;
    ASSERT_TRUE(validCameraFrame(messages.instance, &why)) << why;
    std::set<std::string> shown;
    for (int v = 0; v < frame.height; ++v)
      for (int u = 0; u < frame.width; ++u) {
        const int object = frame.object[static_cast<size_t>(v) * frame.width + u];
        const int listed = instanceAt(messages.instance, u, v);
        if (object < 0 || object >= static_cast<int>(ids.size())) {
          EXPECT_EQ(listed, -1) << "view " << view << " pixel " << u << "," << v;
          continue;
        }
        ASSERT_GE(listed, 0) << "view " << view << " pixel " << u << "," << v;
        ASSERT_LT(listed, messages.instance.num_ids);
        EXPECT_EQ(messages.instance.instance_ids[listed], ids[object]) << "view " << view;
        shown.insert(ids[object]);
      }
    // Nothing listed that no pixel shows, and in the ground truth's order.
    EXPECT_EQ(std::set<std::string>(messages.instance.instance_ids.begin(), messages.instance.instance_ids.end()),
              shown)
        << "view " << view;
    std::vector<int> order;
    for (const auto& id : messages.instance.instance_ids) order.push_back(std::stoi(id.substr(7)));
    EXPECT_TRUE(std::is_sorted(order.begin(), order.end())) << "view " << view;
    views_with_objects += !shown.empty();
  }
  EXPECT_GE(views_with_objects, 6);
}

// The threads take short runs of rows as they come: every row is rendered
// once, whoever takes it, frame after frame, also by a helper that wakes late.
TEST(RowWorkers, EveryRowIsDoneExactlyOnceWhoeverTakesIt) {
  for (int threads : {2, 3}) {
    beft::camera::RowWorkers workers(threads);
    for (int frame = 0; frame < 200; ++frame) {
      const int rows = 5 + frame % 160;
      std::vector<std::atomic<int>> done(static_cast<std::size_t>(rows));
      std::set<std::thread::id> workers_seen;
      std::mutex seen_mutex;
      workers.run(rows, [&](int first, int end) {
        ASSERT_LE(0, first);
        ASSERT_LT(first, end);
        ASSERT_LE(end, rows);
        for (int row = first; row < end; ++row) done[static_cast<std::size_t>(row)]++;
        std::lock_guard<std::mutex> lock(seen_mutex);
        workers_seen.insert(std::this_thread::get_id());
      });
      for (int row = 0; row < rows; ++row)
        ASSERT_EQ(done[static_cast<std::size_t>(row)].load(), 1) << "row " << row << " of frame " << frame;
      ASSERT_LE(workers_seen.size(), static_cast<std::size_t>(threads));
    }
  }
}

// The kept solids are made again exactly when something they are made of
// changes, and then answer like solids made afresh from the message.
TEST(SceneSolids, RemadeOnlyWhenAnObjectsShapePoseOrColourChanges) {
  beft::scene_objects_t scene{};
  for (int i = 0; i < 30; ++i) {
    beft::scene_object_t o{};
    o.id = "o" + std::to_string(i);
    o.shape = i % 2 ? beft::scene_object_t::SHAPE_BOX : beft::scene_object_t::SHAPE_CYLINDER;
    o.x = 2.0 * i;
    o.y = 5.0 + (i % 5);
    o.size_x = o.size_y = 1.0;
    o.size_z = 2.0;
    o.radius = 0.5;
    scene.objects.push_back(o);
  }
  scene.num_objects = static_cast<int32_t>(scene.objects.size());
  SceneSolids kept;
  EXPECT_TRUE(kept.update(scene));
  beft::scene_objects_t next = scene;
  next.tick = 7;
  next.objects[3].label = "person";  // neither makes a solid
  next.objects[3].activity = "yelling";
  EXPECT_FALSE(kept.update(next));
  const auto changed = [&](auto change) {
    beft::scene_objects_t moved = scene;
    change(moved);
    const bool remade = kept.update(moved);
    // Rays along the row of objects, from both ends, meet what fresh solids meet.
    const SceneGeometry fresh = SceneGeometry::fromMessage(moved);
    for (double y = 4.0; y <= 10.0; y += 0.25)
      for (const double dx : {1.0, -1.0}) {
        const Eigen::Vector3d o(dx > 0 ? -5.0 : 70.0, y, 1.0), d(dx, 0.0, 0.0);
        const auto a = kept.solids().firstHit(o, d, 0, 100), b = fresh.firstHit(o, d, 0, 100);
        EXPECT_EQ(a.solid, b.solid);
        EXPECT_EQ(a.t, b.t);
      }
    kept.update(scene);
    return remade;
  };
  EXPECT_TRUE(changed([](beft::scene_objects_t& s) { s.objects[4].y += 0.5; }));
  EXPECT_TRUE(changed([](beft::scene_objects_t& s) { s.objects[5].radius = 0.9; }));
  EXPECT_TRUE(changed([](beft::scene_objects_t& s) { s.objects[6].size_z = 0.5; }));
  EXPECT_TRUE(changed([](beft::scene_objects_t& s) { s.objects[7].color_rgb = 0x00ff00; }));
  EXPECT_TRUE(changed([](beft::scene_objects_t& s) {
    s.objects.pop_back();
    s.num_objects -= 1;
  }));
  EXPECT_TRUE(changed([](beft::scene_objects_t& s) { std::swap(s.objects[0], s.objects[1]); }));
}
