// The paper's equations against numbers computed by hand (spec/model.md).
#include <gtest/gtest.h>

#include <cmath>

#include "lib/model/model.hpp"

using namespace beft::model;

TEST(Geometry, WrapDegreesIntoHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(wrapDegrees(180), 180);
  EXPECT_DOUBLE_EQ(wrapDegrees(-180), 180);
  EXPECT_DOUBLE_EQ(wrapDegrees(190), -170);
  EXPECT_DOUBLE_EQ(wrapDegrees(-190), 170);
  EXPECT_DOUBLE_EQ(wrapDegrees(720 + 45), 45);
  EXPECT_DOUBLE_EQ(wrapDegrees(0), 0);
}

TEST(Geometry, DistanceIsThreeDimensional) {
  EXPECT_DOUBLE_EQ(distance(0, 0, 0, 3, 4, 0), 5);
  EXPECT_DOUBLE_EQ(distance(1, 1, 0, 1, 1, 2), 2);
}

TEST(Geometry, AzimuthStraightAheadIsZero) {
  EXPECT_NEAR(azimuth(0, 0, 0, 5, 0), 0, 1e-12);
  EXPECT_NEAR(azimuth(2, 2, 90, 2, 7), 0, 1e-12);  // nose facing +y
}

TEST(Geometry, AzimuthStraightLeftIsPlus90) {
  EXPECT_NEAR(azimuth(0, 0, 0, 0, 3), 90, 1e-12);
  EXPECT_NEAR(azimuth(0, 0, 0, 0, -3), -90, 1e-12);
}

TEST(Geometry, AzimuthBehindWrapsAtPlusMinus180) {
  EXPECT_NEAR(azimuth(0, 0, 0, -4, 0), 180, 1e-12);
  EXPECT_NEAR(azimuth(0, 0, 0, -4, 1e-9), 180, 1e-6);
  EXPECT_NEAR(azimuth(0, 0, 0, -4, -1e-6), -180, 1e-4);
  // Head turned: nose at 170 deg, object at bearing -170 deg is 20 deg to the left.
  EXPECT_NEAR(azimuth(0, 0, 170, std::cos(-170 * M_PI / 180), std::sin(-170 * M_PI / 180)), 20,
              1e-9);
}

TEST(Degradation, DistanceHalfAtTenMetres) {
  EXPECT_DOUBLE_EQ(distanceDegradation(10), 0.5);
  EXPECT_NEAR(distanceDegradation(0), 1 - 1 / (1 + std::exp(5.0)), 1e-12);  // 0.99331
  EXPECT_NEAR(distanceDegradation(0), 0.993307, 1e-6);
  EXPECT_NEAR(distanceDegradation(20), 0.006693, 1e-6);
}

TEST(Degradation, AzimuthDefaultVarianceIsNinetySquared) {
  EXPECT_DOUBLE_EQ(azimuthDegradation(0), 1.0);
  EXPECT_NEAR(azimuthDegradation(90), 0.606531, 1e-6);
  EXPECT_NEAR(azimuthDegradation(180), 0.135335, 1e-6);
  EXPECT_NEAR(azimuthDegradation(-90), azimuthDegradation(90), 1e-15);
}

TEST(Degradation, AzimuthPrintedVarianceIsOneSettingAway) {
  Parameters printed;
  setParameter(printed, "aw_variance_deg2", "90");
  EXPECT_NEAR(azimuthDegradation(30, printed), 0.0067379, 1e-6);
}

TEST(Degradation, OcclusionTermsInPercent) {
  EXPECT_DOUBLE_EQ(visualOcclusionDegradation(0), 1);
  EXPECT_DOUBLE_EQ(visualOcclusionDegradation(100), 0);
  EXPECT_DOUBLE_EQ(visualOcclusionDegradation(25), 0.75);
  EXPECT_DOUBLE_EQ(acousticOcclusionDegradation(0), 1);
  EXPECT_DOUBLE_EQ(acousticOcclusionDegradation(100), 0.2);
  EXPECT_DOUBLE_EQ(acousticOcclusionDegradation(50), 0.6);
}

TEST(Degradation, PerceptibilitiesAreProductsOfTheTerms) {
  // eq. 1 at d = 10, O_v = 50: 0.5 * 0.5
  EXPECT_DOUBLE_EQ(visualPerceptibility(10, 50), 0.25);
  // eq. 2 at d = 10, O_a = 100, alpha = 90: 0.5 * 0.2 * 0.60653
  EXPECT_NEAR(acousticPerceptibility(10, 100, 90), 0.5 * 0.2 * 0.606531, 1e-6);
}

