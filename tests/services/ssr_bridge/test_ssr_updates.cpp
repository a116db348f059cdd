#include <gtest/gtest.h>

#include <random>

#include "services/ssr_bridge/ssr_updates.hpp"

using namespace beft::ssr_bridge;

namespace {

std::vector<std::string> split(MessageSplitter& splitter, const std::string& bytes) {
  std::vector<std::string> messages;
  splitter.feed(bytes.data(), bytes.size(), messages);
  return messages;
}

const std::string z(1, '\0');

// What ssr-binaural 0.6 sent to a client connecting to a scene of two sources
// (recorded, levels left out).
const std::vector<std::string> kConnectingToTwoSources = {
    "<update><volume>0</volume><transport>start</transport><reference><position x=\"1.5\" y=\"2.5\"/>"
    "<orientation azimuth=\"-60\"/></reference><source id=\"7\" name=\"siren1\" model=\"point\" length=\"110250\" "
    "mute=\"false\" volume=\"0\"><file>/s/siren.wav</file><port>[_s_siren.wav:channel_1</port><position x=\"3\" "
    "y=\"4\"/><orientation azimuth=\"225\"/></source></update>",
    "<update><reference><position x='1.5' y='2.5'/></reference></update>",
    "<update><reference><orientation azimuth='-60'/></reference></update>",
    "<update><scene volume='0'/></update>",
    "<update><source id='1'><position x='3' y='4'/></source></update>",
    "<update><source id='1'><orientation azimuth='225'/></source></update>",
    "<update><source id='1' volume='0'/></update>",
    "<update><source id='1' mute='false'/></update>",
    "<update><source id='1' name='siren1'/></update>",
    "<update><source id='1' model='point'/></update>",
    "<update><source id='1'><position fixed='false'/></source></update>",
    "<update><source id='2'><position x='1' y='2'/></source></update>",
    "<update><source id='2' volume='-6.02'/></update>",
    "<update><source id='2' mute='true'/></update>",
    "<update><source id='2' name='vic&amp;\"1'/></update>",
    "<update><reference_offset><position x='0' y='0'/></reference_offset></update>",
    "<update><reference_offset><orientation azimuth='90'/></reference_offset></update>",
};

}  // namespace

TEST(MessageSplitter, CutsAtEachZeroAcrossReads) {
  MessageSplitter splitter;
  EXPECT_TRUE(split(splitter, "<update>").empty());
  EXPECT_EQ(splitter.pendingBytes(), 8u);
  const auto messages = split(splitter, "</update>" + z + "<a/>" + z + z + "<b");
  ASSERT_EQ(messages.size(), 3u);
  EXPECT_EQ(messages[0], "<update></update>");
  EXPECT_EQ(messages[1], "<a/>");
  EXPECT_EQ(messages[2], "");
  EXPECT_EQ(split(splitter, "/>" + z), std::vector<std::string>{"<b/>"});
}

TEST(MessageSplitter, AMessageWithoutItsZeroNeverGrowsPastTheLimit) {
  MessageSplitter splitter(64);
  EXPECT_TRUE(split(splitter, std::string(50, 'x')).empty());
  EXPECT_TRUE(split(splitter, std::string(5000, 'y')).empty());  // dropped, not kept
  EXPECT_EQ(splitter.pendingBytes(), 0u);
  EXPECT_EQ(splitter.dropped(), 1u);
  // The rest of the long message up to its zero is skipped; the next one is read.
  EXPECT_EQ(split(splitter, "yyy" + z + "<ok/>" + z), std::vector<std::string>{"<ok/>"});
}

TEST(SsrUpdates, TheStateSentOnConnectingIsRead) {
  SsrScene scene;
  std::vector<std::pair<int, std::string>> names;
  bool end_seen_before_last = false;
  for (std::size_t i = 0; i < kConnectingToTwoSources.size(); ++i) {
    UpdateNews news;
    ASSERT_TRUE(applyUpdate(kConnectingToTwoSources[i], scene, &news)) << kConnectingToTwoSources[i];
    names.insert(names.end(), news.names.begin(), news.names.end());
    if (i + 1 < kConnectingToTwoSources.size()) end_seen_before_last |= news.end_of_state;
    else EXPECT_TRUE(news.end_of_state);
  }
  EXPECT_FALSE(end_seen_before_last);
  EXPECT_TRUE(scene.state_received);
  // The summary's source (SSR's internal id 7) is not taken for source number 7.
  ASSERT_EQ(scene.sources.size(), 2u);
  const SsrSource& siren = scene.sources.at(1);
  EXPECT_EQ(siren.name, "siren1");
  EXPECT_DOUBLE_EQ(*siren.x, 3);
  EXPECT_DOUBLE_EQ(*siren.y, 4);
  EXPECT_DOUBLE_EQ(*siren.volume_db, 0);
  EXPECT_FALSE(*siren.mute);
  const SsrSource& victim = scene.sources.at(2);
  EXPECT_EQ(victim.name, "vic&\"1");
  EXPECT_DOUBLE_EQ(*victim.volume_db, -6.02);
  EXPECT_TRUE(*victim.mute);
  EXPECT_DOUBLE_EQ(*scene.reference_x, 1.5);
  EXPECT_DOUBLE_EQ(*scene.reference_y, 2.5);
  EXPECT_DOUBLE_EQ(*scene.reference_azimuth, -60);
  const std::vector<std::pair<int, std::string>> expected = {{1, "siren1"}, {2, "vic&\"1"}};
  EXPECT_EQ(names, expected);
}

