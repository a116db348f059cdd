// What the robot's two ears hear during one block of simulated time: every
// sound source filtered by the head-related impulse responses of its
// direction, delayed and attenuated by its distance, muffled by what stands
// in its way, summed, plus the microphones' noise.
//
// Stateless: a block is computed from the sources' looped signals alone,
// with enough of their history before the block for the filters, so block k
// rendered by itself (by a restarted process, say) equals block k of one
// long rendering (to float rounding, ~1e-6).
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "lib/hearing/hrir_set.hpp"
#include "lib/hearing/occlusion_filter.hpp"

namespace beft::hearing {

class RoomModel;

struct SourceSignal {             // a mono sound, looped from t = 0 of the run
  std::vector<float> samples;     // at the renderer's sample rate
};

struct RenderedSource {
  const SourceSignal* signal = nullptr;  // not owned
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // world frame [m]
  double level = 1.0;             // linear gain of the source [-]
  double occlusion = 0.0;         // O_a in [0,1]: share of source-to-ear lines blocked [-]
  int room_owner = -1;            // the object it belongs to in the room (RoomModel's boxes' owner), -1: none
};

struct HeadPose {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // midpoint between the ears, world frame [m]
  double yaw_deg = 0;             // world heading of the nose, CCW from +x [deg]
};

struct BlockRequest {
  int64_t first_sample = 0;       // absolute sample index of the block's first sample (tick * block length)
  int num_samples = 4410;         // 0.1 s at 44.1 kHz
  HeadPose previous, current;     // pose at the start and end of the block: cross-faded
  std::vector<RenderedSource> sources;
  uint64_t noise_seed = 0;        // sensor noise: a function of (seed, absolute sample index)
  double noise_rms = 1e-4;        // sensor noise level [-]
  // The room the sources are heard in (not owned); null: the free field,
  // direct sound only, rendered exactly as without rooms.
  const RoomModel* room = nullptr;
  bool direct_sound = true;       // false: the room's contribution alone (impulse responses, tests)
};

struct StereoBlock {
  std::vector<float> left, right;
};

class BinauralRenderer {
 public:
  static constexpr double kSpeedOfSound = 343.0;  // [m/s]
  static constexpr double kMinDistance = 0.3;     // 1/r and the delay use at least this [m]
  static constexpr double kMaxBlockSeconds = 600; // longer requests are refused

  // Throws std::invalid_argument if the HRIR set's sample rate is not
  // sample_rate (resample the set first).
  explicit BinauralRenderer(HrirSet hrirs, double sample_rate = 44100, OcclusionModel occlusion = {});

  // Deterministic, no state between calls; safe to call from several threads
  // (scratch buffers are per thread). Throws std::invalid_argument naming
  // the field for a request it cannot render: a negative or huge
  // num_samples, a source without samples, a value that is not finite,
  // occlusion outside [0, 1], a negative level or noise_rms.
  //
  // Per source: head-relative azimuth atan2(source - centre) - yaw
  // (elevation ignored: the HRIRs are horizontal); gain level / r with r the
  // 3-D distance, at least kMinDistance (1/r relative to 1 m); the signal
  // read at t - r / c (fractional, looped); the occlusion low-pass and gain.
  // When the pose changes within the block, the distance's gain and delay
  // move linearly from the previous pose's to the current one's, and the
  // outputs through the previous and the current HRIRs are cross-faded
  // with a raised cosine, so a turning head makes no clicks.
  //
  // In a room (request.room), also each source's early reflections, every
  // image source (RoomModel::imageSources, for each pose) heard from its
  // own direction through its own HRIRs, delayed by its path (fractional,
  // Catmull-Rom), attenuated by 1 / path and sqrt(1 - absorption) per
  // bounce, not occluded (its path is clear), the poses cross-faded as the
  // direct sound's are; and the room's diffuse tail, the sum of the
  // sources (each level times the room's tail amplitude, read at its direct
  // delay plus the tail's onset) through the tail's two responses.
  StereoBlock render(const BlockRequest& request) const;
  // The same into `out`, reusing its buffers.
  void render(const BlockRequest& request, StereoBlock& out) const;

  const HrirSet& hrirs() const { return hrirs_; }
  double sampleRate() const { return sample_rate_; }
  const OcclusionModel& occlusionModel() const { return occlusion_; }
  // Samples of a source's past before the block that its output depends on.
  int historySamples() const { return filter_length_ - 1; }

  // Azimuth [deg] of a world point as the head sees it, in (-180, 180],
  // counter-clockwise, 0 = the nose.
  static double headAzimuthDeg(const HeadPose& pose, const Eigen::Vector3d& point);

 private:
  void renderChunk(const BlockRequest& request, bool turning, int chunk_start, int chunk, StereoBlock& out) const;
  // room_rendering.cpp: the room's early reflections and tail, added to out.
  void addRoom(const BlockRequest& request, bool turning, StereoBlock& out) const;
  void addEarlyReflections(const BlockRequest& request, bool turning, StereoBlock& out) const;
  void addTail(const BlockRequest& request, bool turning, StereoBlock& out) const;

  HrirSet hrirs_;
  double sample_rate_;
  OcclusionModel occlusion_;
  int filter_length_;     // HRIR and occlusion low-pass in series
  double read_advance_;   // samples the signal is read ahead: the set's centre delay and the low-pass's delay
};

}  // namespace beft::hearing
