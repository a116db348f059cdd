#include "lib/report/drawing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace beft::report::draw {

void text(cv::Mat& image, const std::string& content, cv::Point origin, double scale, const cv::Scalar& color,
          int thickness) {
  cv::putText(image, content, origin, cv::FONT_HERSHEY_SIMPLEX, scale, color, thickness, cv::LINE_AA);
}

cv::Size textSize(const std::string& content, double scale, int thickness) {
  int baseline = 0;
  return cv::getTextSize(content, cv::FONT_HERSHEY_SIMPLEX, scale, thickness, &baseline);
}

void labelBox(cv::Mat& image, const std::string& content, cv::Point origin, double scale, const cv::Scalar& color,
              const cv::Scalar& background) {
  const cv::Size size = textSize(content, scale);
  cv::rectangle(image, cv::Rect(origin.x - 2, origin.y - size.height - 3, size.width + 4, size.height + 6),
                background, cv::FILLED);
  text(image, content, origin, scale, color);
}

void dashedLine(cv::Mat& image, cv::Point from, cv::Point to, const cv::Scalar& color, int thickness, int dash,
                int gap) {
  const double dx = to.x - from.x, dy = to.y - from.y;
  const double length = std::hypot(dx, dy);
  if (length < 1) return;
  for (double s = 0; s < length; s += dash + gap) {
    const double e = std::min(length, s + dash);
    const cv::Point a(static_cast<int>(std::lround(from.x + dx * s / length)),
                      static_cast<int>(std::lround(from.y + dy * s / length)));
    const cv::Point b(static_cast<int>(std::lround(from.x + dx * e / length)),
                      static_cast<int>(std::lround(from.y + dy * e / length)));
    cv::line(image, a, b, color, thickness, cv::LINE_AA);
  }
}

std::vector<double> niceTicks(double low, double high, int count) {
  std::vector<double> ticks;
  if (!(high > low) || count < 1) return {low};
  const double raw = (high - low) / count;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double factor : {1.0, 2.0, 5.0, 10.0}) {
    step = factor * magnitude;
    if (step >= raw) break;
  }
  for (double v = std::ceil(low / step - 1e-9) * step; v <= high + step * 1e-9; v += step)
    ticks.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
  return ticks;
}

std::string formatNumber(double value, int max_decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", max_decimals, value);
  std::string s(buffer);
  if (s.find('.') != std::string::npos) {
    while (!s.empty() && s.back() == '0') s.pop_back();
    if (!s.empty() && s.back() == '.') s.pop_back();
  }
  return s == "-0" ? "0" : s;
}

cv::Scalar seriesColor(int index) {
  // Tableau 10, as BGR.
  static const cv::Scalar palette[] = {
      {180, 119, 31}, {14, 127, 255}, {44, 160, 44}, {40, 39, 214},  {189, 103, 148},
      {75, 86, 140},  {194, 119, 227}, {127, 127, 127}, {34, 189, 188}, {207, 190, 23}};
  const int n = static_cast<int>(sizeof palette / sizeof palette[0]);
  return palette[((index % n) + n) % n];
}

cv::Scalar categoryColor(const std::string& label, const std::vector<std::string>& categories) {
  if (label == "person") return {40, 40, 215};     // red
  if (label == "car") return {200, 120, 30};       // blue
  if (label == "siren") return {190, 60, 190};     // magenta
  if (label == "wall") return {90, 110, 140};      // brown-grey
  if (label == "fire") return {0, 140, 255};       // orange
  const auto it = std::find(categories.begin(), categories.end(), label);
  const int index = it == categories.end() ? static_cast<int>(categories.size()) : static_cast<int>(it - categories.begin());
  return seriesColor(index + 2);
}

cv::Scalar lighter(const cv::Scalar& color, double amount) {
  amount = std::clamp(amount, 0.0, 1.0);
  return {color[0] + (255 - color[0]) * amount, color[1] + (255 - color[1]) * amount,
          color[2] + (255 - color[2]) * amount};
}

cv::Scalar darker(const cv::Scalar& color, double amount) {
  amount = std::clamp(amount, 0.0, 1.0);
  return {color[0] * (1 - amount), color[1] * (1 - amount), color[2] * (1 - amount)};
}

}  // namespace beft::report::draw
