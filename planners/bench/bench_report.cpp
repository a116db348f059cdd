#include "planners/bench/bench_report.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

namespace beft::planners::bench {

namespace {

std::string number(double value, int decimals) {
  if (std::isnan(value)) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::ofstream openForWriting(const std::string& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error(file + ": cannot write");
  return out;
}

const cv::Scalar kPalette[] = {{40, 40, 40},   {60, 60, 220},  {40, 150, 40},  {200, 120, 30}, {180, 60, 180},
                               {30, 170, 200}, {120, 90, 40},  {90, 90, 150},  {160, 160, 30}, {40, 100, 240}};

}  // namespace

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

void printTable(std::ostream& out, const std::vector<Summary>& rows) {
  char line[256];
  std::snprintf(line, sizeof line, "%-22s %-18s %5s %8s %8s %29s %9s %7s\n", "planner", "map", "runs", "success",
                "len/opt", "time ms: median [p25 - p75]", "turn deg", "clear");
  out << line;
  for (const Summary& s : rows) {
    std::snprintf(line, sizeof line, "%-22s %-18s %5d %7.1f%% %8s %10s [%7s - %7s] %9s %7s\n", s.planner.c_str(),
                  s.map.c_str(), s.runs, 100.0 * s.success_rate, number(s.ratio_median, 3).c_str(),
                  number(s.time_median, 2).c_str(), number(s.time_p25, 2).c_str(), number(s.time_p75, 2).c_str(),
                  number(s.turning_median, 0).c_str(), number(s.clearance_median, 2).c_str());
    out << line;
  }
}

void writeRunsCsv(const std::string& file, const std::vector<RunRecord>& runs) {
  auto out = openForWriting(file);
  out << "planner,dataset,map,query,map_width,map_height,seed,success,time_ms,setup_ms,length,optimum,ratio,"
         "turning_deg,clearance,waypoints,message\n";
  for (const RunRecord& r : runs) {
    out << csvField(r.planner) << ',' << r.dataset << ',' << csvField(r.map) << ',' << csvField(r.query) << ','
        << r.map_width << ',' << r.map_height << ',' << r.seed << ',' << (r.success ? 1 : 0) << ','
        << number(r.time_ms, 4) << ',' << number(r.setup_ms, 4) << ',' << number(r.length, 4) << ','
        << number(r.optimum, 4) << ',' << number(r.ratio, 5) << ',' << number(r.turning_deg, 2) << ','
        << number(r.clearance, 3) << ',' << r.waypoints << ',' << csvField(r.message) << '\n';
  }
  if (!out) throw std::runtime_error(file + ": write failed");
}

void writeSummaryCsv(const std::string& file, const std::vector<Summary>& rows) {
  auto out = openForWriting(file);
  out << "planner,map,runs,successes,success_rate,ratio_median,ratio_mean,time_median_ms,time_p25_ms,"
         "time_p75_ms,turning_median_deg,clearance_median\n";
  for (const Summary& s : rows) {
    out << csvField(s.planner) << ',' << csvField(s.map) << ',' << s.runs << ',' << s.successes << ','
        << number(s.success_rate, 4) << ',' << number(s.ratio_median, 5) << ',' << number(s.ratio_mean, 5) << ','
        << number(s.time_median, 4) << ',' << number(s.time_p25, 4) << ',' << number(s.time_p75, 4) << ','
        << number(s.turning_median, 2) << ',' << number(s.clearance_median, 3) << '\n';
  }
  if (!out) throw std::runtime_error(file + ": write failed");
}

namespace {

// The axes of the length-ratio plot: planning time on a log scale (whole
// decades), length ratio in steps of 0.05 (at most 2).
struct RatioTimeAxes {
  cv::Rect plot;
  double t_min = 1e9, t_max = 1e-9, r_min = 0.95, r_max = 1.2;
  double lx_min = 0, lx_max = 0;  // decades

