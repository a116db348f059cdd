// beft messages as JSON (lcmToJson) and their JSON Schemas (jsonSchemaOf):
// encoded by lcm-gen's C++, decoded from the .lcm definitions as data.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <beft/camera_frame_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft_test/sample_t.hpp>

#include "lib/foxglove/json_text.hpp"
#include "lib/foxglove/lcm_json.hpp"

using namespace beft::foxglove;
using beft::wire::LcmTypeSet;
using nlohmann::json;

namespace {

template <typename Message>
std::vector<uint8_t> encode(const Message& message) {
  std::vector<uint8_t> bytes(static_cast<std::size_t>(message.getEncodedSize()));
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

const beft::wire::LcmStruct& beftType(const std::string& name) {
  const beft::wire::LcmStruct* type = beftTypeSet().find(name);
  if (!type) throw std::runtime_error("no type " + name);
  return *type;
}

template <typename Message>
json toJson(const Message& message, const std::string& type_name) {
  const auto bytes = encode(message);
  return lcmToJson(beftTypeSet(), beftType(type_name), bytes.data(), bytes.size());
}

beft::robot_state_t robotState() {
  beft::robot_state_t state{};
  state.utime = 4200000;
  state.tick = 42;
  state.x = 1.5;
  state.y = -0.25;
  state.yaw = std::numeric_limits<double>::quiet_NaN();
  state.head_pitch = std::numeric_limits<double>::infinity();
  state.collisions = 3;
  state.collided = true;
  state.last_command = "goto \"door\"";
  return state;
}

beft::hypotheses_t twoHypotheses() {
  beft::hypotheses_t hypotheses{};
  hypotheses.utime = 1000000;
  hypotheses.tick = 10;
  for (const char* id : {"person_1", "siren_2"}) {
    beft::hypothesis_t hypothesis{};
    hypothesis.object_id = id;
    hypothesis.best_category = "person";
    hypothesis.confidence = 0.875;
    hypothesis.categories = {"person", "car"};
    hypothesis.fused = {0.875, 0.125};
    hypothesis.num_categories = 2;
    hypothesis.heard = true;
    hypothesis.first_heard_utime = -1;
    hypothesis.settled_utime = int64_t{1} << 60;
    hypotheses.hypotheses.push_back(hypothesis);
  }
  hypotheses.num_hypotheses = 2;
  return hypotheses;
}

std::string readFile(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

LcmTypeSet sampleTypes() {
  LcmTypeSet types;
  for (const char* name : {"sample_inner_t.lcm", "sample_t.lcm"})
    types.addSchema(name, readFile(std::string(BEFT_TEST_LCM_DIR) + "/" + name));
  types.finalize();
  return types;
}

// Every property of an object schema names a member, in any order, and
// the other way round; nested structs are checked the same way.
void expectPropertiesMatchMembers(const LcmTypeSet& types, const beft::wire::LcmStruct& type, const json& schema) {
  ASSERT_EQ(schema.at("type"), "object") << type.fullName();
  const json& properties = schema.at("properties");
  ASSERT_EQ(properties.size(), type.members.size()) << type.fullName();
  for (const auto& member : type.members) {
    ASSERT_TRUE(properties.contains(member.name)) << type.fullName() << "." << member.name;
    json element = properties.at(member.name);
    for (std::size_t d = 0; d < member.dimensions.size(); ++d) {
      if (member.type == "byte" && d + 1 == member.dimensions.size()) break;
      ASSERT_EQ(element.at("type"), "array") << type.fullName() << "." << member.name;
      element = element.at("items");
    }
    if (!beft::wire::isLcmPrimitive(member.type))
      expectPropertiesMatchMembers(types, *types.find(member.type), element);
  }
}

}  // namespace

TEST(LcmJson, RobotStateFieldsByNameWithNaNAndInfinityAsNull) {
  const json value = toJson(robotState(), "beft.robot_state_t");
  EXPECT_EQ(value.at("utime"), 4200000);
  EXPECT_EQ(value.at("tick"), 42);
  EXPECT_EQ(value.at("x"), 1.5);
  EXPECT_EQ(value.at("y"), -0.25);
  EXPECT_TRUE(value.at("yaw").is_null());
  EXPECT_TRUE(value.at("head_pitch").is_null());
  EXPECT_EQ(value.at("collisions"), 3);
  EXPECT_EQ(value.at("collided"), true);
  EXPECT_EQ(value.at("last_command"), "goto \"door\"");
  EXPECT_EQ(value.size(), beftType("beft.robot_state_t").members.size());
  EXPECT_NE(dumpJson(value).find("\"yaw\":null"), std::string::npos);
}

TEST(LcmJson, NestedStructArraysWithStringAndNumberArrays) {
  const json value = toJson(twoHypotheses(), "beft.hypotheses_t");
  ASSERT_EQ(value.at("hypotheses").size(), 2u);
  const json& second = value.at("hypotheses").at(1);
  EXPECT_EQ(second.at("object_id"), "siren_2");
  EXPECT_EQ(second.at("categories"), json({"person", "car"}));
  EXPECT_EQ(second.at("fused"), json({0.875, 0.125}));
  EXPECT_EQ(second.at("heard"), true);
  EXPECT_EQ(second.at("seen"), false);
  EXPECT_EQ(second.at("first_heard_utime"), -1);
  EXPECT_EQ(second.at("settled_utime").get<int64_t>(), int64_t{1} << 60);  // int64 exact
}

TEST(LcmJson, ByteArraysAreBase64) {
  beft::camera_frame_t frame{};
  frame.width = 2;
  frame.height = 1;
  frame.instance_ids = {"person_1"};
  frame.num_ids = 1;
  frame.data = {'M', 'a', 'n', 0xff, 0x00};
  frame.data_size = 5;
  const json value = toJson(frame, "beft.camera_frame_t");
  EXPECT_EQ(value.at("data"), "TWFu/wA=");
  EXPECT_EQ(value.at("instance_ids"), json({"person_1"}));
  EXPECT_EQ(base64Encode(std::string_view("")), "");
  EXPECT_EQ(base64Encode(std::string_view("Ma")), "TWE=");
}

TEST(LcmJson, SceneObjectsWithEmptyAndNestedLists) {
  beft::scene_objects_t objects{};
  objects.scenario = "yard";
  beft::scene_object_t wall{};
  wall.id = "wall_1";
  wall.shape = beft::scene_object_t::SHAPE_BOX;
  wall.color_rgb = 0x808080;
  objects.objects = {wall};
  objects.num_objects = 1;
  const json value = toJson(objects, "beft.scene_objects_t");
  EXPECT_EQ(value.at("categories"), json::array());
  EXPECT_EQ(value.at("congruency"), json::array());
  EXPECT_EQ(value.at("objects").at(0).at("id"), "wall_1");
  EXPECT_EQ(value.at("objects").at(0).at("color_rgb"), 0x808080);
  EXPECT_EQ(value.at("objects").at(0).at("shape"), 1);
}

TEST(LcmJson, EveryLayoutOfTheSampleType) {
  beft_test::sample_t sample{};
  sample.rows = 2;
  sample.cols = 3;
  sample.grid = {{1, 2, 3}, {4, 5, 6.5}};
  sample.fixed[0] = 7;
  sample.fixed[1] = -8;
  sample.inner.a = -300;
  sample.inner.f = 0.5f;
  sample.inner.s = "in";
  sample.pair[1].s = "second";
  sample.flags[0] = true;
  sample.blob = {1, 2, 3};
  const auto bytes = encode(sample);
  const LcmTypeSet types = sampleTypes();
  const json value = lcmToJson(types, *types.find("beft_test.sample_t"), bytes.data(), bytes.size());
  EXPECT_EQ(value.at("grid"), json({{1.0, 2.0, 3.0}, {4.0, 5.0, 6.5}}));
  EXPECT_EQ(value.at("fixed"), json({7, -8, 0}));
  EXPECT_EQ(value.at("inner"), json({{"a", -300}, {"f", 0.5}, {"s", "in"}}));
  EXPECT_EQ(value.at("pair").at(1).at("s"), "second");
  EXPECT_EQ(value.at("flags"), json({true, false}));
  EXPECT_EQ(value.at("blob"), "AQID");
  const json schema = jsonSchemaOf(types, *types.find("beft_test.sample_t"));
  EXPECT_EQ(schema.at("properties").at("grid").at("items").at("type"), "array");
  EXPECT_EQ(schema.at("properties").at("fixed").at("maxItems"), 3);
  EXPECT_EQ(schema.at("properties").at("blob").at("contentEncoding"), "base64");
  expectPropertiesMatchMembers(types, *types.find("beft_test.sample_t"), schema);
}

TEST(LcmJson, InvalidUtf8InStringsIsReplaced) {
  beft::robot_state_t state = robotState();
  state.last_command = "ok \xff\xc3";
  const json value = toJson(state, "beft.robot_state_t");
  EXPECT_EQ(value.at("last_command"), "ok \xef\xbf\xbd\xef\xbf\xbd");
  EXPECT_NO_THROW(dumpJson(value));
  EXPECT_EQ(validUtf8("\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80"), "\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80");
  EXPECT_EQ(validUtf8("\xc0\xaf"), "\xef\xbf\xbd\xef\xbf\xbd");  // overlong
  EXPECT_EQ(validUtf8("\xed\xa0\x80"), "\xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd");  // surrogate
}

TEST(LcmJson, TruncatedMessagesAreRefusedAtEveryLength) {
  const auto bytes = encode(twoHypotheses());
  const auto& type = beftType("beft.hypotheses_t");
  for (std::size_t size = 0; size < bytes.size(); ++size)
    EXPECT_THROW(lcmToJson(beftTypeSet(), type, bytes.data(), size), std::runtime_error) << size;
  EXPECT_NO_THROW(lcmToJson(beftTypeSet(), type, bytes.data(), bytes.size()));
}

TEST(LcmJson, WrongFingerprintTrailingBytesAndHugeLengthsAreRefused) {
  auto bytes = encode(twoHypotheses());
  const auto& type = beftType("beft.hypotheses_t");
  auto with_extra = bytes;
  with_extra.push_back(0);
  EXPECT_THROW(lcmToJson(beftTypeSet(), type, with_extra.data(), with_extra.size()), std::runtime_error);
  EXPECT_THROW(lcmToJson(beftTypeSet(), beftType("beft.robot_state_t"), bytes.data(), bytes.size()),
               std::runtime_error);
  // num_hypotheses follows the fingerprint and two int64: claim 2^31-1.
  for (std::size_t i = 0; i < 4; ++i) bytes[8 + 16 + i] = i == 0 ? 0x7f : 0xff;
  try {
    lcmToJson(beftTypeSet(), type, bytes.data(), bytes.size());
    ADD_FAILURE() << "a huge length was accepted";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("cannot fit"), std::string::npos) << error.what();
  }
}

TEST(LcmJson, GarbageNeverCrashes) {
  std::vector<uint8_t> bytes = encode(twoHypotheses());
  uint32_t state = 12345;
  for (int round = 0; round < 2000; ++round) {
    auto corrupt = bytes;
    for (int flips = 0; flips < 4; ++flips) {
      state = state * 1664525u + 1013904223u;
      corrupt[8 + state % (corrupt.size() - 8)] ^= static_cast<uint8_t>(state >> 24);
    }
    try {
      dumpJson(lcmToJson(beftTypeSet(), beftType("beft.hypotheses_t"), corrupt.data(), corrupt.size()));
    } catch (const std::runtime_error&) {
    }
  }
  SUCCEED();
}

TEST(LcmJsonSchema, EveryBeftTypeHasASchemaWhosePropertiesAreItsMembers) {
  const auto names = beftTypeSet().typeNames();
  EXPECT_GT(names.size(), 40u);
  for (const std::string& name : names) {
    const auto& type = beftType(name);
    const json schema = jsonSchemaOf(beftTypeSet(), type);
    EXPECT_EQ(schema.at("title"), name);
    EXPECT_EQ(schema.at("$schema"), "http://json-schema.org/draft-07/schema#");
    EXPECT_EQ(schema.at("required").size(), type.members.size()) << name;
    expectPropertiesMatchMembers(beftTypeSet(), type, schema);
  }
}

TEST(LcmJsonSchema, TypesUnitsAndNestedStructs) {
  const json robot = jsonSchemaOf(beftTypeSet(), beftType("beft.robot_state_t"));
  EXPECT_EQ(robot.at("properties").at("x").at("type"), "number");
  EXPECT_EQ(robot.at("properties").at("x").at("description"), "platform centre, world frame [m]");
  EXPECT_EQ(robot.at("properties").at("utime").at("type"), "integer");
  EXPECT_EQ(robot.at("properties").at("collided").at("type"), "boolean");
  EXPECT_EQ(robot.at("properties").at("last_command").at("type"), "string");
  EXPECT_EQ(robot.at("properties").at("collisions").at("maximum"), 2147483647);

  const json hypotheses = jsonSchemaOf(beftTypeSet(), beftType("beft.hypotheses_t"));
  const json& items = hypotheses.at("properties").at("hypotheses").at("items");
  EXPECT_EQ(items.at("title"), "beft.hypothesis_t");
  EXPECT_EQ(items.at("properties").at("categories").at("items").at("type"), "string");

  const json frame = jsonSchemaOf(beftTypeSet(), beftType("beft.camera_frame_t"));
  EXPECT_EQ(frame.at("properties").at("data").at("type"), "string");
  EXPECT_EQ(frame.at("properties").at("data").at("contentEncoding"), "base64");
  const std::string encoding = frame.at("properties").at("encoding").at("description");
  EXPECT_NE(encoding.find("(ENCODING_RGB8 = 0, ENCODING_DEPTH_MM16 = 1, ENCODING_INSTANCE16 = 2)"),
            std::string::npos)
      << encoding;
}

namespace {

std::string refusalOf(const std::string& type_name, const json& value) {
  try {
    jsonToLcm(beftTypeSet(), beftType(type_name), value);
  } catch (const JsonToLcmError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST(JsonToLcm, RoundTripsToTheBytesLcmGenEncodes) {
  const auto hypotheses = encode(twoHypotheses());
  const json value = lcmToJson(beftTypeSet(), beftType("beft.hypotheses_t"), hypotheses.data(), hypotheses.size());
  EXPECT_EQ(jsonToLcm(beftTypeSet(), beftType("beft.hypotheses_t"), value), hypotheses);

  beft::camera_frame_t frame{};
  frame.instance_ids = {"a", "b"};
  frame.num_ids = 2;
  frame.data = {0, 1, 2, 250, 251};
  frame.data_size = 5;
  const auto frame_bytes = encode(frame);
  EXPECT_EQ(jsonToLcm(beftTypeSet(), beftType("beft.camera_frame_t"),
                      lcmToJson(beftTypeSet(), beftType("beft.camera_frame_t"), frame_bytes.data(), frame_bytes.size())),
            frame_bytes);

  beft_test::sample_t sample{};
  sample.rows = 1;
  sample.cols = 2;
  sample.grid = {{1.5, -2}};
  sample.inner.a = -300;
  sample.inner.f = 0.25f;
  sample.blob = {9, 8};
  const auto sample_bytes = encode(sample);
  const LcmTypeSet types = sampleTypes();
  const auto& sample_type = *types.find("beft_test.sample_t");
  EXPECT_EQ(jsonToLcm(types, sample_type, lcmToJson(types, sample_type, sample_bytes.data(), sample_bytes.size())),
            sample_bytes);

  // null is NaN.
  json robot = toJson(robotState(), "beft.robot_state_t");
  const auto robot_bytes = jsonToLcm(beftTypeSet(), beftType("beft.robot_state_t"), robot);
  beft::robot_state_t decoded;
  ASSERT_EQ(decoded.decode(robot_bytes.data(), 0, static_cast<int>(robot_bytes.size())),
            static_cast<int>(robot_bytes.size()));
  EXPECT_TRUE(std::isnan(decoded.yaw));
  EXPECT_EQ(decoded.last_command, "goto \"door\"");
}

TEST(JsonToLcm, EveryRefusalNamesTheMember) {
  const json robot = toJson(robotState(), "beft.robot_state_t");
  auto with = [&](const std::string& key, const json& field) {
    json changed = robot;
    changed[key] = field;
    return refusalOf("beft.robot_state_t", changed);
  };
  json missing = robot;
  missing.erase("tick");
  EXPECT_EQ(refusalOf("beft.robot_state_t", missing), "tick: missing");
  EXPECT_EQ(with("tock", 1), "tock: not a member of beft.robot_state_t");
  EXPECT_EQ(with("tick", "1"), "tick: not an integer");
  EXPECT_EQ(with("tick", 1.5), "tick: not an integer");
  EXPECT_EQ(with("tick", 18446744073709551615ull),
            "tick: 18446744073709551615 is outside -9223372036854775808..9223372036854775807 of int64_t");
  EXPECT_EQ(with("collisions", 2147483648ll), "collisions: 2147483648 is outside -2147483648..2147483647 of int32_t");
  EXPECT_EQ(with("collided", 1), "collided: not true or false");
  EXPECT_EQ(with("x", "1"), "x: not a number or null");
  EXPECT_EQ(with("last_command", std::string("a\0b", 3)), "last_command: a string with a NUL character");
  EXPECT_EQ(refusalOf("beft.robot_state_t", json::array()), "beft.robot_state_t: not a JSON object");

  json hypotheses = toJson(twoHypotheses(), "beft.hypotheses_t");
  hypotheses["hypotheses"][1]["fused"].push_back(0.5);
  EXPECT_EQ(refusalOf("beft.hypotheses_t", hypotheses), "hypotheses[1].fused: 3 entries, num_categories says 2");
  hypotheses["num_hypotheses"] = 3;
  EXPECT_EQ(refusalOf("beft.hypotheses_t", hypotheses), "hypotheses: 2 entries, num_hypotheses says 3");
  hypotheses["num_hypotheses"] = -1;
  EXPECT_EQ(refusalOf("beft.hypotheses_t", hypotheses), "hypotheses: its size num_hypotheses is negative");

  json frame = toJson(beft::camera_frame_t{}, "beft.camera_frame_t");
  frame["data"] = "AQ==";
  EXPECT_EQ(refusalOf("beft.camera_frame_t", frame), "data: 1 bytes, data_size says 0");
  frame["data"] = "A=Q=";
  EXPECT_EQ(refusalOf("beft.camera_frame_t", frame), "data: not valid base64");
}

TEST(JsonToLcm, Base64DecodeIsStrict) {
  EXPECT_EQ(base64Decode("TWFu/wA="), std::string("Man\xff\0", 5));
  EXPECT_EQ(base64Decode(""), "");
  EXPECT_EQ(base64Decode("TWE="), "Ma");
  EXPECT_EQ(base64Decode("TQ=="), "M");
  for (const char* bad : {"TWE", "TW=E", "=QID", "AQ==AQID", "AQI*", "AQ==="})
    EXPECT_FALSE(base64Decode(bad).has_value()) << bad;
}

TEST(LcmJson, EmptyArraysDecodeAndManyEmptyRowsAreRefused) {
  const auto frame = encode(beft::camera_frame_t{});  // ends with an empty byte array
  EXPECT_EQ(lcmToJson(beftTypeSet(), beftType("beft.camera_frame_t"), frame.data(), frame.size()).at("data"), "");

  beft_test::sample_t sample{};
  sample.rows = 1000;
  sample.cols = 0;
  sample.grid.assign(1000, {});
  auto bytes = encode(sample);
  const LcmTypeSet types = sampleTypes();
  const auto& type = *types.find("beft_test.sample_t");
  EXPECT_EQ(lcmToJson(types, type, bytes.data(), bytes.size()).at("grid").size(), 1000u);
  // rows (after the fingerprint, utime and mode) claims 2^31-1 rows of nothing.
  const std::size_t rows_at = 8 + 8 + 1;
  bytes[rows_at] = 0x7f;
  for (std::size_t i = 1; i < 4; ++i) bytes[rows_at + i] = 0xff;
  try {
    lcmToJson(types, type, bytes.data(), bytes.size());
    ADD_FAILURE() << "2^31 empty rows were walked";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("empty arrays are too many"), std::string::npos) << error.what();
  }
}
