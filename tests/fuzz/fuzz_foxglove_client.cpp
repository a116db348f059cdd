// What a Foxglove client may send the bridge, on any bytes: the text and
// binary parsers never throw and give a reason for whatever they refuse;
// the bytes as a message of every beft type (as they are, and with that
// type's fingerprint in front so the walk goes past it) decode to JSON that
// prints, or are refused with a runtime_error; JSON that decoded encodes
// back (jsonToLcm) to bytes that decode to the same JSON, or is refused with
// a JsonToLcmError (a string holding NUL); the bytes as JSON text encode as
// any type or are refused with a JsonToLcmError.
#include <cstdlib>
#include <string_view>
#include <variant>
#include <vector>

#include "lib/foxglove/json_text.hpp"
#include "lib/foxglove/lcm_json.hpp"
#include "lib/foxglove/protocol.hpp"

namespace {

using beft::foxglove::beftTypeSet;

void checkParsed(const beft::foxglove::ClientMessage& message) {
  if (const auto* invalid = std::get_if<beft::foxglove::Invalid>(&message))
    if (invalid->reason.empty()) std::abort();
}

void encodeBack(const beft::wire::LcmStruct& type, const nlohmann::json& value) {
  std::vector<uint8_t> encoded;
  try {
    encoded = beft::foxglove::jsonToLcm(beftTypeSet(), type, value);
  } catch (const beft::foxglove::JsonToLcmError&) {
    return;
  }
  if (beft::foxglove::lcmToJson(beftTypeSet(), type, encoded.data(), encoded.size()) != value) std::abort();
}

void decodeAs(const beft::wire::LcmStruct& type, const uint8_t* data, std::size_t size) {
  nlohmann::json value;
  try {
    value = beft::foxglove::lcmToJson(beftTypeSet(), type, data, size);
  } catch (const std::runtime_error&) {
    return;
  }
  beft::foxglove::dumpJson(value);
  encodeBack(type, value);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  checkParsed(beft::foxglove::parseClientText(bytes));
  checkParsed(beft::foxglove::parseClientBinary(bytes));

  const beft::wire::LcmTypeSet& types = beftTypeSet();
  const nlohmann::json as_json = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
  std::vector<uint8_t> stamped(data, data + size);
  if (stamped.size() < 8) stamped.resize(8);
  for (const std::string& name : types.typeNames()) {
    const beft::wire::LcmStruct& type = *types.find(name);
    decodeAs(type, data, size);
    const uint64_t fingerprint = types.fingerprint(name);
    for (int i = 0; i < 8; ++i) stamped[i] = static_cast<uint8_t>(fingerprint >> (56 - 8 * i));
    decodeAs(type, stamped.data(), stamped.size());
    if (as_json.is_object()) {
      try {
        beft::foxglove::jsonToLcm(types, type, as_json);
      } catch (const beft::foxglove::JsonToLcmError&) {
      }
    }
  }
  return 0;
}
