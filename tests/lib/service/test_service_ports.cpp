// Service ports over LCM's in-process provider (memq://): declared once, they
// give the subscription (on the run's channel, or URL-wide on the bare
// name), decoding through the guard and --interface.
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <beft/done_t.hpp>
#include <beft/plan_result_t.hpp>
#include <beft/run_beacon_t.hpp>
#include <beft/run_status_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include "lib/common/channels.hpp"
#include "lib/service/service.hpp"
#include "lib/transport/control_messages.hpp"
#include "lib/transport/transport.hpp"
#include "lib/wire/reject_counter.hpp"
#include "lib/wire/run_identity.hpp"

using namespace beft;

namespace {

constexpr int64_t kRun = 0x1f3a;

// A service with one port of each kind; what its handlers got, kept.
class Listener : public service::Service {
 public:
  std::string name() const override { return "listener"; }
  std::string description() const override { return "test service"; }
  int serve(service::Context&) override { return 0; }

  std::vector<beft::done_t> dones;
  std::vector<beft::run_beacon_t> beacons;
  std::vector<std::string> stored;
  int statuses = 0;

  service::ReadPort<beft::done_t> done_in{*this, channels::kDone, "an expert finished",
                                          [this](beft::done_t&& done) { dones.push_back(done); }};
  service::ReadPort<beft::run_beacon_t> beacons_in{*this, channels::kRunBeacons, "other runs",
                                                   [this](beft::run_beacon_t&& b) { beacons.push_back(b); },
                                                   service::Receiving().urlWide()};
  service::ReadPort<beft::run_status_t> status_in{*this, channels::kRunStatus, "the run's state",
                                                 [this](beft::run_status_t&&) { ++statuses; },
                                                 service::Receiving().queued().alsoToEveryChannel()};
  service::EveryChannelPort everything_in{
      *this, "the rest", [this](const transport::Message& m) { stored.emplace_back(m.channel); },
      service::Receiving().queued(), &left_out};
  service::WritePort<beft::plan_result_t> results_out{*this, channels::kPlanResult, "answers"};
  service::WritePort<beft::run_beacon_t> beacons_out{*this, channels::kRunBeacons, "", service::Reach::kUrlWide};

  std::vector<std::string> left_out{"FIRE"};
};

class ServicePorts : public ::testing::Test {
 protected:
  void SetUp() override { wire::setRunId(kRun); }
  void TearDown() override { wire::setRunId(0); }

  // Everything published so far, handed to the listener's ports.
  void receiveAll(transport::Receiver& receiver) {
    ASSERT_GE(receiver.drain([this](const transport::Message& m) { listener.dispatch(m); }), 0);
  }

  lcm::LCM lcm{"memq://"};
  Listener listener;
};

beft::done_t doneOf(int64_t firing_id) {
  beft::done_t done{};
  done.expert = "vision";
  done.firing_id = firing_id;
  return done;
}

}  // namespace

TEST_F(ServicePorts, ADeclaredPortTakesItsChannelOnTheRunOnly) {
  ASSERT_TRUE(lcm.good());
  auto receiver = transport::openReceiver(lcm, "memq://", listener.selection(service::Delivery::kWakes));
  const auto mine = doneOf(1), bare = doneOf(2), other_run = doneOf(3);
  lcm.publish(wire::runChannel(channels::kDone), &mine);
  lcm.publish(channels::kDone, &bare);
  lcm.publish(wire::runChannel(channels::kDone, kRun + 1), &other_run);
  receiveAll(*receiver);
  ASSERT_EQ(listener.dones.size(), 1u);
  EXPECT_EQ(listener.dones[0].firing_id, 1);
  EXPECT_EQ(wire::runChannel(channels::kDone), "DONE@1f3a");
}

TEST_F(ServicePorts, AMalformedMessageIsRefusedAndCountedNeverHandled) {
  auto receiver = transport::openReceiver(lcm, "memq://", listener.selection(service::Delivery::kWakes));
  const auto before = wire::processRejects().totals()["DONE"];
  const auto good = doneOf(7);
  std::vector<uint8_t> bytes(good.getEncodedSize());
  good.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  const std::vector<uint8_t> cut(bytes.begin(), bytes.end() - 3);
  lcm.publish(wire::runChannel(channels::kDone), cut.data(), static_cast<unsigned>(cut.size()));
  std::vector<uint8_t> wrong_type = bytes;
  wrong_type[0] ^= 0xff;  // another fingerprint
  lcm.publish(wire::runChannel(channels::kDone), wrong_type.data(), static_cast<unsigned>(wrong_type.size()));
  receiveAll(*receiver);
  EXPECT_TRUE(listener.dones.empty());
  EXPECT_EQ(wire::processRejects().totals()["DONE"], before + 2);
}

TEST_F(ServicePorts, AUrlWidePortIsOnTheBareName) {
  auto receiver = transport::openReceiver(lcm, "memq://", listener.selection(service::Delivery::kWakes));
  beft::run_beacon_t beacon{};
  beacon.run_id = kRun + 5;
  beacon.host = "elsewhere";
  EXPECT_EQ(listener.beacons_out.wireName(), "BEFT_RUNS");
  EXPECT_EQ(listener.results_out.wireName(), "PLAN_RESULT@1f3a");
  listener.beacons_out.publish(lcm, beacon);
  receiveAll(*receiver);
  ASSERT_EQ(listener.beacons.size(), 1u);
  EXPECT_EQ(listener.beacons[0].host, "elsewhere");
}

