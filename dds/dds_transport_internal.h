// The pieces of the DDS transport, shared by dds_transport.cc (life cycle, routing),
// dds_endpoints.cc (readers and writers) and dds_discovery.cc (what remote endpoints say).
// Not part of the public API.
#pragma once

#include <atomic>
#include <chrono>
#include <deque>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/DataWriterListener.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "dds/dds_transport.h"
#include "dds/inbox.h"
#include "dds/shm_port_owners.h"
#include "dds/sim_clock.h"
#include "dds/topic_type.h"
#include "dds/wire_types.h"

namespace arbc::dds {

namespace fdds = eprosima::fastdds::dds;
using ReturnCode_t = eprosima::fastrtps::types::ReturnCode_t;
using eprosima::fastrtps::rtps::SampleIdentity;
using WireTime = eprosima::fastrtps::rtps::Time_t;

class DdsTransport;

// What the live status's writers announce in their USER_DATA (dds_status.cc): another arbc
// process leaves those topics out of what it has "seen in this domain" when it looks for the
// topic a user meant (a status topic of Base/cmd_vel is not a misspelt cmd_vel).
inline constexpr const char* kStatusUserData = "arbc-status";

// One topic this process reads: a source of connections mediated here (an output of a module
// hosted elsewhere) or the input of a hosted module that another process mediates.
class TopicReader : public fdds::DataReaderListener {
 public:
  TopicReader(DdsTransport* transport, const TransportPort& port, bool input, std::string topic,
              std::shared_ptr<const WireType> wire);
  ~TopicReader() override;

  // A decoded sample, with what it answers (an output) or who wrote it (an input).
  struct Buffered {
    Value value;
    uint64_t answered = 0;
    SampleIdentity identity;
  };

  // DDS threads: take every sample into the transport's inbox (dds/inbox.h).
  void on_data_available(fdds::DataReader* reader) override;
  void on_sample_lost(fdds::DataReader* reader, const fdds::SampleLostStatus& status) override;
  void on_subscription_matched(fdds::DataReader* reader,
                               const fdds::SubscriptionMatchedStatus& status) override;
  // A remote publisher DDS will not match for its QoS (best effort, say): reported.
  void on_requested_incompatible_qos(fdds::DataReader* reader,
                                     const fdds::RequestedIncompatibleQosStatus& status) override;
  // The executor thread: hands one sample from the inbox to the engine.
  void hand(const Buffered& b);
  // The executor thread: reports the samples counted lost or undecodable since the last call.
  void report_losses();

  const TransportPort port;
  const bool input;
  const std::string topic;
  const std::shared_ptr<const WireType> wire;
  fdds::DataReader* reader = nullptr;
  std::atomic<uint64_t> received{0}, lost{0}, undecodable{0};
  std::atomic<int> publishers{0};
  std::atomic<bool> ever_matched{false};  // a publisher matched at some time

 private:
  // Queues a decoded sample (or counts it lost: undecodable, or `depth` of this topic's
  // samples are in the inbox already).
  void buffer(Buffered b, bool bad, const std::string& why);
  // Counts `count` samples lost for `reason` with `detail` (mutex_ held), after those lost
  // before: each keeps its own reason and detail until report_losses hands them over.
  void count_loss(DropReason reason, const std::string& detail, uint64_t count);
  // Executor thread: says (once) that samples do not decode, with the first one's detail.
  void report_bad_type(const std::string& why);
  // Decodes one valid sample and buffers it.
  void take_one(WireSample& sample, const fdds::SampleInfo& info);
  DdsTransport* transport_;
  std::mutex take_mutex_;  // one taker at a time (DDS may call from several threads)
  WireSample* sample_ = nullptr;
  std::atomic<int> queued_{0};  // this topic's samples in the inbox
  std::mutex mutex_;            // guards losses_
  // Samples lost since the last report_losses, in the order they were lost; a run of samples
  // with one reason and one detail is one entry (a flood of one kind costs one entry).
  struct Loss {
    DropReason reason;
    std::string detail;
    uint64_t count = 0;
  };
  std::vector<Loss> losses_;
  bool bad_reported_ = false;  // executor thread: a sample that did not decode was reported
};

// One topic this process writes: an output of a hosted module, or the input of a module hosted
// elsewhere that a connection mediated here delivers to. Written on the executor thread.
class TopicWriter : public fdds::DataWriterListener {
 public:
  // `kept`: the samples a transient-local writer keeps for late subscribers (0 when volatile).
  TopicWriter(DdsTransport* transport, const TransportPort& port, bool input, std::string topic,
              std::shared_ptr<const WireType> wire, int kept);
  ~TopicWriter() override;
  // Writes v with `params` (in: the related sample; out: the sample's identity); false when
  // it could not (counted, reported once).
  bool write(const Value& v, eprosima::fastrtps::rtps::WriteParams& params);
  void on_publication_matched(fdds::DataWriter* writer,
                              const fdds::PublicationMatchedStatus& status) override;
  // A remote subscriber DDS will not match for its QoS (transient local, say): reported.
  void on_offered_incompatible_qos(fdds::DataWriter* writer,
                                   const fdds::OfferedIncompatibleQosStatus& status) override;

