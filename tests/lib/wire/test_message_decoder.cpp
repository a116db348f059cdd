// The .lcm schema parser, fingerprints (checked against lcm-gen's) and the
// readable text of decoded messages.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <beft/camera_frame_t.hpp>
#include <beft/hypotheses_t.hpp>
#include <beft/object_labels_t.hpp>
#include <beft/robot_command_t.hpp>
#include <beft/robot_state_t.hpp>
#include <beft_test/sample_t.hpp>

#include "all_beft_types.hpp"
#include "lib/wire/message_decoder.hpp"
#include "lib/wire/lcm_schema.hpp"

using namespace beft::blackboard;
using namespace beft::wire;

namespace {

template <typename Message>
std::vector<uint8_t> encode(const Message& message) {
  std::vector<uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

std::string describe(const std::string& channel, const std::vector<uint8_t>& bytes, int max_lines = 200) {
  return describeMessage(channel, bytes.data(), static_cast<int>(bytes.size()), max_lines);
}

bool hasLine(const std::string& text, const std::string& line) {
  std::istringstream lines(text);
  for (std::string current; std::getline(lines, current);)
    if (current == line) return true;
  return false;
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

std::string schemaError(const std::string& text) {
  try {
    LcmTypeSet types;
    types.addSchema("bad.lcm", text);
    types.finalize();
  } catch (const SchemaError& error) {
    return error.what();
  }
  return "";
}

beft::robot_state_t sampleRobotState() {
  beft::robot_state_t state{};
  state.utime = 4200000;
  state.tick = 42;
  state.x = 1.5;
  state.y = -0.25;
  state.yaw = 90;
  state.collisions = 3;
  state.collided = true;
  state.last_command = "goto \"door\"";
  return state;
}

}  // namespace

TEST(LcmSchema, FingerprintOfEveryBeftTypeMatchesLcmGen) {
  const auto& decoder = MessageDecoder::beftTypes();
  const auto expected = allBeftTypes();
  ASSERT_FALSE(expected.empty());
  for (const auto& [name, hash] : expected) {
    ASSERT_NE(decoder.types().find(name), nullptr) << name << " is not embedded";
    EXPECT_EQ(decoder.types().fingerprint(name), hash) << name;
  }
  EXPECT_EQ(decoder.types().typeNames().size(), expected.size());
}

TEST(LcmSchema, FingerprintsOfMultiDimensionalAndNestedTypesMatchLcmGen) {
  const LcmTypeSet types = sampleTypes();
  EXPECT_EQ(types.fingerprint("beft_test.sample_t"), beft_test::sample_t::getHash());
  EXPECT_EQ(types.fingerprint("beft_test.sample_inner_t"), beft_test::sample_inner_t::getHash());
  const LcmStruct* sample = types.find("beft_test.sample_t");
  ASSERT_NE(sample, nullptr);
  EXPECT_EQ(sample->members.size(), 11u);  // "rows, cols" declares two
  ASSERT_EQ(sample->constants.size(), 3u);
  EXPECT_EQ(sample->constants[1].name, "MODE_B");
  EXPECT_EQ(sample->constants[1].value, "5");
}

TEST(LcmSchema, ErrorsNameTheFileAndLine) {
  EXPECT_NE(schemaError("package p;\nstruct a_t\n{\n  int32_t x\n}\n").find("bad.lcm:5"), std::string::npos);
  EXPECT_NE(schemaError("package p;\nstruct a_t {\n  int32_t x;\n  double  x;\n}\n").find("bad.lcm:4: member 'x' declared twice"),
            std::string::npos);
  EXPECT_NE(schemaError("package p;\nstruct a_t { int32_t x;").find("unexpected end of file"), std::string::npos);
  EXPECT_NE(schemaError("package p;\nstruct a_t { other_t y; }").find("unknown type p.other_t"), std::string::npos);
  EXPECT_NE(schemaError("package p;\nstruct a_t { double v[n]; int32_t n; }").find("not an earlier member"),
            std::string::npos);
  EXPECT_NE(schemaError("package p;\nstruct a_t { double n; double v[n]; }").find("not an integer"), std::string::npos);
  EXPECT_NE(schemaError("package p;\n/* never closed\nstruct a_t {}").find("bad.lcm:2: unterminated"), std::string::npos);
  EXPECT_NE(schemaError("package p; struct a_t { int32_t x; } @").find("unexpected character '@'"), std::string::npos);
}

TEST(MessageDecoder, TypeNameFromTheFingerprint) {
  const auto bytes = encode(sampleRobotState());
  EXPECT_EQ(typeNameOf(bytes.data(), static_cast<int>(bytes.size())), "beft.robot_state_t");
  const std::vector<uint8_t> unknown(16, 0xab);
  EXPECT_EQ(typeNameOf(unknown.data(), 16), "");
  EXPECT_EQ(typeNameOf(bytes.data(), 7), "");
}

TEST(MessageDecoder, RobotStateOneLinePerField) {
  const std::string text = describe("ROBOT_STATE", encode(sampleRobotState()));
  EXPECT_TRUE(hasLine(text, "utime: 4200000 (4.2 s)")) << text;
  EXPECT_TRUE(hasLine(text, "tick: 42")) << text;
  EXPECT_TRUE(hasLine(text, "x: 1.5")) << text;
  EXPECT_TRUE(hasLine(text, "y: -0.25")) << text;
  EXPECT_TRUE(hasLine(text, "yaw: 90")) << text;
  EXPECT_TRUE(hasLine(text, "collisions: 3")) << text;
  EXPECT_TRUE(hasLine(text, "collided: true")) << text;
  EXPECT_TRUE(hasLine(text, "last_command: \"goto \\\"door\\\"\"")) << text;
  // Every member of robot_state_t, nothing else.
  const auto* type = MessageDecoder::beftTypes().types().find("beft.robot_state_t");
  ASSERT_NE(type, nullptr);
  EXPECT_EQ(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')), type->members.size());
}

TEST(MessageDecoder, ConstantsNameTheValueOfTheirField) {
  beft::robot_command_t command{};
  command.mode = beft::robot_command_t::MODE_GOTO;
  command.goal_x = 3;
  const std::string text = describe("ROBOT_CMD", encode(command));
  EXPECT_TRUE(hasLine(text, "mode: 2 (MODE_GOTO)")) << text;
  EXPECT_TRUE(hasLine(text, "goal_x: 3")) << text;
}

TEST(MessageDecoder, NestedStructArraysAreIndented) {
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
    hypothesis.first_heard_utime = -1;
    hypotheses.hypotheses.push_back(hypothesis);
  }
  hypotheses.num_hypotheses = 2;
  const std::string text = describe("HYPOTHESES", encode(hypotheses));
  EXPECT_TRUE(hasLine(text, "num_hypotheses: 2")) << text;
  EXPECT_TRUE(hasLine(text, "hypotheses[0]:")) << text;
  EXPECT_TRUE(hasLine(text, "  object_id: \"person_1\"")) << text;
  EXPECT_TRUE(hasLine(text, "hypotheses[1]:")) << text;
  EXPECT_TRUE(hasLine(text, "  object_id: \"siren_2\"")) << text;
  EXPECT_TRUE(hasLine(text, "  categories: [\"person\", \"car\"]")) << text;
  EXPECT_TRUE(hasLine(text, "  fused: [0.875, 0.125]")) << text;
  EXPECT_TRUE(hasLine(text, "  first_heard_utime: -1")) << text;  // no seconds for "never"
}

TEST(MessageDecoder, ByteArraysAreSummarisedAndLongArraysCut) {
  beft::camera_frame_t frame{};
  frame.utime = 5;
  frame.encoding = beft::camera_frame_t::ENCODING_DEPTH_MM16;
  frame.compression = beft::camera_frame_t::COMPRESSION_ZSTD;
  frame.width = 4;
  frame.height = 2;
  frame.data.assign(16, 7);
  frame.data_size = 16;
  const std::string frame_text = describe("CAMERA_DEPTH", encode(frame));
  EXPECT_TRUE(hasLine(frame_text, "data: <16 bytes>")) << frame_text;
  EXPECT_TRUE(hasLine(frame_text, "encoding: 1 (ENCODING_DEPTH_MM16)")) << frame_text;
  EXPECT_TRUE(hasLine(frame_text, "compression: 1 (COMPRESSION_ZSTD)")) << frame_text;
  EXPECT_TRUE(hasLine(frame_text, "instance_ids: []")) << frame_text;

  beft::object_labels_t labels{};
  for (int i = 0; i < 40; ++i) {
    labels.categories.push_back("k" + std::to_string(i));
    labels.confidence.push_back(i);
  }
  labels.num_categories = 40;
  const std::string labels_text = describe("", encode(labels));
  EXPECT_TRUE(hasLine(labels_text, "confidence: [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, ... +28 more]")) << labels_text;
}

TEST(MessageDecoder, MaxLinesCutsTheTextWithACount) {
  const std::string text = describe("ROBOT_STATE", encode(sampleRobotState()), 5);
  const auto* type = MessageDecoder::beftTypes().types().find("beft.robot_state_t");
  ASSERT_NE(type, nullptr);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 5);
  EXPECT_TRUE(hasLine(text, "... (+" + std::to_string(type->members.size() - 4) + " more lines)")) << text;
}

TEST(MessageDecoder, EveryLayoutOfTheSampleType) {
  beft_test::sample_t sample{};
  sample.utime = 2500000;
  sample.mode = 5;
  sample.rows = 2;
  sample.cols = 3;
  sample.grid = {{1, 2, 3}, {4, 5, 6.5}};
  sample.fixed[0] = 7;
  sample.fixed[1] = -8;
  sample.fixed[2] = 9;
  sample.inner.a = -300;
  sample.inner.f = 0.5f;
  sample.inner.s = "in";
  sample.pair[1].s = "second";
  sample.flags[0] = true;
  sample.blob = {1, 2, 3};
  sample.seen_utime = 1000;
  const auto bytes = encode(sample);

  const MessageDecoder decoder(sampleTypes());
  const std::string text = decoder.describe("SAMPLE", bytes.data(), static_cast<int>(bytes.size()));
  for (const char* line : {"utime: 2500000 (2.5 s)", "mode: 5 (MODE_B)", "rows: 2", "cols: 3",
                           "grid[0]: [1, 2, 3]", "grid[1]: [4, 5, 6.5]", "fixed: [7, -8, 9]", "inner:",
                           "  a: -300", "  f: 0.5", "  s: \"in\"", "pair[0]:", "pair[1]:", "  s: \"second\"",
                           "flags: [true, false]", "blob: <3 bytes>", "seen_utime: 1000 (0.001 s)"})
    EXPECT_TRUE(hasLine(text, line)) << "missing '" << line << "' in\n" << text;
}

TEST(MessageDecoder, TruncatedMessageSaysWhereItEnds) {
  auto bytes = encode(sampleRobotState());
  bytes.resize(bytes.size() - 6);
  const std::string text = describe("ROBOT_STATE", bytes);
  EXPECT_NE(text.find("cannot decode as beft.robot_state_t"), std::string::npos) << text;
  EXPECT_NE(text.find("last_command"), std::string::npos) << text;
}

TEST(MessageDecoder, CorruptLengthDoesNotRunAway) {
  beft::object_labels_t labels{};
  labels.object_id = "a";
  auto bytes = encode(labels);
  // num_categories follows the fingerprint, the string (4 + 2 bytes) and the double.
  const std::size_t offset = 8 + 6 + 8;
  for (std::size_t i = 0; i < 4; ++i) bytes[offset + i] = 0x7f;
  const std::string text = describe("", bytes);
  EXPECT_NE(text.find("cannot fit"), std::string::npos) << text;
}

TEST(MessageDecoder, UnknownFingerprintOnAKnownChannelNamesTheExpectedType) {
  auto bytes = encode(sampleRobotState());
  bytes[0] ^= 0xff;
  const std::string text = describe("ROBOT_STATE", bytes);
  EXPECT_NE(text.find("unknown type"), std::string::npos) << text;
  EXPECT_NE(text.find("ROBOT_STATE carries beft.robot_state_t"), std::string::npos) << text;
  EXPECT_NE(describe("X", std::vector<uint8_t>(3, 0)).find("3 bytes"), std::string::npos);
}

TEST(MessageDecoder, AKnownTypeOnAnotherTypesChannelIsNoted) {
  const std::string text = describe("HYPOTHESES", encode(sampleRobotState()));
  EXPECT_NE(text.find("note: HYPOTHESES normally carries beft.hypotheses_t"), std::string::npos) << text;
  EXPECT_TRUE(hasLine(text, "x: 1.5")) << text;
}

TEST(MessageDecoder, NumbersReadBackExactly) {
  EXPECT_EQ(formatNumber(0.1), "0.1");
  EXPECT_EQ(formatNumber(-2), "-2");
  EXPECT_EQ(std::stod(formatNumber(1.0 / 3.0)), 1.0 / 3.0);
}

TEST(MessageDecoder, CorruptedMessagesNeverCrashOrThrow) {
  // Random byte flips and truncations of real messages: the text must say
  // something, whatever the damage (run under BEFT_SANITIZE to check memory).
  beft::hypotheses_t hypotheses{};
  beft::hypothesis_t hypothesis{};
  hypothesis.object_id = "a";
  hypothesis.categories = {"person", "car"};
  hypothesis.fused = {0.5, 0.5};
  hypothesis.num_categories = 2;
  hypotheses.hypotheses = {hypothesis, hypothesis};
  hypotheses.num_hypotheses = 2;
  const std::vector<std::vector<uint8_t>> originals = {encode(hypotheses), encode(sampleRobotState())};
  uint64_t state = 12345;
  auto next = [&state]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<uint32_t>(state >> 33);
  };
  for (int round = 0; round < 3000; ++round) {
    auto bytes = originals[round % originals.size()];
    const int flips = 1 + static_cast<int>(next() % 4);
    for (int i = 0; i < flips; ++i) {
      // Keep the fingerprint most of the time so the decoder goes deep.
      const std::size_t at = 8 + next() % (bytes.size() - 8);
      bytes[at] = static_cast<uint8_t>(next());
    }
    if (next() % 3 == 0) bytes.resize(next() % bytes.size());
    const std::string text = describe("HYPOTHESES", bytes, 50);
    EXPECT_FALSE(text.empty());
    EXPECT_LE(std::count(text.begin(), text.end(), '\n'), 50);
  }
}
