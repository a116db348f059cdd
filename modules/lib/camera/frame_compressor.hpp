// Camera frames packed for the wire: lossless, each frame on its own (a lost
// or unrecorded frame costs no other), fast enough for every tick of a
// lockstep run. Readers unpack them with decodeCameraFrame
// (frame_decoding.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include <beft/camera_frame_t.hpp>

#include "lib/camera/camera_messages.hpp"

struct ZSTD_CCtx_s;

namespace beft::camera {

// How frames of one encoding are packed: a COMPRESSION_* and the zstd level.
struct Packing {
  int8_t compression = beft::camera_frame_t::COMPRESSION_NONE;
  int level = 0;
};

// The packing chosen for an encoding (measured in frame_compressor.cpp).
Packing packingFor(int8_t encoding);

class FrameCompressor {
 public:
  FrameCompressor();
  ~FrameCompressor();
  FrameCompressor(const FrameCompressor&) = delete;
  FrameCompressor& operator=(const FrameCompressor&) = delete;

  // packed := raw with its pixels packed as packingFor(raw.encoding) says.
  // raw must hold its pixels (validCameraFrame); std::invalid_argument if not.
  void compress(const beft::camera_frame_t& raw, beft::camera_frame_t& packed);
  // The same with an explicit packing (COMPRESSION_NONE copies the pixels).
  void compress(const beft::camera_frame_t& raw, const Packing& packing, beft::camera_frame_t& packed);
  // The three frames of a tick.
  void compress(const CameraMessages& raw, CameraMessages& packed);

 private:
  ZSTD_CCtx_s* context_;          // kept: making one costs more than packing a small frame
  std::vector<uint8_t> filtered_;  // the pixels after the SUB or UP filter
};

}  // namespace beft::camera
