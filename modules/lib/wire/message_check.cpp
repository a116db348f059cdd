#include "lib/wire/message_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <regex>
#include <unordered_map>
#include <vector>

#include "lib/common/channels.hpp"
#include "lib/wire/embedded_schemas.hpp"

namespace beft::wire {

namespace {

enum class Kind : uint8_t { kInt8, kInt16, kInt32, kInt64, kByte, kBoolean, kFloat, kDouble, kString, kStruct };

struct Dimension {
  bool variable = false;
  int slot = -1;       // variable: where the sizing member's value is kept
  int64_t length = 0;  // constant length
};

struct Field {
  std::string path;  // "struct_t.member", what a verdict names
  Kind kind = Kind::kInt8;
  int struct_index = -1;  // kStruct: index into Compiled::structs
  std::vector<Dimension> dimensions;
  int size_slot = -1;             // an integer that sizes later arrays: its value is kept here
  std::vector<int64_t> allowed;   // declared constants; empty: any value
  bool has_lower_bound = false;
  int64_t lower_bound = 0;
  bool nan_allowed = false;
  bool needs_values = false;      // elements must be read one by one (some check applies)
};

struct StructRules {
  std::string name;
  std::vector<Field> fields;
  int slots = 0;
  std::size_t min_size = 0;  // bytes of the smallest valid encoding (every array empty)
};

constexpr int kMaxSlots = 32;   // sizing members per struct
constexpr int kMaxDepth = 32;   // nested structs

std::size_t primitiveSize(Kind kind) {
  switch (kind) {
    case Kind::kInt8: case Kind::kByte: case Kind::kBoolean: return 1;
    case Kind::kInt16: return 2;
    case Kind::kInt32: case Kind::kFloat: case Kind::kString: return 4;  // a string: at least its length
    case Kind::kInt64: case Kind::kDouble: return 8;
    case Kind::kStruct: return 0;
  }
  return 0;
}

Kind kindOf(const std::string& type) {
  static const std::unordered_map<std::string, Kind> kinds = {
      {"int8_t", Kind::kInt8},   {"int16_t", Kind::kInt16}, {"int32_t", Kind::kInt32},
      {"int64_t", Kind::kInt64}, {"byte", Kind::kByte},     {"boolean", Kind::kBoolean},
      {"float", Kind::kFloat},   {"double", Kind::kDouble}, {"string", Kind::kString}};
  auto it = kinds.find(type);
  return it == kinds.end() ? Kind::kStruct : it->second;
}

bool isInteger(Kind kind) {
  return kind == Kind::kInt8 || kind == Kind::kInt16 || kind == Kind::kInt32 || kind == Kind::kInt64;
}

int64_t constantValue(const LcmConstant& constant) {
  try {
    return std::stoll(constant.value, nullptr, 0);
  } catch (const std::exception&) {
    throw SchemaError("constant " + constant.name + " = " + constant.value + " is not an integer");
  }
}

// What the member's comment declares: "PREFIX_*" constants, "NaN", ">= N".
void applyComment(const LcmStruct& lcm_struct, const LcmMember& member, Field& field) {
  static const std::regex enum_pattern(R"(\b([A-Z][A-Z0-9_]*)_\*)");
  static const std::regex bound_pattern(R"(>=\s*(-?[0-9]+))");
  std::smatch match;
  if (std::regex_search(member.comment, match, enum_pattern)) {
    const std::string prefix = match[1].str() + "_";
    for (const LcmConstant& constant : lcm_struct.constants)
      if (constant.name.compare(0, prefix.size(), prefix) == 0) field.allowed.push_back(constantValue(constant));
    if (field.allowed.empty() || !isInteger(field.kind))
      throw SchemaError(lcm_struct.source + ": " + field.path + " names " + prefix + "* constants, but " +
                        (isInteger(field.kind) ? "the struct has none" : "is not an integer"));
  }
  if (std::regex_search(member.comment, match, bound_pattern)) {
    if (!isInteger(field.kind))
      throw SchemaError(lcm_struct.source + ": " + field.path + " declares a bound but is not an integer");
    field.has_lower_bound = true;
    field.lower_bound = std::stoll(match[1].str());
  }
  field.nan_allowed = member.comment.find("NaN") != std::string::npos;
}

uint64_t readBigEndian(const uint8_t* bytes, std::size_t count) {
  uint64_t value = 0;
  for (std::size_t i = 0; i < count; ++i) value = (value << 8) | bytes[i];
  return value;
}

int64_t readSigned(const uint8_t* bytes, std::size_t count) {
  const int shift = 64 - 8 * static_cast<int>(count);
  return static_cast<int64_t>(readBigEndian(bytes, count) << shift) >> shift;
}

}  // namespace

struct MessageRules::Compiled {
  std::vector<StructRules> structs;
  std::unordered_map<uint64_t, int> by_fingerprint;
  std::unordered_map<std::string, uint64_t> fingerprint_of;  // "beft.fire_t" -> fingerprint
};

namespace {

// One pass over the bytes; stops at the first fault.
class Walker {
 public:
  Walker(const std::vector<StructRules>& structs, const uint8_t* data, std::size_t size)
      : structs_(structs), data_(data), size_(size) {}

