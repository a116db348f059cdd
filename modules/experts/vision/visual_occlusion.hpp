// Visual occlusion O_v (spec/model.md) of every object with a visual:
//   O_v = 100 * (1 - visible / expected)
// visible: the object's pixels in the instance image; expected: the pixels
// it would cover from the same camera if nothing were in front of it and the
// image had no borders and no range (camera::expectedPixelsPerObject with
// camera::withoutViewLimits), so the part of an object outside the field of
// view or beyond range counts as occluded. Out of view gives 100.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include <beft/camera_frame_t.hpp>
#include <beft/scene_objects_t.hpp>
#include <beft/visual_percepts_t.hpp>

namespace beft::vision {

// Pixels per object (index into scene.objects) of an INSTANCE16 frame, matched
// through the frame's instance_ids. Throws std::invalid_argument on a frame
// that is not INSTANCE16, has a wrong data size or a pixel value beyond its id
// list; ids not in the scene are ignored.
std::vector<int> countVisiblePixels(const camera_frame_t& instance, const scene_objects_t& scene);

// The same with the scene's index made already: each object's place in
// scene.objects by id (expert::IdPositions), of object_count objects.
std::vector<int> countVisiblePixels(const camera_frame_t& instance,
                                    const std::unordered_map<std::string, std::size_t>& scene_index,
                                    std::size_t object_count);

// One percept per object with a visual that the camera's view covers
// (expected pixels > 0), in scene order; an object out of view has none (its
// O_v is 100). Stamped with the scene's utime and tick. visible and expected are indexed like scene.objects.
visual_percepts_t estimateVisualOcclusion(const scene_objects_t& scene, const std::vector<int>& visible,
                                          const std::vector<int>& expected);

}  // namespace beft::vision
