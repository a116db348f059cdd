// The scenario loader on any bytes: a ScenarioError (or another documented
// error) for bad input, never a crash.
#include <sstream>
#include <stdexcept>

#include "tests/fuzz/fuzz_input.hpp"
#include "lib/scenario/load_scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  beft::fuzz::InputFile file(data, size, ".xml");
  std::ostringstream warnings;
  try {
    beft::scenario::loadScenario(file.path(), &warnings);
  } catch (const std::exception&) {
  }
  return 0;
}
