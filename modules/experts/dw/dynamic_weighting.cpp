#include "experts/dw/dynamic_weighting.hpp"

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

void DynamicWeighting::startCurve(ObjectWeight& object, double c) const {
  object.congruency = c;
  object.rising = c >= parameters_.incongruent_c;
  object.step = 1;
}

double DynamicWeighting::advance(ObjectWeight& object, std::optional<double> c) const {
  const double incongruent = parameters_.incongruent_c;
  const bool on_incongruent_curve = object.congruency >= incongruent;
  double weight = object.weight;
  if (c && *c >= incongruent) {
    // An incongruent stimulus: jump to its curve (w = 0.75), or go on rising.
    if (object.rising && on_incongruent_curve) ++object.step;
    else startCurve(object, *c);
    object.was_incongruent = true;
    weight = curve(object);
  } else if (object.rising) {
    // The incongruent stimulus stopped (another activity, or silence): a
    // falling curve with c kept, from 0.75 down to the residual.
    object.rising = false;
    object.step = 1;
    weight = curve(object);
  } else if (on_incongruent_curve) {
    ++object.step;  // still falling to the residual, heard or not
    weight = curve(object);
  } else if (!c) {
    return weight;  // silent, never incongruent: keeps its weight
  } else {
    // A congruent object: a falling curve, with the new c when its sound is
    // novel; a falling curve never lifts the weight.
    if (*c != object.congruency) startCurve(object, *c);
    else ++object.step;
    weight = std::min(weight, curve(object));
  }
  if (object.was_incongruent) weight = std::max(weight, parameters_.residual_floor);

  if (!c) return weight;
  object.unchanged_steps = std::abs(weight - object.weight) < kUnchangedEpsilon ? object.unchanged_steps + 1 : 0;
  if (parameters_.reevaluate && object.unchanged_steps > parameters_.t_max) {
    // The weight has rested for more than T_max steps: reconsider c. Only a
    // different c or direction starts a new curve, within the floor.
    object.unchanged_steps = 0;
    const bool rises = *c >= incongruent;
    if (*c != object.congruency || rises != object.rising) {
      startCurve(object, *c);
      weight = rises ? curve(object) : std::min(weight, curve(object));
      if (object.was_incongruent) weight = std::max(weight, parameters_.residual_floor);
    }
  }
  return weight;
}

void DynamicWeighting::markEndangered() {
  for (auto& object : objects_) object.endangered = false;
  if (parameters_.danger_radius <= 0) return;
  const double radius2 = parameters_.danger_radius * parameters_.danger_radius;
  for (const auto& hazard : objects_) {
    const bool hazard_label = std::find(parameters_.danger_labels.begin(), parameters_.danger_labels.end(),
                                        hazard.label) != parameters_.danger_labels.end();
    if (!hazard_label || table_.of(hazard.label, hazard.activity) < parameters_.incongruent_c) continue;
    for (auto& object : objects_) {
      if (&object == &hazard || object.label != parameters_.endangered_label) continue;
      const double dx = object.x - hazard.x, dy = object.y - hazard.y;
      if (dx * dx + dy * dy <= radius2) object.endangered = true;
    }
  }
}

std::vector<ReflexTrigger> DynamicWeighting::step(const std::vector<Stimulus>& sounding) {
  const int64_t step_index = steps_taken_++;
  for (auto& object : objects_) object.sounding = false;

  // What is heard now: the pair and position of every sounding object; a
  // newly heard one starts at the initial weight, not yet on a curve.
  std::vector<bool> is_new;
  for (const auto& stimulus : sounding) {
    auto it = std::find_if(objects_.begin(), objects_.end(),
                           [&](const ObjectWeight& o) { return o.object_id == stimulus.object_id; });
    if (it == objects_.end()) {
      ObjectWeight object;
      object.object_id = stimulus.object_id;
      object.weight = std::clamp(parameters_.initial_weight, 0.0, 1.0);
      object.congruency = table_.of(stimulus.label, stimulus.activity);
      object.rising = object.congruency >= parameters_.incongruent_c;
      object.first_step = step_index;
      objects_.push_back(object);
      it = objects_.end() - 1;
      is_new.resize(objects_.size(), false);
      is_new.back() = true;
    } else if (it->sounding) {
      continue;  // listed twice in one step: the first counts
    }
    it->sounding = true;
    it->label = stimulus.label;
    it->activity = stimulus.activity;
    it->x = stimulus.x;
    it->y = stimulus.y;
  }
  is_new.resize(objects_.size(), false);
  markEndangered();

  // Every known object steps, in the order first heard.
  std::vector<ReflexTrigger> triggers;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    ObjectWeight& object = objects_[i];
    if (is_new[i]) continue;
    std::optional<double> c;
    if (object.sounding) c = table_.of(object.label, object.activity);
    if (object.endangered) c = std::max(c.value_or(0.0), parameters_.incongruent_c);
    const double before = object.weight;
    object.weight = std::clamp(advance(object, c), 0.0, 1.0);
    const double threshold = parameters_.reflex_threshold;
    if (before < threshold && object.weight >= threshold)
      triggers.push_back(ReflexTrigger{object.object_id, before, object.weight, object.x, object.y});
  }
  return triggers;
}

int64_t stepIndex(int64_t utime, int64_t step_us) {
  if (step_us <= 0) throw std::invalid_argument("DW step must be > 0");
  // Floor division that also holds for negative times.
  return utime >= 0 ? utime / step_us : -((-utime + step_us - 1) / step_us);
}

}  // namespace beft::dw
