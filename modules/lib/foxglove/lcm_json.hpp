// Any beft message as JSON, and its JSON Schema, from the .lcm definitions
// as data (lib/wire/lcm_schema.hpp): how the bridge shows every channel in
// Foxglove (encoding "json", schemaEncoding "jsonschema") without a
// converter per type.
//
// The JSON of a message: an object with the .lcm member names; integers
// (int64 too) as JSON numbers; boolean as true/false (any byte but 0 is
// true); float and double as numbers, NaN and infinities as null; strings
// made valid UTF-8 (invalid bytes become U+FFFD); arrays as arrays (a 2-D
// array as arrays of arrays); nested structs as objects; byte arrays
// (`byte data[n]`) as one base64 string each, Foxglove's convention for
// bytes in JSON. jsonToLcm goes the other way, for what clients publish.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "lib/wire/lcm_schema.hpp"
#include "lib/wire/lcm_walk.hpp"

namespace beft::foxglove {

// Decodes one encoded message of type (it starts with the 8-byte
// fingerprint) into JSON. The bytes are untrusted: throws
// wire::LcmWalkError (a std::runtime_error) saying which field is wrong when
// the fingerprint is not type's, the bytes end early, a length or string is
// invalid, or bytes are left after the last member. Never reads outside
// [data, data + size).
nlohmann::json lcmToJson(const wire::LcmTypeSet& types, const wire::LcmStruct& type, const uint8_t* data,
                         std::size_t size);

// The JSON Schema (draft-07) of what lcmToJson gives for type: "type":
// "object" with "properties" (every member, nested structs inline, arrays
// with "items", fixed lengths as minItems/maxItems, byte arrays as strings
// with "contentEncoding": "base64"), "required" (every member) and each
// member's .lcm comment (its units, "[m]") as "description". Numbers are
// "type": "number" although NaN arrives as null: Foxglove reads only single
// type names.
nlohmann::json jsonSchemaOf(const wire::LcmTypeSet& types, const wire::LcmStruct& type);

// JSON that does not hold a message of the type it is meant as.
class JsonToLcmError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The reverse of lcmToJson, for what clients publish: the encoded message
// (fingerprint first) of value, checked against type on the way. Every
// member present and no other key; integers in their type's range (int64
// too); booleans true/false; numbers or null (NaN) for float and double;
// strings without '\0'; an array as long as its size member says (sizes
// are members like any other, so they must agree); byte arrays as base64.
// Throws JsonToLcmError naming the first member that is wrong
// ("hypotheses[1].fused: 3 entries, num_categories says 2").
std::vector<uint8_t> jsonToLcm(const wire::LcmTypeSet& types, const wire::LcmStruct& type,
                               const nlohmann::json& value);

// Every type of lcmtypes/*.lcm, finalized (the one the message decoder
// uses). Built on first use; thread-safe.
const wire::LcmTypeSet& beftTypeSet();

}  // namespace beft::foxglove
