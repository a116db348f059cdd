#include "lib/wire/lcm_walk.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <map>
#include <vector>

namespace beft::wire {

uint64_t LcmReader::readUnsigned(int bytes, const std::string& field) {
  need(static_cast<std::size_t>(bytes), field);
  uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value = (value << 8) | data_[position_++];
  return value;
}

int64_t LcmReader::readSigned(int bytes, const std::string& field) {
  const uint64_t raw = readUnsigned(bytes, field);
  const int shift = 64 - 8 * bytes;  // sign-extend
  return static_cast<int64_t>(raw << shift) >> shift;
}

double LcmReader::readDouble(const std::string& field) {
  const uint64_t raw = readUnsigned(8, field);
  double value;
  std::memcpy(&value, &raw, sizeof value);
  return value;
}

float LcmReader::readFloat(const std::string& field) {
  const uint32_t raw = static_cast<uint32_t>(readUnsigned(4, field));
  float value;
  std::memcpy(&value, &raw, sizeof value);
  return value;
}

std::string LcmReader::readString(const std::string& field) {
  const int64_t length = readSigned(4, field);  // includes the final '\0'
  if (length < 1) throw LcmWalkError(field + ": string length " + std::to_string(length) + " is invalid");
  need(static_cast<std::size_t>(length), field);
  const char* start = reinterpret_cast<const char*>(data_ + position_);
  position_ += static_cast<std::size_t>(length);
  if (start[length - 1] != '\0') throw LcmWalkError(field + ": string is not terminated");
  return std::string(start, static_cast<std::size_t>(length - 1));
}

void LcmReader::skip(std::size_t bytes, const std::string& field) {
  need(bytes, field);
  position_ += bytes;
}

void LcmReader::need(std::size_t bytes, const std::string& field) const {
  if (bytes > remaining())
    throw LcmWalkError("message ends at byte " + std::to_string(size_) + " while reading " + field + " (" +
                       std::to_string(bytes) + " bytes wanted at byte " + std::to_string(position_) + ")");
}

namespace {

// Arrays of empty arrays a message may hold beyond one per byte left.
constexpr int64_t kMaxEmptyArrays = 1 << 16;

class Walker {
 public:
  Walker(const LcmTypeSet& types, LcmReader& reader, LcmVisitor& visitor)
      : types_(types), reader_(reader), visitor_(visitor) {}

  void walkStruct(const LcmStruct& type) {
    std::map<std::string, int64_t> integers;  // sizes of the variable arrays
    for (const LcmMember& member : type.members) {
      const std::vector<int64_t> sizes = sizesOf(member, integers);
      if (!sizes.empty()) {
        walkArray(member, sizes, 0, member.name);
      } else if (isLcmPrimitive(member.type)) {
        const LcmValue value = readScalar(member.type, member.name);
        if (value.kind == LcmValue::Kind::kInteger) integers[member.name] = value.integer;
        visitor_.scalar(member, member.name, value);
      } else {
        const LcmStruct& nested = structOf(member.type);
        visitor_.beginStruct(member, member.name, nested);
        walkStruct(nested);
        visitor_.endStruct();
      }
    }
  }

 private:
  std::vector<int64_t> sizesOf(const LcmMember& member, const std::map<std::string, int64_t>& integers) const {
    std::vector<int64_t> sizes;
    for (const LcmDimension& dimension : member.dimensions) {
      int64_t size = 0;
      if (dimension.variable) {
        auto it = integers.find(dimension.size);
        if (it == integers.end()) throw LcmWalkError(member.name + ": size member " + dimension.size + " missing");
        size = it->second;
      } else {
        size = std::stoll(dimension.size);
      }
      if (size < 0)
        throw LcmWalkError(member.name + ": length " + dimension.size + " = " + std::to_string(size) +
                           " is negative");
      sizes.push_back(size);
    }
    return sizes;
  }

  const LcmStruct& structOf(const std::string& type) const {
    const LcmStruct* found = types_.find(type);
    if (!found) throw LcmWalkError("unknown member type " + type);
    return *found;
  }

