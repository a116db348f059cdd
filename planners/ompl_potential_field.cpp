#include "planners/ompl_potential_field.hpp"

#include "planners/ompl_space.hpp"

#include <ompl/base/PlannerData.h>
#include <ompl/base/goals/GoalSampleableRegion.h>
#include <ompl/geometric/PathGeometric.h>

namespace beft::planners {

namespace ob = ompl::base;
namespace og = ompl::geometric;

PotentialFieldOmplPlanner::PotentialFieldOmplPlanner(const ob::SpaceInformationPtr& si,
                                                     std::shared_ptr<const PlanningMap> map,
                                                     PotentialFieldParams params, uint64_t first_seed)
    : ob::Planner(si, params.target == TargetPotential::Geodesic ? "PotentialFieldGeodesic" : "PotentialField"),
      map_(std::move(map)),
      planner_(params),
      next_seed_(first_seed) {
  specs_.approximateSolutions = false;
  specs_.optimizingPaths = false;
  specs_.multithreaded = false;
  // Every parameter, as declared, recorded by OMPL's benchmark log beside the
  // results and settable through OMPL's ParamSet (a new sigma re-blurs the map).
  planner_.params().declare(declared_);
  for (const auto& info : declared_.list()) {
    const std::string name = info.name;
    params_.declareParam<std::string>(
        name, [this, name](std::string value) { declared_.set(name, value); map_ready_ = false; },
        [this, name] { return declared_.current(name); });
  }
}

void PotentialFieldOmplPlanner::setup() {
  ob::Planner::setup();
  if (!map_ready_) {
    planner_.setup(map_);
    map_ready_ = true;
  }
}

void PotentialFieldOmplPlanner::clear() {
  ob::Planner::clear();
  last_path_.clear();
}

ob::PlannerStatus PotentialFieldOmplPlanner::solve(const ob::PlannerTerminationCondition& ptc) {
  checkValidity();
  if (!map_ready_) {
    planner_.setup(map_);
    map_ready_ = true;
  }
  const ob::State* start = pis_.nextStart();
  if (start == nullptr) return ob::PlannerStatus::INVALID_START;
  auto* goal_region = dynamic_cast<ob::GoalSampleableRegion*>(pdef_->getGoal().get());
  if (goal_region == nullptr || !goal_region->canSample()) return ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
  ob::ScopedState<> goal_state(si_);
  goal_region->sampleGoal(goal_state.get());

  planner_.setSeed(next_seed_++);
  const Deadline deadline = Deadline::never().orWhen([&ptc] { return ptc(); });
  const PlanResult result = planner_.solve(toPoint(start), toPoint(goal_state.get()), deadline);
  if (!result.success) {
    OMPL_INFORM("%s: %s", getName().c_str(), result.message.c_str());
    return ptc() ? ob::PlannerStatus::TIMEOUT : ob::PlannerStatus::ABORT;
  }
  last_path_ = result.path;
  auto path = std::make_shared<og::PathGeometric>(si_);
  ob::ScopedState<> state(si_);
  for (const Point2& p : result.path) {
    setState(state.get(), p);
    path->append(state.get());
  }
  pdef_->addSolutionPath(path, false, 0.0, getName());
  return ob::PlannerStatus::EXACT_SOLUTION;
}

void PotentialFieldOmplPlanner::getPlannerData(ob::PlannerData& data) const {
  ob::Planner::getPlannerData(data);
  ob::ScopedState<> a(si_), b(si_);
  for (size_t i = 1; i < last_path_.size(); ++i) {
    setState(a.get(), last_path_[i - 1]);
    setState(b.get(), last_path_[i]);
    data.addEdge(ob::PlannerDataVertex(a.get()), ob::PlannerDataVertex(b.get()));
  }
}

}  // namespace beft::planners
