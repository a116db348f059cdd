#include "lib/hearing/room_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace beft::hearing {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kEndMargin = 1e-3;  // a leg's ends are this far clear of what they touch [m]
constexpr double kMinTailOnset = 0.01, kMaxTailOnset = 0.08;  // [s]

void refuse(const std::string& what) { throw std::invalid_argument("RoomModel: " + what); }

bool share(double value) { return value >= 0 && value <= 1; }

Eigen::Vector3d mirrored(const Eigen::Vector3d& point, const ReflectingFace& face) {
  return point - 2 * (point - face.centre).dot(face.normal) * face.normal;
}

double inFront(const Eigen::Vector3d& point, const ReflectingFace& face) {
  return (point - face.centre).dot(face.normal);
}

// Where the segment from -> to crosses the face's plane, if it does so
// inside the face's rectangle.
bool crossesFace(const Eigen::Vector3d& from, const Eigen::Vector3d& to, const ReflectingFace& face,
                 Eigen::Vector3d& point) {
  const double a = inFront(from, face), b = inFront(to, face);
  if (!(a > 0 && b < 0)) return false;
  point = from + (a / (a - b)) * (to - from);
  const Eigen::Vector3d offset = point - face.centre;
  return std::abs(offset.dot(face.u)) <= face.half_u && std::abs(offset.dot(face.v)) <= face.half_v;
}

// Whether the open segment a + t (b - a), t in (t0, t1), enters the box.
bool segmentEntersBox(const ReflectingBox& box, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t0,
                      double t1) {
  const double yaw = box.yaw_deg * kPi / 180, c = std::cos(yaw), s = std::sin(yaw);
  const Eigen::Vector3d d = b - a;
  const double ox = a.x() - box.x, oy = a.y() - box.y;
  const double origin[3] = {c * ox + s * oy, -s * ox + c * oy, a.z()};
  const double direction[3] = {c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z()};
  const double lo[3] = {-box.size_x / 2, -box.size_y / 2, box.z_min};
  const double hi[3] = {box.size_x / 2, box.size_y / 2, box.z_max};
  for (int axis = 0; axis < 3; ++axis) {
    if (direction[axis] == 0) {
      if (origin[axis] <= lo[axis] || origin[axis] >= hi[axis]) return false;
      continue;
    }
    double ta = (lo[axis] - origin[axis]) / direction[axis], tb = (hi[axis] - origin[axis]) / direction[axis];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 >= t1) return false;
  }
  return true;
}

}  // namespace

double sabineT60(double volume_m3, double surface_m2, double absorption) {
  return 0.161 * volume_m3 / (surface_m2 * absorption);
}

double eyringT60(double volume_m3, double surface_m2, double absorption) {
  return 0.161 * volume_m3 / (-surface_m2 * std::log(1 - absorption));
}

RoomModel::RoomModel(std::vector<ReflectingBox> boxes, const RoomSettings& settings, const HrirSet& hrirs,
                     double sample_rate)
    : settings_(settings) {
  if (settings_.reflection_order < 0 || settings_.reflection_order > 4)
    refuse("reflection order " + std::to_string(settings_.reflection_order) + " is outside 0..4");
  if (!share(settings_.ground_absorption)) refuse("ground absorption is outside [0, 1]");
  if (!(settings_.t60_s >= 0 && settings_.t60_s <= 10)) refuse("T60 is outside [0, 10] s");
  if (!(settings_.volume_m3 >= 0) || !std::isfinite(settings_.volume_m3)) refuse("volume is not finite and >= 0");
  if (!(settings_.max_path_m > 0)) refuse("max_path_m must be > 0");
  setBoxes(std::move(boxes));
  if (settings_.t60_s > 0) {
    // Polack's mixing time, sqrt(V) ms (Polack 1988; Lindau et al. 2012, JAES 60(11)).
    const double onset = std::clamp(1e-3 * std::sqrt(volume_), kMinTailOnset,
                                    std::min(kMaxTailOnset, 0.5 * settings_.t60_s));
    tail_ = std::make_shared<const LateReverb>(hrirs, settings_.t60_s, onset, sample_rate, settings_.seed);
  }
  setTailAmplitude();
}

RoomModel RoomModel::rebuilt(std::vector<ReflectingBox> boxes) const {
  RoomModel room = *this;
  room.setBoxes(std::move(boxes));
  room.setTailAmplitude();
  return room;
}

void RoomModel::setBoxes(std::vector<ReflectingBox> boxes) {
  boxes_ = std::move(boxes);
  faces_.clear();
  double min_x = kInfinity, min_y = kInfinity, max_x = -kInfinity, max_y = -kInfinity, top = 2.5;
  double absorbed = 0, area = 0;
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    const ReflectingBox& box = boxes_[i];
    const bool sized = box.size_x > 0 && box.size_y > 0 && box.z_max > box.z_min && std::isfinite(box.x) &&
                       std::isfinite(box.y) && std::isfinite(box.yaw_deg) && std::isfinite(box.size_x) &&
                       std::isfinite(box.size_y) && std::isfinite(box.z_min) && std::isfinite(box.z_max);
    if (!sized) refuse("box " + std::to_string(i) + " is not finite with positive sizes");
    if (!share(box.absorption)) refuse("box " + std::to_string(i) + ": absorption is outside [0, 1]");
    addFaces(box, static_cast<int>(i));
    const double reach = 0.5 * std::hypot(box.size_x, box.size_y);
    min_x = std::min(min_x, box.x - reach), max_x = std::max(max_x, box.x + reach);
    min_y = std::min(min_y, box.y - reach), max_y = std::max(max_y, box.y + reach);
    top = std::max(top, box.z_max);
    const double face_area = 2 * (box.size_x + box.size_y) * (box.z_max - box.z_min) + box.size_x * box.size_y;
    absorbed += face_area * box.absorption;
    area += face_area;
  }
  if (settings_.ground) {
    ReflectingFace ground;
    ground.centre = Eigen::Vector3d::Zero();
    ground.normal = Eigen::Vector3d::UnitZ();
    ground.u = Eigen::Vector3d::UnitX();
    ground.v = Eigen::Vector3d::UnitY();
    ground.half_u = ground.half_v = kInfinity;
    ground.absorption = settings_.ground_absorption;
    faces_.push_back(ground);
  }
  volume_ = settings_.volume_m3 > 0 ? settings_.volume_m3
                                    : (boxes_.empty() ? 100.0 : std::max(1.0, (max_x - min_x) * (max_y - min_y) * top));
  mean_absorption_ = area > 0 ? absorbed / area : settings_.ground_absorption;
}

