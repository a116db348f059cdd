#include "lib/expert/expert.hpp"

namespace beft::expert {

InputPortBase::InputPortBase(Expert& owner, const char* channel, std::string type)
    : channel_(channel), type_(std::move(type)) {
  owner.inputs_.push_back(this);
}

OutputPortBase::OutputPortBase(Expert& owner, const char* channel, std::string type)
    : channel_(channel), type_(std::move(type)) {
  owner.outputs_.push_back(this);
}

void Output::restrictTo(const std::vector<ChannelSpec>& declared) {
  declared_.clear();
  for (const auto& spec : declared) declared_.insert(spec.channel);
}

std::vector<ChannelSpec> Expert::reads() const {
  std::vector<ChannelSpec> specs;
  for (const auto* port : inputs_)
    if (port->isRead()) specs.push_back({port->channel(), port->type()});
  return specs;
}

std::vector<ChannelSpec> Expert::writes() const {
  std::vector<ChannelSpec> specs;
  for (const auto* port : outputs_) specs.push_back({port->channel(), port->type()});
  return specs;
}

const DeclaredParameters& Expert::parameters() {
  if (!parameters_) {
    parameters_ = std::make_unique<DeclaredParameters>();
    declareParameters(*parameters_);
  }
  return *parameters_;
}

void Expert::startUp(const Parameters& given) {
  parameters();
  parameters_->resetToDefaults();
  parameters_->setAll(given);
  for (auto* port : inputs_) port->setRead(true);
  onStartUp();
}

std::vector<std::string> Expert::inputsLacking(const Firing& firing) const {
  std::vector<std::string> lacking;
  for (const auto* port : inputs_)
    if (port->isRead() && port->lacksTick(firing.tick)) lacking.push_back(port->lackingChannel(firing.tick));
  return lacking;
}

bool Expert::inputsReady(const Firing& firing) const {
  for (const auto* port : inputs_)
    if (port->isRead() && port->lacksTick(firing.tick)) return false;
  return true;
}

bool Expert::onMessage(const std::string& channel, const void* data, int size) {
  for (auto* port : inputs_)
    if (port->isRead() && channel == port->channel()) return port->receive(data, size);
  return false;
}

}  // namespace beft::expert