TEST(ServicePortDeclarations, TheReachMustBeThatOfTheChannel) {
  Listener listener;
  using Beacons = service::WritePort<beft::run_beacon_t>;
  using Results = service::WritePort<beft::plan_result_t>;
  EXPECT_THROW(Beacons(listener, channels::kRunBeacons, "", service::Reach::kRun), std::logic_error);
  EXPECT_THROW(Results(listener, channels::kPlanResult, "", service::Reach::kUrlWide), std::logic_error);
}

TEST_F(ServicePorts, QueuedPortsAndTheirFiltersMakeTheOtherSelection) {
  const transport::Selection wakes = listener.selection(service::Delivery::kWakes);
  EXPECT_EQ(wakes.mode, transport::Selection::Mode::AcceptListed);
  ASSERT_EQ(wakes.rules.size(), 2u);
  EXPECT_EQ(wakes.rules[0].channel, "DONE");
  EXPECT_EQ(wakes.rules[1].channel, "BEFT_RUNS");
  const transport::Selection queued = listener.selection(service::Delivery::kQueued);
  EXPECT_EQ(queued.mode, transport::Selection::Mode::RejectListed) << "a port of every channel is among them";
  ASSERT_EQ(queued.rules.size(), 1u);
  EXPECT_EQ(queued.rules[0].channel, "FIRE");
  EXPECT_FALSE(queued.every_run);
}

TEST_F(ServicePorts, TheRestGoesToThePortOfEveryChannelAndAMarkedPortToo) {
  auto receiver = transport::openReceiver(lcm, "memq://", listener.selection(service::Delivery::kQueued));
  const auto waiting = control::makeRunStatus(beft::run_status_t::STATE_WAITING, 0, 0, "");
  const beft::plan_result_t result{};
  const auto fire = control::makeFire("vision", "t_vision", 0, 0, 1);
  lcm.publish(wire::runChannel(channels::kRunStatus), &waiting);
  lcm.publish(wire::runChannel(channels::kPlanResult), &result);
  lcm.publish(wire::runChannel(channels::kFire), &fire);  // left out
  receiveAll(*receiver);
  EXPECT_EQ(listener.statuses, 1);
  EXPECT_EQ(listener.stored, (std::vector<std::string>{"RUN_STATUS", "PLAN_RESULT"}));
}

// Takes only the RUN_STATUS messages of an arbiter that waits.
class WaitingWatch : public service::PortSet {
 public:
  std::vector<int8_t> states;
  service::ReadPort<beft::run_status_t> waiting_in{
      *this, channels::kRunStatus, "", [this](beft::run_status_t&& s) { states.push_back(s.state); },
      service::Receiving().only(control::runStatusIn(beft::run_status_t::STATE_WAITING, "waiting"))};
};

TEST_F(ServicePorts, AFilteredPortTakesOnlyTheMessagesItsRulesMatch) {
  WaitingWatch watch;
  const transport::Selection selection = watch.selection(service::Delivery::kWakes);
  ASSERT_EQ(selection.rules.size(), 1u);
  EXPECT_FALSE(selection.rules[0].field.empty()) << "the state byte is matched";
  auto receiver = transport::openReceiver(lcm, "memq://", selection);
  for (const int8_t state : {beft::run_status_t::STATE_RUNNING, beft::run_status_t::STATE_WAITING}) {
    const auto status = control::makeRunStatus(state, 0, 0, "");
    lcm.publish(wire::runChannel(channels::kRunStatus), &status);
  }
  ASSERT_GE(receiver->drain([&watch](const transport::Message& m) { watch.dispatch(m); }), 0);
  EXPECT_EQ(watch.states, std::vector<int8_t>{beft::run_status_t::STATE_WAITING});
}

TEST(ServicePortDeclarations, AFilterBesideAPortOfEveryChannelIsRefused) {
  struct Confused : service::PortSet {
    service::ReadPort<beft::run_status_t> waiting_in{
        *this, channels::kRunStatus, "", [](beft::run_status_t&&) {},
        service::Receiving().queued().only(control::runStatusIn(beft::run_status_t::STATE_WAITING, "waiting"))};
    service::EveryChannelPort rest_in{*this, "", nullptr, service::Receiving().queued()};
  } confused;
  EXPECT_THROW(confused.selection(service::Delivery::kQueued), std::logic_error);
  EXPECT_NO_THROW(confused.selection(service::Delivery::kWakes));
}

TEST(ServiceInterface, ListsExactlyTheDeclaredPorts) {
  Listener listener;
  EXPECT_EQ(service::interfaceText(listener, "listener"),
            "process: listener\n"
            "reads:\n"
            "  DONE  (beft.done_t, an expert finished)\n"
            "  BEFT_RUNS  (beft.run_beacon_t, other runs; URL-wide: every run)\n"
            "  RUN_STATUS  (beft.run_status_t, the run's state)\n"
            "  .*  (any beft type, the rest; not FIRE)\n"
            "writes:\n"
            "  PLAN_RESULT  (beft.plan_result_t, answers)\n"
            "  BEFT_RUNS  (beft.run_beacon_t, URL-wide: every run)\n");
}