  const TransportPort port;
  const bool input;
  const std::string topic;
  const std::shared_ptr<const WireType> wire;
  fdds::DataWriter* writer = nullptr;
  // Written, of them while no subscriber had matched and not kept for one (they reach nobody),
  // failed.
  std::atomic<uint64_t> written{0}, to_nobody{0}, failed{0};
  std::atomic<int> subscribers{0};
  std::atomic<bool> ever_matched{false};  // a subscriber matched at some time

 private:
  // Executor thread: counts a sample written while no subscriber had matched, and says so the
  // first time in each stretch without one.
  void wrote_to_nobody();
  DdsTransport* transport_;
  WireSample* sample_ = nullptr;
  bool reported_ = false;
  // A write to nobody was reported since the last subscriber matched (the listener clears it).
  std::atomic<bool> nobody_reported_{false};
  const int kept_;
  // Writes since the last subscriber matched, while none had (the listener clears it).
  std::atomic<uint64_t> unmatched_writes_{0};
};

// Compares what remote endpoints announce with this process's topics.
class DiscoveryListener : public fdds::DomainParticipantListener {
 public:
  explicit DiscoveryListener(DdsTransport* transport) : transport_(transport) {}
  void on_publisher_discovery(fdds::DomainParticipant* participant,
                              eprosima::fastrtps::rtps::WriterDiscoveryInfo&& info) override;
  void on_subscriber_discovery(fdds::DomainParticipant* participant,
                               eprosima::fastrtps::rtps::ReaderDiscoveryInfo&& info) override;
  // A program started on the shared-memory ports of one that vanished is reported.
  void on_participant_discovery(fdds::DomainParticipant* participant,
                                eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override;

 private:
  DdsTransport* transport_;
  ShmPortOwners shm_ports_;
};

class DdsTransport : public Transport {
 public:
  DdsTransport(const model::App& app, DdsOptions options);
  ~DdsTransport() override;
  std::string name() const override { return "dds"; }
  bool open(const TransportPlan& plan, TransportSink* sink, std::string* error) override;
  void publish(int out, const Value& v) override;
  void deliver(int in, const Delivery& d) override;
  void start(const std::atomic<bool>* interrupt) override;
  void close() override;
  std::string summary() const override;
  TransportStatus status() const override;
  std::optional<Nanos> ros_time() const override {
    return sim_clock_ ? std::optional<Nanos>(sim_clock_->now()) : std::nullopt;
  }
  bool carries_status() const override { return diagnostics_ != nullptr; }
  void publish_status(Nanos t, Nanos stamp, const std::vector<PortStatus>& ports) override;

