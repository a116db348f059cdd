#include "tools/bench_experts/expert_chain.hpp"

#include <ctime>
#include <stdexcept>

#include "experts/acoustic_labels/acoustic_labels_expert.hpp"
#include "experts/audio/audio_expert.hpp"
#include "lib/common/channels.hpp"
#include "experts/fusion/fusion_expert.hpp"
#include "lib/wire/hypothesis_changes.hpp"
#include "experts/geometry/geometry_expert.hpp"
#include "experts/vision/vision_expert.hpp"
#include "experts/visual_labels/visual_labels_expert.hpp"

namespace beft::bench {

double threadCpuSeconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return now.tv_sec + 1e-9 * now.tv_nsec;
}

// Collects what one firing publishes, for delivery after it returns.
class ExpertChain::Bus : public expert::Output {
 public:
  void publishEncoded(const std::string& channel, const std::vector<uint8_t>& bytes) override {
    published.emplace_back(channel, bytes);
  }
  std::vector<std::pair<std::string, std::vector<uint8_t>>> published;
};

ExpertChain::ExpertChain(const std::map<std::string, std::map<std::string, std::string>>& parameters) {
  experts_.push_back(std::make_unique<geometry::GeometryExpert>());
  experts_.push_back(std::make_unique<vision::VisionExpert>());
  experts_.push_back(std::make_unique<audio::AudioExpert>());
  experts_.push_back(std::make_unique<visual_labels::VisualLabelsExpert>());
  experts_.push_back(std::make_unique<acoustic_labels::AcousticLabelsExpert>());
  experts_.push_back(std::make_unique<fusion::FusionExpert>());
  levels_ = {{0, 1, 2}, {3, 4}, {5}};
  for (auto& e : experts_) {
    names_.push_back(e->name());
    const auto it = parameters.find(e->name());
    e->startUp(it != parameters.end() ? expert::Parameters(it->second.begin(), it->second.end()) : expert::Parameters{});
  }
}

ExpertChain::~ExpertChain() = default;

bool ExpertChain::latestHypotheses(hypotheses_t& whole) const {
  hypotheses_t keyframe{};
  hypothesis_changes_t changes{};
  return latest(channels::kHypotheses, keyframe) && latest(channels::kHypothesisChanges, changes) &&
         wire::applyChanges(keyframe, changes, whole);
}

std::shared_ptr<const planners::ObstacleCells> ExpertChain::latestObstacleMap() const {
  obstacle_map_t keyframe{};
  obstacle_map_changes_t changes{};
  if (!latest(channels::kObstacleMap, keyframe)) return nullptr;
  const bool with_changes = latest(channels::kObstacleMapChanges, changes);
  return planners::ObstacleMapAssembler().mapOf(keyframe, with_changes ? &changes : nullptr);
}

std::size_t ExpertChain::latestSize(const std::string& channel) const {
  const auto it = latest_.find(channel);
  return it == latest_.end() ? 0 : it->second.size();
}

void ExpertChain::deliver(const std::string& channel, const std::vector<uint8_t>& bytes) {
  latest_[channel] = bytes;
  for (auto& e : experts_)
    for (const auto& spec : e->reads())
      if (spec.channel == channel && !e->onMessage(channel, bytes.data(), static_cast<int>(bytes.size())))
        throw std::runtime_error(e->name() + " did not understand a message on " + channel);
}

template <typename Message>
void ExpertChain::deliver(const std::string& channel, const Message& message) {
  std::vector<uint8_t> bytes(message.getEncodedSize());
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  deliver(channel, bytes);
}

std::vector<std::string> ExpertChain::runTick(const scene_objects_t& scene, const robot_state_t& robot,
                                              const camera_frame_t& depth, const camera_frame_t& instance) {
  deliver(channels::kGroundTruth, scene);
  deliver(channels::kRobotState, robot);
  deliver(channels::kCameraDepth, depth);
  deliver(channels::kCameraInstance, instance);

  std::vector<std::string> failures;
  for (const auto& level : levels_) {
    Bus bus;  // a level's outputs reach the next level, as on the blackboard
    for (int index : level) {
      auto& e = *experts_[index];
      expert::Firing firing;
      firing.expert = e.name();
      firing.transition = "t_" + e.name();
      firing.tick = scene.tick;
      firing.utime = scene.utime;
      firing.firing_id = next_firing_id_++;
      if (!e.inputsReady(firing)) failures.push_back(e.name() + ": inputs not ready");
      const double start = threadCpuSeconds();
      const expert::Outcome outcome = e.fire(firing, bus);
      fire_seconds_[e.name()].push_back(threadCpuSeconds() - start);
      if (!outcome.ok) failures.push_back(e.name() + ": " + outcome.message);
    }
    for (const auto& [channel, bytes] : bus.published) deliver(channel, bytes);
  }
  return failures;
}

}  // namespace beft::bench
