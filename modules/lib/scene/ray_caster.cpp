#include "lib/scene/ray_caster.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

#include <Eigen/Geometry>

namespace beft::camera {

namespace {

struct Rgb {
  float r, g, b;
};

Rgb unpack(uint32_t rgb) {
  return {static_cast<float>((rgb >> 16) & 0xFF), static_cast<float>((rgb >> 8) & 0xFF),
          static_cast<float>(rgb & 0xFF)};
}

// Fixed look of the rendered world.
const Rgb kGround{118, 112, 100};
const Rgb kHaze{196, 206, 218};
const Rgb kSkyZenith{112, 152, 212};
const Eigen::Vector3d kLight = Eigen::Vector3d(0.35, 0.55, 0.76).normalized();
// Light on a surface: ambient, plus sun (fixed direction kLight), plus a
// little from the camera, so faces turned away from the sun still show
// their shape.
constexpr float kAmbient = 0.45f, kSun = 0.35f, kHeadlight = 0.25f;
constexpr float kFogAtRange = 0.4f;  // haze mixed in at the range limit (quadratic in distance)

// 1 / |forward + a left + b up| for a pixel's ray (a, b as in column_a_, row_b_).
inline double inverseRayLength(double a, double b) { return 1.0 / std::sqrt(1.0 + a * a + b * b); }

}  // namespace

const char* renderMethodName(RenderMethod method) {
  switch (method) {
    case RenderMethod::Projection:
      return "projection";
    case RenderMethod::GridTraversal:
      return "grid";
    case RenderMethod::BruteForce:
      return "brute-force";
  }
  return "?";
}

struct RayCaster::SolidFootprint {
  int solid = -1;
  int u0 = 0, v0 = 0, u1 = -1, v1 = -1;  // inclusive pixel rectangle
  double min_depth = 0;                  // no point of the solid is nearer [m]
};

void RayCaster::prepareCamera(const Camera& camera) {
  const bool same_intrinsics = width_ == camera.intrinsics.width && height_ == camera.intrinsics.height &&
                               camera_.intrinsics.fov_deg == camera.intrinsics.fov_deg && tables_ready_;
  camera_ = camera;
  camera_frame_ = CameraFrame(camera);
  width_ = std::max(camera.intrinsics.width, 0);
  height_ = std::max(camera.intrinsics.height, 0);
  const CameraFrame& f = camera_frame_;
  if (!same_intrinsics) {
    column_a_.resize(width_);
    row_b_.resize(height_);
    for (int u = 0; u < width_; ++u) column_a_[u] = (f.cx - (u + 0.5)) / f.focal;
    for (int v = 0; v < height_; ++v) row_b_[v] = (f.cy - (v + 0.5)) / f.focal;
    tables_ready_ = true;
  }
  // Frustum side planes from the rays through the image corners.
  const Eigen::Vector3d corners[4] = {imagePointRay(f, 0, 0), imagePointRay(f, width_, 0),
                                      imagePointRay(f, width_, height_), imagePointRay(f, 0, height_)};
  for (int i = 0; i < 4; ++i) {
    // Corners go clockwise on the image (top-left, top-right, ...), so
    // this x next points into the frustum.
    frustum_normals_[i] = corners[i].cross(corners[(i + 1) % 4]).normalized();
  }
}

// Kept per thread between frames: a row's worth of scratch stays in the
// nearest cache, where whole-image arrays of every stage did not.
struct RayCaster::RowRays {
  std::vector<double> ray_x, ray_y, t_limit, nearest_t;  // per column
  std::vector<double> inverse_length;                     // 1 / |ray|
  std::vector<int32_t> nearest_solid;
  std::vector<Face> nearest_face;
  std::vector<uint8_t> hits_ground;
  double ray_z = 0;  // shared by the row (the camera has no roll)
  // The shaded row.
  std::vector<float> depth;
  std::vector<int32_t> object;
  std::vector<uint8_t> rgb;
  void resize(int width) {
    depth.resize(width);
    object.resize(width);
    rgb.resize(3 * static_cast<size_t>(width));
    ray_x.resize(width);
    ray_y.resize(width);
    inverse_length.resize(width);
    t_limit.resize(width);
    nearest_t.resize(width);
    nearest_solid.resize(width);
    nearest_face.resize(width);
    hits_ground.resize(width);
  }
};

void RayCaster::prepareRow(int v, RowRays& row) const {
  const CameraFrame& f = camera_frame_;
  // Locals and raw pointers: stores to the arrays cannot alias them, so the
  // compiler keeps them in registers.
  const double range = camera_.intrinsics.range;
  const double oz = f.origin.z();
  const double left_x = f.left.x(), left_y = f.left.y();
  const double* column_a = column_a_.data();
  double* inverse_length = row.inverse_length.data();
  double* ray_x = row.ray_x.data();
  double* ray_y = row.ray_y.data();
  double* t_limits = row.t_limit.data();
  double* nearest_t = row.nearest_t.data();
  uint8_t* hits_ground = row.hits_ground.data();
  int32_t* nearest_solid = row.nearest_solid.data();
  // Same summation order as imagePointRay: (forward + b up) + a left.
  const double b = row_b_[v];
  const double row_x = f.forward.x() + b * f.up.x(), row_y = f.forward.y() + b * f.up.y(),
               row_z = f.forward.z() + b * f.up.z();
  // Without roll the camera's left axis is horizontal (left.z == 0), so a
  // whole row shares its rays' z component and its ground distance.
  row.ray_z = row_z;
  const double t_ground = (row_z < 0 && oz > 0) ? -oz / row_z : SceneGeometry::kInfinity;
  for (int u = 0; u < width_; ++u) {
    const double a = column_a[u];
    ray_x[u] = row_x + a * left_x;
    ray_y[u] = row_y + a * left_y;
    inverse_length[u] = inverseRayLength(a, b);
    const double t_range = range * inverse_length[u];
    const bool ground = t_ground <= t_range;
    const double t_limit = ground ? t_ground : t_range;
    t_limits[u] = t_limit;
    hits_ground[u] = ground;
    nearest_t[u] = t_limit;
    nearest_solid[u] = -1;
  }
}

// The pixel rectangle a solid can cover and its nearest depth; false if it
// cannot be seen (behind the camera, beyond range or outside the image).
bool RayCaster::projectSolid(const Solid& solid, SolidFootprint& footprint) const {
  const CameraFrame& f = camera_frame_;
  // Beyond range: nearest point of its bounding box farther than range.
  const double ex = std::max({solid.min_x - f.origin.x(), 0.0, f.origin.x() - solid.max_x});
  const double ey = std::max({solid.min_y - f.origin.y(), 0.0, f.origin.y() - solid.max_y});
  const double ez = std::max({solid.z_min - f.origin.z(), 0.0, f.origin.z() - solid.z_max});
  const double range = camera_.intrinsics.range;
  if (ex * ex + ey * ey + ez * ez > range * range) return false;
  // Outside the frustum: its bounding sphere beyond one of the side planes.
  const double half_height = 0.5 * (solid.z_max - solid.z_min);
  const Eigen::Vector3d centre(solid.x, solid.y, solid.z_min + half_height);
  const double sphere = std::sqrt(solid.half_x * solid.half_x + solid.half_y * solid.half_y + half_height * half_height);
  const Eigen::Vector3d offset = centre - f.origin;
  for (const Eigen::Vector3d& normal : frustum_normals_) {
    if (normal.dot(offset) < -sphere) return false;
  }

  // Corners of its bounding box (oriented for boxes) in camera coordinates:
  // depth (forward), left, up. Bit 0: +x side, bit 1: +y side, bit 2: top.
  double depth[8], left[8], up[8];
  for (int i = 0; i < 8; ++i) {
    const double sx = (i & 1) ? 1.0 : -1.0, sy = (i & 2) ? 1.0 : -1.0;
    double wx, wy;
    if (solid.shape == Solid::Shape::Box) {
      wx = solid.x + sx * solid.half_x * solid.cos_yaw - sy * solid.half_y * solid.sin_yaw;
      wy = solid.y + sx * solid.half_x * solid.sin_yaw + sy * solid.half_y * solid.cos_yaw;
    } else {
      wx = solid.x + sx * solid.radius;
      wy = solid.y + sy * solid.radius;
    }
    const Eigen::Vector3d q = Eigen::Vector3d(wx, wy, (i & 4) ? solid.z_max : solid.z_min) - f.origin;
    depth[i] = q.dot(f.forward);
    left[i] = q.dot(f.left);
    up[i] = q.dot(f.up);
  }
  // The box clipped to depth >= kMinDepth: corners in front plus the points
  // where edges cross that plane. Its image is what the solid can cover.
  double x_min = SceneGeometry::kInfinity, x_max = -SceneGeometry::kInfinity;
  double y_min = SceneGeometry::kInfinity, y_max = -SceneGeometry::kInfinity;
  double min_depth = SceneGeometry::kInfinity;
  const auto addPoint = [&](double d, double l, double u) {
    const double x = f.cx - f.focal * l / d, y = f.cy - f.focal * u / d;
    x_min = std::min(x_min, x);
    x_max = std::max(x_max, x);
    y_min = std::min(y_min, y);
    y_max = std::max(y_max, y);
    min_depth = std::min(min_depth, d);
  };
  for (int i = 0; i < 8; ++i) {
    if (depth[i] >= kMinDepth) addPoint(depth[i], left[i], up[i]);
    for (int bit = 1; bit <= 4; bit <<= 1) {
      const int j = i | bit;
      if (j == i) continue;
      if ((depth[i] >= kMinDepth) == (depth[j] >= kMinDepth)) continue;
      const double s = (kMinDepth - depth[i]) / (depth[j] - depth[i]);
      addPoint(kMinDepth, left[i] + s * (left[j] - left[i]), up[i] + s * (up[j] - up[i]));
    }
  }
  if (!(min_depth < SceneGeometry::kInfinity)) return false;
  // Pixel u's ray passes through x = u + 0.5; one pixel of margin for rounding.
  const auto clampIndex = [](double value, int count) {
    return static_cast<int>(std::clamp(value, -1.0, static_cast<double>(count)));
  };
  footprint.u0 = std::max(clampIndex(std::floor(x_min) - 1, width_), 0);
  footprint.u1 = std::min(clampIndex(std::floor(x_max) + 1, width_), width_ - 1);
  footprint.v0 = std::max(clampIndex(std::floor(y_min) - 1, height_), 0);
  footprint.v1 = std::min(clampIndex(std::floor(y_max) + 1, height_), height_ - 1);
  footprint.min_depth = min_depth;
  return footprint.u0 <= footprint.u1 && footprint.v0 <= footprint.v1;
}

std::vector<RayCaster::SolidFootprint> RayCaster::visibleFootprints(const SceneGeometry& scene) const {
  const std::vector<Solid>& solids = scene.solids();
  std::vector<SolidFootprint> visible;
  visible.reserve(solids.size());
  for (size_t s = 0; s < solids.size(); ++s) {
    SolidFootprint footprint;
    footprint.solid = static_cast<int>(s);
    if (projectSolid(solids[s], footprint)) visible.push_back(footprint);
  }
  // Nearest first, so farther solids find their pixels already covered.
  std::sort(visible.begin(), visible.end(), [](const SolidFootprint& a, const SolidFootprint& b) {
    return a.min_depth < b.min_depth || (a.min_depth == b.min_depth && a.solid < b.solid);
  });
  return visible;
}

void RayCaster::castProjectionRow(const SceneGeometry& scene, const std::vector<SolidFootprint>& visible, int v,
                                  RowRays& row) const {
  const std::vector<Solid>& solids = scene.solids();
  const Eigen::Vector3d& o = camera_frame_.origin;
  LineInterval interval;
  for (const SolidFootprint& footprint : visible) {
    if (v < footprint.v0 || v > footprint.v1) continue;
    const Solid& solid = solids[footprint.solid];
    for (int u = footprint.u0; u <= footprint.u1; ++u) {
      if (row.nearest_t[u] < footprint.min_depth) continue;  // something nearer covers it
      const Eigen::Vector3d d(row.ray_x[u], row.ray_y[u], row.ray_z);
      if (!intersectLine(solid, o, d, interval) || interval.enter < kMinDepth) continue;
      // Same order as the per-ray methods: nearest, then lower solid index.
      const double t = interval.enter;
      if (t < row.nearest_t[u] ||
          (t == row.nearest_t[u] && (row.nearest_solid[u] < 0 || footprint.solid < row.nearest_solid[u]))) {
        row.nearest_t[u] = t;
        row.nearest_solid[u] = footprint.solid;
        row.nearest_face[u] = interval.enter_face;
      }
    }
  }
}

void RayCaster::castPerRayRow(const SceneGeometry& scene, bool use_grid, RowRays& row) const {
  const Eigen::Vector3d& o = camera_frame_.origin;
  for (int u = 0; u < width_; ++u) {
    const Eigen::Vector3d d(row.ray_x[u], row.ray_y[u], row.ray_z);
    const SceneGeometry::RayHit hit = use_grid ? scene.firstHit(o, d, kMinDepth, row.t_limit[u])
                                               : scene.firstHitBruteForce(o, d, kMinDepth, row.t_limit[u]);
    if (hit.solid >= 0) {
      row.nearest_t[u] = hit.t;
      row.nearest_solid[u] = hit.solid;
      row.nearest_face[u] = hit.face;
    }
  }
}

void RayCaster::prepareColours(const SceneGeometry& scene) {
  // The solid colours once, not per pixel.
  solid_colours_.clear();
  solid_colours_.reserve(scene.solids().size());
  for (const Solid& solid : scene.solids()) {
    const Rgb colour = unpack(solid.color_rgb);
    solid_colours_.push_back({colour.r, colour.g, colour.b});
  }
}

void RayCaster::shadeRow(const SceneGeometry& scene, RowRays& row) const {
  const Eigen::Vector3d& o = camera_frame_.origin;
  const float inv_range = static_cast<float>(1.0 / camera_.intrinsics.range);

  // Locals and raw pointers: the byte stores below may alias anything, so
  // without them every member would be reloaded per pixel.
  const double ox = o.x(), oy = o.y();
  const int32_t* nearest_solid = row.nearest_solid.data();
  const uint8_t* hits_ground = row.hits_ground.data();
  const double* ray_x = row.ray_x.data();
  const double* ray_y = row.ray_y.data();
  const double ray_z = row.ray_z;
  const double* inverse_length = row.inverse_length.data();
  const double* nearest_t = row.nearest_t.data();
  const Face* nearest_face = row.nearest_face.data();
  const Solid* solids = scene.solids().data();
  const auto* solid_colours = solid_colours_.data();
  float* depth = row.depth.data();
  int32_t* object = row.object.data();
  uint8_t* rgb = row.rgb.data();
  const auto store = [rgb](size_t p, float r, float g, float b) {
    // Never negative; at most slightly above 255 where lights add up.
    rgb[3 * p] = static_cast<uint8_t>(std::min(r, 255.0f) + 0.5f);
    rgb[3 * p + 1] = static_cast<uint8_t>(std::min(g, 255.0f) + 0.5f);
    rgb[3 * p + 2] = static_cast<uint8_t>(std::min(b, 255.0f) + 0.5f);
  };
  for (int p = 0; p < width_; ++p) {
    const int s = nearest_solid[p];
    if (s < 0 && !hits_ground[p]) {
      // Sky: haze at and below the horizon, bluer towards the zenith.
      const float elevation = std::clamp(static_cast<float>(ray_z * inverse_length[p]), 0.0f, 1.0f);
      const float w = elevation * (2.0f - elevation);
      store(p, kHaze.r + (kSkyZenith.r - kHaze.r) * w, kHaze.g + (kSkyZenith.g - kHaze.g) * w,
            kHaze.b + (kSkyZenith.b - kHaze.b) * w);
      depth[p] = 0;
      object[p] = -1;
      continue;
    }
    const double t = nearest_t[p];
    const float fraction_of_range = static_cast<float>(t * inverse_length[p]) * inv_range;
    const float fog = kFogAtRange * fraction_of_range * fraction_of_range;
    float light;
    Rgb colour;
    if (s >= 0) {
      const Solid& solid = solids[s];
      const Eigen::Vector3d d(ray_x[p], ray_y[p], ray_z);
      const Eigen::Vector3d normal = entryNormal(solid, o + t * d, d, nearest_face[p]);
      const double facing = -normal.dot(d) * inverse_length[p];
      light = kAmbient + kSun * static_cast<float>(std::max(0.0, normal.dot(kLight))) +
              kHeadlight * static_cast<float>(std::max(0.0, facing));
      colour = {solid_colours[s][0], solid_colours[s][1], solid_colours[s][2]};
      object[p] = solid.object_index;
    } else {
      // Ground with a faint 1 m checker, so motion over it shows.
      const double x = ox + t * ray_x[p], y = oy + t * ray_y[p];
      const long cell_x = static_cast<long>(x) - (x < 0), cell_y = static_cast<long>(y) - (y < 0);
      light = ((cell_x + cell_y) & 1) ? 0.92f : 1.0f;
      colour = kGround;
      object[p] = -1;
    }
    const float keep = light * (1.0f - fog);
    store(p, colour.r * keep + kHaze.r * fog, colour.g * keep + kHaze.g * fog, colour.b * keep + kHaze.b * fog);
    depth[p] = static_cast<float>(t);
  }
}

namespace {

// Rows into a RenderedFrame's whole-image buffers.
class WholeFrameWriter : public FrameRowWriter {
 public:
  explicit WholeFrameWriter(RenderedFrame& frame) : frame_(frame) {}
  void writeRow(int v, const float* depth, const int32_t* object, const uint8_t* rgb) override {
    const size_t first = static_cast<size_t>(v) * frame_.width;
    std::copy_n(depth, frame_.width, frame_.depth.data() + first);
    std::copy_n(object, frame_.width, frame_.object.data() + first);
    std::copy_n(rgb, 3 * static_cast<size_t>(frame_.width), frame_.rgb.data() + 3 * first);
  }