TEST(Labelling, DefaultFormSeparatesAtFullPerceptibility) {
  EXPECT_GE(labelConfidence(true, 1.0), 0.99);
  EXPECT_LE(labelConfidence(false, 1.0), 0.01);
  EXPECT_NEAR(labelConfidence(true, 1.0), 0.5 + 0.5 / (1 + std::exp(-10.0)), 1e-12);
}

TEST(Labelling, DefaultFormIsUndecidedAtZeroPerceptibility) {
  EXPECT_NEAR(labelConfidence(true, 0.0), 0.5, 0.01);
  EXPECT_NEAR(labelConfidence(false, 0.0), 0.5, 0.01);
  EXPECT_DOUBLE_EQ(labelConfidence(true, 0.5), 0.75);
  EXPECT_DOUBLE_EQ(labelConfidence(false, 0.5), 0.25);
}

TEST(Labelling, PrintedFormStaysNearOneHalf) {
  Parameters printed;
  setParameter(printed, "label_form", "printed");
  // 0.5 + 0.5 / (1 + 20 e^-0.5) = 0.5 + 0.5 / 13.1306 = 0.538079
  EXPECT_NEAR(labelConfidence(true, 1.0, printed), 0.538079, 1e-6);
  EXPECT_NEAR(labelConfidence(false, 1.0, printed), 0.461921, 1e-6);
  for (double p = 0; p <= 1.0; p += 0.1) {
    EXPECT_LE(std::abs(labelConfidence(true, p, printed) - 0.5), 0.04);
    EXPECT_LE(std::abs(labelConfidence(false, p, printed) - 0.5), 0.04);
  }
}

TEST(Labelling, OneConfidencePerCategory) {
  const auto l = labelConfidences({"person", "car", "siren"}, "car", 1.0);
  ASSERT_EQ(l.size(), 3u);
  EXPECT_LE(l[0], 0.01);
  EXPECT_GE(l[1], 0.99);
  EXPECT_LE(l[2], 0.01);
}

TEST(DynamicWeighting, RisingCurveSpansAQuarterOverTmax) {
  EXPECT_DOUBLE_EQ(weightRising(1, 0.5), 0.5);
  EXPECT_NEAR(weightRising(10, 0.5), 0.75, 1e-12);
  EXPECT_NEAR(weightRising(25, 0.5), 0.75, 1e-12);  // held after T_max
  EXPECT_NEAR(weightRising(10, 0.75), 1.0, 1e-12);
  // log(5) / (2 log 100) + 0.25
  EXPECT_NEAR(weightRising(5, 0.25), std::log(5.0) / (2 * std::log(100.0)) + 0.25, 1e-12);
}

TEST(DynamicWeighting, FallingCurveMirrorsRising) {
  EXPECT_DOUBLE_EQ(weightFalling(1, 0.75), 0.75);
  EXPECT_NEAR(weightFalling(10, 0.75), 0.5, 1e-12);
  EXPECT_NEAR(weightFalling(10, 0.25), 0.0, 1e-12);
  EXPECT_NEAR(weightFalling(3, 0.5), 0.5 - std::log(3.0) / (2 * std::log(100.0)), 1e-12);
}

TEST(DynamicWeighting, CurvesAreClampedToUnitInterval) {
  Parameters wide;
  setParameter(wide, "n", "4");  // log(10)/(2 log 4) = 0.83: would leave [0, 1]
  EXPECT_DOUBLE_EQ(weightRising(10, 0.75, wide), 1.0);
  EXPECT_DOUBLE_EQ(weightFalling(10, 0.25, wide), 0.0);
}

TEST(Parameters, BadNamesAndValuesAreRefusedByName) {
  Parameters p;
  EXPECT_THROW(setParameter(p, "gain", "3"), std::invalid_argument);
  EXPECT_THROW(setParameter(p, "label_gain", "abc"), std::invalid_argument);
  EXPECT_THROW(setParameter(p, "label_gain", "-1"), std::invalid_argument);
  EXPECT_THROW(setParameter(p, "label_form", "literal"), std::invalid_argument);
  try {
    setParameter(p, "label_gain", "nan");
    FAIL() << "nan accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("label_gain"), std::string::npos);
  }
  setParameter(p, "label_gain", "10");
  EXPECT_DOUBLE_EQ(p.label_gain, 10);
}
