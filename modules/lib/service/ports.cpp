#include "lib/service/ports.hpp"


namespace beft::service {

namespace {

// The transport names a channel by run unless it is URL-wide: a port must
// say the same, or what --interface shows would not be what is taken.
void checkReach(const std::string& channel, Reach reach) {
  if (reach == Reach::kEveryRun) return;
  const bool url_wide = wire::isUrlWideChannel(channel);
  if (url_wide && reach != Reach::kUrlWide)
    throw std::logic_error("port on " + channel + ": a URL-wide channel, declare it Reach::kUrlWide");
  if (!url_wide && reach == Reach::kUrlWide)
    throw std::logic_error("port on " + channel + ": declared URL-wide, but channels are taken by run");
}

std::string withReach(std::string note, Reach reach) {
  const char* scope = reach == Reach::kUrlWide ? "URL-wide: every run" : reach == Reach::kEveryRun ? "every run" : "";
  if (*scope == '\0') return note;
  return note.empty() ? scope : note + "; " + scope;
}

}  // namespace

std::vector<const ReadPortBase*> PortSet::allReaders() const {
  std::vector<const ReadPortBase*> readers(readers_.begin(), readers_.end());
  for (const auto* part : parts_) {
    const auto more = part->allReaders();
    readers.insert(readers.end(), more.begin(), more.end());
  }
  return readers;
}

std::vector<Port> PortSet::reads() const {
  std::vector<Port> ports;
  for (const auto* reader : allReaders()) ports.push_back(reader->described());
  return ports;
}

std::vector<Port> PortSet::writes() const {
  std::vector<Port> ports;
  for (const auto* writer : writers_) ports.push_back(writer->described());
  for (const auto* part : parts_) {
    const auto more = part->writes();
    ports.insert(ports.end(), more.begin(), more.end());
  }
  return ports;
}

transport::Selection PortSet::selection(Delivery delivery) const {
  transport::Selection selection;
  std::vector<transport::Rule> named;
  for (const auto* reader : allReaders()) {
    if (reader->receiving().delivery != delivery) continue;
    if (reader->receiving().reach == Reach::kEveryRun) selection.every_run = true;
    const auto rules = reader->rules();
    if (reader->everyChannel()) {
      selection.mode = transport::Selection::Mode::RejectListed;
      selection.rules.insert(selection.rules.end(), rules.begin(), rules.end());
    } else {
      named.insert(named.end(), rules.begin(), rules.end());
    }
  }
  if (selection.mode == transport::Selection::Mode::AcceptListed) {
    selection.rules = std::move(named);
    return selection;
  }
  // Beside a port of every channel the named ones are taken anyway, whole:
  // a filter there would narrow nothing.
  for (const auto* reader : allReaders())
    if (reader->receiving().delivery == delivery && !reader->everyChannel() && !reader->receiving().rules.empty())
      throw std::logic_error("port on " + reader->channel() + ": a filter beside a port of every channel");
  return selection;
}

void PortSet::findReaders(std::string_view channel, const ReadPortBase*& named,
                          const ReadPortBase*& every_channel) const {
  for (const auto* reader : readers_) {
    if (reader->everyChannel()) {
      if (every_channel == nullptr) every_channel = reader;
    } else if (named == nullptr && channel == reader->channel()) {
      named = reader;
    }
  }
  for (const auto* part : parts_) part->findReaders(channel, named, every_channel);
}

bool PortSet::dispatch(const transport::Message& message) const {
  const ReadPortBase* named = nullptr;
  const ReadPortBase* every_channel = nullptr;
  findReaders(message.channel, named, every_channel);
  if (named == nullptr) return every_channel != nullptr && every_channel->receive(message);
  const bool taken = named->receive(message);
  if (named->receiving().also_to_every_channel && every_channel != nullptr) every_channel->receive(message);
  return taken;
}

ReadPortBase::ReadPortBase(PortSet& owner, std::string channel, std::string type, std::string note,
                           Receiving receiving)
    : channel_(std::move(channel)), type_(std::move(type)), note_(std::move(note)), receiving_(std::move(receiving)) {
  checkReach(channel_, receiving_.reach);
  owner.readers_.push_back(this);
}

Port ReadPortBase::described() const { return {channel_, type_, withReach(note_, receiving_.reach)}; }

std::vector<transport::Rule> ReadPortBase::rules() const {
  if (!receiving_.rules.empty()) return receiving_.rules;
  return {transport::channelRule(channel_)};
}

EveryChannelPort::EveryChannelPort(PortSet& owner, std::string note, Handler handler, Receiving receiving,
                                   const std::vector<std::string>* left_out)
    : ReadPortBase(owner, ".*", "any beft type", std::move(note), std::move(receiving)),
      handler_(std::move(handler)),
      left_out_(left_out) {}

Port EveryChannelPort::described() const {
  Port port = ReadPortBase::described();
  if (left_out_ == nullptr || left_out_->empty()) return port;
  std::string list;
  for (const auto& pattern : *left_out_) list += (list.empty() ? "" : ", ") + pattern;
  port.note += "; not " + list;
  return port;
}

std::vector<transport::Rule> EveryChannelPort::rules() const {
  std::vector<transport::Rule> rules;
  if (left_out_ == nullptr) return rules;
  for (const auto& pattern : *left_out_)
    if (transport::isPlainChannel(pattern)) rules.push_back(transport::channelRule(pattern));
  return rules;
}

bool EveryChannelPort::receive(const transport::Message& message) const {
  if (handler_) handler_(message);
  return true;
}

WritePortBase::WritePortBase(PortSet& owner, std::string channel, std::string type, std::string note, Reach reach)
    : channel_(std::move(channel)), type_(std::move(type)), note_(std::move(note)), reach_(reach) {
  checkReach(channel_, reach_);
  owner.writers_.push_back(this);
}

Port WritePortBase::described() const { return {channel_, type_, withReach(note_, reach_)}; }

}  // namespace beft::service