  Verdict run(int struct_index) {
    position_ = 8;  // after the fingerprint
    if (!walkStruct(struct_index, 0)) return verdict_;
    const StructRules& rules = structs_[struct_index];
    if (position_ != size_) return {Fault::kTrailingBytes, rules.name.c_str()};
    return {};
  }

 private:
  std::size_t left() const { return size_ - position_; }

  bool fail(Fault fault, const Field& field) {
    verdict_ = {fault, field.path.c_str()};
    return false;
  }

  bool walkStruct(int struct_index, int depth) {
    const StructRules& rules = structs_[struct_index];
    if (depth > kMaxDepth || rules.min_size > left()) {
      verdict_ = {Fault::kLengthBeyondBytes, rules.name.c_str()};
      return false;
    }
    int64_t slots[kMaxSlots];
    for (const Field& field : rules.fields) {
      uint64_t count = 1;
      for (const Dimension& dimension : field.dimensions) {
        const int64_t length = dimension.variable ? slots[dimension.slot] : dimension.length;
        if (length < 0) return fail(Fault::kNegativeLength, field);
        // Every element takes at least a byte: more elements than bytes left
        // is a corrupt length, refused before anything loops over it.
        if (length > 0 && count > left() / static_cast<uint64_t>(length)) return fail(Fault::kLengthBeyondBytes, field);
        count *= static_cast<uint64_t>(length);
      }
      if (!walkElements(field, count, slots, depth)) return false;
    }
    return true;
  }

  bool walkElements(const Field& field, uint64_t count, int64_t* slots, int depth) {
    if (field.kind == Kind::kStruct) {
      const std::size_t min_size = std::max<std::size_t>(structs_[field.struct_index].min_size, 1);
      if (count > left() / min_size) return fail(Fault::kLengthBeyondBytes, field);
      for (uint64_t i = 0; i < count; ++i)
        if (!walkStruct(field.struct_index, depth + 1)) return false;
      return true;
    }
    if (field.kind == Kind::kString) {
      for (uint64_t i = 0; i < count; ++i)
        if (!walkString(field)) return false;
      return true;
    }
    const std::size_t element = primitiveSize(field.kind);
    if (count > left() / element) return fail(Fault::kLengthBeyondBytes, field);
    if (!field.needs_values) {
      position_ += count * element;
      return true;
    }
    for (uint64_t i = 0; i < count; ++i, position_ += element)
      if (!checkValue(field, data_ + position_, slots)) return false;
    return true;
  }

  bool walkString(const Field& field) {
    if (left() < 4) return fail(Fault::kLengthBeyondBytes, field);
    const int64_t length = readSigned(data_ + position_, 4);  // counts the final NUL
    position_ += 4;
    if (length < 1) return fail(Fault::kNegativeLength, field);
    if (static_cast<uint64_t>(length) > left()) return fail(Fault::kLengthBeyondBytes, field);
    const uint8_t* text = data_ + position_;
    if (text[length - 1] != 0 || std::memchr(text, 0, static_cast<std::size_t>(length - 1)) != nullptr)
      return fail(Fault::kBadString, field);
    position_ += static_cast<std::size_t>(length);
    return true;
  }

