// The room against physics: image sources of a shoebox where Allen and
// Berkley put them, each arriving within a sample of its geometric path; a
// tail whose Schroeder T60 is the one asked for (and Sabine's and
// Eyring's for a closed shoebox of known absorption), with the KEMAR's
// diffuse-field coherence and after the early part; a source behind a wall
// heard through a reflection; blocks the same however they are cut.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "lib/hearing/binaural_cues.hpp"
#include "lib/hearing/binaural_renderer.hpp"
#include "lib/hearing/fft_convolver.hpp"
#include "lib/hearing/late_reverb.hpp"
#include "lib/hearing/room_model.hpp"
#include "tests/lib/hearing/hearing_test_support.hpp"

using namespace beft::hearing;
using namespace beft::hearing::test;

#define REQUIRE_KEMAR()                                                                                \
  if (!kemarInstalled())                                                                               \
  GTEST_SKIP() << HrirSet::kKemarPath << " is missing (Debian package " << HrirSet::kKemarPackage << ")"

namespace {

constexpr double kRate = 44100;
constexpr double kC = BinauralRenderer::kSpeedOfSound;
constexpr double kLx = 8, kLy = 6, kLz = 3;  // the shoebox's inside [m]

// A closed shoebox [0, 8] x [0, 6] x [0, 3]: four walls and a ceiling 0.2 m
// thick, the ground the floor.
std::vector<ReflectingBox> shoebox(double absorption) {
  const double t = 0.2;
  std::vector<ReflectingBox> boxes = {
      {-t / 2, kLy / 2, 0, t, kLy + 2 * t, 0, kLz + t, absorption, 1},
      {kLx + t / 2, kLy / 2, 0, t, kLy + 2 * t, 0, kLz + t, absorption, 2},
      {kLx / 2, -t / 2, 0, kLx + 2 * t, t, 0, kLz + t, absorption, 3},
      {kLx / 2, kLy + t / 2, 0, kLx + 2 * t, t, 0, kLz + t, absorption, 4},
      {kLx / 2, kLy / 2, 0, kLx + 2 * t, kLy + 2 * t, kLz, kLz + t, absorption, 5},
  };
  return boxes;
}

// A head of one direction's worth: both ears a unit impulse at tap 4 from
// every direction, so a rendered response shows arrival times alone.
HrirSet omniHead() {
  const int length = 16, directions = 360;
  std::vector<float> responses(static_cast<std::size_t>(2 * directions * length), 0.0f);
  for (int d = 0; d < 2 * directions; ++d) responses[static_cast<std::size_t>(d * length + 4)] = 1.0f;
  return HrirSet("omni", kRate, length, directions, responses, 4.0);
}

// A unit impulse at t = 0, then silence for `seconds`.
SourceSignal impulse(double seconds) {
  SourceSignal s;
  s.samples.assign(static_cast<std::size_t>(seconds * kRate), 0.0f);
  s.samples[0] = 1.0f;
  return s;
}

// The shoebox's images up to order 2 by Allen and Berkley's lattice: along
// each axis of length L a coordinate x has the images -x, 2L - x (one
// reflection) and x - 2L, x + 2L (two).
std::vector<std::pair<Eigen::Vector3d, int>> latticeImages(const Eigen::Vector3d& s) {
  const double lengths[3] = {kLx, kLy, kLz};
  std::vector<std::pair<double, int>> per_axis[3];
  for (int a = 0; a < 3; ++a) {
    const double x = s[a], l = lengths[a];
    per_axis[a] = {{x, 0}, {-x, 1}, {2 * l - x, 1}, {x - 2 * l, 2}, {x + 2 * l, 2}};
  }
  std::vector<std::pair<Eigen::Vector3d, int>> images;
  for (const auto& [x, nx] : per_axis[0])
    for (const auto& [y, ny] : per_axis[1])
      for (const auto& [z, nz] : per_axis[2])
        if (nx + ny + nz >= 1 && nx + ny + nz <= 2) images.push_back({Eigen::Vector3d(x, y, z), nx + ny + nz});
  return images;
}

std::vector<double> sortedPaths(const std::vector<std::pair<Eigen::Vector3d, int>>& images,
                                const Eigen::Vector3d& listener, int order) {
  std::vector<double> paths;
  for (const auto& [image, n] : images)
    if (n == order) paths.push_back((image - listener).norm());
  std::sort(paths.begin(), paths.end());
  return paths;
}

const Eigen::Vector3d kSource(2, 3.3, 1.5), kListener(5.2, 2, 1.2);

RoomSettings settingsOf(int order, double t60, double absorption = 0.2) {
  RoomSettings settings;
  settings.reflection_order = order;
  settings.ground = true;
  settings.ground_absorption = absorption;
  settings.t60_s = t60;
  settings.volume_m3 = kLx * kLy * kLz;
  return settings;
}

// The room's response alone (no direct sound) to an impulse at kSource,
// heard at kListener facing +x, `seconds` long.
StereoBlock roomResponse(const BinauralRenderer& renderer, const RoomModel& room, const SourceSignal& click,
                         double seconds, const Eigen::Vector3d& source = kSource,
                         const Eigen::Vector3d& listener = kListener) {
  BlockRequest request;
  request.first_sample = 0;
  request.num_samples = static_cast<int>(seconds * kRate);
  request.noise_rms = 0;
  request.previous.centre = request.current.centre = listener;
  request.sources.push_back({&click, source, 1.0, 0.0});
  request.room = &room;
  request.direct_sound = false;
  return renderer.render(request);
}

}  // namespace

