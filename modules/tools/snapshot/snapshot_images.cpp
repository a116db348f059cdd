#include "tools/snapshot/snapshot_images.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <opencv2/imgproc.hpp>

namespace beft::snapshot {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

cv::Scalar bgr(uint32_t rgb) { return cv::Scalar(rgb & 0xFF, (rgb >> 8) & 0xFF, (rgb >> 16) & 0xFF); }

// Display colour of a category: the five defaults fixed, others from a palette.
cv::Scalar categoryColour(const std::string& label, const std::vector<std::string>& categories) {
  static const std::map<std::string, uint32_t> fixed = {
      {"person", 0xe04848}, {"car", 0x3c9a50}, {"siren", 0xe8c020}, {"wall", 0x8c8c8c}, {"fire", 0xff7a10}};
  const auto found = fixed.find(label);
  if (found != fixed.end()) return bgr(found->second);
  static const uint32_t palette[] = {0x8e5cc8, 0x30a0c0, 0xc05890, 0x70a030, 0xa07040, 0x5070e0};
  const auto at = std::find(categories.begin(), categories.end(), label);
  const size_t index = at == categories.end() ? 0 : static_cast<size_t>(at - categories.begin());
  return bgr(palette[index % (sizeof(palette) / sizeof(palette[0]))]);
}

// A distinct, stable colour per instance value.
cv::Vec3b instanceColour(int object) {
  const uint32_t hash = static_cast<uint32_t>(object + 1) * 2654435761u;
  return cv::Vec3b(static_cast<uint8_t>(64 + (hash & 0xBF)), static_cast<uint8_t>(64 + ((hash >> 8) & 0xBF)),
                   static_cast<uint8_t>(64 + ((hash >> 16) & 0xBF)));
}

cv::Mat zoomed(const cv::Mat& image, int zoom) {
  if (zoom <= 1) return image;
  cv::Mat out;
  cv::resize(image, out, cv::Size(), zoom, zoom, cv::INTER_NEAREST);
  return out;
}

void putLabel(cv::Mat& image, const std::string& text, cv::Point at, double scale, const cv::Scalar& colour) {
  // Dark outline first, so text reads on any background.
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, cv::Scalar(20, 20, 20), 3, cv::LINE_AA);
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

std::string format(const char* pattern, double a, double b = 0, double c = 0) {
  char buffer[128];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c);
  return buffer;
}

}  // namespace

cv::Mat colorImage(const camera::RenderedFrame& frame, int zoom) {
  cv::Mat rgb(frame.height, frame.width, CV_8UC3, const_cast<uint8_t*>(frame.rgb.data()));
  cv::Mat image;
  cv::cvtColor(rgb, image, cv::COLOR_RGB2BGR);
  return zoomed(image, zoom);
}

cv::Mat depthImage(const camera::RenderedFrame& frame, int zoom) {
  const double range = frame.camera.intrinsics.range;
  cv::Mat scaled(frame.height, frame.width, CV_8UC1);
  cv::Mat no_return(frame.height, frame.width, CV_8UC1, cv::Scalar(0));
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      const float depth = frame.depth[static_cast<size_t>(v) * frame.width + u];
      // TURBO runs blue (0) to red (255): near is red.
      scaled.at<uint8_t>(v, u) = static_cast<uint8_t>(255.0 * (1.0 - std::clamp(depth / range, 0.0, 1.0)));
      no_return.at<uint8_t>(v, u) = depth <= 0 ? 255 : 0;
    }
  }
  cv::Mat image;
  cv::applyColorMap(scaled, image, cv::COLORMAP_TURBO);
  image.setTo(cv::Scalar(0, 0, 0), no_return);
  image = zoomed(image, zoom);
  // Scale bar: 0 m (left, red) to range (right, blue).
  const int bar_height = 28;
  cv::Mat bar(bar_height, image.cols, CV_8UC1);
  for (int x = 0; x < image.cols; ++x) bar.col(x).setTo(255 - 255 * x / std::max(1, image.cols - 1));
  cv::Mat bar_colour;
  cv::applyColorMap(bar, bar_colour, cv::COLORMAP_TURBO);
  putLabel(bar_colour, "0 m", {4, 19}, 0.45, cv::Scalar(255, 255, 255));
  putLabel(bar_colour, format("%.0f m (no return: black)", range), {image.cols - 190, 19}, 0.45,
           cv::Scalar(255, 255, 255));
  cv::Mat out;
  cv::vconcat(image, bar_colour, out);
  return out;
}

