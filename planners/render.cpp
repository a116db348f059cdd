#include "planners/render.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beft::planners {

cv::Mat renderPlans(const PlanningMap& map, const std::vector<DrawnPlan>& plans, const std::vector<Path>& particles,
                    Point2 goal, const RenderOptions& options) {
  const int w = map.width();
  const int h = map.height();
  const int scale = options.scale > 0 ? options.scale : std::clamp(800 / std::max(w, h), 1, 16);
  cv::Mat cells(h, w, CV_8UC3);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      cv::Vec3b colour(255, 255, 255);
      if (map.raw().blocked(x, y)) colour = cv::Vec3b(0, 0, 0);
      else if (map.inflated().blocked(x, y)) colour = cv::Vec3b(190, 190, 190);
      cells.at<cv::Vec3b>(options.y_up ? h - 1 - y : y, x) = colour;
    }
  }
  cv::Mat image;
  cv::resize(cells, image, cv::Size(w * scale, h * scale), 0, 0, cv::INTER_NEAREST);
  const auto pixel = [&](Point2 p) {
    const double py = options.y_up ? h - p.y : p.y;
    return cv::Point(static_cast<int>(std::lround(p.x * scale)), static_cast<int>(std::lround(py * scale)));
  };
  const int thickness = std::max(1, scale / 3);

  if (!particles.empty()) {
    cv::Mat overlay = image.clone();
    for (const Path& trace : particles) {
      std::vector<cv::Point> points;
      for (const Point2& p : trace) points.push_back(pixel(p));
      if (points.size() >= 2) cv::polylines(overlay, points, false, cv::Scalar(235, 170, 90), 1, cv::LINE_AA);
    }
    cv::addWeighted(overlay, 0.6, image, 0.4, 0, image);
  }
  const int dot = std::max(2, scale / 2 + 1);
  const double arrow = std::max(8.0, 2.5 * scale);
  for (const DrawnPlan& plan : plans) {
    const Path& path = plan.path;
    if (path.size() < 2) continue;
    std::vector<cv::Point> points;
    for (const Point2& p : path) points.push_back(pixel(p));
    cv::polylines(image, points, false, cv::Scalar(30, 30, 220), thickness + 1, cv::LINE_AA);
    for (size_t i = 0; i < path.size(); i += std::max<size_t>(1, plan.every)) {
      // The paper's look: white dots, red-and-white arrows for the intended orientation.
      cv::circle(image, points[i], dot, cv::Scalar(255, 255, 255), cv::FILLED, cv::LINE_AA);
      cv::circle(image, points[i], dot, cv::Scalar(30, 30, 220), 1, cv::LINE_AA);
      if (options.headings && i < plan.headings_rad.size()) {
        const double heading = plan.headings_rad[i];
        const double dy = options.y_up ? -std::sin(heading) : std::sin(heading);
        const cv::Point tip(points[i].x + static_cast<int>(std::lround(arrow * std::cos(heading))),
                            points[i].y + static_cast<int>(std::lround(arrow * dy)));
        cv::arrowedLine(image, points[i], tip, cv::Scalar(255, 255, 255), 3, cv::LINE_AA, 0, 0.35);
        cv::arrowedLine(image, points[i], tip, cv::Scalar(30, 30, 220), 1, cv::LINE_AA, 0, 0.35);
      }
    }
  }
  const int marker = std::max(4, scale);
  for (const DrawnPlan& plan : plans)
    cv::circle(image, pixel(plan.start), marker, cv::Scalar(40, 170, 40), cv::FILLED, cv::LINE_AA);
  cv::circle(image, pixel(goal), marker, cv::Scalar(200, 90, 20), cv::FILLED, cv::LINE_AA);
  return image;
}

cv::Mat renderPlan(const PlanningMap& map, const Path& path, const std::vector<Path>& particles, Point2 start,
                   Point2 goal, const std::vector<double>& headings_rad, const RenderOptions& options) {
  return renderPlans(map, {DrawnPlan{path, headings_rad, start, 1}}, particles, goal, options);
}

void writePng(const std::string& file, const cv::Mat& image) {
  bool ok = false;
  try {
    ok = cv::imwrite(file, image);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(file + ": cannot write the picture: " + e.what());
  }
  if (!ok) throw std::runtime_error(file + ": cannot write the picture");
}

}  // namespace beft::planners
