#include "lib/petri/petri_net.hpp"

#include <algorithm>

namespace beft::arbiter {

const char* actionName(ExpiryAction action) {
  switch (action) {
    case ExpiryAction::Retry: return "retry";
    case ExpiryAction::Skip: return "skip";
    case ExpiryAction::Fail: return "fail";
  }
  return "?";
}

size_t Net::arcCount() const {
  size_t arcs = 0;
  for (const auto& t : transitions) arcs += t.inputs.size() + t.outputs.size();
  return arcs;
}

Marking Net::initialMarking() const {
  Marking marking(places.size(), 0);
  for (size_t i = 0; i < places.size(); ++i) marking[i] = places[i].initial_tokens;
  return marking;
}

std::vector<std::string> Net::experts() const {
  std::vector<std::string> names;
  for (const auto& transition : transitions) {
    if (transition.silent()) continue;
    if (std::find(names.begin(), names.end(), transition.expert) == names.end())
      names.push_back(transition.expert);
  }
  return names;
}

int Net::placeIndex(const std::string& place_id) const {
  for (size_t i = 0; i < places.size(); ++i)
    if (places[i].id == place_id) return static_cast<int>(i);
  return -1;
}

int Net::transitionIndex(const std::string& transition_id) const {
  for (size_t i = 0; i < transitions.size(); ++i)
    if (transitions[i].id == transition_id) return static_cast<int>(i);
  return -1;
}

bool isEnabled(const Transition& transition, const Marking& marking) {
  for (const auto& arc : transition.inputs)
    if (marking[arc.place] < arc.weight) return false;
  return true;
}

void consumeInputs(const Transition& transition, Marking& marking) {
  for (const auto& arc : transition.inputs) marking[arc.place] -= arc.weight;
}

void produceOutputs(const Transition& transition, Marking& marking) {
  for (const auto& arc : transition.outputs) marking[arc.place] += arc.weight;
}

std::string describeMarking(const Net& net, const Marking& marking) {
  std::string text;
  for (size_t i = 0; i < marking.size() && i < net.places.size(); ++i) {
    if (marking[i] == 0) continue;
    if (!text.empty()) text += ' ';
    text += net.places[i].id + "=" + std::to_string(marking[i]);
  }
  return text.empty() ? "empty" : text;
}

}  // namespace beft::arbiter
