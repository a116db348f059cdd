#include "lib/wire/message_decoder.hpp"

#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>

#include "lib/common/channels.hpp"
#include "lib/wire/embedded_schemas.hpp"

namespace beft::blackboard {

using namespace beft::wire;

namespace {

class DecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Big-endian reads with bounds checks.
class Reader {
 public:
  Reader(const uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::size_t position() const { return position_; }
  std::size_t remaining() const { return size_ - position_; }

  uint64_t readUnsigned(int bytes, const std::string& field) {
    need(static_cast<std::size_t>(bytes), field);
    uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | data_[position_++];
    return value;
  }

  int64_t readSigned(int bytes, const std::string& field) {
    const uint64_t raw = readUnsigned(bytes, field);
    const int shift = 64 - 8 * bytes;  // sign-extend
    return static_cast<int64_t>(raw << shift) >> shift;
  }

  double readDouble(const std::string& field) {
    const uint64_t raw = readUnsigned(8, field);
    double value;
    std::memcpy(&value, &raw, sizeof value);
    return value;
  }

  float readFloat(const std::string& field) {
    const uint32_t raw = static_cast<uint32_t>(readUnsigned(4, field));
    float value;
    std::memcpy(&value, &raw, sizeof value);
    return value;
  }

  std::string readString(const std::string& field) {
    const int64_t length = readSigned(4, field);  // includes the final '\0'
    if (length < 1) throw DecodeError(field + ": string length " + std::to_string(length) + " is invalid");
    need(static_cast<std::size_t>(length), field);
    const char* start = reinterpret_cast<const char*>(data_ + position_);
    position_ += static_cast<std::size_t>(length);
    if (start[length - 1] != '\0') throw DecodeError(field + ": string is not terminated");
    return std::string(start, static_cast<std::size_t>(length - 1));
  }

  void skip(std::size_t bytes, const std::string& field) {
    need(bytes, field);
    position_ += bytes;
  }

 private:
  void need(std::size_t bytes, const std::string& field) const {
    if (bytes > remaining())
      throw DecodeError("message ends at byte " + std::to_string(size_) + " while reading " + field +
                        " (" + std::to_string(bytes) + " bytes wanted at byte " +
                        std::to_string(position_) + ")");
  }

  const uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

// Collects lines up to a limit and counts the rest.
class Lines {
 public:
  explicit Lines(int max_lines) : max_lines_(max_lines < 1 ? 1 : max_lines) {}
  void add(const std::string& indent, const std::string& text) {
    if (static_cast<int>(lines_.size()) < max_lines_)
      lines_.push_back(indent + text);
    else
      ++dropped_;
  }
  std::vector<std::string> finish() {
    if (dropped_ > 0) {
      // The last kept line makes way for the count, so the total stays within the limit.
      if (static_cast<int>(lines_.size()) >= max_lines_ && !lines_.empty()) {
        lines_.pop_back();
        ++dropped_;
      }
      lines_.push_back("... (+" + std::to_string(dropped_) + " more lines)");
    }
    return std::move(lines_);
  }

 private:
  int max_lines_;
  long dropped_ = 0;
  std::vector<std::string> lines_;
};

std::string quoted(const std::string& text, int max_chars) {
  std::string out = "\"";
  int count = 0;
  for (unsigned char c : text) {
    if (count++ >= max_chars) {
      out += "...\" (" + std::to_string(text.size()) + " chars)";
      return out;
    }
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      out += escaped;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

bool isTimeField(const std::string& name) {
  const std::string suffix = "_utime";
  return name == "utime" ||
         (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0);
}

std::string upper(std::string text) {
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return text;
}

class StructPrinter {
 public:
  StructPrinter(const LcmTypeSet& types, const DescribeOptions& options, Lines& lines)
      : types_(types), options_(options), lines_(lines) {}

  // Reads one struct (no fingerprint); prints it when print is true.
  void readStruct(const LcmStruct& lcm_struct, Reader& reader, const std::string& indent, bool print) {
    std::map<std::string, int64_t> integers;  // sizes of the variable arrays
    for (const LcmMember& member : lcm_struct.members) {
      std::vector<int64_t> sizes;
      for (const LcmDimension& dimension : member.dimensions) {
        int64_t size = 0;
        if (dimension.variable) {
          auto it = integers.find(dimension.size);
          if (it == integers.end()) throw DecodeError(member.name + ": size member " + dimension.size + " missing");
          size = it->second;
        } else {
          size = std::stoll(dimension.size);
        }
        if (size < 0)
          throw DecodeError(member.name + ": length " + dimension.size + " = " + std::to_string(size) +
                            " is negative");
        sizes.push_back(size);
      }
      if (sizes.empty()) {
        if (isLcmPrimitive(member.type)) {
          const std::string value = readScalar(member.type, member.name, reader, &integers);
          if (print) lines_.add(indent, member.name + ": " + value + annotation(lcm_struct, member, value));
        } else {
          if (print) lines_.add(indent, member.name + ":");
          readStruct(structOf(member.type), reader, indent + "  ", print);
        }
      } else {
        readArray(member, sizes, 0, member.name, reader, indent, print);
      }
    }
  }

 private:
  const LcmStruct& structOf(const std::string& type) const {
    const LcmStruct* found = types_.find(type);
    if (!found) throw DecodeError("unknown member type " + type);
    return *found;
  }

  void readArray(const LcmMember& member, const std::vector<int64_t>& sizes, std::size_t level,
                 const std::string& label, Reader& reader, const std::string& indent, bool print) {
    const int64_t count = sizes[level];
    const bool innermost = level + 1 == sizes.size();
    // Every element takes at least one byte: a length beyond the bytes left
    // is a corrupt message, not a reason to loop for billions of elements.
    const int64_t bytes_left = static_cast<int64_t>(reader.remaining());
    int64_t elements = 1;
    for (std::size_t l = level; l < sizes.size() && elements > 0 && elements <= bytes_left; ++l)
      elements = sizes[l] > bytes_left ? bytes_left + 1 : elements * sizes[l];  // both factors < 2^32
    if (elements > bytes_left)
      throw DecodeError(label + ": " + std::to_string(count) + " elements cannot fit in the " +
                        std::to_string(reader.remaining()) + " bytes left");
    if (innermost && member.type == "byte") {
      reader.skip(static_cast<std::size_t>(count), label);
      if (print) lines_.add(indent, label + ": <" + std::to_string(count) + " bytes>");
      return;
    }
    if (innermost && isLcmPrimitive(member.type)) {
      std::string text = "[";
      for (int64_t i = 0; i < count; ++i) {
        const std::string value = readScalar(member.type, label, reader, nullptr);
        if (i < options_.max_inline_items) text += (i > 0 ? ", " : "") + value;
      }
      if (count > options_.max_inline_items)
        text += ", ... +" + std::to_string(count - options_.max_inline_items) + " more";
      text += "]";
      if (print) lines_.add(indent, label + ": " + text);
      return;
    }
    for (int64_t i = 0; i < count; ++i) {
      const bool print_item = print && i < options_.max_struct_items;
      const std::string item_label = label + "[" + std::to_string(i) + "]";
      if (innermost) {
        if (print_item) lines_.add(indent, item_label + ":");
        readStruct(structOf(member.type), reader, indent + "  ", print_item);
      } else {
        readArray(member, sizes, level + 1, item_label, reader, indent, print_item);
      }
    }
    if (print && count > options_.max_struct_items)
      lines_.add(indent, label + ": ... +" + std::to_string(count - options_.max_struct_items) + " more of " +
                             std::to_string(count));
    if (print && count == 0) lines_.add(indent, label + ": []");
  }

  std::string readScalar(const std::string& type, const std::string& name, Reader& reader,
                         std::map<std::string, int64_t>* integers) {
    if (type == "double") return formatNumber(reader.readDouble(name));
    if (type == "float") return formatNumber(reader.readFloat(name));
    if (type == "string") return quoted(reader.readString(name), options_.max_string_chars);
    if (type == "boolean") {
      const int64_t value = reader.readSigned(1, name);
      return value == 0 ? "false" : value == 1 ? "true" : std::to_string(value);
    }
    const int bytes = type == "int8_t" || type == "byte" ? 1 : type == "int16_t" ? 2 : type == "int32_t" ? 4 : 8;
    const int64_t value = reader.readSigned(bytes, name);
    if (integers) (*integers)[name] = value;
    std::string text = std::to_string(value);
    if (isTimeField(name) && value >= 0) text += " (" + formatNumber(static_cast<double>(value) / 1e6) + " s)";
    return text;
  }

  // "mode: 1 (MODE_VELOCITY)": names the constant a field's value stands
  // for, when the struct declares constants prefixed with the field's name.
  std::string annotation(const LcmStruct& lcm_struct, const LcmMember& member, const std::string& value) const {
    if (lcm_struct.constants.empty() || member.type == "string" || member.type == "double" ||
        member.type == "float" || member.type == "boolean")
      return "";
    const std::string prefix = upper(member.name) + "_";
    for (const LcmConstant& constant : lcm_struct.constants) {
      if (constant.name.compare(0, prefix.size(), prefix) != 0) continue;
      try {
        if (std::stoll(constant.value, nullptr, 0) == std::stoll(value)) return " (" + constant.name + ")";
      } catch (const std::exception&) {
      }
    }
    return "";
  }

  const LcmTypeSet& types_;
  const DescribeOptions& options_;
  Lines& lines_;
};

LcmTypeSet loadEmbeddedTypes() {
  LcmTypeSet types;
  for (const EmbeddedSchema& schema : embeddedLcmSchemas()) types.addSchema(schema.file, schema.text);
  types.finalize();
  return types;
}

std::string hex(uint64_t value) {
  char text[24];
  std::snprintf(text, sizeof text, "0x%016" PRIx64, value);
  return text;
}

}  // namespace

std::string formatNumber(double value) {
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

std::optional<uint64_t> fingerprintOf(const void* data, int size) {
  if (!data || size < 8) return std::nullopt;
  const auto* bytes = static_cast<const uint8_t*>(data);
  uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value = (value << 8) | bytes[i];
  return value;
}

MessageDecoder::MessageDecoder(LcmTypeSet types) : types_(std::move(types)) {}

const MessageDecoder& MessageDecoder::beftTypes() {
  static const MessageDecoder decoder(loadEmbeddedTypes());
  return decoder;
}

const LcmStruct* MessageDecoder::typeOf(const void* data, int size) const {
  const auto fingerprint = fingerprintOf(data, size);
  return fingerprint ? types_.findByFingerprint(*fingerprint) : nullptr;
}

std::vector<std::string> MessageDecoder::describeLines(const std::string& channel, const void* data, int size,
                                                       const DescribeOptions& options) const {
  Lines lines(options.max_lines);
  const auto fingerprint = fingerprintOf(data, size);
  if (!fingerprint) {
    lines.add("", "not an LCM message: " + std::to_string(size < 0 ? 0 : size) +
                      " bytes, fewer than the 8 of a fingerprint");
    return lines.finish();
  }
  const LcmStruct* type = types_.findByFingerprint(*fingerprint);
  const std::string expected = channels::typeOfChannel(channel);
  if (!type) {
    std::string text = "unknown type: fingerprint " + hex(*fingerprint) + ", " + std::to_string(size) + " bytes";
    if (const LcmStruct* expected_type = expected.empty() ? nullptr : types_.find(expected))
      text += "; " + channel + " carries " + expected + " (fingerprint " + hex(types_.fingerprint(expected)) +
              "): the sender was built from another version of " + expected_type->name + ".lcm";
    lines.add("", text);
    return lines.finish();
  }
  if (!expected.empty() && expected != type->fullName())
    lines.add("", "note: " + channel + " normally carries " + expected + ", this is " + type->fullName());
  Reader reader(static_cast<const uint8_t*>(data), static_cast<std::size_t>(size));
  try {
    reader.skip(8, "fingerprint");
    StructPrinter(types_, options, lines).readStruct(*type, reader, "", true);
    if (reader.remaining() > 0)
      lines.add("", "(" + std::to_string(reader.remaining()) + " bytes after the last field)");
  } catch (const std::exception& error) {
    lines.add("", std::string("cannot decode as ") + type->fullName() + ": " + error.what());
  }
  return lines.finish();
}

std::string MessageDecoder::describe(const std::string& channel, const void* data, int size,
                                     const DescribeOptions& options) const {
  std::string text;
  for (const std::string& line : describeLines(channel, data, size, options)) text += line + "\n";
  return text;
}

std::string typeNameOf(const void* data, int size) {
  try {
    const LcmStruct* type = MessageDecoder::beftTypes().typeOf(data, size);
    return type ? type->fullName() : "";
  } catch (const std::exception&) {
    return "";
  }
}

std::string describeMessage(const std::string& channel, const void* data, int size, int max_lines) {
  try {
    DescribeOptions options;
    options.max_lines = max_lines;
    return MessageDecoder::beftTypes().describe(channel, data, size, options);
  } catch (const std::exception& error) {
    return std::string("cannot describe the message: ") + error.what() + "\n";
  }
}

}  // namespace beft::blackboard
