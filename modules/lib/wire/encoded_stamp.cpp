#include "lib/wire/encoded_stamp.hpp"

namespace beft::wire {

namespace {
bool int64At(const uint8_t* data, std::size_t size, std::size_t offset, int64_t& value) {
  if (data == nullptr || size < offset + 8) return false;
  uint64_t read = 0;
  for (std::size_t i = offset; i < offset + 8; ++i) read = (read << 8) | data[i];
  value = static_cast<int64_t>(read);
  return true;
}
}  // namespace

bool encodedUtime(const uint8_t* data, std::size_t size, int64_t& utime) { return int64At(data, size, 8, utime); }
bool encodedTick(const uint8_t* data, std::size_t size, int64_t& tick) { return int64At(data, size, 16, tick); }

}  // namespace beft::wire
