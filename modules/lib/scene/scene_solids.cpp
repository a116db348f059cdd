#include "lib/scene/scene_solids.hpp"

namespace beft::camera {

bool SceneSolids::sameSolids(const beft::scene_objects_t& a, const beft::scene_objects_t& b) {
  if (a.num_objects != b.num_objects || a.objects.size() != b.objects.size()) return false;
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const auto& p = a.objects[i];
    const auto& q = b.objects[i];
    if (p.id != q.id || p.shape != q.shape || p.x != q.x || p.y != q.y || p.z != q.z || p.yaw != q.yaw ||
        p.size_x != q.size_x || p.size_y != q.size_y || p.size_z != q.size_z || p.radius != q.radius ||
        p.color_rgb != q.color_rgb)
      return false;
  }
  return true;
}

bool SceneSolids::update(const beft::scene_objects_t& scene) {
  if (solids_ && sameSolids(scene, scene_)) return false;
  solids_.emplace(SceneGeometry::fromMessage(scene));
  scene_ = scene;
  return true;
}

}  // namespace beft::camera