  // For the endpoints and the discovery listener.
  TransportSink& sink() { return *sink_; }
  bool closing() const { return closing_; }
  int depth() const { return options_.deployment.depth; }
  // Runs fn on the executor thread (from any thread); nothing once the transport closes.
  void post(std::function<void()> fn);
  // DDS threads: queues a sample of `reader` (no sample: its losses to report), in arrival
  // order across topics (dds/inbox.h).
  void to_inbox(TopicReader* reader, std::optional<TopicReader::Buffered> sample);
  // Reports `line` (from any thread) on the executor thread.
  void report(std::string line);
  // Deliveries not yet answered (docs/design.md#deliveries-not-yet-answered). DDS threads: how
  // many of this process's deliveries into modules hosted elsewhere a sample answers: those
  // up to the one it names as related (an arbc process names the last input sample it
  // received), else (a program without arbc) those written before its source timestamp.
  uint64_t answered(const fdds::SampleInfo& info);
  // Executor thread: a hosted module received the input sample `id`; the related sample every
  // output names from now on (none yet: `none`, which answers nothing).
  void received(const SampleIdentity& id) { last_received_ = id; }
  SampleIdentity related(const SampleIdentity& none) const {
    return last_received_ == SampleIdentity::unknown() ? none : last_received_;
  }
  // A remote endpoint on `topic` announced `type` (and, when it is arbc, its spec type in
  // `user_data`): reported once when it is not this process's type.
  void check_remote(const std::string& topic, const std::string& type, const std::string& user_data,
                    const char* what);
  // A remote publisher on `topic` (its USER_DATA `user_data`): reported once when this process
  // writes that topic as the mediator of a module hosted elsewhere, whose only publisher it must
  // be (two mediators, or a program not given a topic of its own, bypass the arbitration).
  void check_other_writer(const std::string& topic, const std::string& user_data);
  // Reports (once) that a remote writer, an arbc process or not, also publishes on the topic
  // of `port`, which this process mediates.
  void report_other_writer(const std::string& topic, const std::string& port, bool arbc);
  // DDS threads: a remote endpoint on `topic` (of `port`) that this process's reader (else
  // writer) does not match because of QoS `policy`: reported once per topic and policy
  // (dds/qos_mismatch.h), and named again by the no-peer reports.
  void report_qos_mismatch(const std::string& topic, const std::string& port, bool reader,
                           fdds::QosPolicyId_t policy);

 private:
  // A topic this process reads or writes, named before any DDS entity exists.
  struct Endpoint {
    TransportPort port;
    bool input = false;  // port is an input (else an output)
    bool reads = false;  // a reader (else a writer)
    std::string topic;
    std::shared_ptr<const WireType> wire;
  };
  bool create_participant(std::string* error);
  fdds::Topic* topic_for(const std::string& topic, const std::shared_ptr<const WireType>& wire,
                         std::string* error);
  bool add_reader(const Endpoint& e, std::string* error);
  bool add_writer(const Endpoint& e, std::string* error);
  // The wire type and topic of a port, checking that no two ports share a topic.
  // Whether the app connects this port, so that its topic expects a peer: an output some
  // connection reads, an input some connection delivers to.
  bool expects_peer(const TransportPort& port, bool input) const;
  // The topics read or written here whose peer is still missing (dds_discovery.cc).
  std::vector<std::string> topics_without_peers() const;
  // What to check when the topics `alone` have no peer: the domain, and remote topics seen that
  // look like them (same type or same last name), the likely typo (dds_discovery.cc).
  std::string peer_hint(const std::vector<std::string>& alone) const;
  // The connected topics that never had a peer (a topic that had one and lost it is reported
  // as it goes).
  std::vector<std::string> topics_never_matched() const;
  // Executor thread: reports the connected topics no peer has matched yet (a domain, a topic or
  // a type that differs from the programs' would otherwise leave the run silently idle), the
  // k-th time (dds/no_peer_reports.h: 10 s into the run, then at growing intervals), and posts
  // the next report while some remain.
  void report_unmatched(int k);
  // Posts the k-th report at its wall time since start().
  void post_unmatched_report(int k);
  double wall_seconds_since_start() const;
  bool wire_of(const TransportPort& port, std::string* topic, std::shared_ptr<const WireType>* wire,
               std::string* error);
  // The live status (dds_status.cc): a latched DiagnosticStatus topic per arbitrated port
  // mediated here and the DiagnosticArray of /diagnostics; false with *error when they cannot
  // be made.
  bool open_status(const TransportPlan& plan, std::string* error);
  fdds::DataWriter* status_writer(const std::string& topic,
                                  const std::shared_ptr<const WireType>& wire, bool latched,
                                  std::string* error);

