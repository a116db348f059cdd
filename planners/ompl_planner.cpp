#include "planners/ompl_planner.hpp"

#include "planners/ompl_space.hpp"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/planners/informedtrees/ABITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <functional>
#include <limits>
#include <map>
#include <stdexcept>

namespace beft::planners {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

using Allocator = std::function<ob::PlannerPtr(const ob::SpaceInformationPtr&)>;

const std::map<std::string, Allocator>& allocators() {
  static const std::map<std::string, Allocator> table = {
      {"RRTConnect", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::RRTConnect>(si); }},
      {"RRT", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::RRT>(si); }},
      {"RRTstar", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::RRTstar>(si); }},
      {"InformedRRTstar", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::InformedRRTstar>(si); }},
      {"BITstar", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::BITstar>(si); }},
      {"ABITstar", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::ABITstar>(si); }},
      {"PRM", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::PRM>(si); }},
      {"PRMstar", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::PRMstar>(si); }},
  };
  return table;
}

}  // namespace

std::vector<std::string> omplPlannerNames() {
  std::vector<std::string> names;
  for (const auto& entry : allocators()) names.push_back(entry.first);
  return names;
}

ob::PlannerPtr allocateOmplPlanner(const std::string& name, const ob::SpaceInformationPtr& si) {
  const auto it = allocators().find(name);
  if (it == allocators().end()) throw std::invalid_argument("unknown OMPL planner '" + name + "'");
  return it->second(si);
}

void seedOmpl(uint64_t seed) {
  ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
  ompl::RNG::setSeed(static_cast<std::uint_fast32_t>(seed & 0xffffffffu));
}

OmplPlanner::OmplPlanner(std::string ompl_name) : ompl_name_(std::move(ompl_name)) {
  if (allocators().count(ompl_name_) == 0) {
    throw std::invalid_argument("unknown OMPL planner '" + ompl_name_ + "'");
  }
  ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
}

void OmplPlanner::setupMap() {
  si_ = makeSpaceInformation(map_);
  planner_ = allocateOmplPlanner(ompl_name_, si_);
}

bool OmplPlanner::isAnytime() const {
  if (planner_) return planner_->getSpecs().optimizingPaths;
  // Not set up yet: ask a planner made on a throwaway space.
  auto space = std::make_shared<ompl::base::RealVectorStateSpace>(2);
  space->setBounds(0, 1);
  return allocateOmplPlanner(ompl_name_, std::make_shared<ompl::base::SpaceInformation>(space))
      ->getSpecs()
      .optimizingPaths;
}

void OmplPlanner::clear() {
  if (planner_) planner_->clear();
}

Path OmplPlanner::solvePath(Point2 start, Point2 goal, const Deadline& deadline, std::string& why_not) {
  ob::ScopedState<> start_state(si_->getStateSpace());
  ob::ScopedState<> goal_state(si_->getStateSpace());
  setState(start_state.get(), start);
  setState(goal_state.get(), goal);
  auto problem = std::make_shared<ob::ProblemDefinition>(si_);
  problem->setStartAndGoalStates(start_state, goal_state, 1e-6);
  auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(si_);
  // Any path satisfies an infinite threshold: optimising planners stop at their first.
  if (stop_at_first_) objective->setCostThreshold(ob::Cost(std::numeric_limits<double>::infinity()));
  problem->setOptimizationObjective(objective);

  planner_->clear();
  planner_->setProblemDefinition(problem);
  planner_->setup();
  const ob::PlannerTerminationCondition stop([&deadline] { return deadline.expired(); });
  const ob::PlannerStatus status = planner_->solve(stop);

  // Progress figures OMPL planners report about themselves, e.g. iterations.
  for (const auto& [property, read] : planner_->getPlannerProgressProperties()) {
    if (property.find("INTEGER") != std::string::npos || property.find("REAL") != std::string::npos) {
      try {
        stats_[property.substr(0, property.rfind(' '))] = std::stod(read());
      } catch (const std::exception&) {
        // "inf" or empty before a first solution: not a figure
      }
    }
  }
  if (status != ob::PlannerStatus::EXACT_SOLUTION || !problem->hasExactSolution()) {
    why_not = name() + ": " + (deadline.expired() ? "no exact solution before the deadline"
                                                  : "no exact solution (" + status.asString() + ")");
    return {};
  }
  og::PathGeometric path = *problem->getSolutionPath()->as<og::PathGeometric>();
  stats_["unsimplified_length"] = path.length();
  if (!planner_->getSpecs().optimizingPaths) {
    og::PathSimplifier simplifier(si_);
    const double budget = std::max(0.0, std::min(deadline.remainingSeconds(), 1.0));
    simplifier.simplify(path, budget);
  }
  Path out;
  for (const ob::State* state : path.getStates()) out.push_back(toPoint(state));
  if (out.empty() || distance(out.front(), start) > 1e-9) out.insert(out.begin(), start);
  if (distance(out.back(), goal) > 1e-9) out.push_back(goal);
  return out;
}

}  // namespace beft::planners
