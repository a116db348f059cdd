// Row filters over the bytes of an image, and their inverses (camera_frame_t
// COMPRESSION_ZSTD_SUB / _UP), after PNG's "sub" and "up": each byte minus,
// modulo 256, the byte one pixel to its left (SUB; in the first column the
// one a row above, which predicts a row's start better than PNG's 0) or one
// row above (UP), 0 outside the image. Smooth images become runs of small,
// repeated values that zstd packs tighter. One filter for the whole image (no
// per-row choice to record): undoing it needs only the image's size.
#pragma once

#include <cstddef>
#include <cstdint>

namespace beft::camera {

// out[i] = in[i] - in[i - bytes_per_pixel] within each row of row_bytes; the
// first pixel of a row minus the one above it.
void subFilter(const uint8_t* in, uint8_t* out, std::size_t row_bytes, std::size_t rows, int bytes_per_pixel);
// The inverse, in place.
void undoSubFilter(uint8_t* bytes, std::size_t row_bytes, std::size_t rows, int bytes_per_pixel);

// out[i] = in[i] - in[i - row_bytes].
void upFilter(const uint8_t* in, uint8_t* out, std::size_t row_bytes, std::size_t rows);
// The inverse, in place.
void undoUpFilter(uint8_t* bytes, std::size_t row_bytes, std::size_t rows);

}  // namespace beft::camera
