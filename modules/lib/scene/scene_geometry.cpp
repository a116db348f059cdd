#include "lib/scene/scene_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <beft/scene_objects_t.hpp>

#include "lib/scenario/scenario.hpp"

namespace beft::camera {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

bool finitePositive(double value) { return std::isfinite(value) && value > 0; }

void requireFinite(double value, const char* what) {
  if (!std::isfinite(value)) throw std::invalid_argument(std::string("solid ") + what + " is not finite");
}

}  // namespace

Eigen::Vector3d entryNormal(const Solid& solid, const Eigen::Vector3d& point, const Eigen::Vector3d& d,
                            Face face) {
  switch (face) {
    case Face::BoxX: {
      const Eigen::Vector3d axis(solid.cos_yaw, solid.sin_yaw, 0);
      return axis.dot(d) > 0 ? Eigen::Vector3d(-axis) : axis;
    }
    case Face::BoxY: {
      const Eigen::Vector3d axis(-solid.sin_yaw, solid.cos_yaw, 0);
      return axis.dot(d) > 0 ? Eigen::Vector3d(-axis) : axis;
    }
    case Face::Cap:
      return Eigen::Vector3d(0, 0, d.z() > 0 ? -1.0 : 1.0);
    case Face::Round: {
      Eigen::Vector3d radial(point.x() - solid.x, point.y() - solid.y, 0);
      const double norm = radial.norm();
      return norm > 0 ? Eigen::Vector3d(radial / norm) : Eigen::Vector3d(-d.normalized());
    }
    case Face::Inside:
      break;
  }
  return -d.normalized();
}

double footprintDistance(const Solid& solid, double x, double y) {
  const double dx = x - solid.x, dy = y - solid.y;
  if (solid.shape == Solid::Shape::Cylinder) return std::hypot(dx, dy) - solid.radius;
  const double lx = solid.cos_yaw * dx + solid.sin_yaw * dy;
  const double ly = -solid.sin_yaw * dx + solid.cos_yaw * dy;
  const double ex = std::abs(lx) - solid.half_x, ey = std::abs(ly) - solid.half_y;
  const double outside = std::hypot(std::max(ex, 0.0), std::max(ey, 0.0));
  const double inside = std::min(std::max(ex, ey), 0.0);
  return outside + inside;
}

// ---- building ----

void SceneGeometry::setObjectCount(int count) {
  object_count_ = std::max(count, 0);
  solid_of_object_.assign(object_count_, -1);
  for (size_t i = 0; i < solids_.size(); ++i) {
    const int object = solids_[i].object_index;
    if (object >= 0 && object < object_count_) solid_of_object_[object] = static_cast<int>(i);
  }
  grid_nx_ = grid_ny_ = 0;
}

void SceneGeometry::addBox(int object_index, double x, double y, double z, double yaw_deg, double size_x,
                           double size_y, double size_z, uint32_t color_rgb) {
  requireFinite(x, "x");
  requireFinite(y, "y");
  requireFinite(z, "z");
  requireFinite(yaw_deg, "yaw");
  if (!finitePositive(size_x) || !finitePositive(size_y) || !finitePositive(size_z)) {
    throw std::invalid_argument("box size must be finite and positive");
  }
  Solid solid;
  solid.shape = Solid::Shape::Box;
  solid.object_index = object_index;
  solid.x = x;
  solid.y = y;
  solid.z_min = z;
  solid.z_max = z + size_z;
  solid.cos_yaw = std::cos(yaw_deg * kDegToRad);
  solid.sin_yaw = std::sin(yaw_deg * kDegToRad);
  solid.half_x = 0.5 * size_x;
  solid.half_y = 0.5 * size_y;
  solid.color_rgb = color_rgb & 0xFFFFFF;
  const double extent_x = std::abs(solid.cos_yaw) * solid.half_x + std::abs(solid.sin_yaw) * solid.half_y;
  const double extent_y = std::abs(solid.sin_yaw) * solid.half_x + std::abs(solid.cos_yaw) * solid.half_y;
  solid.min_x = x - extent_x;
  solid.max_x = x + extent_x;
  solid.min_y = y - extent_y;
  solid.max_y = y + extent_y;
  solids_.push_back(solid);
  if (object_index >= object_count_) setObjectCount(object_index + 1);
  if (object_index >= 0) solid_of_object_[object_index] = static_cast<int>(solids_.size()) - 1;
  grid_nx_ = grid_ny_ = 0;
}

