#include "lib/foxglove/foxglove_values.hpp"

#include <algorithm>
#include <cmath>

#include "lib/foxglove/json_text.hpp"

namespace beft::foxglove {

namespace {
constexpr double kPi = 3.14159265358979323846;
double finite(double value) { return std::isfinite(value) ? value : 0.0; }
}  // namespace

nlohmann::json timeOf(int64_t utime) {
  if (utime < 0) utime = 0;
  return {{"sec", utime / 1000000}, {"nsec", (utime % 1000000) * 1000}};
}

nlohmann::json vector3(double x, double y, double z) { return {{"x", finite(x)}, {"y", finite(y)}, {"z", finite(z)}}; }

nlohmann::json rotation(double yaw_deg, double pitch_deg) {
  // q = q_z(yaw) * q_y(-pitch): about +y a positive angle lowers +x.
  const double half_yaw = finite(yaw_deg) * kPi / 360.0;
  const double half_pitch = -finite(pitch_deg) * kPi / 360.0;
  const double cz = std::cos(half_yaw), sz = std::sin(half_yaw);
  const double cy = std::cos(half_pitch), sy = std::sin(half_pitch);
  return {{"x", -sz * sy}, {"y", cz * sy}, {"z", sz * cy}, {"w", cz * cy}};
}

nlohmann::json pose(double x, double y, double z, double yaw_deg, double pitch_deg) {
  return {{"position", vector3(x, y, z)}, {"orientation", rotation(yaw_deg, pitch_deg)}};
}

nlohmann::json color(double r, double g, double b, double a) { return {{"r", r}, {"g", g}, {"b", b}, {"a", a}}; }

nlohmann::json colorOfRgb(int32_t rgb, double a) {
  const auto channel = [rgb](int shift) {
    return static_cast<double>((static_cast<uint32_t>(rgb) >> shift) & 0xff) / 255.0;
  };
  return color(channel(16), channel(8), channel(0), a);
}

nlohmann::json sceneEntity(const std::string& id, int64_t utime) {
  const nlohmann::json empty = nlohmann::json::array();
  return {{"timestamp", timeOf(utime)},
          {"frame_id", "world"},
          {"id", validUtf8(id)},
          {"lifetime", {{"sec", 0}, {"nsec", 0}}},
          {"frame_locked", false},
          {"metadata", empty},
          {"arrows", empty},
          {"cubes", empty},
          {"spheres", empty},
          {"cylinders", empty},
          {"lines", empty},
          {"triangles", empty},
          {"texts", empty},
          {"models", empty}};
}

nlohmann::json cubePrimitive(const nlohmann::json& pose, const nlohmann::json& size, const nlohmann::json& color) {
  return {{"pose", pose}, {"size", size}, {"color", color}};
}

nlohmann::json cylinderPrimitive(const nlohmann::json& pose, const nlohmann::json& size,
                                 const nlohmann::json& color) {
  return {{"pose", pose}, {"size", size}, {"bottom_scale", 1.0}, {"top_scale", 1.0}, {"color", color}};
}

nlohmann::json spherePrimitive(const nlohmann::json& pose, double diameter, const nlohmann::json& color) {
  return {{"pose", pose}, {"size", vector3(diameter, diameter, diameter)}, {"color", color}};
}

nlohmann::json arrowPrimitive(const nlohmann::json& pose, double length, double diameter,
                              const nlohmann::json& color) {
  const double head_length = std::min(length * 0.3, diameter * 4);
  return {{"pose", pose},
          {"shaft_length", length - head_length},
          {"shaft_diameter", diameter},
          {"head_length", head_length},
          {"head_diameter", diameter * 2.5},
          {"color", color}};
}

nlohmann::json textPrimitive(const nlohmann::json& pose, const std::string& text, double font_size,
                             const nlohmann::json& color) {
  return {{"pose", pose},
          {"billboard", true},
          {"font_size", font_size},
          {"scale_invariant", false},
          {"color", color},
          {"text", validUtf8(text)}};
}

nlohmann::json lineStripPrimitive(const nlohmann::json& points, double thickness, const nlohmann::json& color) {
  return {{"type", 0},  // LINE_STRIP
          {"pose", pose(0, 0, 0)},
          {"thickness", thickness},
          {"scale_invariant", false},
          {"points", points},
          {"color", color},
          {"colors", nlohmann::json::array()},
          {"indices", nlohmann::json::array()}};
}

}  // namespace beft::foxglove