TEST(RoomImageSources, AShoeboxGivesAllenAndBerkleysImages) {
  const HrirSet head = omniHead();
  const RoomModel room(shoebox(0.2), settingsOf(2, 0), head, kRate);
  const std::vector<ImageSource> found = room.imageSources(kSource, -1, kListener);
  const auto lattice = latticeImages(kSource);
  for (int order : {1, 2}) {
    std::vector<double> paths;
    for (const ImageSource& image : found)
      if (image.order == order) paths.push_back(image.path_m);
    std::sort(paths.begin(), paths.end());
    const std::vector<double> expected = sortedPaths(lattice, kListener, order);
    ASSERT_EQ(paths.size(), expected.size()) << "order " << order;  // 6 and 18
    for (std::size_t i = 0; i < paths.size(); ++i) EXPECT_NEAR(paths[i], expected[i], 1e-9) << "order " << order;
  }
  for (const ImageSource& image : found) {
    EXPECT_NEAR(image.path_m, (image.position - kListener).norm(), 1e-12);
    EXPECT_NEAR(image.amplitude, std::pow(std::sqrt(0.8), image.order), 1e-12);
  }
}

TEST(RoomImageSources, EachArrivesWithinOneSampleOfItsPath) {
  const HrirSet head = omniHead();
  const BinauralRenderer renderer(head, kRate);
  const RoomModel room(shoebox(0.2), settingsOf(2, 0), head, kRate);
  const SourceSignal click = impulse(2.0);
  const StereoBlock response = roomResponse(renderer, room, click, 0.12);
  std::vector<double> arrivals;  // [samples]
  for (const auto& [image, n] : latticeImages(kSource)) arrivals.push_back((image - kListener).norm() / kC * kRate);
  std::sort(arrivals.begin(), arrivals.end());
  int isolated = 0;
  for (std::size_t i = 0; i < arrivals.size(); ++i) {
    const bool alone = (i == 0 || arrivals[i] - arrivals[i - 1] > 4) &&
                       (i + 1 == arrivals.size() || arrivals[i + 1] - arrivals[i] > 4);
    if (!alone) continue;
    ++isolated;
    // The largest sample near the arrival, refined by a parabola through it and its neighbours.
    const int centre = static_cast<int>(std::lround(arrivals[i]));
    int peak = centre;
    for (int n = centre - 3; n <= centre + 3; ++n)
      if (response.left[static_cast<std::size_t>(n)] > response.left[static_cast<std::size_t>(peak)]) peak = n;
    const double a = response.left[static_cast<std::size_t>(peak - 1)], b = response.left[static_cast<std::size_t>(peak)],
                 c = response.left[static_cast<std::size_t>(peak + 1)];
    const double refined = peak + 0.5 * (a - c) / (a - 2 * b + c);
    EXPECT_NEAR(refined, arrivals[i], 1.0) << "arrival " << i;
    EXPECT_EQ(response.left[static_cast<std::size_t>(peak)], response.right[static_cast<std::size_t>(peak)]);
  }
  EXPECT_GE(isolated, 10);
  // Nothing before the first reflection.
  const float loudest = *std::max_element(response.left.begin(), response.left.end());
  for (int n = 0; n < static_cast<int>(arrivals[0]) - 4; ++n)
    ASSERT_LT(std::abs(response.left[static_cast<std::size_t>(n)]), 1e-5f * loudest) << n;
}