  bool checkValue(const Field& field, const uint8_t* bytes, int64_t* slots) {
    switch (field.kind) {
      case Kind::kBoolean:
        return bytes[0] <= 1 || fail(Fault::kBadBoolean, field);
      case Kind::kFloat: {
        const uint32_t raw = static_cast<uint32_t>(readBigEndian(bytes, 4));
        float value;
        std::memcpy(&value, &raw, sizeof value);
        return finiteOrAllowed(field, std::isnan(value), std::isinf(value));
      }
      case Kind::kDouble: {
        const uint64_t raw = readBigEndian(bytes, 8);
        double value;
        std::memcpy(&value, &raw, sizeof value);
        return finiteOrAllowed(field, std::isnan(value), std::isinf(value));
      }
      default: {
        const int64_t value = readSigned(bytes, primitiveSize(field.kind));
        if (field.size_slot >= 0) slots[field.size_slot] = value;
        if (field.has_lower_bound && value < field.lower_bound) return fail(Fault::kBelowBound, field);
        if (!field.allowed.empty() &&
            std::find(field.allowed.begin(), field.allowed.end(), value) == field.allowed.end())
          return fail(Fault::kBadEnum, field);
        return true;
      }
    }
  }

  bool finiteOrAllowed(const Field& field, bool is_nan, bool is_infinite) {
    if (is_infinite || (is_nan && !field.nan_allowed)) return fail(Fault::kNonFinite, field);
    return true;
  }

  const std::vector<StructRules>& structs_;
  const uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
  Verdict verdict_;
};

// Turns each struct of the type set into its list of fields.
class Compiler {
 public:
  explicit Compiler(const LcmTypeSet& types) : types_(types) {}

  std::vector<StructRules> compileAll(std::unordered_map<uint64_t, int>& by_fingerprint,
                                     std::unordered_map<std::string, uint64_t>& fingerprint_of) {
    for (const std::string& name : types_.typeNames()) index_[name] = static_cast<int>(index_.size());
    std::vector<StructRules> structs(index_.size());
    for (const auto& [name, index] : index_) {
      structs[index] = compile(*types_.find(name));
      by_fingerprint[types_.fingerprint(name)] = index;
      fingerprint_of[name] = types_.fingerprint(name);
    }
    for (std::size_t i = 0; i < structs.size(); ++i) minSize(structs, static_cast<int>(i), 0);
    return structs;
  }

 private:
  StructRules compile(const LcmStruct& lcm_struct) {
    StructRules rules;
    rules.name = lcm_struct.name;
    std::unordered_map<std::string, int> slot_of;
    for (const LcmMember& member : lcm_struct.members)
      for (const LcmDimension& dimension : member.dimensions)
        if (dimension.variable && !slot_of.count(dimension.size)) {
          const int slot = static_cast<int>(slot_of.size());
          slot_of[dimension.size] = slot;
        }
    if (slot_of.size() > static_cast<std::size_t>(kMaxSlots))
      throw SchemaError(lcm_struct.source + ": " + lcm_struct.name + " has more than 32 array sizes");
    rules.slots = static_cast<int>(slot_of.size());
    for (const LcmMember& member : lcm_struct.members) {
      Field field;
      field.path = lcm_struct.name + "." + member.name;
      field.kind = kindOf(member.type);
      if (field.kind == Kind::kStruct) field.struct_index = index_.at(member.type);
      for (const LcmDimension& dimension : member.dimensions) {
        Dimension compiled;
        compiled.variable = dimension.variable;
        if (dimension.variable) compiled.slot = slot_of.at(dimension.size);
        else compiled.length = std::stoll(dimension.size);
        field.dimensions.push_back(compiled);
      }
      if (auto slot = slot_of.find(member.name); slot != slot_of.end()) field.size_slot = slot->second;
      applyComment(lcm_struct, member, field);
      field.needs_values = field.size_slot >= 0 || !field.allowed.empty() || field.has_lower_bound ||
                           field.kind == Kind::kBoolean || field.kind == Kind::kFloat ||
                           field.kind == Kind::kDouble;
      rules.fields.push_back(std::move(field));
    }
    return rules;
  }

