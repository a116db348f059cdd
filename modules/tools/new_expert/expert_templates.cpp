#include "tools/new_expert/expert_templates.hpp"

#include <stdexcept>

namespace beft::new_expert::templates {

const char* const kExpertCMakeLists = R"(# The {{name}} expert ({{level}} level): the class + its process {{program}}.
add_library(beft_expert_{{name}} STATIC {{name}}_expert.cpp)
target_link_libraries(beft_expert_{{name}} PUBLIC beft_expert beft_common beft_lcmtypes)

add_executable({{program}} main.cpp)
target_link_libraries({{program}} PRIVATE beft_expert_{{name}} beft_expert)
)";

const char* const kMain = R"(// {{program}}: the {{name}} expert process (see --help).
#include {{own_header}}
#include "lib/expert/run_expert.hpp"

int main(int argc, char** argv) {
  beft::{{name}}::{{class}} expert;
  return beft::expert::runExpertMain(argc, argv, expert);
}
)";

const char* const kHeader = R"(// The {{name}} expert as a process ({{level}} level), made by ./beft new expert.
// Reads, by tick: {{reads_list}}
// Writes: {{writes_list}}
// On FIRE for tick k, once its inputs of tick k have arrived, it publishes on
// every output a message stamped with tick k, at ticks that are a multiple of
// every_n_ticks: fire() is where what the expert computes goes.
#pragma once

#include <string>
{{message_includes}}
#include "lib/expert/expert.hpp"
{{port_includes}}
namespace beft::{{name}} {

class {{class}} : public expert::Expert {
 public:
  std::string name() const override { return "{{name}}"; }
  std::string description() const override;
  expert::Outcome fire(const expert::Firing& firing, expert::Output& out) override;

 protected:
  void declareParameters(DeclaredParameters& parameters) override;

 private:
  int every_n_ticks_ = 1;  // publish at ticks that are a multiple of this only
{{ports}}};

}  // namespace beft::{{name}}
)";

const char* const kSource = R"(#include {{own_header}}

#include <string>

namespace beft::{{name}} {

std::string {{class}}::description() const {
  return "{{level_word}}-level expert {{name}}. Reads, by tick: {{reads_list}}. "
         "Writes: {{writes_list}}. On FIRE for tick k, once its inputs of tick k have arrived, publishes on "
         "every output a message stamped with tick k, at ticks that are a multiple of every_n_ticks.";
}

void {{class}}::declareParameters(DeclaredParameters& parameters) {
  parameters.declare("every_n_ticks", every_n_ticks_, 1, 1000000, "publish at ticks that are a multiple of this only");
}

expert::Outcome {{class}}::fire(const expert::Firing& firing, expert::Output& out) {
{{input_checks}}  if (firing.tick % every_n_ticks_ != 0) return expert::Outcome::success();
{{publishing}}  return expert::Outcome::success();
}

}  // namespace beft::{{name}}
)";

const char* const kTestCMakeLists = R"(# The {{name}} expert class without LCM.
add_executable(test_{{name}}_expert test_{{name}}_expert.cpp)
target_link_libraries(test_{{name}}_expert PRIVATE beft_expert_{{name}} beft_expert_test_support GTest::gtest_main)
gtest_discover_tests(test_{{name}}_expert)
)";

const char* const kTest = R"(// The {{name}} expert class without LCM: it waits for its inputs of the
// fired tick, publishes on every output ({{writes_list}}) a message stamped
// with that tick, and every_n_ticks leaves the ticks between out.
#include <gtest/gtest.h>

#include <stdexcept>

#include {{own_header}}
#include "tests/experts/support/expert_harness.hpp"

namespace beft::{{name}} {
namespace {

using testing_support::CollectingOutput;
using testing_support::deliver;
using testing_support::firing;

// Every input of the tick, stamped with the tick and its time.
void deliverInputs({{class}}& expert, int64_t tick) {
{{deliveries}}}

// How many messages the firing of `tick` published, each checked.
std::size_t checkPublished(const CollectingOutput& out, int64_t tick) {
  std::size_t count = 0;
{{expectations}}  return count;
}

TEST({{class}}, PublishesEveryOutputStampedWithTheFiredTick) {
  {{class}} expert;
  expert.startUp();
  deliverInputs(expert, 3);
  ASSERT_TRUE(expert.inputsReady(firing("{{name}}", 3)));
  CollectingOutput out;
  const expert::Outcome outcome = expert.fire(firing("{{name}}", 3), out);
  EXPECT_TRUE(outcome.ok) << outcome.message;
  EXPECT_EQ(checkPublished(out, 3), {{write_count}}u);
  EXPECT_EQ(out.published.size(), {{write_count}}u);
}

TEST({{class}}, EveryNTicksLeavesTheTicksBetweenOut) {
  {{class}} expert;
  expert.startUp({{"every_n_ticks", "2"}});
  CollectingOutput out;
  deliverInputs(expert, 3);
  EXPECT_TRUE(expert.fire(firing("{{name}}", 3), out).ok);
  EXPECT_TRUE(out.published.empty());
  deliverInputs(expert, 4);
  EXPECT_TRUE(expert.fire(firing("{{name}}", 4), out).ok);
  EXPECT_EQ(checkPublished(out, 4), {{write_count}}u);
}

TEST({{class}}, RefusesAParameterOutOfItsRange) {
  {{class}} expert;
  EXPECT_THROW(expert.startUp({{"every_n_ticks", "0"}}), std::invalid_argument);
  EXPECT_THROW(expert.startUp({{"no_such_parameter", "1"}}), std::invalid_argument);
}
{{input_tests}}
}  // namespace
}  // namespace beft::{{name}}
)";

const char* const kMessageType = R"(package beft;

// Output of the {{name}} expert (channel {{channel}}).
struct {{type}}
{
    int64_t utime;          // simulated time [us]
    int64_t tick;           // tick index, >= 0 [-]
}
)";

std::string fill(const std::string& text, const std::map<std::string, std::string>& values) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t open = text.find("{{"); open != std::string::npos; open = text.find("{{", at)) {
    const std::size_t close = text.find("}}", open);
    const std::string key = close == std::string::npos ? "" : text.substr(open + 2, close - open - 2);
    out += text.substr(at, open - at);
    if (key.empty() || key.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") != std::string::npos) {
      out += "{{";  // not a hole: C++ braces such as {{"every_n_ticks", "2"}} stay as written
      at = open + 2;
      continue;
    }
    const auto value = values.find(key);
    if (value == values.end()) throw std::logic_error("template hole {{" + key + "}} has no value");
    out += value->second;
    at = close + 2;
  }
  return out + text.substr(at);
}

}  // namespace beft::new_expert::templates
