#include "lib/foxglove/lcm_json.hpp"

#include <cmath>
#include <vector>

#include "lib/foxglove/json_text.hpp"
#include "lib/wire/message_decoder.hpp"

namespace beft::foxglove {

using wire::LcmMember;
using wire::LcmStruct;
using wire::LcmValue;

namespace {

// Builds the JSON of a walk: a stack of the objects and arrays being filled.
class JsonBuilder : public wire::LcmVisitor {
 public:
  JsonBuilder() : root_(nlohmann::json::object()) { open_.push_back(&root_); }

  nlohmann::json take() { return std::move(root_); }

  void scalar(const LcmMember& member, const std::string&, const LcmValue& value) override {
    add(member, valueOf(value));
  }

  void bytes(const LcmMember& member, const std::string&, const uint8_t* data, std::size_t count) override {
    add(member, base64Encode(data, count));
  }

  void beginStruct(const LcmMember& member, const std::string&, const LcmStruct&) override {
    open_.push_back(&add(member, nlohmann::json::object()));
  }

  void endStruct() override { open_.pop_back(); }

  void beginArray(const LcmMember& member, const std::string&, int64_t count, bool) override {
    nlohmann::json& array = add(member, nlohmann::json::array());
    // count fits in the bytes left (the walk checked), so this is bounded by the message.
    array.get_ref<nlohmann::json::array_t&>().reserve(static_cast<std::size_t>(count));
    open_.push_back(&array);
  }

  void endArray() override { open_.pop_back(); }

 private:
  static nlohmann::json valueOf(const LcmValue& value) {
    switch (value.kind) {
      case LcmValue::Kind::kInteger:
        return value.integer;
      case LcmValue::Kind::kBoolean:
        return value.integer != 0;
      case LcmValue::Kind::kFloat:
      case LcmValue::Kind::kDouble:
        if (!std::isfinite(value.number)) return nullptr;
        return value.number;
      case LcmValue::Kind::kString:
        return validUtf8(value.text);
    }
    return nullptr;
  }

  // Into the open array, or as the member of the open object. A reference
  // stays valid while it is open: nothing is added to its parent meanwhile.
  nlohmann::json& add(const LcmMember& member, nlohmann::json value) {
    nlohmann::json& open = *open_.back();
    if (open.is_array()) {
      open.push_back(std::move(value));
      return open.back();
    }
    nlohmann::json& slot = open[member.name];
    slot = std::move(value);
    return slot;
  }

  nlohmann::json root_;
  std::vector<nlohmann::json*> open_;
};

}  // namespace

nlohmann::json lcmToJson(const wire::LcmTypeSet& types, const wire::LcmStruct& type, const uint8_t* data,
                         std::size_t size) {
  JsonBuilder builder;
  wire::walkLcmMessage(types, type, data, size, builder);
  return builder.take();
}

const wire::LcmTypeSet& beftTypeSet() { return blackboard::MessageDecoder::beftTypes().types(); }

}  // namespace beft::foxglove
