#include "lib/camera/pixel_filters.hpp"

#include <algorithm>

namespace beft::camera {

void subFilter(const uint8_t* in, uint8_t* out, std::size_t row_bytes, std::size_t rows, int bytes_per_pixel) {
  const std::size_t step = std::min<std::size_t>(static_cast<std::size_t>(bytes_per_pixel), row_bytes);
  for (std::size_t r = 0; r < rows; ++r) {
    const uint8_t* row = in + r * row_bytes;
    uint8_t* filtered = out + r * row_bytes;
    for (std::size_t i = 0; i < step; ++i)
      filtered[i] = static_cast<uint8_t>(r == 0 ? row[i] : row[i] - row[i - row_bytes]);
    for (std::size_t i = step; i < row_bytes; ++i) filtered[i] = static_cast<uint8_t>(row[i] - row[i - step]);
  }
}

void undoSubFilter(uint8_t* bytes, std::size_t row_bytes, std::size_t rows, int bytes_per_pixel) {
  const std::size_t step = std::min<std::size_t>(static_cast<std::size_t>(bytes_per_pixel), row_bytes);
  for (std::size_t r = 0; r < rows; ++r) {
    uint8_t* row = bytes + r * row_bytes;
    if (r > 0)
      for (std::size_t i = 0; i < step; ++i) row[i] = static_cast<uint8_t>(row[i] + row[i - row_bytes]);
    for (std::size_t i = step; i < row_bytes; ++i) row[i] = static_cast<uint8_t>(row[i] + row[i - step]);
  }
}

void upFilter(const uint8_t* in, uint8_t* out, std::size_t row_bytes, std::size_t rows) {
  if (rows == 0) return;
  std::copy_n(in, row_bytes, out);
  for (std::size_t i = row_bytes; i < row_bytes * rows; ++i) out[i] = static_cast<uint8_t>(in[i] - in[i - row_bytes]);
}

void undoUpFilter(uint8_t* bytes, std::size_t row_bytes, std::size_t rows) {
  for (std::size_t i = row_bytes; i < row_bytes * rows; ++i)
    bytes[i] = static_cast<uint8_t>(bytes[i] + bytes[i - row_bytes]);
}

}  // namespace beft::camera