cv::Mat instanceImage(const camera::RenderedFrame& frame, const world::WorldSimulation& world, int zoom) {
  cv::Mat image(frame.height, frame.width, CV_8UC3, cv::Scalar(0, 0, 0));
  std::map<int, cv::Point2d> sum;
  std::map<int, int> count;
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      const int object = frame.object[static_cast<size_t>(v) * frame.width + u];
      if (object < 0) continue;
      image.at<cv::Vec3b>(v, u) = instanceColour(object);
      sum[object] += cv::Point2d(u + 0.5, v + 0.5);
      ++count[object];
    }
  }
  image = zoomed(image, std::max(zoom, 1));
  for (const auto& [object, total] : sum) {
    const cv::Point2d centre = total / count[object] * std::max(zoom, 1);
    const std::string text = world.objectIds()[object] + " (" + std::to_string(count[object]) + " px)";
    int baseline = 0;
    const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &baseline);
    const int x = std::clamp(static_cast<int>(centre.x) - size.width / 2, 2, std::max(2, image.cols - size.width - 2));
    const int y = std::clamp(static_cast<int>(centre.y), size.height + 2, image.rows - 4);
    putLabel(image, text, cv::Point(x, y), 0.45, cv::Scalar(255, 255, 255));
  }
  return image;
}

