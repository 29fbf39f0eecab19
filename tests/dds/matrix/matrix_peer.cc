// A plain Fast-DDS program (no arbc in it) for the interop matrix: the types are fastddsgen's,
// from the IDL gen_types.py writes (matrix_types.h lists them). Two modes:
//   matrix_peer pub DOMAIN FILE   reads lines `INDEX HEX` (a serialized sample of type INDEX),
//                                 turns each into its fastddsgen type and publishes it on
//                                 rt/in/mINDEX, printing `sent INDEX HEX` of the sample as its
//                                 own type serializes it;
//   matrix_peer sub DOMAIN LINGER TIMEOUT
//                                 prints `got INDEX HEX` for each sample received on
//                                 rt/out/mINDEX, serialized by its own type; stops LINGER seconds
//                                 after the last sample (TIMEOUT with none).
// The driver (matrix.py) compares the lines: the bytes must be equal.
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

#include "interop_participant.h"
#include "matrixPubSubTypes.h"
#include "matrix_types.h"

namespace {

namespace fdds = eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::SerializedPayload_t;
using eprosima::fastrtps::types::ReturnCode_t;

std::string hex(const SerializedPayload_t& p) {
  static const char* digits = "0123456789abcdef";
  std::string out;
  for (uint32_t i = 0; i < p.length; ++i) {
    out += digits[p.data[i] >> 4];
    out += digits[p.data[i] & 15];
  }
  return out;
}

// One message type of the matrix: its topics, and its samples to and from bytes.
struct Channel {
  virtual ~Channel() = default;
  int index = 0;
  const char* name = "";
  fdds::DataWriter* writer = nullptr;
  fdds::DataReader* reader = nullptr;
  virtual fdds::TypeSupport type() = 0;
  virtual bool publish(const std::string& hex_bytes) = 0;  // prints `sent`
  virtual bool take() = 0;                                 // prints `got`
};

template <class T, class PubSub>
struct TypedChannel : Channel {
  PubSub codec;
  fdds::TypeSupport type() override { return fdds::TypeSupport(new PubSub()); }
  std::string bytes_of(T& sample) {
    SerializedPayload_t p(codec.getSerializedSizeProvider(&sample)());
    if (!codec.serialize(&sample, &p)) return "";
    return hex(p);
  }
  bool publish(const std::string& h) override {
    SerializedPayload_t p(static_cast<uint32_t>(h.size() / 2));
    for (size_t i = 0; i < h.size() / 2; ++i)
      p.data[i] = static_cast<unsigned char>(std::stoi(h.substr(2 * i, 2), nullptr, 16));
    p.length = static_cast<uint32_t>(h.size() / 2);
    T sample;
    if (!codec.deserialize(&p, &sample)) {
      std::fprintf(stderr, "matrix_peer: sample of %s does not deserialize\n", name);
      return false;
    }
    std::printf("sent %d %s\n", index, bytes_of(sample).c_str());
    std::fflush(stdout);
    return writer->write(&sample);
  }
  bool take() override {
    T sample;
    fdds::SampleInfo info;
    if (reader->take_next_sample(&sample, &info) != ReturnCode_t::RETCODE_OK) return false;
    if (info.valid_data) {
      std::printf("got %d %s\n", index, bytes_of(sample).c_str());
      std::fflush(stdout);
    }
    return true;
  }
};

std::vector<std::unique_ptr<Channel>> channels(fdds::DomainParticipant* p) {
  std::vector<std::unique_ptr<Channel>> out;
#define ARBC_MATRIX_CHANNEL(i, text, T, PS)               \
  out.push_back(std::make_unique<TypedChannel<T, PS>>()); \
  out.back()->index = i;                                  \
  out.back()->name = text;
  ARBC_MATRIX_TYPES(ARBC_MATRIX_CHANNEL)
#undef ARBC_MATRIX_CHANNEL
  for (auto& c : out) c->type().register_type(p);
  return out;
}

fdds::Topic* topic(fdds::DomainParticipant* p, const char* dir, const Channel& c) {
  std::string name = std::string("rt/") + dir + "/m" + std::to_string(c.index);
  return p->create_topic(name, c.name, fdds::TOPIC_QOS_DEFAULT);
}

int publish(int domain, const char* file) {
  fdds::DomainParticipant* p = interop::plain_participant(domain, "matrix_pub");
  auto all = channels(p);
  fdds::Publisher* pub = p->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  fdds::DataWriterQos qos = pub->get_default_datawriter_qos();
  interop::reliable(qos);
  qos.history().depth = 10;
  for (auto& c : all) c->writer = pub->create_datawriter(topic(p, "in", *c), qos);
  for (auto& c : all) {
    if (!interop::matched(c->writer)) {
      std::fprintf(stderr, "matrix_peer: no reader of rt/in/m%d (%s)\n", c->index, c->name);
      return 3;
    }
  }
  std::ifstream in(file);
  int index = 0;
  std::string bytes;
  while (in >> index >> bytes) {
    if (index < 0 || index >= static_cast<int>(all.size()) || !all[index]->publish(bytes)) return 4;
    // One sample in flight per type at a time: the subscriber's history never overflows.
    all[index]->writer->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(30, 0));
  }
  for (auto& c : all) c->writer->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(30, 0));
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return 0;
}

int subscribe(int domain, double linger, double timeout) {
  fdds::DomainParticipant* p = interop::plain_participant(domain, "matrix_sub");
  auto all = channels(p);
  fdds::Subscriber* sub = p->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  fdds::DataReaderQos qos = sub->get_default_datareader_qos();
  interop::reliable(qos);
  for (auto& c : all) c->reader = sub->create_datareader(topic(p, "out", *c), qos);
  std::fprintf(stderr, "matrix_peer: listening\n");
  interop::take_until_quiet(
      [&] {
        bool took = false;
        for (auto& c : all) took = c->take() || took;
        return took;
      },
      linger, timeout);
  p->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(p);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "pub" && argc == 4) return publish(std::atoi(argv[2]), argv[3]);
  if (mode == "sub" && argc == 5)
    return subscribe(std::atoi(argv[2]), std::atof(argv[3]), std::atof(argv[4]));
  std::fprintf(stderr, "usage: matrix_peer pub DOMAIN FILE | sub DOMAIN LINGER TIMEOUT\n");
  return 2;
}
