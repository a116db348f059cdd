// The source tree keeps its layers (include_layers.hpp), and the check
// catches what breaks them: planted trees with one wrong include each.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/rules/include_layers.hpp"
#include "tests/rules/planted_tree.hpp"

namespace fs = std::filesystem;
using beft::layers::checkIncludes;
using beft::layers::describe;
using beft::layers::layerOf;
using beft::layers::mayInclude;

namespace {

// A tree that keeps the rules: a library, an expert on it, a tool on a
// service and a planner.
class PlantedTree : public beft::rules::PlantedTree {
 public:
  PlantedTree() {
    write("modules/lib/common/log.hpp", "#pragma once\n");
    write("modules/lib/wire/codec.hpp", "#pragma once\n#include \"lib/common/log.hpp\"\n");
    write("modules/experts/audio/heard.hpp", "#pragma once\n#include \"lib/wire/codec.hpp\"\n");
    write("modules/experts/vision/seen.hpp", "#pragma once\n");
    write("modules/services/arbiter/core.hpp", "#pragma once\n");
    write("modules/tools/report/main.cpp", "#include \"services/arbiter/core.hpp\"\n#include \"planners/plan.hpp\"\n");
    write("planners/plan.hpp", "#pragma once\n#include \"lib/common/log.hpp\"\n");
  }
};

}  // namespace

TEST(Layers, TheSourceTreeKeepsItsLayers) {
  const auto violations = checkIncludes(BEFT_SOURCE_DIR);
  for (const auto& violation : violations) ADD_FAILURE() << describe(violation);
  EXPECT_TRUE(violations.empty());
}

TEST(Layers, APlantedTreeThatKeepsTheRulesPasses) {
  PlantedTree tree;
  EXPECT_TRUE(checkIncludes(tree.root()).empty());
}

TEST(Layers, ALibraryReachingUpFailsWithItsFileAndLine) {
  PlantedTree tree;
  tree.write("modules/lib/wire/decoder.cpp",
             "#include \"lib/wire/codec.hpp\"\n\n#include \"experts/audio/heard.hpp\"\n");
  const auto violations = checkIncludes(tree.root());
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].file, "modules/lib/wire/decoder.cpp");
  EXPECT_EQ(violations[0].line, 3);
  EXPECT_EQ(describe(violations[0]),
            "modules/lib/wire/decoder.cpp:3: #include \"experts/audio/heard.hpp\": lib/wire may not include "
            "experts/audio");
}

TEST(Layers, AnExpertIncludingAnotherExpertOrTheSimulationFails) {
  PlantedTree tree;
  tree.write("modules/sim/world/camera.hpp", "#pragma once\n");
  tree.write("modules/experts/audio/use.cpp",
             "#include \"experts/vision/seen.hpp\"\n#include \"sim/world/camera.hpp\"\n");
  const auto violations = checkIncludes(tree.root());
  ASSERT_EQ(violations.size(), 2u);
  EXPECT_EQ(violations[0].reason, "experts/audio may not include experts/vision");
  EXPECT_EQ(violations[1].reason, "experts/audio may not include sim/world");
}

TEST(Layers, ABareNameIsAllowedOnlyBesideItsFile) {
  PlantedTree tree;
  tree.write("modules/experts/audio/heard.cpp", "#include \"heard.hpp\"\n");           // beside: fine
  tree.write("modules/experts/vision/seen.cpp", "#include \"seen.hpp\"\n#include \"codec.hpp\"\n");
  tree.write("tests/lib/test_codec.cpp", "#include \"codec.hpp\"\n#include \"generated_types.hpp\"\n");
  const auto violations = checkIncludes(tree.root());
  ASSERT_EQ(violations.size(), 2u);
  EXPECT_EQ(violations[0].file, "modules/experts/vision/seen.cpp");
  EXPECT_EQ(violations[0].line, 2);
  EXPECT_EQ(violations[1].file, "tests/lib/test_codec.cpp");  // a generated header is not in the tree: allowed
  EXPECT_EQ(violations[1].line, 1);
}

TEST(Layers, AnIncludeThatNamesNoHeaderOfTheTreeFails) {
  PlantedTree tree;
  tree.write("modules/lib/wire/old.cpp", "#include \"lib/wire/moved_away.hpp\"\n");
  const auto violations = checkIncludes(tree.root());
  ASSERT_EQ(violations.size(), 1u);
  EXPECT_EQ(violations[0].reason, "not found from the repository root or modules/");
}

TEST(Layers, TheRulesBetweenGroups) {
  EXPECT_EQ(layerOf("modules/experts/audio/x.cpp"), "experts/audio");
  EXPECT_EQ(layerOf("planners/bench/x.cpp"), "planners");
  EXPECT_EQ(layerOf("blackboard/store.hpp"), "blackboard");
  EXPECT_EQ(layerOf("tests/system/run_support.hpp"), "");
  EXPECT_TRUE(mayInclude("lib/expert", "lib/wire"));
  EXPECT_FALSE(mayInclude("lib/expert", "blackboard"));
  EXPECT_FALSE(mayInclude("lib/expert", "planners"));
  EXPECT_TRUE(mayInclude("planners", "lib/common"));
  EXPECT_FALSE(mayInclude("planners", "experts/tasks"));
  EXPECT_TRUE(mayInclude("sim/world", "sim/ears"));
  EXPECT_FALSE(mayInclude("sim/ears", "experts/audio"));
  EXPECT_TRUE(mayInclude("experts/vision", "planners"));
  EXPECT_FALSE(mayInclude("experts/dw", "experts/tasks"));
  EXPECT_FALSE(mayInclude("services/planner", "experts/tasks"));
  EXPECT_FALSE(mayInclude("services/planner", "blackboard"));
  EXPECT_TRUE(mayInclude("tools/spy", "blackboard"));
  EXPECT_TRUE(mayInclude("tools/bench_experts", "experts/audio"));
  EXPECT_FALSE(mayInclude("tools/run", "tools/launch"));
}
