// The geometry expert as a process (low level): stores GT_OBJECTS and
// ROBOT_STATE, and on FIRE for tick k publishes GEOMETRY for tick k.
#pragma once

#include <beft/robot_state_t.hpp>
#include <beft/scene_objects_t.hpp>

#include "expert.hpp"
#include "tick_channel.hpp"

namespace beft::geometry {

class GeometryExpert : public expert::Expert {
 public:
  std::string name() const override { return "geometry"; }
  std::string description() const override;
  std::vector<expert::ChannelSpec> reads() const override;
  std::vector<expert::ChannelSpec> writes() const override;
  bool onMessage(const std::string& channel, const void* data, int size) override;
  bool inputsReady(const expert::Firing& firing) const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 private:
  expert::TickChannel<scene_objects_t> scene_;
  expert::TickChannel<robot_state_t> robot_;
};

}  // namespace beft::geometry
