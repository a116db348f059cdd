#include "tools/generate/district_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

namespace beft::generate {

namespace {

constexpr double kStreet = 6.0;          // street width between blocks [m]
constexpr double kMinBlock = 14.0;       // smallest block edge [m]
constexpr double kWallThickness = 0.2;   // [m]
constexpr double kPassage = 1.4;         // free gap kept between placed things [m]
constexpr double kCarWidth = 1.8, kCarLength = 4.2;

// A portable generator (splitmix64): the same seed gives the same district
// with any standard library.
std::string metres(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%g", value);
  return buffer;
}

class Random {
 public:
  explicit Random(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform(double low, double high) { return low + (high - low) * (next() >> 11) * 0x1.0p-53; }
  int below(int n) { return static_cast<int>(next() % static_cast<uint64_t>(n)); }
  bool chance(double p) { return uniform(0, 1) < p; }

 private:
  uint64_t state_;
};

struct Rect {
  double x0, y0, x1, y1;
  bool overlaps(const Rect& other, double gap) const {
    return x0 < other.x1 + gap && other.x0 < x1 + gap && y0 < other.y1 + gap && other.y0 < y1 + gap;
  }
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

Rect boxAround(double x, double y, double size_x, double size_y) {
  return {x - size_x / 2, y - size_y / 2, x + size_x / 2, y + size_y / 2};
}

const uint32_t kPersonColors[] = {0xd04040, 0x3060d0, 0xc07020, 0x8040a0, 0x20a0a0};
const uint32_t kCarColors[] = {0x2a6f3a, 0x2a3f8f, 0xa02020, 0xc0c0c0, 0x404040};

class DistrictBuilder {
 public:
  DistrictBuilder(const DistrictParameters& parameters, int attempt)
      : random_(parameters.seed * 1000003ULL + static_cast<uint64_t>(attempt)) {
    district_.parameters = parameters;
  }

  District build() {
    const DistrictParameters& p = district_.parameters;
    const int columns = static_cast<int>(std::floor((p.width - kStreet) / (kMinBlock + kStreet)));
    const int rows = static_cast<int>(std::floor((p.height - kStreet) / (kMinBlock + kStreet)));
    if (columns < 1 || rows < 1) {
      throw std::invalid_argument("a district needs at least " + metres(2 * kStreet + kMinBlock) +
                                  " m in each direction for one block between streets");
    }
    const double block_w = (p.width - kStreet * (columns + 1)) / columns;
    const double block_h = (p.height - kStreet * (rows + 1)) / rows;
    for (int row = 0; row < rows; ++row) {
      for (int col = 0; col < columns; ++col) {
        const double x0 = kStreet + col * (block_w + kStreet), y0 = kStreet + row * (block_h + kStreet);
        blocks_.push_back({x0, y0, x0 + block_w, y0 + block_h});
      }
    }
    district_.robot_x = kStreet / 2;
    district_.robot_y = kStreet / 2;
    district_.robot_yaw = 45;
    district_.duration = std::max(300.0, std::round(p.width * p.height * 0.2));
    // The robot's start stays clear.
    occupied_.push_back(boxAround(district_.robot_x, district_.robot_y, 2.0, 2.0));

    // Buildings first, up to two per block and about 60 % of the objects.
    const int building_budget = static_cast<int>(0.6 * p.objects);
    for (int round = 0; round < 2; ++round) {
      for (std::size_t b = 0; b < blocks_.size(); ++b) {
        if (placedCount() + 4 > building_budget) break;
        if (random_.chance(0.85)) placeBuilding(b, round);
      }
    }
    // Then the open air until the count is reached.
    int failures = 0;
    while (placedCount() < p.objects) {
      if (!placeOutside()) {
        if (++failures > 200 * p.objects) {
          throw std::invalid_argument(std::to_string(p.objects) + " objects do not fit in " +
                                      metres(p.width) + " x " + metres(p.height) +
                                      " m (placed " + std::to_string(placedCount()) + ")");
        }
      }
    }
    std::sort(district_.events.begin(), district_.events.end(),
              [](const PlacedEvent& a, const PlacedEvent& b) { return a.t < b.t; });
    return district_;
  }

 private:
  int placedCount() const { return static_cast<int>(district_.objects.size()); }

  bool isFree(const Rect& rect, double gap) const {
    for (const Rect& other : occupied_) {
      if (rect.overlaps(other, gap)) return false;
    }
    return true;
  }

  PlacedObject& add(PlacedObject object, const Rect& footprint) {
    occupied_.push_back(footprint);
    district_.objects.push_back(std::move(object));
    return district_.objects.back();
  }

  PlacedObject box(const std::string& id, const std::string& label, double x, double y, double sx,
                   double sy, double sz, uint32_t color) {
    PlacedObject object;
    object.id = id;
    object.label = label;
    object.x = x;
    object.y = y;
    object.size_x = sx;
    object.size_y = sy;
    object.size_z = sz;
    object.color = color;
    return object;
  }

  PlacedSound sound(const std::string& file, double level, const std::string& label = "") {
    return PlacedSound{district_.parameters.sounds_dir + "/" + file, true, level, label};
  }

