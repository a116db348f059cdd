// beft-arbiter as a service: loads a PNML net and fires the experts it
// names, in lockstep ticks, until the run ends.
#pragma once

#include <string>
#include <vector>

#include "services/arbiter/arbiter_core.hpp"
#include "services/arbiter/arbiter_inbox.hpp"
#include "services/arbiter/lcm_arbiter.hpp"
#include "lib/service/service.hpp"

namespace beft::arbiter {

class ArbiterProcess : public service::Service {
 public:
  std::string name() const override { return "arbiter"; }
  std::string description() const override;
  ArbiterProcess();
  void addOptions(CLI::App& app) override;
  // Reads the net (std::invalid_argument with every problem, FILE:LINE).
  void onStartUp() override;
  int serve(service::Context& context) override;

 private:
  std::string net_path_;
  std::string firing_log_path_;
  ArbiterConfig config_;
  bool quiet_ = false;
  int spin_us_ = 1000;
  std::string pace_ = "fast";
  Net net_;
  ArbiterInbox inbox_;
  ArbiterOutlets outlets_;
};

}  // namespace beft::arbiter