namespace {

// A top-down picture of the world: pixels_per_metre, a margin around it and
// a legend band above; world (x, y) has y up, the image y down.
struct TopDownCanvas {
  cv::Mat image;
  double pixels_per_metre = 0, width = 0, height = 0;
  int margin = 30, legend = 60;
  cv::Point toPixel(double x, double y) const {
    return cv::Point(static_cast<int>(std::lround(margin + x * pixels_per_metre)),
                     static_cast<int>(std::lround(margin + legend + (height - y) * pixels_per_metre)));
  }
  int metres(double m) const { return static_cast<int>(std::lround(m * pixels_per_metre)); }
};

void drawGround(TopDownCanvas& c) {
  // Ground and 1 m grid (every 5 m darker), with axis labels.
  cv::rectangle(c.image, c.toPixel(0, c.height), c.toPixel(c.width, 0), cv::Scalar(206, 214, 220), cv::FILLED);
  for (int x = 0; x <= static_cast<int>(c.width); ++x) {
    cv::line(c.image, c.toPixel(x, 0), c.toPixel(x, c.height), x % 5 ? cv::Scalar(222, 226, 230) : cv::Scalar(180, 186, 192), 1);
    if (x % 5 == 0) putLabel(c.image, std::to_string(x), c.toPixel(x, 0) + cv::Point(-4, 18), 0.4, cv::Scalar(255, 255, 255));
  }
  for (int y = 0; y <= static_cast<int>(c.height); ++y) {
    cv::line(c.image, c.toPixel(0, y), c.toPixel(c.width, y), y % 5 ? cv::Scalar(222, 226, 230) : cv::Scalar(180, 186, 192), 1);
    if (y % 5 == 0) putLabel(c.image, std::to_string(y), c.toPixel(0, y) + cv::Point(-26, 4), 0.4, cv::Scalar(255, 255, 255));
  }
  cv::rectangle(c.image, c.toPixel(0, c.height), c.toPixel(c.width, 0), cv::Scalar(90, 90, 90), 2);

}

void drawFieldOfView(TopDownCanvas& c, const camera::Camera& camera) {
  // Camera field of view: a wedge out to the range, under everything else.
  const double yaw = camera.pose.yaw_deg, half_fov = camera.intrinsics.fov_deg / 2;
  const double range = camera.intrinsics.range;
  std::vector<cv::Point> wedge{c.toPixel(camera.pose.x, camera.pose.y)};
  for (double a = yaw - half_fov; a <= yaw + half_fov + 1e-9; a += half_fov / 16) {
    wedge.push_back(c.toPixel(camera.pose.x + range * std::cos(a * kDegToRad), camera.pose.y + range * std::sin(a * kDegToRad)));
  }
  {
    // Drawn on a copy, blended back inside the world's rectangle only.
    cv::Mat overlay = c.image.clone();
    cv::fillPoly(overlay, std::vector<std::vector<cv::Point>>{wedge}, cv::Scalar(120, 220, 250), cv::LINE_AA);
    cv::polylines(overlay, std::vector<std::vector<cv::Point>>{wedge}, true, cv::Scalar(20, 120, 200), 2, cv::LINE_AA);
    const cv::Rect inside(c.toPixel(0, c.height), c.toPixel(c.width, 0) + cv::Point(1, 1));
    cv::Mat region = c.image(inside);
    cv::addWeighted(overlay(inside), 0.4, region, 0.6, 0, region);
  }

}

void drawPaths(TopDownCanvas& c, const scenario::Scenario& scenario) {
  // Paths, dashed.
  for (const scenario::Path& path : scenario.paths) {
    std::vector<scenario::Waypoint> points = path.waypoints;
    if (path.loop && !points.empty()) points.push_back(points.front());
    for (size_t i = 1; i < points.size(); ++i) {
      const double dx = points[i].x - points[i - 1].x, dy = points[i].y - points[i - 1].y;
      const double length = std::hypot(dx, dy);
      for (double s = 0; s < length; s += 0.5) {
        const double e = std::min(s + 0.25, length);
        cv::line(c.image, c.toPixel(points[i - 1].x + dx * s / length, points[i - 1].y + dy * s / length),
                 c.toPixel(points[i - 1].x + dx * e / length, points[i - 1].y + dy * e / length), cv::Scalar(110, 80, 60), 1,
                 cv::LINE_AA);
      }
    }
  }

}

// Footprints by category; sound sources ringed (double ring when active).
void drawObject(TopDownCanvas& c, const scenario::Object& object, const std::vector<std::string>& categories) {
  const cv::Scalar colour = categoryColour(object.label, categories);
  const cv::Point centre = c.toPixel(object.x, object.y);
  if (object.visual && object.visual->shape == scenario::Visual::Shape::Box) {
    const double cos_yaw = std::cos(object.yaw * kDegToRad), sin_yaw = std::sin(object.yaw * kDegToRad);
    const double hx = object.visual->size_x / 2, hy = object.visual->size_y / 2;
    std::vector<cv::Point> corners;
    for (const auto& [sx, sy] : std::vector<std::pair<int, int>>{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
      corners.push_back(c.toPixel(object.x + sx * hx * cos_yaw - sy * hy * sin_yaw, object.y + sx * hx * sin_yaw + sy * hy * cos_yaw));
    }
    cv::fillConvexPoly(c.image, corners, colour, cv::LINE_AA);
    cv::polylines(c.image, std::vector<std::vector<cv::Point>>{corners}, true, cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
  } else if (object.visual) {
    cv::circle(c.image, centre, std::max(2, c.metres(object.visual->radius)), colour, cv::FILLED, cv::LINE_AA);
    cv::circle(c.image, centre, std::max(2, c.metres(object.visual->radius)), cv::Scalar(40, 40, 40), 1, cv::LINE_AA);
  } else {
    // Heard, never seen: a hollow diamond.
    const int r = 7;
    std::vector<cv::Point> diamond{centre + cv::Point(0, -r), centre + cv::Point(r, 0), centre + cv::Point(0, r),
                                   centre + cv::Point(-r, 0)};
    cv::polylines(c.image, std::vector<std::vector<cv::Point>>{diamond}, true, colour, 2, cv::LINE_AA);
  }
  if (object.acoustic) {
    const int ring = std::max(8, c.metres(0.6));
    cv::circle(c.image, centre, ring, cv::Scalar(160, 40, 160), 1, cv::LINE_AA);
    if (object.acoustic->active) cv::circle(c.image, centre, ring + 4, cv::Scalar(160, 40, 160), 1, cv::LINE_AA);
  }
  std::string text = object.id;
  if (object.activity != "idle") text += " (" + object.activity + ")";
  putLabel(c.image, text, centre + cv::Point(6, -8), 0.42, cv::Scalar(255, 255, 255));
}

void drawRobot(TopDownCanvas& c, const world::WorldSimulation& world) {
  const scenario::Scenario& scenario = world.scenario();
  // The robot: its disc, heading (platform) and nose (camera) direction.
  const cv::Point robot = c.toPixel(world.robot().x(), world.robot().y());
  const int radius = std::max(3, c.metres(scenario.robot.radius));
  cv::circle(c.image, robot, radius, cv::Scalar(150, 70, 20), cv::FILLED, cv::LINE_AA);
  cv::circle(c.image, robot, radius, cv::Scalar(20, 20, 20), 1, cv::LINE_AA);
  const double heading = world.robot().yaw() * kDegToRad;
  cv::arrowedLine(c.image, robot,
                  robot + cv::Point(static_cast<int>(1.8 * radius * std::cos(heading)),
                                    static_cast<int>(-1.8 * radius * std::sin(heading))),
                  cv::Scalar(20, 20, 20), 2, cv::LINE_AA, 0, 0.3);
  putLabel(c.image, "robot", robot + cv::Point(radius + 4, radius + 12), 0.45, cv::Scalar(255, 255, 255));

}

void drawTitleAndLegend(TopDownCanvas& c, const world::WorldSimulation& world) {
  const scenario::Scenario& scenario = world.scenario();
  // Title and legend.
  putLabel(c.image,
           scenario.name + format("   tick %.0f   t = %.1f s", static_cast<double>(world.tick()), world.time()) +
               format("   robot (%.2f, %.2f) yaw %.0f", world.robot().x(), world.robot().y(), world.robot().yaw()) +
               format(" head %.0f/%.0f", world.robot().headYaw(), world.robot().headPitch()),
           {c.margin, 22}, 0.55, cv::Scalar(255, 255, 255));
  int x = c.margin;
  for (const std::string& category : scenario.categories) {
    cv::rectangle(c.image, cv::Rect(x, 34, 14, 14), categoryColour(category, scenario.categories), cv::FILLED);
    putLabel(c.image, category, {x + 18, 46}, 0.45, cv::Scalar(255, 255, 255));
    int baseline = 0;
    x += 34 + cv::getTextSize(category, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &baseline).width;
  }
  cv::circle(c.image, {x + 8, 41}, 7, cv::Scalar(160, 40, 160), 1, cv::LINE_AA);
  putLabel(c.image, "sound (double ring: active)", {x + 20, 46}, 0.45, cv::Scalar(255, 255, 255));
}

}  // namespace

cv::Mat topDownImage(const world::WorldSimulation& world, double pixels_per_metre) {
  const scenario::Scenario& scenario = world.scenario();
  TopDownCanvas c;
  c.width = scenario.world.width;
  c.height = scenario.world.height;
  if (!(pixels_per_metre > 0)) pixels_per_metre = std::clamp(1200.0 / std::max(c.width, c.height), 4.0, 80.0);
  c.pixels_per_metre = pixels_per_metre;
  const int image_width = static_cast<int>(std::ceil(c.width * pixels_per_metre)) + 2 * c.margin;
  const int image_height = static_cast<int>(std::ceil(c.height * pixels_per_metre)) + 2 * c.margin + c.legend;
  c.image = cv::Mat(image_height, image_width, CV_8UC3, cv::Scalar(236, 238, 240));
  drawGround(c);
  drawFieldOfView(c, world.camera());
  drawPaths(c, scenario);
  for (const scenario::Object& object : world.objects()) drawObject(c, object, scenario.categories);
  drawRobot(c, world);
  drawTitleAndLegend(c, world);
  return c.image;
}

}  // namespace beft::snapshot