TEST(RoomImageSources, ASourceBehindAWallIsHeardThroughTheSideWall) {
  const HrirSet head = omniHead();
  const BinauralRenderer renderer(head, kRate);
  const Eigen::Vector3d listener(2, 5, 1.6), source(8, 5, 1.0);
  ReflectingBox wall{5, 5, 0, 0.2, 4, 0, 2.5, 0.2, 1};     // between them, y 3..7
  ReflectingBox side{5, 9.1, 0, 12, 0.2, 0, 3, 0.2, 2};    // a wall along y = 9
  RoomSettings settings = settingsOf(1, 0);
  const RoomModel without_side({wall}, settings, head, kRate);
  const RoomModel with_side({wall, side}, settings, head, kRate);
  // The ground's reflection passes through the wall; the side wall's goes round it.
  EXPECT_TRUE(without_side.imageSources(source, -1, listener).empty());
  const std::vector<ImageSource> heard = with_side.imageSources(source, -1, listener);
  ASSERT_EQ(heard.size(), 1u);
  const Eigen::Vector3d image(8, 13, 1.0);  // mirrored in y = 9
  EXPECT_NEAR((heard[0].position - image).norm(), 0, 1e-9);
  EXPECT_NEAR(heard[0].path_m, (image - listener).norm(), 1e-9);

  const SourceSignal click = impulse(2.0);
  const StereoBlock silent = roomResponse(renderer, without_side, click, 0.1, source, listener);
  for (float s : silent.left) ASSERT_EQ(s, 0.0f);
  const StereoBlock through = roomResponse(renderer, with_side, click, 0.1, source, listener);
  const int arrival = static_cast<int>(std::lround(heard[0].path_m / kC * kRate));
  const float expected = static_cast<float>(std::sqrt(0.8) / heard[0].path_m);
  float sum = 0;  // the fractional delay's taps sum to one
  for (int n = arrival - 4; n <= arrival + 4; ++n) sum += through.left[static_cast<std::size_t>(n)];
  EXPECT_NEAR(sum, expected, 0.01 * expected);
  EXPECT_NEAR(std::max_element(through.left.begin(), through.left.end()) - through.left.begin(), arrival, 1);

  // Through the KEMAR, it comes from the left, where the side wall is.
  if (!kemarInstalled()) return;
  const StereoBlock ears = roomResponse(kemarRenderer(), with_side, whiteNoise(2.0, 3), 0.2, source, listener);
  EXPECT_GT(rms(ears.left), 1.5 * rms(ears.right));
}