  model::App app_;
  DdsOptions options_;
  TransportSink* sink_ = nullptr;
  std::unique_ptr<WireNaming> naming_;
  DiscoveryListener discovery_{this};
  fdds::DomainParticipant* participant_ = nullptr;
  fdds::Publisher* publisher_ = nullptr;
  fdds::Subscriber* subscriber_ = nullptr;
  std::unique_ptr<SimClock> sim_clock_;             // --use-sim-time: /clock, what age() reads
  std::map<std::string, fdds::TypeSupport> types_;  // registered, by DDS type name
  std::map<std::string, fdds::Topic*> topics_;      // by topic name
  std::map<std::string, std::string> type_of_topic_, port_of_topic_;
  std::vector<std::unique_ptr<TopicReader>> readers_;
  // Executor thread: hands over the oldest sample of the inbox, posting itself again while
  // more wait.
  void drain_inbox();
  struct Inbound {
    TopicReader* reader;
    std::optional<TopicReader::Buffered> sample;
  };
  Inbox<Inbound> inbox_;
  std::vector<std::unique_ptr<TopicWriter>> writers_;
  std::vector<TopicWriter*> output_writer_, input_writer_;  // by port index (null: none)
  std::vector<bool> output_mediated_, input_hosted_;
  std::atomic<bool> closing_{false};
  bool closed_ = false;
  std::chrono::steady_clock::time_point started_at_;  // when start() was called
  // Deliveries written into modules hosted elsewhere, not yet answered.
  struct Pending {
    eprosima::fastrtps::rtps::GUID_t writer;
    eprosima::fastrtps::rtps::SequenceNumber_t seq;
    uint64_t ticket = 0;  // 1 for the first delivery into a module elsewhere, 2, ...
    WireTime time;        // wall clock, as source timestamps are
    double at = 0;        // run time, as the runtime counts lifetimes
  };
  std::mutex acks_mutex_;  // guards sent_ and pending_
  uint64_t sent_ = 0;
  std::deque<Pending> pending_;   // in the order written
  double longest_lifetime_ = 0;   // of the app's events
  SampleIdentity last_received_;  // the last input sample a hosted module received
  mutable std::mutex mismatch_mutex_;
  std::set<std::string> mismatches_;      // reported lines
  std::set<std::string> qos_mismatched_;  // topics with a QoS mismatch, for peer_hint
  // Guarded by mismatch_mutex_ (add_writer fills the first while discovery runs):
  // topics written here as the mediator of a module hosted elsewhere -> its port;
  std::map<std::string, std::string> mediated_input_of_topic_;
  // remote topics that are not this process's -> their types (for peer_hint);
  std::map<std::string, std::string> seen_remote_;
  // topics remote processes publish on -> whether one of them is arbc.
  std::map<std::string, bool> remote_writers_;

  // The live status (dds_status.cc). Its types are named as ROS 2 names them, whatever the
  // deployment's "ros2" says, so they have a naming of their own.
  model::App status_app_;
  Deployment status_deployment_;
  std::unique_ptr<WireNaming> status_naming_;
  struct StatusTopic {
    std::string port, topic;
    fdds::DataWriter* writer = nullptr;
    Value last;  // what it last wrote: written again only when it changes
  };
  std::vector<StatusTopic> status_topics_;
  fdds::DataWriter* diagnostics_ = nullptr;
  Nanos diagnostics_at_ = -kNever;  // run time of the last /diagnostics write
  WireSample status_sample_;
  bool status_failed_ = false;  // a write of the status failed (reported once)
  std::shared_ptr<const WireType> status_wire_, array_wire_;
};

}  // namespace arbc::dds
