#include "dynamic_weighting.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beft::dw {

namespace {
// Weights equal to this precision count as unchanged (a saturated curve).
constexpr double kUnchangedEpsilon = 1e-9;
}  // namespace

CongruencyTable::CongruencyTable() {
  // The default pairs of the scenario format; a scenario may override them.
  set("person", "walking", 0.25);
  set("person", "idle", 0.25);
  set("person", "yelling", 0.75);
  set("fire", "burning", 0.5);
  set("fire", "spreading", 0.75);
  set("siren", "ringing", 0.5);
  set("car", "idle", 0.25);
}

void CongruencyTable::set(const std::string& label, const std::string& activity, double c) {
  if (!std::isfinite(c) || c < 0 || c > 1)
    throw std::invalid_argument("congruency of (" + label + ", " + activity +
                                ") must be in [0, 1], not " + std::to_string(c));
  values_[{label, activity}] = c;
}

double CongruencyTable::of(const std::string& label, const std::string& activity) const {
  const auto it = values_.find({label, activity});
  return it == values_.end() ? default_value_ : it->second;
}

DynamicWeighting::DynamicWeighting(DwParameters parameters, CongruencyTable table)
    : parameters_(parameters), table_(std::move(table)) {
  if (parameters_.t_max < 1) throw std::invalid_argument("t_max must be >= 1");
  if (!(parameters_.n > 1)) throw std::invalid_argument("n must be > 1");
  curve_parameters_.t_max = parameters_.t_max;
  curve_parameters_.n = parameters_.n;
}

const ObjectWeight* DynamicWeighting::find(const std::string& object_id) const {
  for (const auto& object : objects_)
    if (object.object_id == object_id) return &object;
  return nullptr;
}

double DynamicWeighting::curve(const ObjectWeight& object) const {
  // Eq. 4: the rising or the falling branch, t saturating at T_max.
  return object.rising ? model::weightRising(object.step, object.congruency, curve_parameters_)
                       : model::weightFalling(object.step, object.congruency, curve_parameters_);
}

double DynamicWeighting::advance(ObjectWeight& object, double pair_c) const {
  const bool pair_rises = pair_c >= parameters_.incongruent_c;
  if (pair_c > object.congruency) {
    // A more incongruent pair: jump to its c and start its curve.
    object.congruency = pair_c;
    object.rising = pair_rises;
    object.step = 1;
  } else if (pair_rises != object.rising) {
    // Back to a lower c (or, for a kept c, a change of direction): keep c and
    // start the curve the other way from it.
    object.rising = pair_rises;
    object.step = 1;
  } else {
    ++object.step;
  }
  double weight = curve(object);

  object.unchanged_steps =
      std::abs(weight - object.weight) < kUnchangedEpsilon ? object.unchanged_steps + 1 : 0;
  if (parameters_.reevaluate && object.unchanged_steps > parameters_.t_max) {
    // The weight has rested for more than T_max steps: reconsider c. Only a
    // different c or direction starts a new curve.
    object.unchanged_steps = 0;
    if (pair_c != object.congruency || pair_rises != object.rising) {
      object.congruency = pair_c;
      object.rising = pair_rises;
      object.step = 1;
      weight = curve(object);
    }
  }
  return weight;
}

std::vector<ReflexTrigger> DynamicWeighting::step(const std::vector<Stimulus>& sounding) {
  const int64_t step_index = steps_taken_++;
  for (auto& object : objects_) object.sounding = false;

  std::vector<ReflexTrigger> triggers;
  std::vector<std::pair<std::size_t, ReflexTrigger>> ordered;  // (first-heard rank, trigger)
  for (const auto& stimulus : sounding) {
    const double pair_c = table_.of(stimulus.label, stimulus.activity);
    auto it = std::find_if(objects_.begin(), objects_.end(), [&](const ObjectWeight& o) {
      return o.object_id == stimulus.object_id;
    });
    double before;
    if (it == objects_.end()) {
      // A newly heard object starts at the initial weight, not yet on a curve.
      ObjectWeight object;
      object.object_id = stimulus.object_id;
      object.weight = std::clamp(parameters_.initial_weight, 0.0, 1.0);
      object.congruency = pair_c;
      object.rising = pair_c >= parameters_.incongruent_c;
      object.step = 0;
      object.first_step = step_index;
      objects_.push_back(object);
      it = objects_.end() - 1;
      before = object.weight;
    } else {
      if (it->sounding) continue;  // listed twice in one step: the first counts
      before = it->weight;
      it->weight = std::clamp(advance(*it, pair_c), 0.0, 1.0);
    }
    it->sounding = true;
    it->label = stimulus.label;
    it->activity = stimulus.activity;
    it->x = stimulus.x;
    it->y = stimulus.y;
    const double threshold = parameters_.reflex_threshold;
    if (before < threshold && it->weight >= threshold)
      ordered.push_back({static_cast<std::size_t>(it - objects_.begin()),
                         ReflexTrigger{it->object_id, before, it->weight, it->x, it->y}});
  }
  std::sort(ordered.begin(), ordered.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& entry : ordered) triggers.push_back(std::move(entry.second));
  return triggers;
}

int64_t stepIndex(int64_t utime, int64_t step_us) {
  if (step_us <= 0) throw std::invalid_argument("DW step must be > 0");
  // Floor division that also holds for negative times.
  return utime >= 0 ? utime / step_us : -((-utime + step_us - 1) / step_us);
}

}  // namespace beft::dw
