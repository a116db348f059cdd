// The arbiter's PNML reader on any text: a NetError for what is not a net.
#include <stdexcept>
#include <string>

#include "pnml_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  try {
    beft::arbiter::readPnmlString(std::string(reinterpret_cast<const char*>(data), size), "fuzz.pnml");
  } catch (const std::exception&) {
  }
  return 0;
}
