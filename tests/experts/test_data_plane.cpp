// The data plane (channels.hpp, Plane::kData) is what the world and the
// experts write: checked against the output ports of their classes, so the
// channel table cannot drift from the code that publishes.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "experts/acoustic_labels/acoustic_labels_expert.hpp"
#include "experts/audio/audio_expert.hpp"
#include "experts/dw/dw_expert.hpp"
#include "experts/exploration/exploration_expert.hpp"
#include "experts/fusion/fusion_expert.hpp"
#include "experts/geometry/geometry_expert.hpp"
#include "experts/tasks/tasks_expert.hpp"
#include "experts/vision/vision_expert.hpp"
#include "experts/visual_labels/visual_labels_expert.hpp"
#include "lib/common/channels.hpp"
#include "sim/ears/ears_expert.hpp"
#include "sim/world/world_expert.hpp"

using namespace beft;

namespace {

// Every channel written by the world or an expert, with who writes it.
std::map<std::string, std::set<std::string>> writersByChannel() {
  std::vector<std::unique_ptr<expert::Expert>> writers;
  writers.push_back(std::make_unique<world::WorldExpert>());
  writers.push_back(std::make_unique<ears::EarsExpert>());
  writers.push_back(std::make_unique<geometry::GeometryExpert>());
  writers.push_back(std::make_unique<vision::VisionExpert>());
  writers.push_back(std::make_unique<audio::AudioExpert>());
  writers.push_back(std::make_unique<visual_labels::VisualLabelsExpert>());
  writers.push_back(std::make_unique<acoustic_labels::AcousticLabelsExpert>());
  writers.push_back(std::make_unique<fusion::FusionExpert>());
  writers.push_back(std::make_unique<dw::DwExpert>());
  writers.push_back(std::make_unique<exploration::ExplorationExpert>());
  writers.push_back(std::make_unique<tasks::TasksExpert>());
  std::map<std::string, std::set<std::string>> by_channel;
  for (const auto& writer : writers)
    for (const auto& spec : writer->writes()) by_channel[spec.channel].insert(writer->name());
  return by_channel;
}

std::set<std::string> dataPlane() {
  std::set<std::string> names;
  for (const auto& entry : channels::allChannels())
    if (channels::isDataPlaneChannel(entry.name)) names.insert(entry.name);
  return names;
}

channels::Plane planeOf(const std::string& channel) {
  for (const auto& entry : channels::allChannels())
    if (channel == entry.name) return entry.plane;
  ADD_FAILURE() << channel << " is not in the channel table";
  return channels::Plane::kService;
}

}  // namespace

TEST(DataPlane, EveryChannelTheWorldAndTheExpertsWriteIsDataPlaneButAReportAndAControlMessage) {
  std::set<std::string> not_data;
  for (const auto& [channel, writers] : writersByChannel()) {
    const channels::Plane plane = planeOf(channel);
    if (plane == channels::Plane::kData) continue;
    EXPECT_TRUE(plane == channels::Plane::kReport || plane == channels::Plane::kControl)
        << channel << " (written by " << *writers.begin() << ") is of neither the data plane nor a report";
    not_data.insert(channel);
  }
  // The tasks expert's record of what its stack did, and exploration's request to end the run.
  EXPECT_EQ(not_data, (std::set<std::string>{"STOP_REQUEST", "TASK_EVENTS"}));
}

TEST(DataPlane, EveryDataPlaneChannelIsWrittenByTheWorldOrAnExpert) {
  const auto writers = writersByChannel();
  for (const auto& channel : dataPlane()) EXPECT_TRUE(writers.count(channel)) << channel << " is written by none";
}

// The mission digests are of exactly these channels (tests/system/run_support.cpp).
TEST(DataPlane, IsTheSetTheMissionDigestsAreOf) {
  EXPECT_EQ(dataPlane(),
            (std::set<std::string>{"GT_OBJECTS", "GT_VERSION", "ROBOT_STATE", "CONTACT", "CAMERA_COLOR", "CAMERA_DEPTH",
                                   "CAMERA_INSTANCE", "EARS", "GEOMETRY", "VISION", "OBSTACLE_MAP",
                                   "OBSTACLE_MAP_CHANGES", "OBSTACLE_MAP_FELT", "AUDIO", "LABELS_VISUAL",
                                   "LABELS_ACOUSTIC", "HYPOTHESES", "HYPOTHESIS_CHANGES", "DYNAMIC_WEIGHTS",
                                   "TASK_STACK", "TASK_COMMAND", "ROBOT_CMD", "PLAN_REQUEST"}));
  EXPECT_FALSE(channels::isDataPlaneChannel("PLAN_RESULT")) << "its planning time is of the wall clock";
  EXPECT_FALSE(channels::isDataPlaneChannel("SCALED")) << "not in the table";
}
