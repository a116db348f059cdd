#include "tools/experiment/plots.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <map>

#include "lib/report/drawing.hpp"

namespace beft::experiment {
namespace {

namespace draw = beft::report::draw;

constexpr int kLeft = 70, kRight = 30, kTop = 40, kBottom = 50;

struct Axes {
  cv::Rect area;  // the plotting area in pixels
  double x_max = 1, y_max = 1;
  cv::Point at(double x, double y) const {
    return {area.x + static_cast<int>(area.width * x / x_max), area.y + area.height - static_cast<int>(area.height * y / y_max)};
  }
};

// Grid, ticks and labels; no y ticks for an axis of categories (y_label "").
void drawAxes(cv::Mat& image, const Axes& axes, const std::string& x_label, const std::string& y_label) {
  for (const double x : draw::niceTicks(0, axes.x_max, 8)) {
    cv::line(image, axes.at(x, 0), axes.at(x, axes.y_max), draw::kLightGrey);
    draw::text(image, draw::formatNumber(x), axes.at(x, 0) + cv::Point(-8, 18), 0.4, draw::kDarkGrey);
  }
  for (const double y : y_label.empty() ? std::vector<double>{} : draw::niceTicks(0, axes.y_max, 5)) {
    cv::line(image, axes.at(0, y), axes.at(axes.x_max, y), draw::kLightGrey);
    draw::text(image, draw::formatNumber(y), axes.at(0, y) + cv::Point(-40, 5), 0.4, draw::kDarkGrey);
  }
  cv::rectangle(image, axes.area, draw::kDarkGrey);
  draw::text(image, x_label, {axes.area.x + (axes.area.width - draw::textSize(x_label).width) / 2, image.rows - 12}, 0.5);
  draw::text(image, y_label, {8, kTop - 14}, 0.5);
}

// Each condition's name in its colour, top left inside the area.
void drawLegend(cv::Mat& image, const Axes& axes, const std::vector<std::string>& names) {
  for (size_t i = 0; i < names.size(); ++i) {
    const cv::Point origin(axes.area.x + 10, axes.area.y + 20 + 18 * static_cast<int>(i));
    cv::line(image, origin + cv::Point(0, -5), origin + cv::Point(20, -5), draw::seriesColor(static_cast<int>(i)), 2);
    draw::labelBox(image, names[i], origin + cv::Point(26, 0), 0.42, draw::kBlack, draw::kWhite);
  }
}

// The share of the persons present found by each time: (time, share) steps.
std::vector<cv::Point2d> foundCurve(const std::vector<const EpisodeResult*>& episodes) {
  std::vector<double> times;
  int present = 0;
  for (const auto* r : episodes) {
    present += r->metrics->persons_present;
    times.insert(times.end(), r->metrics->found_at_s.begin(), r->metrics->found_at_s.end());
  }
  std::sort(times.begin(), times.end());
  std::vector<cv::Point2d> curve = {{0, 0}};
  for (size_t i = 0; i < times.size(); ++i) curve.push_back({times[i], present > 0 ? (i + 1.0) / present : 0});
  return curve;
}

}  // namespace

bool writeSuccessPlot(const Summary& summary, const std::string& file) {
  int label_width = 0;
  for (const auto& c : summary.conditions) label_width = std::max(label_width, draw::textSize(c.condition, 0.45).width);
  const int row = 34, rows = static_cast<int>(summary.conditions.size());
  cv::Mat image(kTop + kBottom + row * std::max(rows, 1), label_width + 520, CV_8UC3, draw::kWhite);
  Axes axes{{label_width + 20, kTop, 460, row * std::max(rows, 1)}, 100, static_cast<double>(std::max(rows, 1))};
  drawAxes(image, axes, "success [%] with its 95 % Wilson interval", "");
  for (int i = 0; i < rows; ++i) {
    const auto& c = summary.conditions[i];
    const double y = rows - i - 0.5, rate = c.done > 0 ? 100.0 * c.successes / c.done : 0;
    const cv::Scalar colour = draw::seriesColor(i);
    cv::rectangle(image, axes.at(0, y + 0.3), axes.at(rate, y - 0.3), draw::lighter(colour, 0.5), cv::FILLED);
    cv::line(image, axes.at(100 * c.success_95.low, y), axes.at(100 * c.success_95.high, y), draw::kBlack, 2);
    for (const double end : {c.success_95.low, c.success_95.high})
      cv::line(image, axes.at(100 * end, y + 0.2), axes.at(100 * end, y - 0.2), draw::kBlack, 2);
    draw::text(image, c.condition, {8, axes.at(0, y).y + 5}, 0.45);
    draw::text(image, std::to_string(c.successes) + "/" + std::to_string(c.done), axes.at(2, y) + cv::Point(0, 5), 0.4);
  }
  return cv::imwrite(file, image);
}

bool writeTimeToFindPlot(const std::vector<EpisodeResult>& results, const std::string& file) {
  std::map<std::string, std::vector<const EpisodeResult*>> by_condition;
  std::vector<std::string> names;
  for (const auto& r : results) {
    if (!r.metrics) continue;
    if (by_condition.count(r.episode.condition()) == 0) names.push_back(r.episode.condition());
    by_condition[r.episode.condition()].push_back(&r);
  }
  Axes axes{{kLeft, kTop, 760, 420}, 1, 1};
  for (const auto& r : results)
    if (r.metrics) axes.x_max = std::max(axes.x_max, r.metrics->sim_time_s);
  cv::Mat image(kTop + 420 + kBottom, kLeft + 760 + kRight, CV_8UC3, draw::kWhite);
  drawAxes(image, axes, "simulated time [s]", "share of the persons present found");
  for (size_t i = 0; i < names.size(); ++i) {
    const auto curve = foundCurve(by_condition[names[i]]);
    for (size_t k = 1; k < curve.size(); ++k) {  // steps: along, then up
      const cv::Point corner = axes.at(curve[k].x, curve[k - 1].y);
      cv::line(image, axes.at(curve[k - 1].x, curve[k - 1].y), corner, draw::seriesColor(static_cast<int>(i)), 2);
      cv::line(image, corner, axes.at(curve[k].x, curve[k].y), draw::seriesColor(static_cast<int>(i)), 2);
    }
  }
  drawLegend(image, axes, names);
  return cv::imwrite(file, image);
}

}  // namespace beft::experiment
