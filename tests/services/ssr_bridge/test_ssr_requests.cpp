#include <gtest/gtest.h>

#include <tinyxml2.h>

#include "services/ssr_bridge/ssr_requests.hpp"

using namespace beft::ssr_bridge;

namespace {

// The request as SSR's XML parser would see it.
struct Parsed {
  tinyxml2::XMLDocument doc;
  const tinyxml2::XMLElement* child(const char* name) const {
    const auto* root = doc.RootElement();
    return root ? root->FirstChildElement(name) : nullptr;
  }
};
void parse(const std::string& request, Parsed& parsed) {
  ASSERT_EQ(parsed.doc.Parse(request.c_str()), tinyxml2::XML_SUCCESS) << request;
  ASSERT_STREQ(parsed.doc.RootElement()->Name(), "request");
}

}  // namespace

TEST(SsrRequests, NewSourceCarriesItsWholeState) {
  const std::string request = newSourceRequest({"siren1", "/data/sounds/siren.wav", 6, 13.25, -6.0206, true});
  EXPECT_EQ(request,
            "<request><source new=\"true\" name=\"siren1\" file=\"/data/sounds/siren.wav\" volume=\"-6.02\" "
            "mute=\"true\"><position x=\"6.000\" y=\"13.250\"/></source></request>");
}

TEST(SsrRequests, NamesAndPathsAreEscaped) {
  const std::string name = "a&b <c> \"d\" 'e'\ttab";
  const std::string file = "/tmp/odd dir/x&y'<z>\".wav";
  Parsed parsed;
  const std::string request = newSourceRequest({name, file, 0, 0, 0, false});
  parse(request, parsed);
  const auto* source = parsed.child("source");
  ASSERT_NE(source, nullptr);
  EXPECT_STREQ(source->Attribute("name"), name.c_str());
  EXPECT_STREQ(source->Attribute("file"), file.c_str());
  EXPECT_EQ(request.find('\t'), std::string::npos);  // a parser would make a space of it
  EXPECT_EQ(escapeAttribute("\xC3\xA9t\xC3\xA9"), "\xC3\xA9t\xC3\xA9");  // UTF-8 stays as it is
}

TEST(SsrRequests, OnlyPrintableUtf8IsRepresentable) {
  EXPECT_TRUE(representable("victim_1"));
  EXPECT_TRUE(representable("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x94\x8A"));
  EXPECT_TRUE(representable("line\nbreak\ttab"));
  EXPECT_FALSE(representable(std::string("zero\0byte", 9)));  // would end the message early
  EXPECT_FALSE(representable("bell\x07"));
  EXPECT_FALSE(representable("\x7F"));
  EXPECT_FALSE(representable("\xC3"));          // cut short
  EXPECT_FALSE(representable("\xC0\xAF"));      // overlong
  EXPECT_FALSE(representable("\xED\xA0\x80"));  // a surrogate
  EXPECT_FALSE(representable("\xFF"));
}

TEST(SsrRequests, ASourceChangeSendsOnlyWhatChanged) {
  EXPECT_EQ(sourceChangeRequest(3, {1.5, -2.0, std::nullopt, std::nullopt}),
            "<request><source id=\"3\"><position x=\"1.500\" y=\"-2.000\"/></source></request>");
  EXPECT_EQ(sourceChangeRequest(12, {std::nullopt, std::nullopt, std::nullopt, true}),
            "<request><source id=\"12\" mute=\"true\"/></request>");
  Parsed parsed;
  parse(sourceChangeRequest(1, {0.0, 0.0, -120.0, false}), parsed);
  const auto* source = parsed.child("source");
  ASSERT_NE(source, nullptr);
  EXPECT_STREQ(source->Attribute("id"), "1");
  EXPECT_STREQ(source->Attribute("volume"), "-120.00");
  EXPECT_STREQ(source->Attribute("mute"), "false");
  EXPECT_NE(source->FirstChildElement("position"), nullptr);
  EXPECT_EQ(source->Attribute("new"), nullptr);
}

TEST(SsrRequests, TheReferenceTakesPositionAndOrOrientation) {
  EXPECT_EQ(referenceRequest({2.0, 3.0, 120.0}),
            "<request><reference><position x=\"2.000\" y=\"3.000\"/><orientation azimuth=\"120.00\"/>"
            "</reference></request>");
  EXPECT_EQ(referenceRequest({std::nullopt, std::nullopt, 359.994}),
            "<request><reference><orientation azimuth=\"359.99\"/></reference></request>");
  Parsed parsed;
  parse(referenceRequest({-1.0, 0.25, std::nullopt}), parsed);
  const auto* reference = parsed.child("reference");
  ASSERT_NE(reference, nullptr);
  EXPECT_EQ(reference->FirstChildElement("orientation"), nullptr);
  EXPECT_STREQ(reference->FirstChildElement("position")->Attribute("x"), "-1.000");
}

TEST(SsrRequests, ClearingTheScene) {
  Parsed parsed;
  parse(clearSceneRequest(), parsed);
  ASSERT_NE(parsed.child("scene"), nullptr);
  EXPECT_STREQ(parsed.child("scene")->Attribute("clear"), "true");
}
