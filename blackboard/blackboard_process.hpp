// beft-blackboard as a service: keeps the history of everything published on
// the bus and answers late joiners' snapshot queries. Not an expert: it is
// never fired, it runs freely beside the system.
#pragma once

#include <string>
#include <vector>

#include <beft/bb_query_t.hpp>
#include <beft/bb_snapshot_t.hpp>
#include <beft/heartbeat_t.hpp>
#include <beft/run_status_t.hpp>

#include "blackboard/blackboard_service.hpp"
#include "lib/service/service.hpp"

namespace beft::blackboard {

class Traffic;  // what serve() does with the messages (blackboard_process.cpp)

class BlackboardProcess : public service::Service {
 public:
  std::string name() const override { return "blackboard"; }
  std::string description() const override;
  void addOptions(CLI::App& app) override;
  void onStartUp() override;
  int serve(service::Context& context) override;

 private:
  BlackboardService::Options options_;
  double max_channel_mb_ = static_cast<double>(options_.limits.max_channel_bytes) / (1 << 20);
  double status_period_ = 10.0;
  int queue_capacity_ = 2000;
  int batch_ms_ = 10;
  Traffic* traffic_ = nullptr;  // while serving
  bool arbiter_waiting_ = false;

  // A query wakes the process; the rest waits in the kernel for the next batch.
  service::ReadPort<beft::bb_query_t> queries_in_{*this, channels::kBlackboardQuery, "",
                                                  [this](beft::bb_query_t&& query) { onQuery(query); }};
  service::ReadPort<beft::run_status_t> run_status_in_{
      *this, channels::kRunStatus, "stored; an arbiter waiting for heartbeats is answered at once",
      [this](beft::run_status_t&& status) {
        if (status.state == beft::run_status_t::STATE_WAITING) arbiter_waiting_ = true;
      },
      service::Receiving().queued().alsoToEveryChannel()};
  service::EveryChannelPort stored_in_{*this, "every channel of the run but BB_QUERY and BB_SNAPSHOT_*",
                                       [this](const transport::Message& message) { store(message); },
                                       service::Receiving().queued(), &options_.exclude};
  service::AnswerWritePort<beft::bb_snapshot_t> answers_out_{*this, channels::kBlackboardSnapshotPrefix,
                                                             "the answer to a query"};
  service::WritePort<beft::heartbeat_t> heartbeat_out_{*this, channels::kHeartbeat, "every second"};

  void onQuery(const beft::bb_query_t& query);
  void store(const transport::Message& message);
};

}  // namespace beft::blackboard