  // Smallest encoding: fixed arrays at their length, variable ones empty.
  std::size_t minSize(std::vector<StructRules>& structs, int index, int depth) {
    if (depth > kMaxDepth) return 0;
    std::size_t total = 0;
    for (const Field& field : structs[index].fields) {
      uint64_t count = 1;
      for (const Dimension& dimension : field.dimensions) count *= dimension.variable ? 0 : dimension.length;
      const std::size_t element =
          field.kind == Kind::kStruct ? minSize(structs, field.struct_index, depth + 1) : primitiveSize(field.kind);
      total += count * element;
    }
    if (depth == 0) structs[index].min_size = total;
    return total;
  }

  const LcmTypeSet& types_;
  std::unordered_map<std::string, int> index_;
};

}  // namespace

const char* faultName(Fault fault) {
  switch (fault) {
    case Fault::kNone: return "ok";
    case Fault::kTooShort: return "too short for a fingerprint";
    case Fault::kUnknownType: return "fingerprint of no beft type";
    case Fault::kWrongType: return "another type than the channel's";
    case Fault::kLengthBeyondBytes: return "length beyond the bytes";
    case Fault::kNegativeLength: return "negative length";
    case Fault::kBadString: return "string not terminated, or NUL inside";
    case Fault::kTrailingBytes: return "trailing bytes";
    case Fault::kNonFinite: return "non-finite value";
    case Fault::kBadBoolean: return "boolean other than 0 or 1";
    case Fault::kBadEnum: return "value not among the declared constants";
    case Fault::kBelowBound: return "value below the declared bound";
    case Fault::kUndecodable: return "refused by the generated decoder";
    case Fault::kBadPayload: return "payload refused by its reader";
    case Fault::kOtherRun: return "of another run on this URL";
    case Fault::kUnauthenticated: return "without a valid tag of the run's key";
  }
  return "unknown fault";
}

std::string Verdict::text() const {
  std::string text = field[0] == '\0' ? std::string(faultName(fault)) : std::string(field) + ": " + faultName(fault);
  if (fault == Fault::kOtherRun) text += " (run " + std::to_string(other_run) + ")";
  return text;
}

MessageRules::MessageRules(const LcmTypeSet& types) {
  auto compiled = std::make_unique<Compiled>();
  compiled->structs = Compiler(types).compileAll(compiled->by_fingerprint, compiled->fingerprint_of);
  compiled_ = std::move(compiled);
}

MessageRules::~MessageRules() = default;

const MessageRules& MessageRules::beftTypes() {
  static const MessageRules rules = [] {
    LcmTypeSet types;
    for (const EmbeddedSchema& schema : embeddedLcmSchemas()) types.addSchema(schema.file, schema.text);
    types.finalize();
    return MessageRules(types);
  }();
  return rules;
}

bool MessageRules::knows(uint64_t fingerprint) const { return compiled_->by_fingerprint.count(fingerprint) > 0; }

Verdict MessageRules::check(uint64_t fingerprint, const void* data, std::size_t size) const {
  if (data == nullptr || size < 8) return {Fault::kTooShort, ""};
  const auto* bytes = static_cast<const uint8_t*>(data);
  const uint64_t found = readBigEndian(bytes, 8);
  if (found != fingerprint) return {knows(found) ? Fault::kWrongType : Fault::kUnknownType, ""};
  auto it = compiled_->by_fingerprint.find(fingerprint);
  if (it == compiled_->by_fingerprint.end()) return {Fault::kUnknownType, ""};
  return Walker(compiled_->structs, bytes, size).run(it->second);
}

Verdict MessageRules::checkForChannel(const std::string& channel, const void* data, std::size_t size) const {
  const std::string type = channels::typeOfChannel(channel);
  if (type.empty()) return checkAnyType(data, size);
  auto it = compiled_->fingerprint_of.find(type);
  if (it == compiled_->fingerprint_of.end()) return {Fault::kUnknownType, ""};
  return check(it->second, data, size);
}

Verdict MessageRules::checkAnyType(const void* data, std::size_t size) const {
  if (data == nullptr || size < 8) return {Fault::kTooShort, ""};
  return check(readBigEndian(static_cast<const uint8_t*>(data), 8), data, size);
}

}  // namespace beft::wire