void SceneGeometry::addCylinder(int object_index, double x, double y, double z, double radius, double height,
                                uint32_t color_rgb) {
  requireFinite(x, "x");
  requireFinite(y, "y");
  requireFinite(z, "z");
  if (!finitePositive(radius) || !finitePositive(height)) {
    throw std::invalid_argument("cylinder radius and height must be finite and positive");
  }
  Solid solid;
  solid.shape = Solid::Shape::Cylinder;
  solid.object_index = object_index;
  solid.x = x;
  solid.y = y;
  solid.z_min = z;
  solid.z_max = z + height;
  solid.radius = radius;
  solid.half_x = solid.half_y = radius;
  solid.color_rgb = color_rgb & 0xFFFFFF;
  solid.min_x = x - radius;
  solid.max_x = x + radius;
  solid.min_y = y - radius;
  solid.max_y = y + radius;
  solids_.push_back(solid);
  if (object_index >= object_count_) setObjectCount(object_index + 1);
  if (object_index >= 0) solid_of_object_[object_index] = static_cast<int>(solids_.size()) - 1;
  grid_nx_ = grid_ny_ = 0;
}

void SceneGeometry::buildIndex(double cell_size) {
  cell_start_.clear();
  cell_items_.clear();
  grid_nx_ = grid_ny_ = 0;
  if (solids_.empty()) return;
  double x0 = kInfinity, y0 = kInfinity, x1 = -kInfinity, y1 = -kInfinity;
  for (const Solid& solid : solids_) {
    x0 = std::min(x0, solid.min_x);
    y0 = std::min(y0, solid.min_y);
    x1 = std::max(x1, solid.max_x);
    y1 = std::max(y1, solid.max_y);
  }
  const double width = std::max(x1 - x0, 1e-3), height = std::max(y1 - y0, 1e-3);
  if (!(cell_size > 0) || !std::isfinite(cell_size)) {
    // About two solids per cell, between 0.5 m and 4 m.
    cell_size = std::clamp(std::sqrt(2.0 * width * height / static_cast<double>(solids_.size())), 0.5, 4.0);
  }
  // Keep the grid to a few million cells whatever the extent.
  constexpr double kMaxCells = 4e6;
  cell_size = std::max(cell_size, std::sqrt(width * height / kMaxCells));
  cell_size_ = cell_size;
  grid_x0_ = x0;
  grid_y0_ = y0;
  grid_nx_ = std::max(1, static_cast<int>(std::ceil(width / cell_size)));
  grid_ny_ = std::max(1, static_cast<int>(std::ceil(height / cell_size)));

  const auto cellRange = [&](const Solid& solid, int& ix0, int& iy0, int& ix1, int& iy1) {
    ix0 = std::clamp(static_cast<int>(std::floor((solid.min_x - grid_x0_) / cell_size_)), 0, grid_nx_ - 1);
    iy0 = std::clamp(static_cast<int>(std::floor((solid.min_y - grid_y0_) / cell_size_)), 0, grid_ny_ - 1);
    ix1 = std::clamp(static_cast<int>(std::floor((solid.max_x - grid_x0_) / cell_size_)), 0, grid_nx_ - 1);
    iy1 = std::clamp(static_cast<int>(std::floor((solid.max_y - grid_y0_) / cell_size_)), 0, grid_ny_ - 1);
  };
  // Two passes: count per cell, then fill (compressed rows, ascending ids).
  std::vector<int> counts(static_cast<size_t>(grid_nx_) * grid_ny_ + 1, 0);
  for (const Solid& solid : solids_) {
    int ix0, iy0, ix1, iy1;
    cellRange(solid, ix0, iy0, ix1, iy1);
    for (int iy = iy0; iy <= iy1; ++iy)
      for (int ix = ix0; ix <= ix1; ++ix) ++counts[iy * grid_nx_ + ix];
  }
  cell_start_.assign(counts.size(), 0);
  for (size_t c = 1; c < counts.size(); ++c) cell_start_[c] = cell_start_[c - 1] + counts[c - 1];
  cell_items_.assign(cell_start_.back(), -1);
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (size_t i = 0; i < solids_.size(); ++i) {
    int ix0, iy0, ix1, iy1;
    cellRange(solids_[i], ix0, iy0, ix1, iy1);
    for (int iy = iy0; iy <= iy1; ++iy)
      for (int ix = ix0; ix <= ix1; ++ix) cell_items_[fill[iy * grid_nx_ + ix]++] = static_cast<int>(i);
  }
}