  cv::Point at(double time_ms, double ratio) const {
    const double fx = (std::log10(std::max(time_ms, 1e-3)) - lx_min) / (lx_max - lx_min);
    const double fy = (std::min(ratio, r_max) - r_min) / (r_max - r_min);
    return cv::Point(plot.x + static_cast<int>(fx * plot.width), plot.y + plot.height - static_cast<int>(fy * plot.height));
  }
};

RatioTimeAxes axesOfSuccesses(const std::vector<RunRecord>& runs, const cv::Rect& plot) {
  RatioTimeAxes axes;
  axes.plot = plot;
  for (const RunRecord& r : runs) {
    if (!r.success) continue;
    axes.t_min = std::min(axes.t_min, std::max(r.time_ms, 1e-3));
    axes.t_max = std::max(axes.t_max, std::max(r.time_ms, 1e-3));
    axes.r_min = std::min(axes.r_min, r.ratio);
    axes.r_max = std::max(axes.r_max, r.ratio);
  }
  if (axes.t_min > axes.t_max) { axes.t_min = 0.1; axes.t_max = 1000; }
  axes.lx_min = std::floor(std::log10(axes.t_min));
  axes.lx_max = std::max(axes.lx_min + 1, std::ceil(std::log10(axes.t_max)));
  axes.r_min = std::floor(axes.r_min * 20) / 20;
  axes.r_max = std::min(2.0, std::ceil(axes.r_max * 20) / 20);
  return axes;
}

void putLabel(cv::Mat& image, const std::string& s, cv::Point at, double scale = 0.45,
              cv::Scalar colour = {0, 0, 0}) {
  cv::putText(image, s, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

// Grid: decades of time, steps of 0.05 in ratio; the optimum line at 1.
void drawRatioTimeGrid(cv::Mat& image, const RatioTimeAxes& axes) {
  const cv::Rect& plot = axes.plot;
  for (int decade = static_cast<int>(axes.lx_min); decade <= static_cast<int>(axes.lx_max); ++decade) {
    const int x = axes.at(std::pow(10.0, decade), axes.r_min).x;
    cv::line(image, {x, plot.y}, {x, plot.y + plot.height}, cv::Scalar(225, 225, 225));
    char label[32];
    std::snprintf(label, sizeof label, decade >= 0 ? "%.0f" : "%g", std::pow(10.0, decade));
    putLabel(image, label, {x - 10, plot.y + plot.height + 20});
  }
  const double ratio_step = (axes.r_max - axes.r_min) > 0.5 ? 0.1 : 0.05;
  for (double ratio = axes.r_min; ratio <= axes.r_max + 1e-9; ratio += ratio_step) {
    const int y = axes.at(axes.t_min, ratio).y;
    cv::line(image, {plot.x, y}, {plot.x + plot.width, y}, cv::Scalar(225, 225, 225));
    putLabel(image, number(ratio, 2), {plot.x - 45, y + 5});
  }
  if (1.0 >= axes.r_min && 1.0 <= axes.r_max) {
    const int y = axes.at(axes.t_min, 1.0).y;
    cv::line(image, {plot.x, y}, {plot.x + plot.width, y}, cv::Scalar(120, 120, 120), 1, cv::LINE_AA);
    putLabel(image, "octile optimum", {plot.x + 5, y - 5}, 0.4, {90, 90, 90});
  }
}

// One planner's runs as small dots, its median as a large marker, and its
// line of the legend (the index-th).
void drawPlannerRuns(cv::Mat& image, const RatioTimeAxes& axes, const std::vector<RunRecord>& runs,
                     const std::string& planner, size_t index) {
  const cv::Rect& plot = axes.plot;
  const cv::Scalar colour = kPalette[index % (sizeof kPalette / sizeof kPalette[0])];
  std::vector<double> times, ratios;
  int total = 0, successes = 0;
  cv::Mat overlay = image.clone();
  for (const RunRecord& r : runs) {
    if (r.planner != planner) continue;
    ++total;
    if (!r.success) continue;
    ++successes;
    times.push_back(r.time_ms);
    ratios.push_back(r.ratio);
    cv::circle(overlay, axes.at(r.time_ms, r.ratio), 3, colour, cv::FILLED, cv::LINE_AA);
  }
  cv::addWeighted(overlay, 0.45, image, 0.55, 0, image);
  if (!times.empty()) {
    const cv::Point centre = axes.at(median(times), median(ratios));
    cv::drawMarker(image, centre, colour, cv::MARKER_DIAMOND, 18, 3, cv::LINE_AA);
  }
  const int y = plot.y + 20 + 24 * static_cast<int>(index);
  cv::drawMarker(image, {plot.x + plot.width + 20, y - 4}, colour, cv::MARKER_DIAMOND, 12, 2, cv::LINE_AA);
  const std::string rate = total > 0 ? number(100.0 * successes / total, 0) + "%" : "-";
  putLabel(image, planner + "  " + rate, {plot.x + plot.width + 35, y}, 0.45, colour);
}

}  // namespace

cv::Mat plotLengthRatioVsTime(const std::vector<RunRecord>& runs, const std::vector<std::string>& planners,
                              const std::string& title) {
  const int width = 1100, height = 720;
  const int left = 80, right = 260, top = 50, bottom = 70;
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const cv::Rect plot(left, top, width - left - right, height - top - bottom);
  const RatioTimeAxes axes = axesOfSuccesses(runs, plot);

  drawRatioTimeGrid(image, axes);
  cv::rectangle(image, plot, cv::Scalar(0, 0, 0));
  putLabel(image, "planning time [ms], log scale", {plot.x + plot.width / 2 - 110, height - 25}, 0.5);
  putLabel(image, "path length / octile optimum", {10, 30}, 0.5);
  putLabel(image, title, {plot.x + 220, 30}, 0.55);

  // Runs as small dots, medians as large markers with a legend.
  for (size_t i = 0; i < planners.size(); ++i) drawPlannerRuns(image, axes, runs, planners[i], i);
  putLabel(image, "diamond: median; dots: runs", {plot.x + plot.width + 20, plot.y + plot.height}, 0.4, {90, 90, 90});
  return image;
}

}  // namespace beft::planners::bench