  std::string nextId(const std::string& kind) { return kind + std::to_string(++counters_[kind]); }

  // A ruined house: three walls, the fourth side (towards the nearest street)
  // open; one thing inside. The house and the way from its open side to the
  // street are kept clear of anything else.
  void placeBuilding(std::size_t block_index, int round) {
    const Rect& block = blocks_[block_index];
    const bool split_x = block.width() >= block.height();
    Rect half = block;
    if (split_x) {
      (round == 0 ? half.x1 : half.x0) = (block.x0 + block.x1) / 2;
    } else {
      (round == 0 ? half.y1 : half.y0) = (block.y0 + block.y1) / 2;
    }
    const double w = random_.uniform(5.5, std::min(9.0, half.width() - 2.0));
    const double h = random_.uniform(5.0, std::min(8.0, half.height() - 2.0));
    if (w < 5.5 || h < 5.0) return;
    const double x0 = random_.uniform(half.x0 + 1.0, half.x1 - 1.0 - w);
    const double y0 = random_.uniform(half.y0 + 1.0, half.y1 - 1.0 - h);
    const Rect house{x0, y0, x0 + w, y0 + h};
    // Open towards the nearest edge of the block (0 west, 1 east, 2 south, 3 north).
    const double distances[4] = {house.x0 - block.x0, block.x1 - house.x1, house.y0 - block.y0,
                                 block.y1 - house.y1};
    const int open_side = static_cast<int>(std::min_element(distances, distances + 4) - distances);
    Rect approach = house;
    if (open_side == 0) approach = {block.x0 - 0.5, house.y0, house.x0, house.y1};
    if (open_side == 1) approach = {house.x1, house.y0, block.x1 + 0.5, house.y1};
    if (open_side == 2) approach = {house.x0, block.y0 - 0.5, house.x1, house.y0};
    if (open_side == 3) approach = {house.x0, house.y1, house.x1, block.y1 + 0.5};
    if (!isFree(house, kPassage) || !isFree(approach, kPassage)) return;

    const std::string name = "house" + std::to_string(++district_.buildings);
    const double wall_height = random_.uniform(1.2, 2.8);  // ruined: some can be seen over
    const uint32_t wall_color = 0x808080 + 0x0a0a0a * static_cast<uint32_t>(random_.below(4));
    const double t = kWallThickness;
    const char* side_names[4] = {"_wall_west", "_wall_east", "_wall_south", "_wall_north"};
    for (int side = 0; side < 4; ++side) {
      if (side == open_side) continue;
      const bool vertical = side < 2;
      const double x = side == 0 ? house.x0 + t / 2 : side == 1 ? house.x1 - t / 2 : (house.x0 + house.x1) / 2;
      const double y = side == 2 ? house.y0 + t / 2 : side == 3 ? house.y1 - t / 2 : (house.y0 + house.y1) / 2;
      PlacedObject wall = box(name + side_names[side], "wall", x, y, vertical ? t : w, vertical ? h : t,
                              wall_height, wall_color);
      district_.objects.push_back(wall);
    }
    occupied_.push_back(house);
    occupied_.push_back(approach);

    // One thing inside, away from the walls.
    const double cx = random_.uniform(house.x0 + 2.0, house.x1 - 2.0);
    const double cy = random_.uniform(house.y0 + 2.0, house.y1 - 2.0);
    const double roll = random_.uniform(0, 1);
    if (roll < 0.2) {
      addPerson(name + "_person", cx, cy, true);
    } else if (roll < 0.42) {
      addPerson(name + "_person", cx, cy, false);
    } else if (roll < 0.56) {
      addRadio(name + "_radio", cx, cy);
    } else {
      district_.objects.push_back(rubble(name + "_rubble", cx, cy));
    }
  }

  void addPerson(const std::string& id, double x, double y, bool calling) {
    PlacedObject person;
    const bool lying = random_.chance(0.4);
    if (lying) {
      person = box(id, "person", x, y, 1.8, 0.6, 0.4, kPersonColors[random_.below(5)]);
      person.yaw = random_.chance(0.5) ? 0 : 90;
    } else {
      person = box(id, "person", x, y, 0, 0, 0, kPersonColors[random_.below(5)]);
      person.cylinder = true;
      person.radius = 0.3;
      person.height = 1.8;
    }
    ++district_.persons;
    if (calling) {
      ++district_.calling_persons;
      person.activity = "yelling";
      person.sound = sound("help.wav", 1.0);
      // Some start calling only later.
      if (random_.chance(0.3)) {
        person.sound->active = false;
        person.activity = "idle";
        const double t = std::round(random_.uniform(20, district_.duration / 3));
        district_.events.push_back({t, id, "yelling", true});
      }
    }
    district_.objects.push_back(person);
  }

  void addRadio(const std::string& id, double x, double y) {
    PlacedObject radio = box(id, "siren", x, y, 0.5, 0.3, 0.35, 0x303030);
    radio.activity = "talking";
    radio.sound = sound("voice_radio.wav", 1.0, "person");
    ++district_.radios;
    district_.objects.push_back(radio);
  }