TEST(RoomTail, SchroedersT60IsTheOneAskedFor) {
  REQUIRE_KEMAR();
  const SourceSignal click = impulse(4.0);
  for (double t60 : {0.3, 0.6, 0.9}) {
    SCOPED_TRACE(t60);
    RoomSettings settings = settingsOf(0, t60);
    settings.ground = false;
    const RoomModel room({}, settings, kemar(), kRate);
    const StereoBlock response = roomResponse(kemarRenderer(), room, click, t60 + 0.2);
    EXPECT_NEAR(schroederT60(response.left, response.right, kRate), t60, 0.1 * t60);
    EXPECT_NEAR(schroederT60(response.left, kRate), t60, 0.1 * t60);
  }
}

TEST(RoomTail, AClosedShoeboxDecaysAsSabineAndEyringPredict) {
  REQUIRE_KEMAR();
  const double volume = kLx * kLy * kLz, surface = 2 * (kLx * kLy + kLx * kLz + kLy * kLz);
  const double absorption = 0.2;
  const double sabine = sabineT60(volume, surface, absorption), eyring = eyringT60(volume, surface, absorption);
  EXPECT_NEAR(sabine, 0.644, 0.001);
  EXPECT_NEAR(eyring, 0.577, 0.001);
  const SourceSignal click = impulse(4.0);
  for (double t60 : {sabine, eyring}) {
    const RoomModel room(shoebox(absorption), settingsOf(2, t60, absorption), kemar(), kRate);
    EXPECT_NEAR(room.meanAbsorption(), absorption, 1e-12);
    // Early reflections and tail together, as the ears hear them.
    const StereoBlock response = roomResponse(kemarRenderer(), room, click, t60 + 0.2);
    EXPECT_NEAR(schroederT60(response.left, response.right, kRate), t60, 0.1 * t60);
  }
}

TEST(RoomTail, StartsAfterTheEarlyPartWithTheDiffuseFieldsCoherence) {
  REQUIRE_KEMAR();
  RoomSettings settings = settingsOf(0, 0.6);
  settings.ground = false;
  const RoomModel room({}, settings, kemar(), kRate);
  const SourceSignal click = impulse(4.0);
  const StereoBlock response = roomResponse(kemarRenderer(), room, click, 0.8);
  const double direct = (kSource - kListener).norm() / kC * kRate;
  const int onset = static_cast<int>(direct + room.tail()->onset() * kRate);
  const float peak = *std::max_element(response.left.begin(), response.left.end());
  for (int n = 0; n < onset - 1; ++n) ASSERT_LT(std::abs(response.left[static_cast<std::size_t>(n)]), 1e-5f * peak) << n;
  EXPECT_NEAR(room.tail()->onset(), 1e-3 * std::sqrt(kLx * kLy * kLz), 1e-9);  // Polack's sqrt(V) ms

  // Coherence per band of the tail's two responses (one transform of each
  // whole response) against the KEMAR's diffuse field.
  const LateReverb& tail = *room.tail();
  const int size = 1024;
  const DiffuseField field = diffuseField(kemar(), size);
  const RealFft whole(fastFftSize(tail.length()));
  std::vector<std::complex<float>> sl, sr;
  whole.forward(tail.left(), sl);
  whole.forward(tail.right(), sr);
  const int ratio = whole.size() / size;
  std::vector<std::complex<double>> cross(static_cast<std::size_t>(size / 2 + 1));
  std::vector<double> pl(cross.size()), pr(cross.size());
  for (std::size_t k = 0; k < sl.size(); ++k) {
    const std::size_t bin = std::min(cross.size() - 1, static_cast<std::size_t>(std::lround(static_cast<double>(k) / ratio)));
    cross[bin] += std::complex<double>(sl[k]) * std::conj(std::complex<double>(sr[k]));
    pl[bin] += std::norm(std::complex<double>(sl[k]));
    pr[bin] += std::norm(std::complex<double>(sr[k]));
  }
  int bands = 0;
  for (double low : {100.0, 200.0, 400.0, 800.0, 1600.0, 3200.0}) {
    const int k0 = static_cast<int>(low * size / kRate), k1 = static_cast<int>(2 * low * size / kRate);
    std::complex<double> c = 0;
    double el = 0, er = 0, target = 0, weights = 0;
    for (int k = k0; k < k1; ++k) {
      const auto i = static_cast<std::size_t>(k);
      c += cross[i];
      el += pl[i];
      er += pr[i];
      const double weight = std::sqrt(field.power_left[i] * field.power_right[i]);  // as the cross-power weighs it
      target += weight * field.coherence[i];
      weights += weight;
    }
    target /= weights;
    EXPECT_NEAR(c.real() / std::sqrt(el * er), target, 0.15) << low << " Hz";
    ++bands;
  }
  EXPECT_EQ(bands, 6);
  // A diffuse field at a head is coherent at low frequencies and not at high ones.
  EXPECT_GT(field.coherence[static_cast<std::size_t>(150 * size / kRate)], 0.7);
  EXPECT_LT(std::abs(field.coherence[static_cast<std::size_t>(4000 * size / kRate)]), 0.3);
}

