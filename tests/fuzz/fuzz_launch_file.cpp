// The launch-file reader on any bytes: a LaunchError naming the line.
#include <stdexcept>

#include "tests/fuzz/fuzz_input.hpp"
#include "lib/launch/launch_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  beft::fuzz::InputFile file(data, size, ".launch.xml");
  try {
    beft::launch::loadLaunchFile(file.path(), {});
  } catch (const std::exception&) {
  }
  return 0;
}
