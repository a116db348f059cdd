#include "lib/report/map_picture.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <opencv2/imgproc.hpp>

#include <beft/obstacle_map_t.hpp>

#include "lib/report/drawing.hpp"

namespace beft::report {
namespace {

constexpr int kMarginLeft = 64;
constexpr int kMarginTop = 56;
constexpr int kMarginBottom = 78;
constexpr int kLegendWidth = 300;
constexpr int kMinHeight = 640;  // room for the legend

const cv::Scalar kUnknownColor(222, 222, 222);
const cv::Scalar kFreeColor(255, 255, 255);
const cv::Scalar kOccupiedColor(60, 60, 60);
const cv::Scalar kPathColor(200, 90, 0);
const cv::Scalar kVerifiedColor(40, 150, 40);
const cv::Scalar kFalsifiedColor(30, 30, 220);
const cv::Scalar kUnsettledColor(0, 150, 240);
const cv::Scalar kSeenOnlyColor(150, 120, 90);

double degToRad(double deg) { return deg * M_PI / 180.0; }

void paintObstacleMap(cv::Mat& image, const MapLayout& layout, const RunRecord& record) {
  const cv::Rect world(layout.left, layout.top, layout.world_px_width, layout.world_px_height);
  cv::rectangle(image, world, kUnknownColor, cv::FILLED);
  if (!record.obstacle_map) return;
  const auto& map = *record.obstacle_map;
  for (int py = world.y; py < world.y + world.height; ++py) {
    const double y = (layout.top + layout.world_px_height - (py + 0.5)) / layout.scale;
    const int row = static_cast<int>(std::floor((y - map.origin_y) / map.resolution));
    if (row < 0 || row >= map.height) continue;
    auto* pixels = image.ptr<cv::Vec3b>(py);
    for (int px = world.x; px < world.x + world.width; ++px) {
      const double x = (px + 0.5 - layout.left) / layout.scale;
      const int column = static_cast<int>(std::floor((x - map.origin_x) / map.resolution));
      if (column < 0 || column >= map.width) continue;
      const uint8_t cell = map.at(column, row);
      const cv::Scalar& color = cell == obstacle_map_t::CELL_OCCUPIED ? kOccupiedColor
                                : cell == obstacle_map_t::CELL_FREE   ? kFreeColor
                                                                      : kUnknownColor;
      pixels[px] = cv::Vec3b(static_cast<uint8_t>(color[0]), static_cast<uint8_t>(color[1]),
                             static_cast<uint8_t>(color[2]));
    }
  }
}

void drawGridAndAxes(cv::Mat& image, const MapLayout& layout, double world_width, double world_height) {
  const auto xs = draw::niceTicks(0, world_width, 10);
  const auto ys = draw::niceTicks(0, world_height, 8);
  const cv::Scalar grid(200, 200, 200);
  for (double x : xs) {
    const cv::Point top = layout.toPixel(x, world_height), bottom = layout.toPixel(x, 0);
    draw::dashedLine(image, top, bottom, grid, 1, 2, 4);
    cv::line(image, bottom, bottom + cv::Point(0, 5), draw::kBlack, 1);
    const std::string label = draw::formatNumber(x, 1);
    draw::text(image, label, bottom + cv::Point(-draw::textSize(label, 0.4).width / 2, 19), 0.4);
  }
  for (double y : ys) {
    const cv::Point left = layout.toPixel(0, y), right = layout.toPixel(world_width, y);
    draw::dashedLine(image, left, right, grid, 1, 2, 4);
    cv::line(image, left, left - cv::Point(5, 0), draw::kBlack, 1);
    const std::string label = draw::formatNumber(y, 1);
    draw::text(image, label, left + cv::Point(-9 - draw::textSize(label, 0.4).width, 5), 0.4);
  }
  cv::rectangle(image, cv::Rect(layout.left, layout.top, layout.world_px_width, layout.world_px_height),
                draw::kBlack, 1);
  draw::text(image, "x [m]", cv::Point(layout.left + layout.world_px_width - 36, layout.top + layout.world_px_height + 36),
             0.45);
  draw::text(image, "y [m]", cv::Point(8, layout.top - 8), 0.45);
}

void drawScaleBar(cv::Mat& image, const MapLayout& layout) {
  // The largest 1-2-5 length not longer than a fifth of the world's width.
  const double wanted = layout.world_px_width / layout.scale / 5.0;
  double length = 1;
  for (double magnitude = 0.01; magnitude <= 1e5; magnitude *= 10)
    for (double factor : {1.0, 2.0, 5.0})
      if (factor * magnitude <= wanted) length = factor * magnitude;
  const int px = static_cast<int>(std::lround(length * layout.scale));
  const cv::Point a(layout.left, layout.top + layout.world_px_height + 56);
  const cv::Point b = a + cv::Point(px, 0);
  cv::rectangle(image, cv::Rect(a.x, a.y - 4, px / 2, 8), draw::kBlack, cv::FILLED);
  cv::rectangle(image, cv::Rect(a.x, a.y - 4, px, 8), draw::kBlack, 1);
  draw::text(image, "0", a + cv::Point(-4, -8), 0.4);
  const std::string label = draw::formatNumber(length, 2) + " m";
  draw::text(image, label, b + cv::Point(6, 5), 0.45);
}

// Moves a label's origin (bottom-left) so the text stays within the world's frame.
cv::Point keepInside(const MapLayout& layout, cv::Point origin, cv::Size size) {
  origin.x = std::min(origin.x, layout.left + layout.world_px_width - size.width - 3);
  origin.x = std::max(origin.x, layout.left + 3);
  origin.y = std::max(origin.y, layout.top + size.height + 4);
  origin.y = std::min(origin.y, layout.top + layout.world_px_height - 4);
  return origin;
}

// Places text labels so they do not cover each other: each label takes the
// first free spot among its preferred one and spots shifted up or down.
class LabelPlacer {
 public:
  explicit LabelPlacer(const MapLayout& layout) : layout_(layout) {}
  // origin: preferred bottom-left of the text. Returns where to draw it.
  cv::Point place(cv::Point origin, cv::Size size) {
    const int line = size.height + 8;
    cv::Point chosen = keepInside(layout_, origin, size);
    for (int k : {0, 1, -1, 2, -2, 3, -3, 4, -4}) {
      const cv::Point candidate = keepInside(layout_, origin + cv::Point(0, k * line), size);
      if (free(box(candidate, size))) {
        chosen = candidate;
        break;
      }
    }
    taken_.push_back(box(chosen, size));
    return chosen;
  }

