#include "lib/camera/frame_decoding.hpp"

#include <zstd.h>

#include <cstdint>
#include <vector>

#include "lib/camera/camera_messages.hpp"
#include "lib/camera/pixel_filters.hpp"

namespace beft::camera {

namespace {

using Frame = beft::camera_frame_t;

bool refuse(std::string* why, const std::string& reason) {
  if (why) *why = reason;
  return false;
}

// One decompression context per thread, kept: making one costs more than
// decompressing a small frame.
ZSTD_DCtx* threadContext() {
  struct Holder {
    ZSTD_DCtx* context = ZSTD_createDCtx();
    ~Holder() { ZSTD_freeDCtx(context); }
  };
  thread_local Holder holder;
  return holder.context;
}

// RFC 8878: a zstd frame starts with the magic number, then the frame header
// descriptor, whose bit 2 says whether a checksum of the content ends it.
bool hasChecksum(const std::vector<uint8_t>& payload) {
  return payload.size() > 4 && (payload[4] & 0x04) != 0;
}

// Unpacks a compressed payload of the frame into out (expected bytes).
bool unpack(const Frame& frame, int64_t expected, std::vector<uint8_t>& out, std::string* why) {
  const std::vector<uint8_t>& payload = frame.data;
  const std::size_t whole = ZSTD_findFrameCompressedSize(payload.data(), payload.size());
  if (ZSTD_isError(whole)) return refuse(why, std::string("not a zstd frame: ") + ZSTD_getErrorName(whole));
  if (whole != payload.size()) {
    return refuse(why, "zstd frame of " + std::to_string(whole) + " bytes followed by " +
                           std::to_string(payload.size() - whole) + " other bytes");
  }
  const unsigned long long declared = ZSTD_getFrameContentSize(payload.data(), payload.size());
  if (declared == ZSTD_CONTENTSIZE_UNKNOWN || declared == ZSTD_CONTENTSIZE_ERROR)
    return refuse(why, "zstd frame without its content size");
  if (declared != static_cast<unsigned long long>(expected)) {
    return refuse(why, "zstd frame declares " + std::to_string(declared) + " bytes, but " +
                           std::to_string(frame.width) + "x" + std::to_string(frame.height) + " pixels are " +
                           std::to_string(expected));
  }
  if (!hasChecksum(payload)) return refuse(why, "zstd frame without a checksum");
  out.resize(static_cast<std::size_t>(expected));
  // The output buffer bounds the work: decompression stops at its end.
  const std::size_t written =
      ZSTD_decompressDCtx(threadContext(), out.data(), out.size(), payload.data(), payload.size());
  if (ZSTD_isError(written)) return refuse(why, std::string("zstd payload refused: ") + ZSTD_getErrorName(written));
  if (written != out.size()) {
    return refuse(why, "zstd payload decompresses to " + std::to_string(written) + " bytes, " +
                           std::to_string(expected) + " expected");
  }
  const std::size_t row_bytes = static_cast<std::size_t>(expected) / static_cast<std::size_t>(frame.height);
  const std::size_t rows = static_cast<std::size_t>(frame.height);
  if (frame.compression == Frame::COMPRESSION_ZSTD_SUB)
    undoSubFilter(out.data(), row_bytes, rows, bytesPerPixel(frame.encoding));
  if (frame.compression == Frame::COMPRESSION_ZSTD_UP) undoUpFilter(out.data(), row_bytes, rows);
  return true;
}

}  // namespace

bool decodeCameraFrame(Frame& frame, std::string* why) {
  const int64_t expected = pixelBytesOf(frame, why);
  if (expected < 0) return false;
  if (frame.data_size != static_cast<int32_t>(frame.data.size())) {
    return refuse(why, "data_size " + std::to_string(frame.data_size) + " but " +
                           std::to_string(frame.data.size()) + " bytes of data");
  }
  switch (frame.compression) {
    case Frame::COMPRESSION_NONE:
      return validCameraFrame(frame, why);
    case Frame::COMPRESSION_ZSTD:
    case Frame::COMPRESSION_ZSTD_SUB:
    case Frame::COMPRESSION_ZSTD_UP: {
      std::vector<uint8_t> pixels;
      if (!unpack(frame, expected, pixels, why)) return false;
      frame.data.swap(pixels);
      frame.data_size = static_cast<int32_t>(frame.data.size());
      frame.compression = Frame::COMPRESSION_NONE;
      return true;
    }
    default:
      return refuse(why, "unknown compression " + std::to_string(frame.compression));
  }
}

bool decodeCameraFrame(const Frame& received, Frame& pixels, std::string* why) {
  if (&pixels == &received) return decodeCameraFrame(pixels, why);
  Frame copy = received;  // a compressed payload is small; raw pixels are copied once in any case
  if (!decodeCameraFrame(copy, why)) return false;
  pixels = std::move(copy);
  return true;
}

}  // namespace beft::camera