TEST(SsrUpdates, LevelsAndOtherReportsChangeNothingMirrored) {
  SsrScene scene;
  ASSERT_TRUE(applyUpdate("<update><source id='1' name='a'/></update>", scene));
  EXPECT_TRUE(applyUpdate("<update><source id='1' level='-23.5'/></update>", scene));
  EXPECT_TRUE(applyUpdate("<update><cpu load='0.1'/></update>", scene));
  EXPECT_EQ(scene.sources.at(1).name, "a");
  EXPECT_FALSE(scene.sources.at(1).x.has_value());
}

TEST(SsrUpdates, ADeletionRenumbersTheSourcesAfterIt) {
  SsrScene scene;
  for (const char* m : {"<update><source id='1' name='a'/></update>", "<update><source id='2' name='b'/></update>",
                        "<update><source id='3' name='c'/></update>",
                        "<update><delete><source id='2'/></delete></update>"})
    ASSERT_TRUE(applyUpdate(m, scene)) << m;
  ASSERT_EQ(scene.sources.size(), 2u);
  EXPECT_EQ(scene.sources.at(1).name, "a");
  EXPECT_EQ(scene.sources.at(2).name, "c");
}

TEST(SsrUpdates, WhatIsNotAnUpdateIsRefusedAndChangesNothing) {
  SsrScene scene;
  ASSERT_TRUE(applyUpdate("<update><source id='1' name='a'><position x='1' y='2'/></source></update>", scene));
  const std::vector<std::string> refused = {
      "",
      "garbage",
      "<update><source id='1'",                                        // cut short
      "<request><source id='1' mute='true'/></request>",               // another root
      "<update><source id='0' mute='true'/></update>",                 // numbers start at 1
      "<update><source id='-3' mute='true'/></update>",
      "<update><source id='99999999999999' mute='true'/></update>",
      "<update><source id='x' mute='true'/></update>",
      "<update><source mute='true'/></update>",
      "<update><source id='1' mute='maybe'/></update>",
      "<update><source id='1' volume='loud'/></update>",
      "<update><source id='1' volume='nan'/></update>",
      "<update><source id='1' volume='1e999'/></update>",
      "<update><source id='1'><position x='1'/></source></update>",   // x without y
      "<update><source id='1'><position x='1' y='2m'/></source></update>",
      "<update><reference><orientation azimuth='inf'/></reference></update>",
      "<update><source id='1' mute='true'/><source id='1' volume='x'/></update>",  // all or nothing
      std::string("<update>\0</update>", 18),
  };
  for (const auto& message : refused) {
    UpdateNews news;
    EXPECT_FALSE(applyUpdate(message, scene, &news)) << message;
    EXPECT_TRUE(news.names.empty());
  }
  ASSERT_EQ(scene.sources.size(), 1u);
  EXPECT_EQ(scene.sources.at(1).name, "a");
  EXPECT_DOUBLE_EQ(*scene.sources.at(1).x, 1);
  EXPECT_FALSE(scene.sources.at(1).mute.has_value());
  EXPECT_FALSE(scene.reference_azimuth.has_value());
}

TEST(SsrUpdates, RandomBytesNeverCrashTheReader) {
  std::mt19937 random(7);
  const std::string alphabet = std::string("<>/='\" updatesourcidnamepositionxy0123456789.-&;") + z;
  MessageSplitter splitter(4096);
  SsrScene scene;
  std::size_t messages_read = 0;
  for (int round = 0; round < 2000; ++round) {
    std::string bytes;
    const int length = static_cast<int>(random() % 200);
    for (int i = 0; i < length; ++i)
      bytes += random() % 4 == 0 ? static_cast<char>(random() % 256) : alphabet[random() % alphabet.size()];
    // Now and then a real message in between, which must still be read.
    if (round % 50 == 0) bytes += z + "<update><source id='4' name='kept'/></update>" + z;
    for (const auto& message : split(splitter, bytes)) {
      applyUpdate(message, scene);
      ++messages_read;
    }
  }
  EXPECT_GT(messages_read, 0u);
  ASSERT_TRUE(scene.sources.count(4));
}