 private:
  static cv::Rect box(cv::Point origin, cv::Size size) {
    return {origin.x - 2, origin.y - size.height - 3, size.width + 4, size.height + 6};
  }
  bool free(const cv::Rect& r) const {
    for (const auto& t : taken_)
      if ((r & t).area() > 0) return false;
    return true;
  }
  const MapLayout& layout_;
  std::vector<cv::Rect> taken_;
};

std::vector<cv::Point> footprint(const MapLayout& layout, const TruthObject& object) {
  const double c = std::cos(degToRad(object.yaw)), s = std::sin(degToRad(object.yaw));
  std::vector<cv::Point> corners;
  for (auto [u, v] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}) {
    const double lx = u * object.size_x, ly = v * object.size_y;
    corners.push_back(layout.toPixel(object.x + c * lx - s * ly, object.y + s * lx + c * ly));
  }
  return corners;
}

void drawTruth(cv::Mat& image, const MapLayout& layout, const RunRecord& record) {
  // Trails of objects that moved, under everything else.
  for (const auto& object : record.truth) {
    const auto trail = record.trails.find(object.id);
    if (trail == record.trails.end() || trail->second.size() < 2) continue;
    std::vector<cv::Point> points;
    for (const auto& [x, y] : trail->second) points.push_back(layout.toPixel(x, y));
    cv::polylines(image, points, false, draw::lighter(draw::categoryColor(object.label, record.categories), 0.35), 1,
                  cv::LINE_AA);
  }
  cv::Mat overlay = image.clone();
  for (const auto& object : record.truth) {
    const cv::Scalar color = draw::lighter(draw::categoryColor(object.label, record.categories), 0.3);
    const cv::Point centre = layout.toPixel(object.x, object.y);
    if (object.shape == TruthObject::Shape::Box) {
      const auto corners = footprint(layout, object);
      cv::fillConvexPoly(overlay, corners, color, cv::LINE_AA);
    } else if (object.shape == TruthObject::Shape::Cylinder) {
      cv::circle(overlay, centre, std::max(2, static_cast<int>(std::lround(object.radius * layout.scale))), color,
                 cv::FILLED, cv::LINE_AA);
    }
  }
  cv::addWeighted(overlay, 0.55, image, 0.45, 0, image);
  for (const auto& object : record.truth) {
    const cv::Scalar color = draw::categoryColor(object.label, record.categories);
    const cv::Point centre = layout.toPixel(object.x, object.y);
    if (object.shape == TruthObject::Shape::Box) {
      cv::polylines(image, footprint(layout, object), true, color, 2, cv::LINE_AA);
    } else if (object.shape == TruthObject::Shape::Cylinder) {
      const int r = std::max(2, static_cast<int>(std::lround(object.radius * layout.scale)));
      cv::circle(image, centre, r, color, 2, cv::LINE_AA);
    } else {  // sound only: a diamond
      const std::vector<cv::Point> diamond{centre + cv::Point(0, -7), centre + cv::Point(7, 0),
                                           centre + cv::Point(0, 7), centre + cv::Point(-7, 0)};
      cv::polylines(image, diamond, true, color, 2, cv::LINE_AA);
    }
  }
}

// Object ids above their footprints, drawn last so that nothing hides them.
void drawTruthLabels(cv::Mat& image, const MapLayout& layout, const RunRecord& record, LabelPlacer& placer) {
  for (const auto& object : record.truth) {
    const cv::Point centre = layout.toPixel(object.x, object.y);
    int half_height = 7;
    if (object.shape == TruthObject::Shape::Box) {
      for (const auto& corner : footprint(layout, object)) half_height = std::max(half_height, centre.y - corner.y);
    } else if (object.shape == TruthObject::Shape::Cylinder) {
      half_height = std::max(half_height, static_cast<int>(std::lround(object.radius * layout.scale)));
    }
    const cv::Size size = draw::textSize(object.id, 0.42);
    const cv::Point origin = placer.place(centre + cv::Point(-size.width / 2, -half_height - 5), size);
    draw::labelBox(image, object.id, origin, 0.42, draw::darker(draw::categoryColor(object.label, record.categories)),
                   cv::Scalar(255, 255, 255));
  }
}

void drawPath(cv::Mat& image, const MapLayout& layout, const RunRecord& record) {
  if (record.robot.empty()) return;
  std::vector<cv::Point> points;
  for (const auto& sample : record.robot) {
    const cv::Point p = layout.toPixel(sample.x, sample.y);
    if (points.empty() || points.back() != p) points.push_back(p);
  }
  cv::polylines(image, points, false, kPathColor, 2, cv::LINE_AA);
  const cv::Point start = layout.toPixel(record.robot.front().x, record.robot.front().y);
  cv::circle(image, start, 6, kPathColor, 2, cv::LINE_AA);
  draw::labelBox(image, "start", start + cv::Point(9, 16), 0.4, kPathColor, draw::kWhite);
  const auto& end = record.robot.back();
  const cv::Point last = layout.toPixel(end.x, end.y);
  const int r = std::max(5, static_cast<int>(std::lround(record.robot_radius * layout.scale)));
  cv::circle(image, last, r, kPathColor, cv::FILLED, cv::LINE_AA);
  const double heading = degToRad(end.yaw), gaze = degToRad(end.yaw + end.head_yaw);
  cv::line(image, last, last + cv::Point(static_cast<int>(std::lround(std::cos(heading) * (r + 8))),
                                         static_cast<int>(std::lround(-std::sin(heading) * (r + 8)))),
           kPathColor, 2, cv::LINE_AA);
  cv::line(image, last, last + cv::Point(static_cast<int>(std::lround(std::cos(gaze) * (r + 16))),
                                         static_cast<int>(std::lround(-std::sin(gaze) * (r + 16)))),
           draw::kBlack, 1, cv::LINE_AA);
}

cv::Scalar hypothesisColor(const HypothesisState& h) {
  if (h.falsified) return kFalsifiedColor;
  if (h.verified) return kVerifiedColor;
  if (h.heard) return kUnsettledColor;
  return kSeenOnlyColor;
}

std::string hypothesisText(const HypothesisState& h) {
  std::string text = h.object_id + ": " + (h.best_category.empty() ? "?" : h.best_category) + " " +
                     draw::formatNumber(h.confidence, 2);
  if (h.verified) text += " verified";
  if (h.falsified) text += " falsified (heard " + h.heard_as + ", seen " + h.seen_as + ")";
  if (!h.verified && !h.falsified) {
    if (h.heard) text += h.seen ? " seen+heard" : " heard, not seen";
    else text += h.seen ? " seen" : " glimpsed";
  }
  return text;
}

void drawHypotheses(cv::Mat& image, const MapLayout& layout, const RunRecord& record, LabelPlacer& placer) {
  if (record.hypotheses.empty()) return;
  for (const auto& h : record.hypotheses.back().hypotheses) {
    const cv::Scalar color = hypothesisColor(h);
    const cv::Point p = layout.toPixel(h.x, h.y);
    cv::circle(image, p, 9, color, 2, cv::LINE_AA);
    cv::circle(image, p, 2, color, cv::FILLED, cv::LINE_AA);
    if (h.falsified) {
      cv::line(image, p + cv::Point(-6, -6), p + cv::Point(6, 6), color, 2, cv::LINE_AA);
      cv::line(image, p + cv::Point(-6, 6), p + cv::Point(6, -6), color, 2, cv::LINE_AA);
    }
    const std::string text = hypothesisText(h);
    const cv::Size size = draw::textSize(text, 0.42);
    cv::Point origin = p + cv::Point(12, 20);
    if (origin.x + size.width > layout.left + layout.world_px_width - 3) origin.x = p.x - 12 - size.width;  // to the left
    draw::labelBox(image, text, placer.place(origin, size), 0.42, color, cv::Scalar(250, 250, 250));
  }
}

// The legend panel at (x, y), one entry per line.
class Legend {
 public:
  Legend(cv::Mat& image, int x, int y) : image_(image), x_(x), y_(y) {}
  void heading(const std::string& title) {
    y_ += 10;
    draw::text(image_, title, {x_, y_}, 0.5, draw::kBlack, 1);
    y_ += 22;
  }
  void swatch(const cv::Scalar& fill, const cv::Scalar& edge, const std::string& label) {
    cv::rectangle(image_, cv::Rect(x_, y_ - 12, 22, 14), fill, cv::FILLED);
    cv::rectangle(image_, cv::Rect(x_, y_ - 12, 22, 14), edge, 1);
    line(label);
  }
  void marker(const std::function<void(cv::Point)>& paint, const std::string& label) {
    paint({x_ + 11, y_ - 5});
    line(label);
  }
  void note(const std::string& label) { line(label, 0); }

