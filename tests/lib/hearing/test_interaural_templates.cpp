// The MIT KEMAR templates: orientation, plausible ITD and ILD, refusals.
#include <gtest/gtest.h>

#include "lib/hearing/interaural_templates.hpp"

namespace beft::hearing {
namespace {

const InterauralTemplates& mitTemplates() {
  static const InterauralTemplates templates = InterauralTemplates::fromSofa();
  return templates;
}

TEST(InterauralTemplates, ItdAtTheLeftIsAboutSevenTenthsOfAMillisecondAndPositive) {
  const auto& t = mitTemplates();
  EXPECT_GE(t.itd(90), 0.6e-3);
  EXPECT_LE(t.itd(90), 0.8e-3);
  EXPECT_LE(t.itd(270), -0.6e-3);
  EXPECT_GE(t.itd(270), -0.8e-3);
  EXPECT_NEAR(t.itd(0), 0, 30e-6);
  EXPECT_NEAR(t.itd(180), 0, 30e-6);
  // Grows from the front to the side, and front and back mirror each other.
  EXPECT_LT(t.itd(10), t.itd(30));
  EXPECT_LT(t.itd(30), t.itd(60));
  EXPECT_NEAR(t.itd(30), t.itd(150), 60e-6);
}

TEST(InterauralTemplates, TheLeftEarIsLouderForASourceOnTheLeft) {
  const auto& t = mitTemplates();
  double left = 0, right = 0;
  for (int b = t.firstLevelBand(); b < t.bands().size(); ++b) left += t.ild(90, b), right += t.ild(270, b);
  const int count = t.bands().size() - t.firstLevelBand();
  EXPECT_GT(left / count, 8.0);
  EXPECT_LT(right / count, -8.0);
  EXPECT_GT(t.phaseBins(), 20);
  EXPECT_NEAR(std::abs(t.interauralPhase(45, 10)), 1.0f, 1e-5f);
}

TEST(InterauralTemplates, AMissingFileIsAClearError) {
  try {
    InterauralTemplates::fromSofa("/nonexistent/head.sofa");
    FAIL() << "no error";
  } catch (const SofaError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/head.sofa"), std::string::npos) << e.what();
  }
}

TEST(InterauralTemplates, ResponsesOfTheWrongShapeAreRefused) {
  HorizontalHrirs too_few;
  too_few.sample_rate = 44100;
  too_few.left.resize(10, std::vector<float>(64, 0.0f));
  too_few.right = too_few.left;
  EXPECT_THROW(InterauralTemplates(too_few, AnalysisLayout{}), std::invalid_argument);
  HorizontalHrirs wrong_rate = loadSofaHorizontal(kMitKemarSofa, 48000);
  EXPECT_THROW(InterauralTemplates(wrong_rate, AnalysisLayout{}), std::invalid_argument);
}

}  // namespace
}  // namespace beft::hearing