  // Every element takes at least one byte: a length beyond the bytes left
  // is a corrupt message, not a reason to loop for billions of elements.
  // An empty dimension ends the count (nothing below it is read), but the
  // levels above it still loop, byte-free, so they are bounded as well.
  void checkFits(const std::vector<int64_t>& sizes, std::size_t level, const std::string& label) const {
    const int64_t bytes_left = static_cast<int64_t>(reader_.remaining());
    const int64_t too_many = std::max<int64_t>(bytes_left, kMaxEmptyArrays) + 1;
    int64_t elements = 1;  // of the levels so far, at most too_many
    for (std::size_t l = level; l < sizes.size(); ++l) {
      if (sizes[l] == 0) {
        if (elements >= too_many)
          throw LcmWalkError(label + ": " + std::to_string(sizes[level]) + " empty arrays are too many");
        return;
      }
      elements = sizes[l] >= too_many || elements * sizes[l] >= too_many ? too_many : elements * sizes[l];
    }
    if (elements > bytes_left)
      throw LcmWalkError(label + ": " + std::to_string(sizes[level]) + " elements cannot fit in the " +
                         std::to_string(reader_.remaining()) + " bytes left");
  }

  void walkArray(const LcmMember& member, const std::vector<int64_t>& sizes, std::size_t level,
                 const std::string& label) {
    const int64_t count = sizes[level];
    const bool innermost = level + 1 == sizes.size();
    checkFits(sizes, level, label);
    if (innermost && member.type == "byte") {
      const uint8_t* start = reader_.here();
      reader_.skip(static_cast<std::size_t>(count), label);
      visitor_.bytes(member, label, start, static_cast<std::size_t>(count));
      return;
    }
    const bool of_scalars = innermost && isLcmPrimitive(member.type);
    visitor_.beginArray(member, label, count, of_scalars);
    for (int64_t i = 0; i < count; ++i) {
      if (of_scalars) {
        visitor_.scalar(member, label, readScalar(member.type, label));
        continue;
      }
      visitor_.element(i);
      const std::string item_label = label + "[" + std::to_string(i) + "]";
      if (innermost) {
        const LcmStruct& nested = structOf(member.type);
        visitor_.beginStruct(member, item_label, nested);
        walkStruct(nested);
        visitor_.endStruct();
      } else {
        walkArray(member, sizes, level + 1, item_label);
      }
    }
    visitor_.endArray();
  }

  LcmValue readScalar(const std::string& type, const std::string& name) {
    LcmValue value;
    if (type == "double") {
      value.kind = LcmValue::Kind::kDouble;
      value.number = reader_.readDouble(name);
    } else if (type == "float") {
      value.kind = LcmValue::Kind::kFloat;
      value.number = reader_.readFloat(name);
    } else if (type == "string") {
      value.kind = LcmValue::Kind::kString;
      value.text = reader_.readString(name);
    } else if (type == "boolean") {
      value.kind = LcmValue::Kind::kBoolean;
      value.integer = reader_.readSigned(1, name);
    } else if (type == "byte") {
      value.integer = static_cast<int64_t>(reader_.readUnsigned(1, name));  // LCM's byte is uint8_t
    } else {
      const int bytes = type == "int8_t" ? 1 : type == "int16_t" ? 2 : type == "int32_t" ? 4 : 8;
      value.integer = reader_.readSigned(bytes, name);
    }
    return value;
  }

  const LcmTypeSet& types_;
  LcmReader& reader_;
  LcmVisitor& visitor_;
};

std::string hex(uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%016" PRIx64, value);
  return text;
}

}  // namespace

void walkLcmStruct(const LcmTypeSet& types, const LcmStruct& type, LcmReader& reader, LcmVisitor& visitor) {
  Walker(types, reader, visitor).walkStruct(type);
}

void walkLcmMessage(const LcmTypeSet& types, const LcmStruct& type, const uint8_t* data, std::size_t size,
                    LcmVisitor& visitor) {
  if (!data && size > 0) throw LcmWalkError("no bytes");
  LcmReader reader(data, size);
  const uint64_t fingerprint = reader.readUnsigned(8, "fingerprint");
  const uint64_t expected = types.fingerprint(type.fullName());
  if (fingerprint != expected)
    throw LcmWalkError("fingerprint " + hex(fingerprint) + " is not " + type.fullName() + "'s " + hex(expected));
  walkLcmStruct(types, type, reader, visitor);
  if (reader.remaining() > 0)
    throw LcmWalkError(std::to_string(reader.remaining()) + " bytes after the last field of " + type.fullName());
}

}  // namespace beft::wire