 private:
  void line(const std::string& label, int indent = 32) {
    draw::text(image_, label, {x_ + indent, y_}, 0.45);
    y_ += 22;
  }
  cv::Mat& image_;
  int x_, y_;
};

void drawLegend(cv::Mat& image, const MapLayout& layout, const RunRecord& record, const RunReport& report) {
  const int x = layout.left + layout.world_px_width + 24;
  cv::rectangle(image, cv::Rect(x - 10, layout.top, kLegendWidth - 20, image.rows - layout.top - 16), draw::kMidGrey, 1);
  Legend legend(image, x, layout.top + 14);
  legend.heading("Ground truth (by category)");
  std::vector<std::string> labels;
  bool sound_only = false;
  for (const auto& object : record.truth) {
    if (std::find(labels.begin(), labels.end(), object.label) == labels.end()) labels.push_back(object.label);
    sound_only = sound_only || object.shape == TruthObject::Shape::None;
  }
  for (const auto& label : labels) {
    const cv::Scalar color = draw::categoryColor(label, record.categories);
    legend.swatch(draw::lighter(color, 0.45), color, label);
  }
  if (sound_only)
    legend.marker(
        [&](cv::Point c) {
          cv::polylines(image, std::vector<cv::Point>{c + cv::Point(0, -6), c + cv::Point(6, 0), c + cv::Point(0, 6),
                                                      c + cv::Point(-6, 0)},
                        true, draw::kDarkGrey, 2, cv::LINE_AA);
        },
        "sound only (no visual)");
  legend.heading("Obstacle map (robot's view)");
  legend.swatch(kOccupiedColor, draw::kBlack, "occupied");
  legend.swatch(kFreeColor, draw::kBlack, "free");
  legend.swatch(kUnknownColor, draw::kBlack, record.obstacle_map ? "unknown" : "unknown (no map in log)");
  legend.heading("Robot");
  legend.marker([&](cv::Point c) { cv::line(image, c - cv::Point(11, 0), c + cv::Point(11, 0), kPathColor, 2); },
                "path (" + draw::formatNumber(report.path_length_m, 1) + " m)");
  legend.marker([&](cv::Point c) { cv::circle(image, c, 6, kPathColor, cv::FILLED, cv::LINE_AA); },
                "end pose (line: gaze)");
  legend.heading("Hypotheses (label, confidence)");
  legend.marker([&](cv::Point c) { cv::circle(image, c, 8, kVerifiedColor, 2, cv::LINE_AA); }, "verified");
  legend.marker(
      [&](cv::Point c) {
        cv::circle(image, c, 8, kFalsifiedColor, 2, cv::LINE_AA);
        cv::line(image, c + cv::Point(-5, -5), c + cv::Point(5, 5), kFalsifiedColor, 2, cv::LINE_AA);
      },
      "falsified");
  legend.marker([&](cv::Point c) { cv::circle(image, c, 8, kUnsettledColor, 2, cv::LINE_AA); }, "heard, not settled");
  legend.marker([&](cv::Point c) { cv::circle(image, c, 8, kSeenOnlyColor, 2, cv::LINE_AA); }, "silent: seen or glimpsed");
  legend.heading("Outcome");
  legend.note("persons found: " + std::to_string(report.victims.size()) + " of " + std::to_string(report.persons));
  legend.note("falsified: " + std::to_string(report.falsified.size()) +
              ", collisions: " + std::to_string(report.collisions));
  legend.note(report.completed ? "mission completed" : "mission not completed");
}

}  // namespace

