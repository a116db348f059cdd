// The solids of a GT_OBJECTS message, kept from one firing to the next: they
// are made again only when an object's shape, pose, size or colour changes
// (objects rarely change, and at 450 objects making them at every tick of a
// drive was a good part of an expert's firing).
#pragma once

#include <optional>

#include <beft/scene_objects_t.hpp>

#include "lib/scene/scene_geometry.hpp"

namespace beft::camera {

class SceneSolids {
 public:
  // Brings the solids to the scene's objects; true when they were made again.
  bool update(const beft::scene_objects_t& scene);
  // Those of the last update (none before the first).
  const SceneGeometry& solids() const { return *solids_; }

  // Whether two messages make the same solids (SceneGeometry::fromMessage).
  static bool sameSolids(const beft::scene_objects_t& a, const beft::scene_objects_t& b);

 private:
  std::optional<SceneGeometry> solids_;
  beft::scene_objects_t scene_{};  // the objects they were made of
};

}  // namespace beft::camera
