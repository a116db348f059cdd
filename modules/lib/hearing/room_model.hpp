// The room a scene makes for the ears: the faces of its solids and the
// ground, off which sound reflects (early reflections, by image sources),
// and a diffuse late tail of a given T60 (late_reverb.hpp). Built from plain
// boxes, so nothing here reads a scenario or a scene message: sim/ears turns
// the scene's solids into ReflectingBoxes, the bench builds its rooms by
// hand.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "lib/hearing/hrir_set.hpp"
#include "lib/hearing/late_reverb.hpp"

namespace beft::hearing {

// A vertical box standing on z_min, turned by yaw: a wall, a car, debris; a
// cylinder enters as its bounding box (the scenario format's "cylinders'
// bounding faces").
struct ReflectingBox {
  double x = 0, y = 0;            // footprint centre [m]
  double yaw_deg = 0;             // CCW from +x [deg]
  double size_x = 0, size_y = 0;  // full extents along its own axes [m]
  double z_min = 0, z_max = 0;    // base and top [m]
  double absorption = 0.2;        // share of sound energy each face absorbs, [0, 1]
  int owner = -1;                 // the object it belongs to: a source of that object is neither
                                  // reflected nor blocked by it (the source stands inside)
};

// One plane rectangle that reflects: centre, outward normal, two in-plane
// axes and half extents along them (infinite for the ground).
struct ReflectingFace {
  Eigen::Vector3d centre, normal, u, v;
  double half_u = 0, half_v = 0;
  double absorption = 0;
  int box = -1;    // index into the room's boxes; -1: the ground
  int owner = -1;  // the box's owner
};

// A reflected path from a source to the listener.
struct ImageSource {
  Eigen::Vector3d position;  // the mirror image: the last leg arrives from its direction
  double path_m = 0;         // length of the whole path = |image - listener| [m]
  double amplitude = 1;      // product over the bounces of sqrt(1 - absorption) [-]
  int order = 0;             // bounces
};

struct RoomSettings {
  int reflection_order = 0;        // 0..4: image sources up to this many bounces
  bool ground = true;              // the plane z = 0 reflects
  double ground_absorption = 0.2;  // [0, 1]
  double t60_s = 0;                // diffuse tail's reverberation time; 0: no tail [s]
  // The room's volume for the energy balance of the tail [m^3]; 0: the
  // bounding box of the boxes' footprints times their height (at least 2.5 m).
  double volume_m3 = 0;
  double max_path_m = 80;          // longer reflected paths are dropped [m]
  uint64_t seed = 1;               // of the tail's noise
};

class RoomModel {
 public:
  // hrirs and sample_rate shape the tail (its diffuse-field coherence and
  // spectrum); throws std::invalid_argument on an order outside 0..4, an
  // absorption outside [0, 1], a T60 outside [0, 10] or a box that is not
  // finite and positive.
  RoomModel(std::vector<ReflectingBox> boxes, const RoomSettings& settings, const HrirSet& hrirs,
            double sample_rate);

  // The same room (settings, tail) with other boxes: the scene's solids of
  // another tick, without making the tail again.
  RoomModel rebuilt(std::vector<ReflectingBox> boxes) const;

  const RoomSettings& settings() const { return settings_; }
  const std::vector<ReflectingBox>& boxes() const { return boxes_; }
  const std::vector<ReflectingFace>& faces() const { return faces_; }

  // Every reflected path from `source` to `listener` up to the reflection
  // order (Allen and Berkley 1979 for a shoebox; Borish 1984, JASA 75(6),
  // for any polyhedral scene): the source mirrored in a face's plane,
  // x' = x - 2 ((x - c) . n) n, for each sequence of faces whose every image
  // lies in front of the next face; then checked by tracing back from the
  // listener that each leg meets its face inside the face's rectangle and
  // that no box (except the source owner's) stands on any leg. Order
  // first, then the faces' order; deterministic.
  std::vector<ImageSource> imageSources(const Eigen::Vector3d& source, int source_owner,
                                        const Eigen::Vector3d& listener) const;

  // Whether the segment a -> b passes through a box other than the owner's
  // (ends excluded by a millimetre, so a leg that starts on a face is not
  // blocked by the face itself).
  bool blocked(const Eigen::Vector3d& a, const Eigen::Vector3d& b, int ignore_owner) const;

  // The tail (null without one) and its amplitude relative to the direct
  // sound of the same source heard at 1 m: Sabine's diffuse field, energy
  // density 4W/(cR), R = A / (1 - a) and A = 0.161 V / T60 (Kuttruff, Room
  // Acoustics, 5th ed., eqs. 5.37 and 5.42), so the reverberant-to-direct
  // energy at 1 m is 16 pi (1 - a) / A; the tail carries the part after its
  // onset (late_reverb.hpp).
  const LateReverb* tail() const { return tail_.get(); }
  double tailAmplitude() const { return tail_amplitude_; }
  double volume() const { return volume_; }
  double meanAbsorption() const { return mean_absorption_; }

 private:
  void setBoxes(std::vector<ReflectingBox> boxes);
  void setTailAmplitude();
  void addFaces(const ReflectingBox& box, int index);
  bool validPath(const std::vector<int>& sequence, const std::vector<Eigen::Vector3d>& images,
                 const Eigen::Vector3d& listener, int source_owner) const;

  std::vector<ReflectingBox> boxes_;
  RoomSettings settings_;
  std::vector<ReflectingFace> faces_;
  std::shared_ptr<const LateReverb> tail_;
  double tail_amplitude_ = 0;
  double volume_ = 0;
  double mean_absorption_ = 0;
};

// Reverberation time predictions for a closed room of volume V [m^3],
// surface S [m^2] and mean absorption a: Sabine, T = 0.161 V / (S a), and
// Eyring, T = 0.161 V / (-S ln(1 - a)) (Kuttruff, eqs. 5.24 and 5.31;
// 0.161 = 24 ln 10 / 343 s/m).
double sabineT60(double volume_m3, double surface_m2, double absorption);
double eyringT60(double volume_m3, double surface_m2, double absorption);

}  // namespace beft::hearing
