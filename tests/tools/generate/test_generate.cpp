// The district generator: its files pass the contract, hold the objects
// asked for, have every person reachable, and the same arguments write the
// same bytes (the shipped districts are exactly what their command makes).
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include <gtest/gtest.h>

#include "tools/generate/district_layout.hpp"
#include "tools/generate/generate_district.hpp"
#include "lib/scenario/load_scenario.hpp"
#include "lib/scenario/reachability.hpp"
#include "lib/scenario/sight_lines.hpp"

namespace beft::generate {
namespace {

namespace fs = std::filesystem;

class GenerateTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("beft_generate_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  DistrictParameters parameters(double width, double height, int objects, uint64_t seed) const {
    DistrictParameters p;
    p.width = width;
    p.height = height;
    p.objects = objects;
    p.seed = seed;
    p.sounds_dir = fs::relative(fs::path(BEFT_SOURCE_DIR) / "scenarios" / "sounds", dir_).string();
    return p;
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

int countLabel(const scenario::Scenario& s, const std::string& label) {
  int n = 0;
  for (const auto& object : s.objects) n += object.label == label;
  return n;
}

TEST_F(GenerateTest, EverySeedPassesTheContractWithEveryPersonReachableAndEveryObjectSeen) {
  struct Size { double w, h; int objects; };
  const Size sizes[] = {{80, 60, 114}, {50, 40, 40}, {120, 45, 200}, {160, 120, 450}};
  int checked = 0;
  for (const Size& size : sizes) {
    const int seeds = size.objects > 300 ? 4 : 15;
    for (int seed = 1; seed <= seeds; ++seed) {
      SCOPED_TRACE(std::to_string(size.w) + "x" + std::to_string(size.h) + " seed " + std::to_string(seed));
      const std::string file = path("d.xml");
      generateDistrict(parameters(size.w, size.h, size.objects, seed), file, "test");
      const scenario::Scenario loaded = scenario::loadScenario(file);
      EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
      EXPECT_EQ(static_cast<int>(loaded.objects.size()), size.objects);
      EXPECT_GT(countLabel(loaded, "person"), 0);
      EXPECT_GT(countLabel(loaded, "wall"), 0);
      EXPECT_TRUE(scenario::unreachablePersons(loaded).empty());
      EXPECT_TRUE(scenario::unseeableObjects(loaded).empty());
      ++checked;
    }
  }
  EXPECT_EQ(checked, 3 * 15 + 4);
}

TEST_F(GenerateTest, TheSameArgumentsWriteTheSameBytesAndAnotherSeedAnotherDistrict) {
  generateDistrict(parameters(80, 60, 114, 5), path("d.xml"), "test");
  const std::string first = readFile(path("d.xml"));
  generateDistrict(parameters(80, 60, 114, 5), path("d.xml"), "test");
  const std::string again = readFile(path("d.xml"));
  generateDistrict(parameters(80, 60, 114, 6), path("d.xml"), "test");
  EXPECT_FALSE(first.empty());
  EXPECT_EQ(first, again);
  EXPECT_NE(first, readFile(path("d.xml")));
}

TEST_F(GenerateTest, TheShippedDistrictsAreWhatTheirCommandWrites) {
  struct Shipped { const char* name; double w, h; int objects; };
  for (const Shipped& shipped : {Shipped{"district_small", 80, 60, 114}, Shipped{"district_large", 160, 120, 450}}) {
    const std::string shipped_path = std::string(BEFT_SOURCE_DIR) + "/scenarios/" + shipped.name + ".xml";
    const std::string header = readFile(shipped_path);
    ASSERT_FALSE(header.empty()) << shipped_path;
    DistrictParameters p = parameters(shipped.w, shipped.h, shipped.objects, 1);
    p.sounds_dir = "sounds";
    const std::string how = std::string("./beft generate district, size ") + std::to_string(int(shipped.w)) + " " +
                            std::to_string(int(shipped.h)) + ", objects " + std::to_string(shipped.objects) +
                            ", seed 1";
    const District district = layDistrict(p);
    // Written into the scenarios folder's neighbour would need the sounds; compare the XML text instead.
    const std::string regenerated_path = path(std::string(shipped.name) + ".xml");
    fs::create_directories(dir_ / "sounds");
    for (const char* sound : {"help.wav", "voice_radio.wav", "siren.wav", "fire.wav", "engine.wav"}) {
      fs::copy_file(fs::path(BEFT_SOURCE_DIR) / "scenarios" / "sounds" / sound, dir_ / "sounds" / sound,
                    fs::copy_options::overwrite_existing);
    }
    const GeneratedScenario generated = generateDistrict(p, regenerated_path, how);
    EXPECT_EQ(readFile(regenerated_path), header) << shipped.name << " differs from what its command writes";
    EXPECT_EQ(generated.district.objects.size(), district.objects.size());
  }
}

TEST_F(GenerateTest, AWorldTooSmallOrTooFullIsRefusedWithTheReason) {
  try {
    layDistrict(parameters(20, 20, 10, 1));
    FAIL() << "a 20 x 20 m district was made";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("at least"), std::string::npos) << error.what();
  }
  try {
    layDistrict(parameters(30, 30, 5000, 1));
    FAIL() << "5000 objects were placed in 30 x 30 m";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("do not fit"), std::string::npos) << error.what();
  }
}

// The reachability check itself: a person walled in on four sides is
// unreachable; open one side wide enough for the footprint and it is not.
TEST(Reachability, AWalledInPersonIsUnreachableUntilAWideGapOpens) {
  scenario::Scenario s;
  s.world.width = 20;
  s.world.height = 20;
  s.robot.x = 2;
  s.robot.y = 2;
  auto wall = [](const std::string& id, double x, double y, double sx, double sy) {
    scenario::Object o;
    o.id = id;
    o.label = "wall";
    o.x = x;
    o.y = y;
    o.visual = scenario::Visual{};
    o.visual->size_x = sx;
    o.visual->size_y = sy;
    o.visual->size_z = 2;
    return o;
  };
  scenario::Object person;
  person.id = "p";
  person.label = "person";
  person.x = 12;
  person.y = 12;
  person.visual = scenario::Visual{scenario::Visual::Shape::Cylinder, 0, 0, 0, 0.3, 1.8};
  s.objects = {person, wall("s", 12, 9, 6.2, 0.2), wall("n", 12, 15, 6.2, 0.2), wall("w", 9, 12, 0.2, 6.2),
               wall("e", 15, 12, 0.2, 6.2)};
  EXPECT_EQ(scenario::unreachablePersons(s), std::vector<std::string>{"p"});
  // A 0.8 m gap is narrower than the footprint's 0.9 m: still unreachable.
  s.objects[2] = wall("n1", 10.25, 15, 2.7, 0.2);
  s.objects.push_back(wall("n2", 13.75, 15, 2.7, 0.2));
  EXPECT_EQ(scenario::unreachablePersons(s), std::vector<std::string>{"p"});
  // A 2 m gap lets it in.
  s.objects[2] = wall("n1", 9.95, 15, 2.1, 0.2);
  s.objects.back() = wall("n2", 14.05, 15, 2.1, 0.2);
  EXPECT_TRUE(scenario::unreachablePersons(s).empty());
}

}  // namespace
}  // namespace beft::generate
