#include "lib/wire/message_decoder.hpp"

#include <charconv>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <map>
#include <stdexcept>

#include "lib/common/channels.hpp"
#include "lib/wire/embedded_schemas.hpp"
#include "lib/wire/lcm_walk.hpp"

namespace beft::blackboard {

using namespace beft::wire;

namespace {

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

// The readable text of a walk: one line per field, nested structs indented,
// arrays of structs cut after max_struct_items (still read, not printed).
class StructPrinter : public LcmVisitor {
 public:
  StructPrinter(const LcmStruct& root, const DescribeOptions& options, Lines& lines)
      : options_(options), lines_(lines) {
    levels_.push_back(level(&root, "", true));
  }

  void scalar(const LcmMember& member, const std::string& label, const LcmValue& value) override {
    Level& level = levels_.back();
    const std::string text = format(value, label);
    if (level.array_of_scalars) {
      if (level.seen < options_.max_inline_items) level.text += (level.seen > 0 ? ", " : "") + text;
      ++level.seen;
      return;
    }
    if (level.print)
      lines_.add(level.indent, member.name + ": " + text + annotation(*level.type, member, value));
  }

  void bytes(const LcmMember&, const std::string& label, const uint8_t*, std::size_t count) override {
    if (printing()) lines_.add(levels_.back().indent, label + ": <" + std::to_string(count) + " bytes>");
  }

  void beginStruct(const LcmMember&, const std::string& label, const LcmStruct& type) override {
    const bool print = printing();
    const std::string indent = levels_.back().indent;
    if (print) lines_.add(indent, label + ":");
    levels_.push_back(level(&type, indent + "  ", print));
  }

  void endStruct() override { levels_.pop_back(); }

  void beginArray(const LcmMember&, const std::string& label, int64_t count, bool of_scalars) override {
    Level level = StructPrinter::level(levels_.back().type, levels_.back().indent, printing());
    level.label = label;
    level.count = count;
    level.array = true;
    level.array_of_scalars = of_scalars;
    level.text = "[";
    levels_.push_back(level);
  }

  void element(int64_t index) override {
    Level& level = levels_.back();
    level.element_print = level.print && index < options_.max_struct_items;
  }

  void endArray() override {
    const Level level = levels_.back();
    levels_.pop_back();
    if (!level.print) return;
    if (level.array_of_scalars) {
      std::string text = level.text;
      if (level.count > options_.max_inline_items)
        text += ", ... +" + std::to_string(level.count - options_.max_inline_items) + " more";
      lines_.add(level.indent, level.label + ": " + text + "]");
      return;
    }
    if (level.count > options_.max_struct_items)
      lines_.add(level.indent, level.label + ": ... +" + std::to_string(level.count - options_.max_struct_items) +
                                   " more of " + std::to_string(level.count));
    if (level.count == 0) lines_.add(level.indent, level.label + ": []");
  }

 private:
  struct Level {
    const LcmStruct* type = nullptr;  // the struct whose members are being read
    std::string indent;
    bool print = true;
    bool array = false;
    bool array_of_scalars = false;
    bool element_print = false;  // of the current element of an array
    std::string label;
    int64_t count = 0;
    int64_t seen = 0;
    std::string text;  // the elements of a number/string array so far
  };

  static Level level(const LcmStruct* type, const std::string& indent, bool print) {
    Level level;
    level.type = type;
    level.indent = indent;
    level.print = print;
    return level;
  }

  // Whether what comes next (a struct, an array, bytes) is printed.
  bool printing() const {
    const Level& level = levels_.back();
    return level.array && !level.array_of_scalars ? level.element_print : level.print;
  }

  std::string format(const LcmValue& value, const std::string& name) const {
    switch (value.kind) {
      case LcmValue::Kind::kDouble:
      case LcmValue::Kind::kFloat:
        return formatNumber(value.number);
      case LcmValue::Kind::kString:
        return quoted(value.text, options_.max_string_chars);
      case LcmValue::Kind::kBoolean:
        return value.integer == 0 ? "false" : value.integer == 1 ? "true" : std::to_string(value.integer);
      case LcmValue::Kind::kInteger:
        break;
    }
    std::string text = std::to_string(value.integer);
    if (isTimeField(name) && value.integer >= 0)
      text += " (" + formatNumber(static_cast<double>(value.integer) / 1e6) + " s)";
    return text;
  }

  // "mode: 1 (MODE_VELOCITY)": names the constant a field's value stands
  // for, when the struct declares constants prefixed with the field's name.
  std::string annotation(const LcmStruct& lcm_struct, const LcmMember& member, const LcmValue& value) const {
    if (lcm_struct.constants.empty() || value.kind != LcmValue::Kind::kInteger) return "";
    const std::string prefix = upper(member.name) + "_";
    for (const LcmConstant& constant : lcm_struct.constants) {
      if (constant.name.compare(0, prefix.size(), prefix) != 0) continue;
      try {
        if (std::stoll(constant.value, nullptr, 0) == value.integer) return " (" + constant.name + ")";
      } catch (const std::exception&) {
      }
    }
    return "";
  }

  const DescribeOptions& options_;
  Lines& lines_;
  std::vector<Level> levels_;
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
  LcmReader reader(static_cast<const uint8_t*>(data), static_cast<std::size_t>(size));
  try {
    reader.skip(8, "fingerprint");
    StructPrinter printer(*type, options, lines);
    walkLcmStruct(types_, *type, reader, printer);
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