SceneGeometry SceneGeometry::fromObjects(const std::vector<scenario::Object>& objects) {
  SceneGeometry scene;
  scene.setObjectCount(static_cast<int>(objects.size()));
  for (size_t i = 0; i < objects.size(); ++i) {
    const scenario::Object& object = objects[i];
    if (!object.visual) continue;
    const scenario::Visual& visual = *object.visual;
    if (visual.shape == scenario::Visual::Shape::Box) {
      scene.addBox(static_cast<int>(i), object.x, object.y, object.z, object.yaw, visual.size_x, visual.size_y,
                   visual.size_z, visual.color_rgb);
    } else {
      scene.addCylinder(static_cast<int>(i), object.x, object.y, object.z, visual.radius, visual.height,
                        visual.color_rgb);
    }
  }
  scene.buildIndex();
  return scene;
}

SceneGeometry SceneGeometry::fromScenario(const scenario::Scenario& scenario) {
  return fromObjects(scenario.objects);
}

SceneGeometry SceneGeometry::fromMessage(const beft::scene_objects_t& message) {
  SceneGeometry scene;
  const int count = std::min<int>(message.num_objects, static_cast<int>(message.objects.size()));
  scene.setObjectCount(count);
  for (int i = 0; i < count; ++i) {
    const beft::scene_object_t& object = message.objects[i];
    try {
      if (object.shape == beft::scene_object_t::SHAPE_BOX) {
        scene.addBox(i, object.x, object.y, object.z, object.yaw, object.size_x, object.size_y, object.size_z,
                     static_cast<uint32_t>(object.color_rgb));
      } else if (object.shape == beft::scene_object_t::SHAPE_CYLINDER) {
        scene.addCylinder(i, object.x, object.y, object.z, object.radius, object.size_z,
                          static_cast<uint32_t>(object.color_rgb));
      }
    } catch (const std::invalid_argument&) {
      // Not a usable shape: the object stays without a solid.
    }
  }
  scene.buildIndex();
  return scene;
}

int SceneGeometry::solidOfObject(int object_index) const {
  if (object_index < 0 || object_index >= static_cast<int>(solid_of_object_.size())) return -1;
  return solid_of_object_[object_index];
}

// ---- queries ----

