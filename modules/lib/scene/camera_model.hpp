// The head camera's geometry: where it sits, where it looks, and which ray
// each pixel sees. The world's renderer and every expert that reads camera
// images use these functions, so depth back-projection matches the renderer
// exactly.
//
// Conventions (world frame: x east, y north, z up; angles in degrees):
// - The camera sits over the platform centre: (robot x, robot y,
//   camera height_above_ground).
// - Its optical axis has heading = platform yaw + head yaw (CCW from +x) and
//   elevation = head pitch (up positive). There is no roll.
// - Pinhole with square pixels: focal length f = (width / 2) / tan(fov / 2) in
//   pixels, fov being the horizontal field of view. The principal point is the
//   image centre (width / 2, height / 2).
// - Pixel (u, v): column u from the left, row v from the top (row 0 at the top).
//   It covers the image area [u, u+1) x [v, v+1); its ray passes through the
//   pixel centre (u + 0.5, v + 0.5).
// - Ray direction of image point (x, y):
//       forward + ((cx - x) / f) * left + ((cy - y) / f) * up
//   with forward, left, up the camera's unit axes (see CameraFrame). This
//   direction is NOT normalised: its forward component is 1, so a point at ray
//   parameter t has depth t.
// - Depth is the distance along the optical axis (z-depth, as RGBD cameras
//   report it), not the length of the ray. Range limits the ray length: a
//   surface farther than `range` from the camera gives no return.
#pragma once

#include <optional>

#include <Eigen/Core>

namespace beft {
struct camera_frame_t;
struct robot_state_t;
}  // namespace beft

namespace beft::camera {

struct CameraIntrinsics {
  double fov_deg = 90;   // horizontal field of view [deg], in (0, 180)
  int width = 160;       // [px]
  int height = 120;      // [px]
  double range = 20;     // maximum ray length with a return [m]
};

struct CameraPose {
  double x = 0, y = 0, z = 1.6;  // optical centre, world frame [m]
  double yaw_deg = 0;            // optical axis heading, CCW from +x [deg]
  double pitch_deg = 0;          // optical axis elevation, up positive [deg]
};

struct Camera {
  CameraPose pose;
  CameraIntrinsics intrinsics;
};

// The camera's unit axes and projection constants, derived once per pose.
struct CameraFrame {
  Eigen::Vector3d origin;
  Eigen::Vector3d forward, left, up;  // right-handed: forward x left = up
  double focal = 1;                   // [px]
  double cx = 0, cy = 0;              // principal point [px]
  explicit CameraFrame(const Camera& camera);
};

// The camera of a robot with the given platform pose and head angles.
Camera cameraOnRobot(double robot_x, double robot_y, double robot_yaw_deg, double head_yaw_deg,
                     double head_pitch_deg, double camera_height, const CameraIntrinsics& intrinsics);
// The same from a ROBOT_STATE message (x, y, yaw, head_yaw, head_pitch,
// camera_height).
Camera cameraOnRobot(const beft::robot_state_t& state, const CameraIntrinsics& intrinsics);
// The camera that took a CAMERA_* frame (its pose and intrinsics fields).
Camera cameraOfFrame(const beft::camera_frame_t& frame);

// Focal length in pixels for a horizontal field of view and image width.
double focalLengthPx(double fov_deg, int width);

// The camera an object's whole silhouette is counted with, for the
// denominator of the visual occlusion O_v (spec/model.md: the part of an
// object outside the field of view or beyond range counts as occluded): the
// same optical centre, axis and focal length in pixels, an image plane
// `widen` times as wide and high (centred on the same axis), and no range
// limit within the world.
Camera withoutViewLimits(const Camera& camera, int widen = 3);

// Ray through the centre of pixel (u, v), from the optical centre; forward
// component 1 (see above). Pixels outside the image are allowed.
Eigen::Vector3d pixelRay(const Camera& camera, int u, int v);
Eigen::Vector3d pixelRay(const CameraFrame& frame, int u, int v);
// Ray through the continuous image point (x, y) [px]; pixelRay(u, v) is
// imagePointRay(u + 0.5, v + 0.5).
Eigen::Vector3d imagePointRay(const CameraFrame& frame, double x, double y);

// The world point seen at pixel (u, v) at the given depth [m] (z-depth).
Eigen::Vector3d backProject(const Camera& camera, int u, int v, double depth);

// Where a world point appears: continuous image coordinates (x right, y down,
// pixel (u, v) spans [u, u+1) x [v, v+1)) and its depth. Empty when the point
// is not in front of the camera (depth <= 0). The point may fall outside the
// image; check inImage().
struct ImagePoint {
  double x = 0, y = 0, depth = 0;
};
std::optional<ImagePoint> projectPoint(const Camera& camera, const Eigen::Vector3d& world_point);
bool inImage(const Camera& camera, const ImagePoint& point);

}  // namespace beft::camera