void RoomModel::setTailAmplitude() {
  tail_amplitude_ = 0;
  if (tail_ == nullptr) return;
  const double equivalent_area = 0.161 * volume_ / settings_.t60_s;  // Sabine's A [m^2]
  const double a = std::min(mean_absorption_, 0.99);
  tail_amplitude_ = std::sqrt(16 * kPi * (1 - a) / equivalent_area);
}

void RoomModel::addFaces(const ReflectingBox& box, int index) {
  const double yaw = box.yaw_deg * kPi / 180;
  const Eigen::Vector3d ax(std::cos(yaw), std::sin(yaw), 0), ay(-std::sin(yaw), std::cos(yaw), 0);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const double hx = box.size_x / 2, hy = box.size_y / 2, hz = (box.z_max - box.z_min) / 2;
  const Eigen::Vector3d centre(box.x, box.y, box.z_min + hz);
  auto add = [&](const Eigen::Vector3d& normal, double distance, const Eigen::Vector3d& u, double half_u,
                 const Eigen::Vector3d& v, double half_v) {
    ReflectingFace face;
    face.centre = centre + distance * normal;
    face.normal = normal;
    face.u = u;
    face.v = v;
    face.half_u = half_u;
    face.half_v = half_v;
    face.absorption = box.absorption;
    face.box = index;
    face.owner = box.owner;
    faces_.push_back(face);
  };
  add(ax, hx, ay, hy, z, hz);
  add(-ax, hx, ay, hy, z, hz);
  add(ay, hy, ax, hx, z, hz);
  add(-ay, hy, ax, hx, z, hz);
  add(z, hz, ax, hx, ay, hy);
  if (box.z_min > 0) add(-z, hz, ax, hx, ay, hy);
}

bool RoomModel::blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int ignore_owner) const {
  const double length = (b - a).norm();
  if (!(length > 2 * kEndMargin)) return false;
  const double t0 = kEndMargin / length, t1 = 1 - t0;
  for (const ReflectingBox& box : boxes_) {
    if (ignore_owner >= 0 && box.owner == ignore_owner) continue;
    if (segmentEntersBox(box, a, b, t0, t1)) return true;
  }
  return false;
}

// images[0] is the source, images[j] its mirror in the faces sequence[0..j).
bool RoomModel::validPath(const std::vector<int>& sequence, const std::vector<Eigen::Vector3d>& images,
                          const Eigen::Vector3d& listener, int source_owner) const {
  Eigen::Vector3d to = listener;
  std::vector<Eigen::Vector3d> points(sequence.size());
  for (std::size_t j = sequence.size(); j-- > 0;) {
    if (!crossesFace(to, images[j + 1], faces_[static_cast<std::size_t>(sequence[j])], points[j])) return false;
    to = points[j];
  }
  Eigen::Vector3d from = images[0];
  for (const Eigen::Vector3d& point : points) {
    if (blocked(from, point, source_owner)) return false;
    from = point;
  }
  return !blocked(from, listener, source_owner);
}

std::vector<ImageSource> RoomModel::imageSources(const Eigen::Vector3d& source, int source_owner,
                                                 const Eigen::Vector3d& listener) const {
  std::vector<ImageSource> found;
  const int order = settings_.reflection_order;
  if (order == 0 || faces_.empty()) return found;
  // Depth-first over face sequences, collected by order afterwards.
  std::vector<int> sequence;
  std::vector<Eigen::Vector3d> images = {source};
  std::vector<double> amplitudes = {1.0};
  std::vector<std::vector<ImageSource>> by_order(static_cast<std::size_t>(order) + 1);
  auto visit = [&](auto&& self) -> void {
    const Eigen::Vector3d image = images.back();  // a copy: images grows below
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
      const ReflectingFace& face = faces_[static_cast<std::size_t>(f)];
      if (!sequence.empty() && sequence.back() == f) continue;
      if (source_owner >= 0 && face.owner == source_owner) continue;
      if (!(inFront(image, face) > 0)) continue;
      const Eigen::Vector3d next = mirrored(image, face);
      // Any path through this sequence and more is at least this long.
      const double distance = (next - listener).norm();
      if (distance > settings_.max_path_m) continue;
      sequence.push_back(f);
      images.push_back(next);
      amplitudes.push_back(amplitudes.back() * std::sqrt(1 - face.absorption));
      if (inFront(listener, face) > 0 && validPath(sequence, images, listener, source_owner))
        by_order[sequence.size()].push_back({next, distance, amplitudes.back(), static_cast<int>(sequence.size())});
      if (static_cast<int>(sequence.size()) < order) self(self);
      sequence.pop_back();
      images.pop_back();
      amplitudes.pop_back();
    }
  };
  visit(visit);
  for (auto& images_of_order : by_order) found.insert(found.end(), images_of_order.begin(), images_of_order.end());
  return found;
}

}  // namespace beft::hearing
