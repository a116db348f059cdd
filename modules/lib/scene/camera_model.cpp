#include "lib/scene/camera_model.hpp"

#include <cmath>

#include <beft/camera_frame_t.hpp>
#include <beft/robot_state_t.hpp>

namespace beft::camera {

namespace {
constexpr double kDegToRad = M_PI / 180.0;
}

CameraFrame::CameraFrame(const Camera& camera) {
  const double yaw = camera.pose.yaw_deg * kDegToRad;
  const double pitch = camera.pose.pitch_deg * kDegToRad;
  const double cy_ = std::cos(yaw), sy_ = std::sin(yaw);
  const double cp = std::cos(pitch), sp = std::sin(pitch);
  origin = Eigen::Vector3d(camera.pose.x, camera.pose.y, camera.pose.z);
  forward = Eigen::Vector3d(cp * cy_, cp * sy_, sp);
  left = Eigen::Vector3d(-sy_, cy_, 0.0);
  up = Eigen::Vector3d(-sp * cy_, -sp * sy_, cp);
  focal = focalLengthPx(camera.intrinsics.fov_deg, camera.intrinsics.width);
  cx = 0.5 * camera.intrinsics.width;
  cy = 0.5 * camera.intrinsics.height;
}

Camera withoutViewLimits(const Camera& camera, int widen) {
  Camera wide = camera;
  const double half_tan = std::tan(0.5 * camera.intrinsics.fov_deg * kDegToRad) * widen;
  wide.intrinsics.fov_deg = 2.0 * std::atan(half_tan) / kDegToRad;
  wide.intrinsics.width = camera.intrinsics.width * widen;
  wide.intrinsics.height = camera.intrinsics.height * widen;
  wide.intrinsics.range = 1e5;  // beyond any world: range no longer limits
  return wide;
}

double focalLengthPx(double fov_deg, int width) {
  return 0.5 * width / std::tan(0.5 * fov_deg * kDegToRad);
}

Camera cameraOnRobot(double robot_x, double robot_y, double robot_yaw_deg, double head_yaw_deg,
                     double head_pitch_deg, double camera_height, const CameraIntrinsics& intrinsics) {
  Camera camera;
  camera.pose.x = robot_x;
  camera.pose.y = robot_y;
  camera.pose.z = camera_height;
  camera.pose.yaw_deg = robot_yaw_deg + head_yaw_deg;
  camera.pose.pitch_deg = head_pitch_deg;
  camera.intrinsics = intrinsics;
  return camera;
}

Camera cameraOnRobot(const beft::robot_state_t& state, const CameraIntrinsics& intrinsics) {
  return cameraOnRobot(state.x, state.y, state.yaw, state.head_yaw, state.head_pitch, state.camera_height,
                       intrinsics);
}

Camera cameraOfFrame(const beft::camera_frame_t& frame) {
  Camera camera;
  camera.pose = {frame.cam_x, frame.cam_y, frame.cam_z, frame.cam_yaw, frame.cam_pitch};
  camera.intrinsics = {frame.fov, frame.width, frame.height, frame.range};
  return camera;
}

Eigen::Vector3d imagePointRay(const CameraFrame& frame, double x, double y) {
  // Summed as (forward + b up) + a left: the renderer builds rays row by row
  // in this order, so its rays equal these bit for bit.
  const double a = (frame.cx - x) / frame.focal, b = (frame.cy - y) / frame.focal;
  return Eigen::Vector3d(frame.forward.x() + b * frame.up.x() + a * frame.left.x(),
                         frame.forward.y() + b * frame.up.y() + a * frame.left.y(),
                         frame.forward.z() + b * frame.up.z() + a * frame.left.z());
}

Eigen::Vector3d pixelRay(const CameraFrame& frame, int u, int v) {
  return imagePointRay(frame, u + 0.5, v + 0.5);
}

Eigen::Vector3d pixelRay(const Camera& camera, int u, int v) {
  return pixelRay(CameraFrame(camera), u, v);
}

Eigen::Vector3d backProject(const Camera& camera, int u, int v, double depth) {
  const CameraFrame frame(camera);
  return frame.origin + depth * pixelRay(frame, u, v);
}

std::optional<ImagePoint> projectPoint(const Camera& camera, const Eigen::Vector3d& world_point) {
  const CameraFrame frame(camera);
  const Eigen::Vector3d q = world_point - frame.origin;
  const double depth = q.dot(frame.forward);
  if (!(depth > 0)) return std::nullopt;
  ImagePoint point;
  point.depth = depth;
  point.x = frame.cx - frame.focal * q.dot(frame.left) / depth;
  point.y = frame.cy - frame.focal * q.dot(frame.up) / depth;
  return point;
}

bool inImage(const Camera& camera, const ImagePoint& point) {
  return point.x >= 0 && point.y >= 0 && point.x < camera.intrinsics.width && point.y < camera.intrinsics.height;
}

}  // namespace beft::camera
