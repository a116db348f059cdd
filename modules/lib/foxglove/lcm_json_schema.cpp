// jsonSchemaOf (lcm_json.hpp): the JSON Schema of a type's JSON.
#include <cctype>
#include <limits>
#include <string>

#include "lib/foxglove/lcm_json.hpp"

namespace beft::foxglove {

namespace {

template <typename Integer>
nlohmann::json integerSchema() {
  return {{"type", "integer"},
          {"minimum", std::numeric_limits<Integer>::min()},
          {"maximum", std::numeric_limits<Integer>::max()}};
}

nlohmann::json primitiveSchema(const std::string& type) {
  if (type == "int8_t") return integerSchema<int8_t>();
  if (type == "int16_t") return integerSchema<int16_t>();
  if (type == "int32_t") return integerSchema<int32_t>();
  if (type == "int64_t") return {{"type", "integer"}};
  if (type == "byte") return integerSchema<uint8_t>();
  if (type == "boolean") return {{"type", "boolean"}};
  if (type == "float" || type == "double") return {{"type", "number"}};
  return {{"type", "string"}};
}

nlohmann::json structSchema(const wire::LcmTypeSet& types, const wire::LcmStruct& type);

// The member's comment (its units), and the constants named after it
// ("mode": MODE_IDLE = 0, ...), as the readable decoder names them.
std::string descriptionOf(const wire::LcmStruct& type, const wire::LcmMember& member) {
  const std::size_t first = member.comment.find_first_not_of(" \t");
  const std::size_t last = member.comment.find_last_not_of(" \t\r");
  std::string description = first == std::string::npos ? "" : member.comment.substr(first, last - first + 1);
  std::string prefix;
  for (char c : member.name) prefix += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  prefix += "_";
  std::string constants;
  for (const wire::LcmConstant& constant : type.constants)
    if (constant.name.compare(0, prefix.size(), prefix) == 0)
      constants += (constants.empty() ? "" : ", ") + constant.name + " = " + constant.value;
  if (!constants.empty()) description += (description.empty() ? "" : " ") + ("(" + constants + ")");
  return description;
}

// The schema of one member: its element, wrapped in an array per dimension
// (the innermost dimension of a byte array is one base64 string).
nlohmann::json memberSchema(const wire::LcmTypeSet& types, const wire::LcmMember& member) {
  std::size_t dimensions = member.dimensions.size();
  nlohmann::json schema;
  if (member.type == "byte" && dimensions > 0) {
    schema = {{"type", "string"}, {"contentEncoding", "base64"}};
    --dimensions;
  } else if (wire::isLcmPrimitive(member.type)) {
    schema = primitiveSchema(member.type);
  } else {
    const wire::LcmStruct* nested = types.find(member.type);
    if (!nested) throw wire::SchemaError("unknown member type " + member.type);
    schema = structSchema(types, *nested);
  }
  for (std::size_t d = dimensions; d-- > 0;) {
    nlohmann::json array = {{"type", "array"}, {"items", std::move(schema)}};
    const wire::LcmDimension& dimension = member.dimensions[d];
    if (!dimension.variable) {
      const long long length = std::stoll(dimension.size);
      array["minItems"] = length;
      array["maxItems"] = length;
    }
    schema = std::move(array);
  }
  return schema;
}

nlohmann::json structSchema(const wire::LcmTypeSet& types, const wire::LcmStruct& type) {
  nlohmann::json properties = nlohmann::json::object();
  nlohmann::json required = nlohmann::json::array();
  for (const wire::LcmMember& member : type.members) {
    nlohmann::json schema = memberSchema(types, member);
    const std::string description = descriptionOf(type, member);
    if (!description.empty()) schema["description"] = description;
    properties[member.name] = std::move(schema);
    required.push_back(member.name);
  }
  return {{"title", type.fullName()}, {"type", "object"}, {"properties", properties}, {"required", required}};
}

}  // namespace

nlohmann::json jsonSchemaOf(const wire::LcmTypeSet& types, const wire::LcmStruct& type) {
  nlohmann::json schema = structSchema(types, type);
  schema["$schema"] = "http://json-schema.org/draft-07/schema#";
  return schema;
}

}  // namespace beft::foxglove
