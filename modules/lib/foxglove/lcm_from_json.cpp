// jsonToLcm (lcm_json.hpp): a message from JSON, checked member by member
// against its .lcm definition and encoded as LCM does (big-endian).
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

#include "lib/foxglove/json_text.hpp"
#include "lib/foxglove/lcm_json.hpp"

namespace beft::foxglove {

namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw JsonToLcmError(where + ": " + what); }

class Encoder {
 public:
  explicit Encoder(const wire::LcmTypeSet& types) : types_(types) {}

  std::vector<uint8_t> take() { return std::move(out_); }

  void putUnsigned(uint64_t value, int bytes) {
    for (int i = bytes - 1; i >= 0; --i) out_.push_back(static_cast<uint8_t>(value >> (8 * i)));
  }

  void encodeStruct(const wire::LcmStruct& type, const json& value, const std::string& path) {
    if (!value.is_object()) fail(path.empty() ? type.fullName() : path, "not a JSON object");
    for (const auto& item : value.items())
      if (!memberNamed(type, item.key())) fail(join(path, item.key()), "not a member of " + type.fullName());
    std::map<std::string, int64_t> integers;  // sizes of the variable arrays
    for (const wire::LcmMember& member : type.members) {
      const std::string where = join(path, member.name);
      const auto field = value.find(member.name);
      if (field == value.end()) fail(where, "missing");
      if (!member.dimensions.empty()) {
        encodeArray(member, sizesOf(member, integers, where), 0, *field, where);
      } else if (wire::isLcmPrimitive(member.type)) {
        const int64_t integer = encodeScalar(member.type, *field, where);
        integers[member.name] = integer;
      } else {
        encodeStruct(structOf(member.type), *field, where);
      }
    }
  }

 private:
  static std::string join(const std::string& path, const std::string& name) {
    return path.empty() ? name : path + "." + name;
  }

  static bool memberNamed(const wire::LcmStruct& type, const std::string& name) {
    for (const wire::LcmMember& member : type.members)
      if (member.name == name) return true;
    return false;
  }

  const wire::LcmStruct& structOf(const std::string& name) const {
    const wire::LcmStruct* found = types_.find(name);
    if (!found) throw JsonToLcmError("unknown member type " + name);
    return *found;
  }

  static std::vector<int64_t> sizesOf(const wire::LcmMember& member, const std::map<std::string, int64_t>& integers,
                                      const std::string& where) {
    std::vector<int64_t> sizes;
    for (const wire::LcmDimension& dimension : member.dimensions) {
      const auto it = integers.find(dimension.size);
      const int64_t size = dimension.variable ? (it == integers.end() ? -1 : it->second) : std::stoll(dimension.size);
      if (size < 0) fail(where, "its size " + dimension.size + " is negative");
      sizes.push_back(size);
    }
    return sizes;
  }

  void encodeArray(const wire::LcmMember& member, const std::vector<int64_t>& sizes, std::size_t level,
                   const json& value, const std::string& where) {
    const int64_t count = sizes[level];
    const bool innermost = level + 1 == sizes.size();
    const std::string size_name = member.dimensions[level].size;
    if (innermost && member.type == "byte") {
      if (!value.is_string()) fail(where, "not a base64 string");
      const auto bytes = base64Decode(value.get_ref<const std::string&>());
      if (!bytes) fail(where, "not valid base64");
      if (static_cast<int64_t>(bytes->size()) != count)
        fail(where, std::to_string(bytes->size()) + " bytes, " + size_name + " says " + std::to_string(count));
      out_.insert(out_.end(), bytes->begin(), bytes->end());
      return;
    }
    if (!value.is_array()) fail(where, "not an array");
    if (static_cast<int64_t>(value.size()) != count)
      fail(where, std::to_string(value.size()) + " entries, " + size_name + " says " + std::to_string(count));
    for (std::size_t i = 0; i < value.size(); ++i) {
      const std::string item = where + "[" + std::to_string(i) + "]";
      if (!innermost)
        encodeArray(member, sizes, level + 1, value[i], item);
      else if (wire::isLcmPrimitive(member.type))
        encodeScalar(member.type, value[i], item);
      else
        encodeStruct(structOf(member.type), value[i], item);
    }
  }

  // Writes one primitive; gives back an integer's value (0 for others).
  int64_t encodeScalar(const std::string& type, const json& value, const std::string& where) {
    if (type == "double" || type == "float") {
      encodeNumber(type == "float", value, where);
      return 0;
    }
    if (type == "string") {
      if (!value.is_string()) fail(where, "not a string");
      const std::string& text = value.get_ref<const std::string&>();
      if (text.find('\0') != std::string::npos) fail(where, "a string with a NUL character");
      if (text.size() >= static_cast<std::size_t>(std::numeric_limits<int32_t>::max())) fail(where, "too long");
      putUnsigned(text.size() + 1, 4);
      out_.insert(out_.end(), text.begin(), text.end());
      out_.push_back(0);
      return 0;
    }
    if (type == "boolean") {
      if (!value.is_boolean()) fail(where, "not true or false");
      out_.push_back(value.get<bool>() ? 1 : 0);
      return 0;
    }
    return encodeInteger(type, value, where);
  }

  void encodeNumber(bool single, const json& value, const std::string& where) {
    double number = std::numeric_limits<double>::quiet_NaN();  // null stands for NaN
    if (value.is_number()) number = value.get<double>();
    else if (!value.is_null()) fail(where, "not a number or null");
    if (single) {
      if (std::isfinite(number) && std::fabs(number) > std::numeric_limits<float>::max())
        fail(where, value.dump() + " does not fit a float");
      const float narrow = static_cast<float>(number);
      uint32_t raw;
      std::memcpy(&raw, &narrow, sizeof raw);
      putUnsigned(raw, 4);
    } else {
      uint64_t raw;
      std::memcpy(&raw, &number, sizeof raw);
      putUnsigned(raw, 8);
    }
  }

  int64_t encodeInteger(const std::string& type, const json& value, const std::string& where) {
    if (!value.is_number_integer()) fail(where, "not an integer");
    const int bytes = type == "int8_t" || type == "byte" ? 1 : type == "int16_t" ? 2 : type == "int32_t" ? 4 : 8;
    int64_t low = std::numeric_limits<int64_t>::min(), high = std::numeric_limits<int64_t>::max();
    if (type == "byte") {
      low = 0;
      high = 255;
    } else if (bytes < 8) {
      high = (int64_t{1} << (8 * bytes - 1)) - 1;
      low = -high - 1;
    }
    const bool too_big = value.is_number_unsigned() && value.get<uint64_t>() > static_cast<uint64_t>(high);
    const int64_t integer = too_big ? 0 : value.get<int64_t>();
    if (too_big || integer < low || integer > high)
      fail(where, value.dump() + " is outside " + std::to_string(low) + ".." + std::to_string(high) + " of " + type);
    putUnsigned(static_cast<uint64_t>(integer), bytes);
    return integer;
  }

  const wire::LcmTypeSet& types_;
  std::vector<uint8_t> out_;
};

}  // namespace

std::vector<uint8_t> jsonToLcm(const wire::LcmTypeSet& types, const wire::LcmStruct& type,
                               const nlohmann::json& value) {
  Encoder encoder(types);
  encoder.putUnsigned(types.fingerprint(type.fullName()), 8);
  encoder.encodeStruct(type, value, "");
  return encoder.take();
}

}  // namespace beft::foxglove
