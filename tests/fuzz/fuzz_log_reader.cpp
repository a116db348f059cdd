// The log reader on any bytes, every event then through the guard: it ends,
// without throwing, whatever the file holds.
#include "tests/fuzz/fuzz_input.hpp"
#include "lib/wire/log_reader.hpp"
#include "lib/wire/message_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  beft::fuzz::InputFile file(data, size, ".lcmlog");
  beft::wire::LogReader log(file.path());
  beft::wire::LogEvent event;
  while (log.next(event))
    beft::wire::MessageRules::beftTypes().checkForChannel(event.channel, event.data.data(), event.data.size());
  return 0;
}
