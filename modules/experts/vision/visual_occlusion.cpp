#include "experts/vision/visual_occlusion.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "lib/expert/id_index.hpp"

namespace beft::vision {

std::vector<int> countVisiblePixels(const camera_frame_t& instance, const scene_objects_t& scene) {
  expert::IdPositions<scene_object_t> positions;
  return countVisiblePixels(instance, positions.of(scene.objects, &scene_object_t::id), scene.objects.size());
}

std::vector<int> countVisiblePixels(const camera_frame_t& instance,
                                    const std::unordered_map<std::string, std::size_t>& scene_index,
                                    std::size_t object_count) {
  if (instance.encoding != camera_frame_t::ENCODING_INSTANCE16)
    throw std::invalid_argument("instance frame has encoding " + std::to_string(instance.encoding) +
                                ", expected INSTANCE16");
  if (instance.compression != camera_frame_t::COMPRESSION_NONE)
    throw std::invalid_argument("instance frame still compressed (camera::decodeCameraFrame unpacks it)");
  if (instance.width < 0 || instance.height < 0) throw std::invalid_argument("instance frame has a negative size");
  const std::size_t pixels = static_cast<std::size_t>(instance.width) * static_cast<std::size_t>(instance.height);
  if (instance.data.size() != 2 * pixels)
    throw std::invalid_argument("instance frame holds " + std::to_string(instance.data.size()) + " bytes, expected " +
                                std::to_string(2 * pixels) + " for " + std::to_string(instance.width) + "x" +
                                std::to_string(instance.height));

  std::vector<int> object_of_value(instance.instance_ids.size() + 1, -1);  // pixel value -> scene index
  for (std::size_t v = 0; v < instance.instance_ids.size(); ++v) {
    const auto it = scene_index.find(instance.instance_ids[v]);
    if (it != scene_index.end()) object_of_value[v + 1] = static_cast<int>(it->second);
  }

  std::vector<int> count_of_value(object_of_value.size(), 0);
  for (std::size_t p = 0; p < pixels; ++p) {
    const unsigned value = instance.data[2 * p] | (static_cast<unsigned>(instance.data[2 * p + 1]) << 8);
    if (value >= count_of_value.size())
      throw std::invalid_argument("instance pixel " + std::to_string(p) + " has value " + std::to_string(value) +
                                  " but the frame lists " + std::to_string(instance.instance_ids.size()) + " ids");
    ++count_of_value[value];
  }
  std::vector<int> visible(object_count, 0);
  for (std::size_t v = 1; v < count_of_value.size(); ++v)
    if (object_of_value[v] >= 0) visible[object_of_value[v]] += count_of_value[v];
  return visible;
}

visual_percepts_t estimateVisualOcclusion(const scene_objects_t& scene, const std::vector<int>& visible,
                                          const std::vector<int>& expected) {
  visual_percepts_t out{};
  out.utime = scene.utime;
  out.tick = scene.tick;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto& object = scene.objects[i];
    if (object.shape != scene_object_t::SHAPE_BOX && object.shape != scene_object_t::SHAPE_CYLINDER) continue;
    visual_percept_t percept;
    percept.object_id = object.id;
    percept.expected_pixels = i < expected.size() ? expected[i] : 0;
    // Never more than expected: both come from the same rays.
    percept.visible_pixels = std::min(i < visible.size() ? visible[i] : 0, percept.expected_pixels);
    // Out of the camera's view altogether (O_v 100, nothing expected): no
    // entry, an absent object reads as that. At 450 objects these were most
    // of the message; an object in view but hidden keeps its entry.
    if (percept.expected_pixels <= 0) continue;
    percept.occlusion = 100.0 * (1.0 - static_cast<double>(percept.visible_pixels) / percept.expected_pixels);
    out.percepts.push_back(percept);
  }
  out.num_percepts = static_cast<int32_t>(out.percepts.size());
  return out;
}

}  // namespace beft::vision
