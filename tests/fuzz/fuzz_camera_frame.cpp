// The camera frame decoder (frame_decoding.hpp) on any bytes: as a whole
// received message (the guard, then the decoder), and as the payload behind a
// well-formed header (the first byte picks encoding, compression and size),
// so the fuzzer reaches zstd at once. Whatever it accepts holds exactly its
// pixels; nothing it is given may crash it or make it allocate beyond them.
#include <cstdint>
#include <cstdlib>
#include <string>

#include <beft/camera_frame_t.hpp>

#include "lib/camera/camera_messages.hpp"
#include "lib/camera/frame_decoding.hpp"
#include "lib/wire/guarded_decode.hpp"

namespace {

void decodeAndCheck(beft::camera_frame_t& frame) {
  const beft::camera_frame_t original = frame;
  std::string why;
  if (beft::camera::decodeCameraFrame(frame, &why)) {
    if (!beft::camera::validCameraFrame(frame, &why)) std::abort();  // accepted, so it must hold its pixels
  } else if (frame.data != original.data || frame.compression != original.compression) {
    std::abort();  // a refusal leaves the frame as it was
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  beft::camera_frame_t frame{};
  if (beft::wire::guardedDecode(data, size, frame).ok()) decodeAndCheck(frame);
  if (size == 0) return 0;
  static const int kSizes[][2] = {{160, 120}, {16, 8}, {1, 1}, {3, 2}};
  const uint8_t choice = data[0];
  beft::camera_frame_t header{};
  header.encoding = static_cast<int8_t>(choice % 3);
  header.compression = static_cast<int8_t>((choice / 3) % 5);  // 4: no such compression
  header.width = kSizes[(choice / 15) % 4][0];
  header.height = kSizes[(choice / 15) % 4][1];
  header.data.assign(data + 1, data + size);
  header.data_size = static_cast<int32_t>(header.data.size());
  decodeAndCheck(header);
  return 0;
}
