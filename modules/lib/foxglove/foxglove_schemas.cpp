// The JSON Schemas of the Foxglove messages this library makes
// (foxgloveSchema in scene_messages.hpp), built from their parts. They follow
// Foxglove's published message definitions (docs.foxglove.dev, "Message
// schemas"): the field names, types, enumerations and the conventions
// Foxglove reads from a JSON Schema - "title": "time" for {sec, nsec},
// "contentEncoding": "base64" for bytes, "oneOf" of consts for an enum -
// with every nested type written inline, as Foxglove takes no "$ref".
#include <stdexcept>
#include <utility>
#include <vector>

#include "lib/foxglove/scene_messages.hpp"

namespace beft::foxglove {

namespace {

using nlohmann::json;

json typed(const char* type, const std::string& description) { return {{"type", type}, {"description", description}}; }
json number(const std::string& description) { return typed("number", description); }
json text(const std::string& description) { return typed("string", description); }
json boolean(const std::string& description) { return typed("boolean", description); }
json count(const std::string& description) {
  json schema = typed("integer", description);
  schema["minimum"] = 0;
  return schema;
}
json bytes(const std::string& description) {
  json schema = text(description);
  schema["contentEncoding"] = "base64";
  return schema;
}
json arrayOf(json items, const std::string& description) {
  return {{"type", "array"}, {"items", std::move(items)}, {"description", description}};
}

// A message or nested type: every listed property required.
json record(const std::string& title, const std::string& description,
            std::vector<std::pair<std::string, json>> fields) {
  json properties = json::object();
  json required = json::array();
  for (auto& [name, schema] : fields) {
    required.push_back(name);
    properties[name] = std::move(schema);
  }
  return {{"title", title}, {"description", description}, {"type", "object"}, {"properties", properties},
          {"required", required}};
}

// An enumeration: Foxglove reads the constants' names from the titles.
json enumeration(const std::string& title, const std::string& description,
                 const std::vector<std::pair<std::string, int>>& values) {
  json alternatives = json::array();
  for (const auto& [name, value] : values) alternatives.push_back({{"title", name}, {"const", value}});
  return {{"title", title}, {"description", description}, {"oneOf", alternatives}};
}

json timeSchema(const std::string& title, const std::string& description) {
  json nsec = {{"type", "integer"}, {"minimum", 0}, {"maximum", 999999999}};
  json sec = {{"type", "integer"}};
  if (title == "time") sec["minimum"] = 0;
  return {{"type", "object"}, {"title", title}, {"description", description},
          {"properties", {{"sec", sec}, {"nsec", nsec}}}, {"required", {"sec", "nsec"}}};
}

json vector3(const std::string& description) {
  return record("foxglove.Vector3", description,
                {{"x", number("x coordinate")}, {"y", number("y coordinate")}, {"z", number("z coordinate")}});
}

json quaternion(const std::string& description) {
  return record("foxglove.Quaternion", description,
                {{"x", number("x")}, {"y", number("y")}, {"z", number("z")}, {"w", number("w")}});
}

json poseSchema(const std::string& description) {
  return record("foxglove.Pose", description,
                {{"position", vector3("Position")}, {"orientation", quaternion("Orientation")}});
}

json colorSchema(const std::string& description) {
  return record("foxglove.Color", description,
                {{"r", number("Red, 0..1")}, {"g", number("Green, 0..1")}, {"b", number("Blue, 0..1")},
                 {"a", number("Alpha, 0..1")}});
}

json point3() {
  return record("foxglove.Point3", "A point",
                {{"x", number("x coordinate")}, {"y", number("y coordinate")}, {"z", number("z coordinate")}});
}

json keyValuePair() {
  return record("foxglove.KeyValuePair", "A key and its value", {{"key", text("Key")}, {"value", text("Value")}});
}

json arrowPrimitive() {
  return record("foxglove.ArrowPrimitive", "An arrow",
                {{"pose", poseSchema("Tail of the arrow; identity orientation points along +x")},
                 {"shaft_length", number("Length of the shaft")},
                 {"shaft_diameter", number("Diameter of the shaft")},
                 {"head_length", number("Length of the head")},
                 {"head_diameter", number("Diameter of the head")},
                 {"color", colorSchema("Colour")}});
}

// Cubes and spheres: a pose, a size along each axis, a colour.
json sizedPrimitive(const std::string& title, const std::string& description) {
  return record(title, description,
                {{"pose", poseSchema("Centre and orientation")},
                 {"size", vector3("Size along each axis")},
                 {"color", colorSchema("Colour")}});
}

json cylinderPrimitive() {
  return record("foxglove.CylinderPrimitive", "A cylinder, cone or truncated cone",
                {{"pose", poseSchema("Centre and orientation; the axis is +z")},
                 {"size", vector3("Size of the bounding box")},
                 {"bottom_scale", number("Bottom radius as a fraction of the bounding box")},
                 {"top_scale", number("Top radius as a fraction of the bounding box")},
                 {"color", colorSchema("Colour")}});
}

json linePrimitive() {
  return record("foxglove.LinePrimitive", "A line strip, loop or list of segments",
                {{"type", enumeration("foxglove.LineType", "How the points are connected",
                                      {{"LINE_STRIP", 0}, {"LINE_LOOP", 1}, {"LINE_LIST", 2}})},
                 {"pose", poseSchema("Origin of the points")},
                 {"thickness", number("Line thickness")},
                 {"scale_invariant", boolean("Thickness in screen pixels (true) or world units (false)")},
                 {"points", arrayOf(point3(), "Points along the line")},
                 {"color", colorSchema("Colour of the whole line")},
                 {"colors", arrayOf(colorSchema("Colour"), "Colour per point, instead of color")},
                 {"indices", arrayOf(count("Index"), "Indices into points; all points in order when empty")}});
}

json triangleListPrimitive() {
  return record("foxglove.TriangleListPrimitive", "A set of triangles",
                {{"pose", poseSchema("Origin of the points")},
                 {"points", arrayOf(point3(), "Vertices, three per triangle")},
                 {"color", colorSchema("Colour of the whole set")},
                 {"colors", arrayOf(colorSchema("Colour"), "Colour per vertex, instead of color")},
                 {"indices", arrayOf(count("Index"), "Indices into points; all points in order when empty")}});
}

json textPrimitive() {
  return record("foxglove.TextPrimitive", "A text label",
                {{"pose", poseSchema("Centre of the text")},
                 {"billboard", boolean("Always faces the viewer (true) or follows pose.orientation (false)")},
                 {"font_size", number("Height of a line of text")},
                 {"scale_invariant", boolean("font_size in screen pixels (true) or world units (false)")},
                 {"color", colorSchema("Colour")},
                 {"text", text("Text")}});
}

json modelPrimitive() {
  return record("foxglove.ModelPrimitive", "A 3-D model from a URL or embedded data",
                {{"pose", poseSchema("Origin of the model")},
                 {"scale", vector3("Scale along each axis")},
                 {"color", colorSchema("Colour, when override_color is set")},
                 {"override_color", boolean("Paint the model in color")},
                 {"url", text("URL of the model")},
                 {"media_type", text("Media type of data")},
                 {"data", bytes("The model, when url is empty")}});
}

json sceneEntity() {
  return record(
      "foxglove.SceneEntity", "One thing in a 3-D scene, made of primitives that share a frame",
      {{"timestamp", timeSchema("time", "Time of the entity")},
       {"frame_id", text("Frame of reference")},
       {"id", text("Identifier; an entity replaces the earlier one of the same id on its topic")},
       {"lifetime", timeSchema("duration", "How long after timestamp the entity is removed; 0 keeps it")},
       {"frame_locked", boolean("Follows its frame as that frame moves (true) or stays where it was (false)")},
       {"metadata", arrayOf(keyValuePair(), "Key-value pairs, keys unique")},
       {"arrows", arrayOf(arrowPrimitive(), "Arrows")},
       {"cubes", arrayOf(sizedPrimitive("foxglove.CubePrimitive", "A box"), "Boxes")},
       {"spheres", arrayOf(sizedPrimitive("foxglove.SpherePrimitive", "A sphere or ellipsoid"), "Spheres")},
       {"cylinders", arrayOf(cylinderPrimitive(), "Cylinders")},
       {"lines", arrayOf(linePrimitive(), "Lines")},
       {"triangles", arrayOf(triangleListPrimitive(), "Triangles")},
       {"texts", arrayOf(textPrimitive(), "Texts")},
       {"models", arrayOf(modelPrimitive(), "Models")}});
}

json sceneUpdate() {
  const json deletion = record(
      "foxglove.SceneEntityDeletion", "Removes entities",
      {{"timestamp", timeSchema("time", "Only entities older than this are removed")},
       {"type", enumeration("foxglove.SceneEntityDeletionType", "What is removed", {{"MATCHING_ID", 0}, {"ALL", 1}})},
       {"id", text("Entity to remove when type is MATCHING_ID")}});
  return record("foxglove.SceneUpdate", "Changes to the entities of a 3-D scene",
                {{"deletions", arrayOf(deletion, "Entities to remove")},
                 {"entities", arrayOf(sceneEntity(), "Entities to add or replace")}});
}

json frameTransform() {
  return record("foxglove.FrameTransform", "Where a child frame is in its parent frame",
                {{"timestamp", timeSchema("time", "Time of the transform")},
                 {"parent_frame_id", text("Parent frame")},
                 {"child_frame_id", text("Child frame")},
                 {"translation", vector3("Position of the child's origin in the parent")},
                 {"rotation", quaternion("Orientation of the child in the parent")}});
}

json frameTransforms() {
  return record("foxglove.FrameTransforms", "Several frame transforms",
                {{"transforms", arrayOf(frameTransform(), "The transforms")}});
}

json grid() {
  const json field = record(
      "foxglove.PackedElementField", "A field of each cell in data",
      {{"name", text("Name of the field")},
       {"offset", count("Byte offset within a cell")},
       {"type", enumeration("foxglove.NumericType", "Type of the field (little-endian)",
                            {{"UNKNOWN", 0}, {"UINT8", 1}, {"INT8", 2}, {"UINT16", 3}, {"INT16", 4},
                             {"UINT32", 5}, {"INT32", 6}, {"FLOAT32", 7}, {"FLOAT64", 8}})}});
  const json cell_size = record("foxglove.Vector2", "Size of a cell along x and y",
                                {{"x", number("x coordinate")}, {"y", number("y coordinate")}});
  return record("foxglove.Grid", "A 2-D grid of cells",
                {{"timestamp", timeSchema("time", "Time of the grid")},
                 {"frame_id", text("Frame of reference")},
                 {"pose", poseSchema("Corner of cell (0, 0); the grid lies in the x-y plane of this pose")},
                 {"column_count", count("Columns")},
                 {"cell_size", cell_size},
                 {"row_stride", count("Bytes from one row to the next in data")},
                 {"cell_stride", count("Bytes from one cell to the next within a row")},
                 {"fields", arrayOf(field, "Fields of each cell")},
                 {"data", bytes("Cells, row by row (rows along y)")}});
}

json rawImage() {
  return record("foxglove.RawImage", "An uncompressed image",
                {{"timestamp", timeSchema("time", "Time of the image")},
                 {"frame_id", text("Frame of the camera (+x right, +y down, +z forward)")},
                 {"width", count("Width [px]")},
                 {"height", count("Height [px]")},
                 {"encoding", text("Pixel format: rgb8, mono16, 16UC1, ...")},
                 {"step", count("Bytes per row")},
                 {"data", bytes("Pixels, row by row")}});
}

json logSchema() {
  return record("foxglove.Log", "A log message",
                {{"timestamp", timeSchema("time", "Time of the message")},
                 {"level", enumeration("foxglove.LogLevel", "Level",
                                       {{"UNKNOWN", 0}, {"DEBUG", 1}, {"INFO", 2}, {"WARNING", 3}, {"ERROR", 4},
                                        {"FATAL", 5}})},
                 {"message", text("Message")},
                 {"name", text("Process or node")},
                 {"file", text("Source file")},
                 {"line", count("Line in the source file")}});
}

}  // namespace

nlohmann::json foxgloveSchema(const std::string& schema_name) {
  if (schema_name == kSceneUpdateSchema) return sceneUpdate();
  if (schema_name == kFrameTransformsSchema) return frameTransforms();
  if (schema_name == "foxglove.FrameTransform") return frameTransform();
  if (schema_name == kGridSchema) return grid();
  if (schema_name == kRawImageSchema) return rawImage();
  if (schema_name == kLogSchema) return logSchema();
  throw std::invalid_argument("no JSON Schema for \"" + schema_name + "\" (known: " + kSceneUpdateSchema + ", " +
                              kFrameTransformsSchema + ", foxglove.FrameTransform, " + kGridSchema + ", " +
                              kRawImageSchema + ", " + kLogSchema + ")");
}

}  // namespace beft::foxglove
