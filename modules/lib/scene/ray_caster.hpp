// The RGBD camera: a CPU ray caster over the scene's boxes and cylinders,
// a ground plane at z = 0 and a sky, for one camera pose (camera_model.hpp).
//
// Per pixel it reports the depth (z-depth, metres), the object seen (index
// into the ground-truth list; -1 for ground or sky) and a colour (the object's
// colour shaded by surface normal and distance, a ground colour with a faint
// 1 m checker, a sky gradient). The ground gives depth but no object.
//
// Three methods give the same images (tests check it), at different speeds:
// - Projection (default): each solid's bounding box is projected into the
//   image and only the pixels it covers are ray-tested, nearest solids first,
//   skipping pixels already covered by something nearer. Cost grows with the
//   image area the visible solids cover, hardly with their number.
// - GridTraversal: each pixel's ray walks the 2-D grid cells under it and
//   stops at the first cell holding a hit.
// - BruteForce: every solid for every ray (the baseline).
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "lib/scene/camera_model.hpp"
#include "lib/scene/row_workers.hpp"
#include "lib/scene/scene_geometry.hpp"

namespace beft::camera {

enum class RenderMethod { Projection, GridTraversal, BruteForce };
const char* renderMethodName(RenderMethod method);

// Surfaces nearer than this (z-depth) are not seen [m].
inline constexpr double kMinDepth = 1e-3;

struct RenderedFrame {
  Camera camera;
  int width = 0, height = 0;
  std::vector<float> depth;      // z-depth [m] per pixel, 0 = no return within range
  std::vector<int32_t> object;   // object index per pixel, -1 = none (ground or sky)
  std::vector<uint8_t> rgb;      // 3 bytes per pixel
  // Pixels are row-major, row 0 at the top: pixel (u, v) is element v * width + u.
};

// Where a render puts its pixels, one finished row at a time (rows may come
// from several threads at once, never the same row twice).
class FrameRowWriter {
 public:
  virtual ~FrameRowWriter() = default;
  // Row v: width z-depths [m] (0 = no return), object indices (-1 = none)
  // and 3 * width RGB bytes.
  virtual void writeRow(int v, const float* depth, const int32_t* object, const uint8_t* rgb) = 0;
};

// Keeps its tables between frames; one instance per thread (it may use
// helper threads of its own, see setThreads).
class RayCaster {
 public:
  void render(const SceneGeometry& scene, const Camera& camera, RenderedFrame& frame,
              RenderMethod method = RenderMethod::Projection);
  // The same pixels, handed to a writer row by row (no whole-image buffer).
  void render(const SceneGeometry& scene, const Camera& camera, FrameRowWriter& writer,
              RenderMethod method = RenderMethod::Projection);
  // Threads a Projection render splits its rows over (1: the caller's only).
  // The image is the same for any count.
  void setThreads(int threads);
  int threads() const;
  // For each object index, the number of pixels whose ray meets that object
  // within range if every other object were absent (the denominator of the
  // visual occlusion O_v). Objects without a solid get 0. With `only_touching`
  // (pixel columns u0..u1, rows v0..v1 of this camera), only the solids whose
  // projection reaches into that rectangle are counted, the others get 0:
  // for a widened camera, the objects the real image cannot show at all.
  struct PixelRect {
    int u0 = 0, v0 = 0, u1 = -1, v1 = -1;
  };
  std::vector<int> expectedPixelsPerObject(const SceneGeometry& scene, const Camera& camera,
                                           const PixelRect* only_touching = nullptr);
  // The same as the vision expert counts them (spec/model.md, O_v): without
  // the image's borders and range (what falls outside them counts as
  // occluded), and 0 for the objects the real image cannot show at all.
  std::vector<int> expectedPixelsInView(const SceneGeometry& scene, const Camera& real);

  // expectedPixelsInView shared between threads: after prepareExpectedInView,
  // every thread calls countExpected with its own counts (any number of
  // threads, concurrently); each counts the solids it claims from
  // `next_solid` until none is left. The counts summed are
  // expectedPixelsInView's, however the solids fell to the threads.
  void prepareExpectedInView(const Camera& real);
  void countExpected(const SceneGeometry& scene, std::atomic<size_t>& next_solid, std::vector<int>& counts) const;

 private:
  struct SolidFootprint;  // a solid's covered pixel rectangle and nearest depth
  struct RowRays;         // one image row's rays and nearest hits (per thread, reused)
  // The camera's frame, frustum and per-intrinsics tables.
  void prepareCamera(const Camera& camera);
  // Row v's rays and distance limits; nothing hit yet.
  void prepareRow(int v, RowRays& row) const;
  bool projectSolid(const Solid& solid, SolidFootprint& footprint) const;
  // The solids in view, nearest first, with the pixels they can cover.
  std::vector<SolidFootprint> visibleFootprints(const SceneGeometry& scene) const;
  void castProjectionRow(const SceneGeometry& scene, const std::vector<SolidFootprint>& visible, int v,
                         RowRays& row) const;
  void castPerRayRow(const SceneGeometry& scene, bool use_grid, RowRays& row) const;
  // The solids' colours of this frame.
  void prepareColours(const SceneGeometry& scene);
  // Depth, object and colour of row v's pixels into the row's own buffers.
  void shadeRow(const SceneGeometry& scene, RowRays& row) const;

  // Counts into `counts` the solids claimed from next_solid (camera prepared).
  void countClaimedSolids(const SceneGeometry& scene, const Camera& camera, const PixelRect* only_touching,
                          std::atomic<size_t>& next_solid, std::vector<int>& counts) const;

  Camera camera_;
  CameraFrame camera_frame_{Camera{}};
  Camera expected_wide_;           // of prepareExpectedInView
  PixelRect expected_image_;       // the real image on expected_wide_'s plane
  int width_ = 0, height_ = 0;
  // Depend on the intrinsics only: per column a = (cx - (u + 0.5)) / f, per
  // row b likewise.
  std::vector<double> column_a_, row_b_;
  bool tables_ready_ = false;
  // Inward unit normals of the view frustum's four side planes.
  Eigen::Vector3d frustum_normals_[4];
  std::vector<std::array<float, 3>> solid_colours_;  // RGB per solid of the frame being rendered
  std::unique_ptr<RowWorkers> workers_;  // none: one thread
};

// One-off helpers (allocate a RayCaster each call).
RenderedFrame renderFrame(const SceneGeometry& scene, const Camera& camera,
                          RenderMethod method = RenderMethod::Projection);
std::vector<int> expectedPixelsPerObject(const SceneGeometry& scene, const Camera& camera);

}  // namespace beft::camera
