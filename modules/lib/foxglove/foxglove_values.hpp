// The small values of Foxglove's message schemas as JSON: time, vectors,
// quaternions, poses, colours and the scene primitives. Angles in degrees
// as beft messages have them.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace beft::foxglove {

// {sec, nsec} of a time in microseconds (negative times become 0).
nlohmann::json timeOf(int64_t utime);
nlohmann::json vector3(double x, double y, double z);
// Rotation by yaw about +z, then pitch up (a positive pitch raises +x).
nlohmann::json rotation(double yaw_deg, double pitch_deg = 0);
nlohmann::json pose(double x, double y, double z, double yaw_deg = 0, double pitch_deg = 0);
nlohmann::json color(double r, double g, double b, double a = 1);
// 0xRRGGBB as a colour.
nlohmann::json colorOfRgb(int32_t rgb, double a = 1);

// A foxglove.SceneEntity in "world" with every primitive list empty.
nlohmann::json sceneEntity(const std::string& id, int64_t utime);

nlohmann::json cubePrimitive(const nlohmann::json& pose, const nlohmann::json& size, const nlohmann::json& color);
nlohmann::json cylinderPrimitive(const nlohmann::json& pose, const nlohmann::json& size, const nlohmann::json& color);
nlohmann::json spherePrimitive(const nlohmann::json& pose, double diameter, const nlohmann::json& color);
nlohmann::json arrowPrimitive(const nlohmann::json& pose, double length, double diameter, const nlohmann::json& color);
// A label that always faces the viewer.
nlohmann::json textPrimitive(const nlohmann::json& pose, const std::string& text, double font_size,
                             const nlohmann::json& color);
// A line strip through points (Vector3 JSON).
nlohmann::json lineStripPrimitive(const nlohmann::json& points, double thickness, const nlohmann::json& color);

}  // namespace beft::foxglove
