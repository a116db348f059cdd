// beft-blackboard as a service: keeps the history of everything published on
// the bus and answers late joiners' snapshot queries. Not an expert: it is
// never fired, it runs freely beside the system.
#pragma once

#include <string>
#include <vector>

#include "blackboard/blackboard_service.hpp"
#include "lib/service/service.hpp"

namespace beft::blackboard {

class BlackboardProcess : public service::Service {
 public:
  std::string name() const override { return "blackboard"; }
  std::string description() const override;
  std::vector<service::Port> reads() const override;
  std::vector<service::Port> writes() const override;
  void addOptions(CLI::App& app) override;
  void onStartUp() override;
  int serve(service::Context& context) override;

 private:
  BlackboardService::Options options_;
  double max_channel_mb_ = static_cast<double>(options_.limits.max_channel_bytes) / (1 << 20);
  double status_period_ = 10.0;
  int queue_capacity_ = 2000;
  int batch_ms_ = 10;
};

}  // namespace beft::blackboard
