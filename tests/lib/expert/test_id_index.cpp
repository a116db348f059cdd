// Looking items of a message's list up by id (expert/id_index.hpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <beft/scene_objects_t.hpp>

#include "lib/expert/id_index.hpp"

using namespace beft;

namespace {

std::vector<scene_object_t> objectsNamed(const std::vector<std::string>& ids) {
  std::vector<scene_object_t> objects(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) objects[i].id = ids[i];
  return objects;
}

}  // namespace

TEST(IdIndex, FindsTheLastItemOfAnIdAndNothingForAnUnknownOne) {
  const auto objects = objectsNamed({"a", "b", "a"});
  expert::IdIndex<scene_object_t> index;
  index.rebuild(objects, &scene_object_t::id);
  EXPECT_EQ(index.find("a"), &objects[2]);
  EXPECT_EQ(index.find("b"), &objects[1]);
  EXPECT_EQ(index.find("c"), nullptr);
  const auto fewer = objectsNamed({"c"});
  index.rebuild(fewer, &scene_object_t::id);
  EXPECT_EQ(index.find("a"), nullptr);
  EXPECT_EQ(index.find("c"), &fewer[0]);
}

// Kept while the ids stay the same, made again as soon as they change in any
// way: added, removed, renamed or reordered.
TEST(IdPositions, FollowTheIdsOfEachList) {
  expert::IdPositions<scene_object_t> positions;
  const auto expectPositions = [&](const std::vector<std::string>& ids) {
    const auto objects = objectsNamed(ids);
    const auto& of = positions.of(objects, &scene_object_t::id);
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      bool repeated_later = false;
      for (std::size_t j = i + 1; j < ids.size(); ++j) repeated_later = repeated_later || ids[j] == ids[i];
      if (repeated_later) continue;  // the last place counts
      ++distinct;
      ASSERT_EQ(of.count(ids[i]), 1u) << ids[i];
      EXPECT_EQ(of.at(ids[i]), i) << ids[i];
    }
    EXPECT_EQ(of.size(), distinct);
  };
  expectPositions({"a", "b", "c"});
  expectPositions({"a", "b", "c"});
  expectPositions({"b", "a", "c"});
  expectPositions({"b", "a"});
  expectPositions({"b", "a", "d"});
  expectPositions({"x", "a", "x"});
  expectPositions({});
}
