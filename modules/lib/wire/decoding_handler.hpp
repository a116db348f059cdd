// A handler of one message type behind the guard: received bytes are decoded
// (guarded_decode.hpp, a refusal counted under the channel) and only a whole
// message reaches the handler. An expert's HandledInput and a service's
// ReadPort both hand messages on through it.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <utility>

#include "lib/wire/guarded_decode.hpp"

namespace beft::wire {

template <typename Message>
class DecodingHandler {
 public:
  using Handler = std::function<void(Message&&)>;
  explicit DecodingHandler(Handler handler) : handler_(std::move(handler)) {}

  // False, and the handler not called, if the bytes are not exactly one valid Message.
  bool operator()(const std::string& channel, const void* data, std::size_t size) const {
    Message message{};
    if (!decodeFrom(channel, data, size, message)) return false;
    handler_(std::move(message));
    return true;
  }

 private:
  Handler handler_;
};

}  // namespace beft::wire
