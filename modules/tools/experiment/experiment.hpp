// What an experiment file declares: the scenes, the factors whose product
// makes the episodes, and the pairs of conditions to compare.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace beft::experiment {

// The factor names besides "scene"; a --set parameter's factor is "set:NAME".
inline const char* const kScene = "scene";
inline const char* const kSeed = "seed";

struct Generation {  // a scene made by beft-generate
  std::string kind;  // "district"
  int width = 0, height = 0, objects = 0;
  uint64_t seed = 0;
};

struct Scene {
  std::string name;                     // its value of the factor "scene"
  std::string file;                     // absolute; empty for a generated scene until generated
  std::optional<Generation> generation;
};

struct Factor {
  std::string name;                 // "seed", "planner", "acoustics", "net" or "set:NAME"
  std::vector<std::string> values;  // as written (a net's file relative to the experiment file)
};

// A paired comparison: the conditions with `factor` = a against those with = b,
// everything else equal, over the same scenes and seeds.
struct Comparison {
  std::string factor, a, b;
};

struct Experiment {
  std::string file;      // the experiment file
  std::string base_dir;  // its folder: relative paths inside are relative to it
  std::string name;
  long long max_ticks = -1;  // -1: each scenario's duration
  std::vector<Scene> scenes;
  std::vector<Factor> factors;  // besides the scene, in the order first declared
  std::vector<Comparison> comparisons;
  // <episode> elements: when there are any, the episodes are these (each
  // a value for the scene and every factor, in that order), not the product.
  std::vector<std::vector<std::pair<std::string, std::string>>> listed;
};

// One run of the experiment: a value for the scene and every factor.
struct Episode {
  std::string id;  // stable: made from the values, a folder name
  std::vector<std::pair<std::string, std::string>> values;  // scene first, then the factors in order
  const std::string* value(const std::string& factor) const;
  std::string condition() const;  // the values other than scene and seed ("planner-astar" ...; "all" if none)
  std::string pairing() const;    // the scene and seed, what paired comparisons match on
};

class ExperimentError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace beft::experiment