SceneGeometry::RayHit SceneGeometry::firstHit(const Eigen::Vector3d& o, const Eigen::Vector3d& d, double t_min,
                                              double t_max) const {
  RayHit best;
  LineInterval interval;
  traverseCells(o, d, t_min, t_max, [&](int first, int last, double t_cell_exit) {
    for (int i = first; i < last; ++i) {
      const int s = cell_items_[i];
      if (!intersectLine(solids_[s], o, d, interval)) continue;
      if (interval.enter < t_min || interval.enter > t_max) continue;
      // Same order as the brute force: nearest first, then lower index.
      if (interval.enter < best.t || (interval.enter == best.t && s < best.solid)) {
        best.solid = s;
        best.t = interval.enter;
        best.face = interval.enter_face;
      }
    }
    // A hit inside this cell is nearer than anything in later cells.
    return !(best.solid >= 0 && best.t < t_cell_exit);
  });
  return best;
}

SceneGeometry::RayHit SceneGeometry::firstHitBruteForce(const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                                                        double t_min, double t_max) const {
  RayHit best;
  LineInterval interval;
  for (size_t s = 0; s < solids_.size(); ++s) {
    if (!intersectLine(solids_[s], o, d, interval)) continue;
    if (interval.enter < t_min || interval.enter > t_max) continue;
    if (interval.enter < best.t) {
      best.solid = static_cast<int>(s);
      best.t = interval.enter;
      best.face = interval.enter_face;
    }
  }
  return best;
}

void SceneGeometry::solidsNear(double x, double y, double radius, std::vector<int>& out) const {
  if (grid_nx_ == 0 || !std::isfinite(x) || !std::isfinite(y) || !(radius >= 0)) return;
  const auto cellIndex = [&](double value, double origin, int count) {
    const double cell = std::floor((value - origin) / cell_size_);
    return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(count - 1)));
  };
  const int ix0 = cellIndex(x - radius, grid_x0_, grid_nx_), ix1 = cellIndex(x + radius, grid_x0_, grid_nx_);
  const int iy0 = cellIndex(y - radius, grid_y0_, grid_ny_), iy1 = cellIndex(y + radius, grid_y0_, grid_ny_);
  const size_t first_new = out.size();
  for (int iy = iy0; iy <= iy1; ++iy) {
    for (int ix = ix0; ix <= ix1; ++ix) {
      const int cell = iy * grid_nx_ + ix;
      for (int i = cell_start_[cell]; i < cell_start_[cell + 1]; ++i) {
        const Solid& solid = solids_[cell_items_[i]];
        if (solid.min_x > x + radius || solid.max_x < x - radius || solid.min_y > y + radius ||
            solid.max_y < y - radius) {
          continue;
        }
        out.push_back(cell_items_[i]);
      }
    }
  }
  std::sort(out.begin() + first_new, out.end());
  out.erase(std::unique(out.begin() + first_new, out.end()), out.end());
}

int segmentHitsObject(const SceneGeometry& scene, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      int ignore_object) {
  const Eigen::Vector3d d = b - a;
  int best_object = -1;
  double best_t = SceneGeometry::kInfinity;
  LineInterval interval;
  scene.forEachSolidAlong(a, d, 0.0, 1.0, [&](int s) {
    const Solid& solid = scene.solids()[s];
    if (solid.object_index == ignore_object && ignore_object >= 0) return true;
    if (!intersectLine(solid, a, d, interval)) return true;
    if (interval.exit < 0 || interval.enter > 1) return true;
    const double t = std::max(interval.enter, 0.0);
    if (t < best_t || (t == best_t && solid.object_index < best_object)) {
      best_t = t;
      best_object = solid.object_index;
    }
    return true;
  });
  return best_object;
}

bool segmentBlocked(const SceneGeometry& scene, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                    int ignore_object) {
  const Eigen::Vector3d d = b - a;
  bool blocked = false;
  LineInterval interval;
  scene.forEachSolidAlong(a, d, 0.0, 1.0, [&](int s) {
    const Solid& solid = scene.solids()[s];
    if (solid.object_index == ignore_object && ignore_object >= 0) return true;
    if (intersectLine(solid, a, d, interval) && interval.exit >= 0 && interval.enter <= 1) {
      blocked = true;
      return false;
    }
    return true;
  });
  return blocked;
}

}  // namespace beft::camera