cv::Point MapLayout::toPixel(double x, double y) const {
  return {left + static_cast<int>(std::lround(x * scale)),
          top + world_px_height - static_cast<int>(std::lround(y * scale))};
}

MapLayout mapLayout(double world_width, double world_height) {
  world_width = world_width > 0 ? world_width : 10;
  world_height = world_height > 0 ? world_height : 10;
  MapLayout layout;
  layout.scale = std::clamp(std::min(1000.0 / world_width, 760.0 / world_height), 0.5, 200.0);
  layout.world_px_width = static_cast<int>(std::lround(world_width * layout.scale));
  layout.world_px_height = static_cast<int>(std::lround(world_height * layout.scale));
  layout.left = kMarginLeft;
  layout.top = kMarginTop;
  layout.width = kMarginLeft + layout.world_px_width + 20 + kLegendWidth;
  layout.height = std::max(kMinHeight, kMarginTop + layout.world_px_height + kMarginBottom);
  return layout;
}

cv::Mat renderMap(const RunRecord& record, const RunReport& report) {
  const MapLayout layout = mapLayout(record.world_width, record.world_height);
  const double world_width = layout.world_px_width / layout.scale, world_height = layout.world_px_height / layout.scale;
  cv::Mat image(layout.height, layout.width, CV_8UC3, draw::kWhite);
  paintObstacleMap(image, layout, record);
  drawGridAndAxes(image, layout, world_width, world_height);
  drawTruth(image, layout, record);
  drawPath(image, layout, record);
  LabelPlacer placer(layout);
  drawTruthLabels(image, layout, record, placer);
  drawHypotheses(image, layout, record, placer);
  drawScaleBar(image, layout);
  drawLegend(image, layout, record, report);
  const std::string title = (record.scenario_name.empty() ? std::string("run") : record.scenario_name) +
                            ": map after " + draw::formatNumber(report.sim_time_s, 1) + " s simulated";
  draw::text(image, title, {layout.left, 30}, 0.7, draw::kBlack, 2);
  return image;
}

}  // namespace beft::report