 private:
  RenderedFrame& frame_;
};

}  // namespace

void RayCaster::render(const SceneGeometry& scene, const Camera& camera, RenderedFrame& frame,
                       RenderMethod method) {
  frame.camera = camera;
  frame.width = std::max(camera.intrinsics.width, 0);
  frame.height = std::max(camera.intrinsics.height, 0);
  const size_t pixels = static_cast<size_t>(frame.width) * frame.height;
  frame.depth.resize(pixels);
  frame.object.resize(pixels);
  frame.rgb.resize(3 * pixels);
  WholeFrameWriter writer(frame);
  render(scene, camera, writer, method);
}

void RayCaster::render(const SceneGeometry& scene, const Camera& camera, FrameRowWriter& writer,
                       RenderMethod method) {
  prepareCamera(camera);
  prepareColours(scene);
  const bool projection = method == RenderMethod::Projection;
  const std::vector<SolidFootprint> visible = projection ? visibleFootprints(scene) : std::vector<SolidFootprint>{};
  // Row by row, each pixel through every stage while its row is in cache;
  // bands of rows on the threads (a pixel needs nothing outside its row).
  const std::function<void(int, int)> band = [&](int first_row, int end_row) {
    thread_local RowRays row;  // one per thread; a band uses it only while it runs
    row.resize(width_);
    for (int v = first_row; v < end_row; ++v) {
      prepareRow(v, row);
      if (projection) castProjectionRow(scene, visible, v, row);
      else castPerRayRow(scene, method == RenderMethod::GridTraversal, row);
      shadeRow(scene, row);
      writer.writeRow(v, row.depth.data(), row.object.data(), row.rgb.data());
    }
  };
  if (workers_ && projection) workers_->run(height_, band);
  else band(0, height_);
}

void RayCaster::setThreads(int threads) {
  if (threads <= 1) workers_.reset();
  else if (!workers_ || workers_->threads() != threads) workers_ = std::make_unique<RowWorkers>(threads);
}

int RayCaster::threads() const { return workers_ ? workers_->threads() : 1; }

std::vector<int> RayCaster::expectedPixelsPerObject(const SceneGeometry& scene, const Camera& camera,
                                                    const PixelRect* only_touching) {
  prepareCamera(camera);
  std::vector<int> counts;
  std::atomic<size_t> next_solid{0};
  countClaimedSolids(scene, camera, only_touching, next_solid, counts);
  return counts;
}

void RayCaster::countClaimedSolids(const SceneGeometry& scene, const Camera& camera, const PixelRect* only_touching,
                                   std::atomic<size_t>& next_solid, std::vector<int>& counts) const {
  // Rays only inside each solid's footprint, by the same formula (and order
  // of operations) as prepareRayRows, so the counts are those of full rays.
  // A row of rays is a plane through the camera; the part of a convex solid
  // in front of the camera, above the ground and within range is convex, so
  // the pixels of a row that see it are one run. Each row's run is found
  // from its ends, starting from the run of the row above: the cost follows
  // the solid's outline, not its area (a solid filling the view was
  // 170 000 rays a tick in the wide camera).
  counts.assign(std::max(scene.objectCount(), 0), 0);
  const CameraFrame& f = camera_frame_;
  const Eigen::Vector3d& o = f.origin;
  const double range = camera.intrinsics.range;
  const std::vector<Solid>& solids = scene.solids();
  for (size_t s = next_solid.fetch_add(1); s < solids.size(); s = next_solid.fetch_add(1)) {
    const Solid& solid = solids[s];
    if (solid.object_index < 0 || solid.object_index >= static_cast<int>(counts.size())) continue;
    SolidFootprint footprint;
    if (!projectSolid(solid, footprint)) continue;
    if (only_touching != nullptr &&
        (footprint.u1 < only_touching->u0 || footprint.u0 > only_touching->u1 || footprint.v1 < only_touching->v0 ||
         footprint.v0 > only_touching->v1))
      continue;
    int count = 0;
    int run_first = -1, run_last = -1;  // the row above's run; -1: it had none
    for (int v = footprint.v0; v <= footprint.v1; ++v) {
      const double b = row_b_[v];
      const double row_x = f.forward.x() + b * f.up.x(), row_y = f.forward.y() + b * f.up.y(),
                   row_z = f.forward.z() + b * f.up.z();
      const double t_ground = (row_z < 0 && o.z() > 0) ? -o.z() / row_z : SceneGeometry::kInfinity;
      const auto sees = [&](int u) {
        const double a = column_a_[u];
        const Eigen::Vector3d d(row_x + a * f.left.x(), row_y + a * f.left.y(), row_z);
        const double t_range = range * inverseRayLength(a, b);
        const double t_limit = t_ground <= t_range ? t_ground : t_range;
        LineInterval interval;
        return intersectLine(solid, o, d, interval) && interval.enter >= kMinDepth && interval.enter <= t_limit;
      };
      int first = -1;
      if (run_first >= 0 && sees(run_first)) {
        for (first = run_first; first > footprint.u0 && sees(first - 1);) --first;
      } else {
        for (int u = footprint.u0; u <= footprint.u1; ++u)
          if (sees(u)) {
            first = u;
            break;
          }
      }
      if (first < 0) {
        run_first = run_last = -1;
        continue;
      }
      int last = first;
      if (run_last > first && sees(run_last)) {
        for (last = run_last; last < footprint.u1 && sees(last + 1);) ++last;
      } else {
        for (int u = footprint.u1; u > first; --u)
          if (sees(u)) {
            last = u;
            break;
          }
      }
      count += last - first + 1;
      run_first = first;
      run_last = last;
    }
    counts[solid.object_index] += count;
  }
}

void RayCaster::prepareExpectedInView(const Camera& real) {
  expected_wide_ = withoutViewLimits(real);
  expected_image_ = PixelRect{};
  expected_image_.u0 = (expected_wide_.intrinsics.width - real.intrinsics.width) / 2;
  expected_image_.v0 = (expected_wide_.intrinsics.height - real.intrinsics.height) / 2;
  expected_image_.u1 = expected_image_.u0 + real.intrinsics.width - 1;
  expected_image_.v1 = expected_image_.v0 + real.intrinsics.height - 1;
  prepareCamera(expected_wide_);
}

void RayCaster::countExpected(const SceneGeometry& scene, std::atomic<size_t>& next_solid,
                              std::vector<int>& counts) const {
  countClaimedSolids(scene, expected_wide_, &expected_image_, next_solid, counts);
}

std::vector<int> RayCaster::expectedPixelsInView(const SceneGeometry& scene, const Camera& real) {
  prepareExpectedInView(real);
  std::vector<int> counts;
  std::atomic<size_t> next_solid{0};
  countExpected(scene, next_solid, counts);
  return counts;
}

RenderedFrame renderFrame(const SceneGeometry& scene, const Camera& camera, RenderMethod method) {
  RayCaster caster;
  RenderedFrame frame;
  caster.render(scene, camera, frame, method);
  return frame;
}

std::vector<int> expectedPixelsPerObject(const SceneGeometry& scene, const Camera& camera) {
  RayCaster caster;
  return caster.expectedPixelsPerObject(scene, camera);
}

}  // namespace beft::camera
