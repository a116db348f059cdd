// Small drawing helpers shared by the report's pictures (OpenCV imgproc):
// readable text, dashed lines, axis ticks, category and series colours.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace beft::report::draw {

inline const cv::Scalar kBlack(0, 0, 0);
inline const cv::Scalar kWhite(255, 255, 255);
inline const cv::Scalar kDarkGrey(70, 70, 70);
inline const cv::Scalar kMidGrey(150, 150, 150);
inline const cv::Scalar kLightGrey(225, 225, 225);

// Anti-aliased Hershey text; origin is the bottom-left of the text.
void text(cv::Mat& image, const std::string& content, cv::Point origin, double scale = 0.5,
          const cv::Scalar& color = kBlack, int thickness = 1);
cv::Size textSize(const std::string& content, double scale = 0.5, int thickness = 1);
// Text on a filled box (for labels over busy backgrounds).
void labelBox(cv::Mat& image, const std::string& content, cv::Point origin, double scale,
              const cv::Scalar& color, const cv::Scalar& background);

void dashedLine(cv::Mat& image, cv::Point from, cv::Point to, const cv::Scalar& color, int thickness = 1,
                int dash = 8, int gap = 6);

// Round tick values (1, 2, 5 x 10^k steps) covering [low, high], about `count` of them.
std::vector<double> niceTicks(double low, double high, int count);
// "12", "2.5", "0.25": no trailing zeros.
std::string formatNumber(double value, int max_decimals = 2);

// BGR colour of a category: fixed for the format's default ones, a palette
// colour (by position in `categories`) for the others.
cv::Scalar categoryColor(const std::string& label, const std::vector<std::string>& categories);
// The i-th colour of a palette of distinct, readable line colours.
cv::Scalar seriesColor(int index);
// color blended toward white by `amount` in [0, 1].
cv::Scalar lighter(const cv::Scalar& color, double amount);
// color scaled toward black by `amount` in [0, 1] (text in a category's colour).
cv::Scalar darker(const cv::Scalar& color, double amount = 0.35);

}  // namespace beft::report::draw