TEST(RoomBlocks, BlockByBlockEqualsOneLongRendering) {
  REQUIRE_KEMAR();
  const RoomModel room(shoebox(0.2), settingsOf(2, 0.3), kemar(), kRate);
  const SourceSignal noise = whiteNoise(2.0, 11);
  BlockRequest request;
  request.noise_rms = 0;
  request.previous.centre = request.current.centre = kListener;
  request.sources.push_back({&noise, kSource, 1.0, 0.0});
  request.room = &room;
  request.first_sample = 44100;
  request.num_samples = 8820;
  const StereoBlock whole = kemarRenderer().render(request);
  request.num_samples = 4410;
  const StereoBlock first = kemarRenderer().render(request);
  request.first_sample += 4410;
  const StereoBlock second = kemarRenderer().render(request);
  for (int n = 0; n < 4410; ++n) {
    ASSERT_NEAR(whole.left[static_cast<std::size_t>(n)], first.left[static_cast<std::size_t>(n)], 1e-5);
    ASSERT_NEAR(whole.right[static_cast<std::size_t>(4410 + n)], second.right[static_cast<std::size_t>(n)], 1e-5);
  }
}

TEST(RoomBlocks, WithoutARoomTheBlockIsBitIdenticalToTheFreeField) {
  REQUIRE_KEMAR();
  const SourceSignal noise = whiteNoise(2.0, 12);
  BlockRequest request = staticScene(noise, 40, 3.0, 44100, 4410, 0.3);
  request.previous.yaw_deg = -5;  // a turning head
  const StereoBlock free_field = kemarRenderer().render(request);
  // A room with nothing in it and no tail adds exactly nothing.
  RoomSettings settings = settingsOf(2, 0);
  settings.ground = false;
  const RoomModel empty({}, settings, kemar(), kRate);
  request.room = &empty;
  const StereoBlock in_empty_room = kemarRenderer().render(request);
  EXPECT_EQ(free_field.left, in_empty_room.left);
  EXPECT_EQ(free_field.right, in_empty_room.right);
}

TEST(RoomModel, RefusesWhatItCannotModel) {
  const HrirSet head = omniHead();
  RoomSettings settings;
  settings.reflection_order = 5;
  EXPECT_THROW(RoomModel({}, settings, head, kRate), std::invalid_argument);
  settings.reflection_order = 1;
  settings.t60_s = 11;
  EXPECT_THROW(RoomModel({}, settings, head, kRate), std::invalid_argument);
  settings.t60_s = 0;
  EXPECT_THROW(RoomModel({{0, 0, 0, 1, 1, 0, 1, 1.5, -1}}, settings, head, kRate), std::invalid_argument);
  EXPECT_THROW(RoomModel({{0, 0, 0, 0, 1, 0, 1, 0.5, -1}}, settings, head, kRate), std::invalid_argument);
}
