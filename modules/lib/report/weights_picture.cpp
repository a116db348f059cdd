#include "lib/report/weights_picture.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "lib/report/drawing.hpp"

namespace beft::report {
namespace {

// Plot frames [px].
constexpr int kLeft = 84;
constexpr int kRight = kWeightsPictureWidth - 250;  // legend to the right
constexpr int kWeightsTop = 84, kWeightsBottom = 500;
constexpr int kTaskTop = 530, kTaskBottom = 570;
constexpr int kTaskKeyY = 594;  // baseline of the task colour key
constexpr int kViewTop = 648, kViewBottom = 820;

const cv::Scalar kCommandedColor(40, 40, 200);
const cv::Scalar kActualColor(140, 140, 140);

// Maps sim time to a column, a value to a row within [top, bottom].
struct Axes {
  double t0 = 0, t1 = 1;
  int x(double t) const { return kLeft + static_cast<int>(std::lround((t - t0) / (t1 - t0) * (kRight - kLeft))); }
  static int y(double value, double low, double high, int top, int bottom) {
    return bottom - static_cast<int>(std::lround((value - low) / (high - low) * (bottom - top)));
  }
};

double wrap180(double deg) {
  deg = std::fmod(deg + 180.0, 360.0);
  if (deg < 0) deg += 360.0;
  return deg - 180.0;
}

void timeTicks(cv::Mat& image, const Axes& axes, int top, int bottom, bool labels) {
  for (double t : draw::niceTicks(axes.t0, axes.t1, 12)) {
    const int x = axes.x(t);
    draw::dashedLine(image, {x, top}, {x, bottom}, cv::Scalar(215, 215, 215), 1, 2, 4);
    cv::line(image, {x, bottom}, {x, bottom + 5}, draw::kBlack, 1);
    if (labels) {
      const std::string label = draw::formatNumber(t, 1);
      draw::text(image, label, {x - draw::textSize(label, 0.42).width / 2, bottom + 20}, 0.42);
    }
  }
}

// Ordered acoustic objects: order of first appearance in DYNAMIC_WEIGHTS.
std::vector<std::string> objectOrder(const RunRecord& record) {
  std::vector<std::string> order;
  for (const auto& sample : record.weights)
    for (const auto& entry : sample.weights)
      if (std::find(order.begin(), order.end(), entry.first) == order.end()) order.push_back(entry.first);
  return order;
}

std::string labelOf(const RunRecord& record, const std::string& id) {
  for (const auto& object : record.truth)
    if (object.id == id) return object.label;
  return "";
}

void drawWeights(cv::Mat& image, const RunRecord& record, const Axes& axes, const std::vector<std::string>& objects) {
  const auto y = [](double w) { return Axes::y(w, 0.0, 1.0, kWeightsTop, kWeightsBottom); };
  timeTicks(image, axes, kWeightsTop, kWeightsBottom, true);
  for (double w : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    cv::line(image, {kLeft - 5, y(w)}, {kLeft, y(w)}, draw::kBlack, 1);
    const std::string label = draw::formatNumber(w, 2);
    draw::text(image, label, {kLeft - 10 - draw::textSize(label, 0.45).width, y(w) + 5}, 0.45);
  }
  for (double level : {0.25, 0.5, 0.75}) draw::dashedLine(image, {kLeft, y(level)}, {kRight, y(level)}, draw::kDarkGrey, 1, 10, 7);

  // Turn-to reflexes: where the attended object changes to a new one.
  std::string attended;
  for (const auto& sample : record.weights) {
    if (sample.attended_object != attended && !sample.attended_object.empty()) {
      const auto it = std::find(objects.begin(), objects.end(), sample.attended_object);
      const cv::Scalar color = it == objects.end() ? draw::kDarkGrey : draw::seriesColor(static_cast<int>(it - objects.begin()));
      const int x = axes.x(sample.t);
      draw::dashedLine(image, {x, kWeightsTop}, {x, kWeightsBottom}, color, 1, 3, 3);
      const std::vector<cv::Point> arrow{{x - 6, kWeightsTop - 10}, {x + 6, kWeightsTop - 10}, {x, kWeightsTop}};
      cv::fillConvexPoly(image, arrow, color, cv::LINE_AA);
    }
    attended = sample.attended_object;
  }

  for (size_t i = 0; i < objects.size(); ++i) {
    const cv::Scalar color = draw::seriesColor(static_cast<int>(i));
    std::vector<cv::Point> points;
    for (const auto& sample : record.weights) {
      const auto it = sample.weights.find(objects[i]);
      if (it == sample.weights.end()) continue;
      points.emplace_back(axes.x(sample.t), y(std::clamp(it->second, 0.0, 1.0)));
    }
    if (points.size() == 1) cv::circle(image, points.front(), 3, color, cv::FILLED, cv::LINE_AA);
    cv::polylines(image, points, false, color, 2, cv::LINE_AA);
  }
  cv::rectangle(image, cv::Rect(kLeft, kWeightsTop, kRight - kLeft, kWeightsBottom - kWeightsTop), draw::kBlack, 1);
  draw::text(image, "weight w [-]", {12, kWeightsTop - 18}, 0.5);
  if (record.weights.empty())
    draw::text(image, "no DYNAMIC_WEIGHTS messages in the log", {kLeft + 20, (kWeightsTop + kWeightsBottom) / 2}, 0.7,
               draw::kDarkGrey, 2);

  // Legend.
  int ly = kWeightsTop + 14;
  const int lx = kRight + 18;
  draw::text(image, "acoustic objects", {lx, ly}, 0.5);
  ly += 24;
  for (size_t i = 0; i < objects.size(); ++i) {
    cv::line(image, {lx, ly - 5}, {lx + 26, ly - 5}, draw::seriesColor(static_cast<int>(i)), 3, cv::LINE_AA);
    const std::string label = labelOf(record, objects[i]);
    draw::text(image, objects[i] + (label.empty() ? "" : " (" + label + ")"), {lx + 34, ly}, 0.45);
    ly += 22;
  }
  ly += 10;
  draw::dashedLine(image, {lx, ly - 5}, {lx + 26, ly - 5}, draw::kDarkGrey, 1, 6, 4);
  draw::text(image, "c = 0.25, 0.5, 0.75", {lx + 34, ly}, 0.45);
  ly += 22;
  const std::vector<cv::Point> arrow{{lx + 7, ly - 12}, {lx + 19, ly - 12}, {lx + 13, ly - 2}};
  cv::fillConvexPoly(image, arrow, draw::kDarkGrey, cv::LINE_AA);
  draw::text(image, "turn-to reflex", {lx + 34, ly}, 0.45);
}

// The task over time: DW's current_task, or the stack's top task.
std::vector<std::pair<double, std::string>> taskTimeline(const RunRecord& record) {
  std::vector<std::pair<double, std::string>> timeline;
  bool dw_has_tasks = false;
  for (const auto& sample : record.weights) dw_has_tasks = dw_has_tasks || !sample.current_task.empty();
  if (dw_has_tasks)
    for (const auto& sample : record.weights) timeline.emplace_back(sample.t, sample.current_task);
  else
    for (const auto& sample : record.tasks) timeline.emplace_back(sample.t, sample.top);
  return timeline;
}

void drawTaskStrip(cv::Mat& image, const RunRecord& record, const Axes& axes) {
  draw::text(image, "task", {12, (kTaskTop + kTaskBottom) / 2 + 5}, 0.5);
  const auto timeline = taskTimeline(record);
  std::vector<std::string> kinds;  // colour per task kind (first word)
  for (size_t i = 0; i < timeline.size();) {
    size_t j = i + 1;
    while (j < timeline.size() && timeline[j].second == timeline[i].second) ++j;
    const double end = j < timeline.size() ? timeline[j].first : axes.t1;
    const std::string& task = timeline[i].second;
    if (!task.empty()) {
      const std::string kind = task.substr(0, task.find_first_of(" ("));
      auto it = std::find(kinds.begin(), kinds.end(), kind);
      if (it == kinds.end()) it = kinds.insert(kinds.end(), kind);
      const cv::Scalar color = draw::lighter(draw::seriesColor(static_cast<int>(it - kinds.begin()) + 3), 0.55);
      const cv::Rect box(cv::Point(axes.x(timeline[i].first), kTaskTop), cv::Point(std::max(axes.x(end), axes.x(timeline[i].first) + 1), kTaskBottom));
      cv::rectangle(image, box, color, cv::FILLED);
      cv::rectangle(image, box, draw::kMidGrey, 1);
      std::string label = task;
      while (!label.empty() && draw::textSize(label, 0.4).width > box.width - 6) label.pop_back();
      if (label.size() >= 3) draw::text(image, label, {box.x + 3, box.y + box.height / 2 + 5}, 0.4);
    }
    i = j;
  }
  cv::rectangle(image, cv::Rect(kLeft, kTaskTop, kRight - kLeft, kTaskBottom - kTaskTop), draw::kBlack, 1);
  // Key: the colour of each kind, for segments too short to carry their name.
  int x = kLeft;
  for (size_t k = 0; k < kinds.size(); ++k) {
    const cv::Scalar color = draw::lighter(draw::seriesColor(static_cast<int>(k) + 3), 0.55);
    const int width = draw::textSize(kinds[k], 0.42).width;
    if (x + 22 + width > kRight) break;
    cv::rectangle(image, cv::Rect(x, kTaskKeyY - 11, 16, 12), color, cv::FILLED);
    cv::rectangle(image, cv::Rect(x, kTaskKeyY - 11, 16, 12), draw::kMidGrey, 1);
    draw::text(image, kinds[k], {x + 21, kTaskKeyY}, 0.42);
    x += 21 + width + 18;
  }
  if (timeline.empty())
    draw::text(image, "no task information in the log", {kLeft + 8, (kTaskTop + kTaskBottom) / 2 + 5}, 0.45, draw::kDarkGrey);
}

void plotHeading(cv::Mat& image, const std::vector<std::pair<double, double>>& series, const Axes& axes,
                 const cv::Scalar& color, int thickness) {
  const auto y = [](double deg) { return Axes::y(deg, -180, 180, kViewTop, kViewBottom); };
  std::vector<cv::Point> segment;
  double previous = 0;
  for (const auto& [t, heading] : series) {
    if (!std::isfinite(heading)) {  // no direction (DW: no weight at the reflex threshold): a gap
      if (!segment.empty()) cv::polylines(image, segment, false, color, thickness, cv::LINE_AA);
      segment.clear();
      continue;
    }
    const double h = wrap180(heading);
    if (!segment.empty() && std::abs(h - previous) > 180) {  // wrapped around: break the line
      cv::polylines(image, segment, false, color, thickness, cv::LINE_AA);
      segment.clear();
    }
    segment.emplace_back(axes.x(t), y(h));
    previous = h;
  }
  if (!segment.empty()) cv::polylines(image, segment, false, color, thickness, cv::LINE_AA);
}

void drawViewingDirection(cv::Mat& image, const RunRecord& record, const Axes& axes) {
  const auto y = [](double deg) { return Axes::y(deg, -180, 180, kViewTop, kViewBottom); };
  timeTicks(image, axes, kViewTop, kViewBottom, true);
  for (double deg : {-180.0, -90.0, 0.0, 90.0, 180.0}) {
    cv::line(image, {kLeft - 5, y(deg)}, {kLeft, y(deg)}, draw::kBlack, 1);
    const std::string label = draw::formatNumber(deg, 0);
    draw::text(image, label, {kLeft - 10 - draw::textSize(label, 0.42).width, y(deg) + 5}, 0.42);
    if (deg > -180 && deg < 180) draw::dashedLine(image, {kLeft, y(deg)}, {kRight, y(deg)}, cv::Scalar(215, 215, 215), 1, 2, 4);
  }
  std::vector<std::pair<double, double>> actual, commanded;
  for (const auto& sample : record.robot) actual.emplace_back(sample.t, sample.yaw + sample.head_yaw);
  for (const auto& sample : record.weights) commanded.emplace_back(sample.t, sample.viewing_direction);
  plotHeading(image, actual, axes, kActualColor, 2);
  plotHeading(image, commanded, axes, kCommandedColor, 1);
  cv::rectangle(image, cv::Rect(kLeft, kViewTop, kRight - kLeft, kViewBottom - kViewTop), draw::kBlack, 1);
  draw::text(image, "viewing direction [deg]", {12, kViewTop - 14}, 0.5);
  draw::text(image, "simulated time [s]", {(kLeft + kRight) / 2 - 70, kViewBottom + 44}, 0.55);
  const int lx = kRight + 18;
  cv::line(image, {lx, kViewTop + 20}, {lx + 26, kViewTop + 20}, kCommandedColor, 2, cv::LINE_AA);
  draw::text(image, "DW viewing direction", {lx + 34, kViewTop + 25}, 0.45);
  cv::line(image, {lx, kViewTop + 44}, {lx + 26, kViewTop + 44}, kActualColor, 2, cv::LINE_AA);
  draw::text(image, "head heading (actual)", {lx + 34, kViewTop + 49}, 0.45);
  draw::text(image, "0 = +x, CCW positive", {lx, kViewTop + 78}, 0.42, draw::kDarkGrey);
}

}  // namespace

cv::Mat renderWeights(const RunRecord& record) {
  cv::Mat image(kWeightsPictureHeight, kWeightsPictureWidth, CV_8UC3, draw::kWhite);
  Axes axes;
  axes.t1 = record.simTime();
  for (const auto& sample : record.weights) axes.t1 = std::max(axes.t1, sample.t);
  if (axes.t1 <= axes.t0) axes.t1 = axes.t0 + 1;
  const auto objects = objectOrder(record);
  drawWeights(image, record, axes, objects);
  drawTaskStrip(image, record, axes);
  drawViewingDirection(image, record, axes);
  // The paper's Fig. 4 names the viewing direction DW computes in its title.
  std::string direction = "none";
  for (const auto& sample : record.weights)
    if (std::isfinite(sample.viewing_direction)) direction = draw::formatNumber(wrap180(sample.viewing_direction), 0) + " deg";
  const std::string title = "Dynamic weighting (eq. 4)" +
                            (record.scenario_name.empty() ? std::string() : ": " + record.scenario_name) +
                            ", DW viewing direction at the end: " + direction;
  draw::text(image, title, {kLeft, 34}, 0.75, draw::kBlack, 2);
  return image;
}

}  // namespace beft::report