  PlacedObject rubble(const std::string& id, double x, double y) {
    PlacedObject object = box(id, "wall", x, y, random_.uniform(0.6, 1.6), random_.uniform(0.5, 1.2),
                              random_.uniform(0.3, 0.9), 0x6b5b4b + 0x080808 * static_cast<uint32_t>(random_.below(3)));
    return object;
  }

  // One thing in the open: in a block, or a car parked along a street.
  bool placeOutside() {
    const double roll = random_.uniform(0, 1);
    if (roll < 0.22) return placeCar();
    const Rect& block = blocks_[random_.below(static_cast<int>(blocks_.size()))];
    const double x = random_.uniform(block.x0 + 0.8, block.x1 - 0.8);
    const double y = random_.uniform(block.y0 + 0.8, block.y1 - 0.8);
    if (roll < 0.62) {
      PlacedObject object = rubble("", x, y);
      const Rect footprint = boxAround(x, y, object.size_x, object.size_y);
      if (!isFree(footprint, kPassage)) return false;
      object.id = nextId("rubble");
      add(object, footprint);
      return true;
    }
    if (roll < 0.72) {  // a fire, some of which spread later
      const Rect footprint = boxAround(x, y, 1.0, 1.0);
      if (!isFree(footprint, kPassage + 1.0)) return false;
      const std::string id = nextId("fire");
      PlacedObject fire = box(id, "fire", x, y, 0, 0, 0, 0xff6a00);
      fire.cylinder = true;
      fire.radius = 0.5;
      fire.height = 1.0;
      fire.activity = "burning";
      fire.sound = sound("fire.wav", 1.0);
      if (random_.chance(0.3)) {
        district_.events.push_back({std::round(random_.uniform(30, district_.duration / 2)), id, "spreading", {}});
      }
      add(fire, footprint);
      return true;
    }
    if (roll < 0.8) {  // a siren on a mast: two objects; the mast's foot covers the siren's footprint (no overhang to drive into)
      if (placedCount() + 2 > district_.parameters.objects) return false;
      const Rect footprint = boxAround(x, y, 0.4, 0.4);
      if (!isFree(footprint, kPassage)) return false;
      const std::string id = nextId("siren");
      PlacedObject siren = box(id, "siren", x, y, 0.3, 0.3, 0.3, 0xe0c020);
      siren.z = 1.8;
      siren.activity = "ringing";
      siren.sound = sound("siren.wav", 1.0);
      PlacedObject pole = box(id + "_pole", "wall", x, y, 0, 0, 0, 0x505050);
      pole.cylinder = true;
      pole.radius = 0.22;  // >= the siren's half diagonal (0.21 m)
      pole.height = 1.8;
      add(siren, footprint);
      district_.objects.push_back(pole);
      return true;
    }
    const Rect footprint = boxAround(x, y, 1.8, 1.8);
    if (!isFree(footprint, kPassage)) return false;
    if (roll < 0.96) {
      occupied_.push_back(footprint);
      addPerson(nextId("person"), x, y, roll < 0.84);
    } else {
      occupied_.push_back(footprint);
      addRadio(nextId("radio"), x, y);
    }
    return true;
  }

  // Cars park along the south side of a street running east-west, or the
  // west side of one running north-south, leaving 4 m of the street free.
  bool placeCar() {
    const Rect& block = blocks_[random_.below(static_cast<int>(blocks_.size()))];
    PlacedObject car;
    Rect footprint{};
    if (random_.chance(0.5)) {  // in the street north of the block
      const double x = random_.uniform(block.x0 + kCarLength / 2, block.x1 - kCarLength / 2);
      const double y = block.y1 + 0.2 + kCarWidth / 2;
      car = box("", "car", x, y, kCarLength, kCarWidth, 1.5, kCarColors[random_.below(5)]);
      footprint = boxAround(x, y, kCarLength, kCarWidth);
    } else {  // in the street east of the block
      const double x = block.x1 + 0.2 + kCarWidth / 2;
      const double y = random_.uniform(block.y0 + kCarLength / 2, block.y1 - kCarLength / 2);
      car = box("", "car", x, y, kCarLength, kCarWidth, 1.5, kCarColors[random_.below(5)]);
      car.yaw = 90;
      footprint = boxAround(x, y, kCarWidth, kCarLength);
    }
    if (!isFree(footprint, kPassage)) return false;
    car.id = nextId("car");
    if (random_.chance(0.4)) car.sound = sound("engine.wav", 0.5);
    add(car, footprint);
    return true;
  }

  Random random_;
  District district_;
  std::vector<Rect> blocks_, occupied_;
  std::map<std::string, int> counters_;
};

}  // namespace

District layDistrict(const DistrictParameters& parameters, int attempt) {
  if (!(parameters.width > 0) || !(parameters.height > 0)) throw std::invalid_argument("the size must be positive");
  if (parameters.objects < 1) throw std::invalid_argument("--objects must be at least 1");
  return DistrictBuilder(parameters, attempt).build();
}

}  // namespace beft::generate
