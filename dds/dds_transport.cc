// The DDS transport's life cycle (participant, topics, endpoints; deletion) and routing.
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>

#include "dds/dds_transport_internal.h"
#include "dds/participant_qos.h"
#include "runtime/executor.h"

namespace arbc::dds {

std::unique_ptr<Transport> make_dds_transport(const model::App& app, DdsOptions options) {
  return std::make_unique<DdsTransport>(app, std::move(options));
}

DdsTransport::DdsTransport(const model::App& app, DdsOptions options)
    : app_(app), options_(std::move(options)) {
  for (const model::Event& e : app_.events) {
    if (e.lifetime) longest_lifetime_ = std::max(longest_lifetime_, seconds_of(*e.lifetime));
  }
}

DdsTransport::~DdsTransport() { close(); }

// Routes each port whose other end may run elsewhere through a topic (dds/dds_transport.h).
// Every topic and type is named before the participant exists, so that the discovery listener
// (DDS threads) only ever reads complete maps.
bool DdsTransport::open(const TransportPlan& plan, TransportSink* sink, std::string* error) {
  sink_ = sink;
  // `arbc run` checks the file before it makes the transport, with the file's lines quoted;
  // this is for programs that link the transport themselves.
  if (std::vector<Diagnostic> problems; !check_deployment(options_.deployment, app_, &problems)) {
    *error = deployment_errors_text(problems);
    return false;
  }
  naming_ = std::make_unique<WireNaming>(app_, options_.deployment);
  output_writer_.assign(plan.outputs.size(), nullptr);
  input_writer_.assign(plan.inputs.size(), nullptr);
  output_mediated_.assign(plan.outputs.size(), false);
  input_hosted_.assign(plan.inputs.size(), false);
  std::vector<Endpoint> endpoints;
  for (const TransportPort& p : plan.outputs) {
    output_mediated_[static_cast<size_t>(p.index)] = p.mediated;
    if (p.hosted || p.mediated) endpoints.push_back({p, false, !p.hosted, {}, {}});
  }
  for (const TransportPort& p : plan.inputs) {
    input_hosted_[static_cast<size_t>(p.index)] = p.hosted;
    if (p.hosted != p.mediated) endpoints.push_back({p, true, p.hosted, {}, {}});
  }
  for (Endpoint& e : endpoints) {
    if (!wire_of(e.port, &e.topic, &e.wire, error)) return false;
  }
  if (!create_participant(error)) return false;
  for (const Endpoint& e : endpoints) {
    if (!(e.reads ? add_reader(e, error) : add_writer(e, error))) return false;
  }
  if (options_.use_sim_time) {
    sim_clock_ = std::make_unique<SimClock>();
    if (!sim_clock_->open(participant_, subscriber_, error)) return false;
  }
  if (options_.status && options_.deployment.status && !open_status(plan, error)) return false;
  return true;
}

// The participant's QoS: the user's profile, then arbc's settings over it (dds/participant_qos.h).
bool DdsTransport::create_participant(std::string* error) {
  fdds::DomainParticipantQos qos;
  std::string note;
  if (!participant_qos({"arbc " + app_.name, options_.domain, options_.lease_seconds}, &qos, &note,
                       error)) {
    return false;
  }
  if (!note.empty()) sink_->report(note);
  fdds::DomainParticipantFactory* factory = fdds::DomainParticipantFactory::get_instance();
  fdds::StatusMask mask = fdds::StatusMask::none();  // endpoint events go to their own listeners
  participant_ = factory->create_participant(options_.domain, qos, &discovery_, mask);
  if (!participant_) {
    *error = "DDS: cannot create a participant in domain " + std::to_string(options_.domain) +
             " (Fast-DDS said why above; check FASTRTPS_DEFAULT_PROFILES_FILE and the domain)";
    return false;
  }
  publisher_ = participant_->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
  subscriber_ = participant_->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  if (!publisher_ || !subscriber_) {
    *error = "DDS: cannot create a publisher and a subscriber";
    return false;
  }
  return true;
}

bool DdsTransport::wire_of(const TransportPort& port, std::string* topic,
                           std::shared_ptr<const WireType>* wire, std::string* error) {
  *topic = naming_->topic(port.qualified);
  auto [it, fresh] = port_of_topic_.emplace(*topic, port.qualified);
  if (!fresh) {
    *error = "DDS: ports " + it->second + " and " + port.qualified + " would both be on topic " +
             *topic + "; give one another topic in the deployment file's \"topics\"";
    return false;
  }
  *wire = naming_->port_type(port.module, port.port, port.type, error);
  if (!*wire) {
    *error = "DDS: port " + port.qualified + ": " + *error;
    return false;
  }
  type_of_topic_[*topic] = (*wire)->name;
  return true;
}

fdds::Topic* DdsTransport::topic_for(const std::string& topic,
                                     const std::shared_ptr<const WireType>& wire,
                                     std::string* error) {
  if (!types_.count(wire->name)) {
    fdds::TypeSupport support(new WireTopicType(wire));
    if (support.register_type(participant_) != ReturnCode_t::RETCODE_OK) {
      *error = "DDS: cannot register type " + wire->name;
      return nullptr;
    }
    types_.emplace(wire->name, support);
  }
  fdds::Topic* t = participant_->create_topic(topic, wire->name, fdds::TOPIC_QOS_DEFAULT);
  if (!t) *error = "DDS: cannot create topic " + topic + " of type " + wire->name;
  topics_[topic] = t;
  return t;
}

void DdsTransport::publish(int out, const Value& v) {
  if (output_mediated_[static_cast<size_t>(out)])
    sink_->from_source(out, v, TransportSink::kAnswersAll);
  if (TopicWriter* w = output_writer_[static_cast<size_t>(out)]) {
    SampleIdentity none;  // "received nothing yet": this writer, sequence number 0
    none.writer_guid(w->writer->guid()).sequence_number({});
    eprosima::fastrtps::rtps::WriteParams params;
    params.related_sample_identity(related(none));
    w->write(v, params);
  }
}

// Into a module hosted elsewhere: written, and pending until answered. A write that failed
// is answered at once (nothing reached the module).
void DdsTransport::deliver(int in, const Delivery& d) {
  if (input_hosted_[static_cast<size_t>(in)]) {
    sink_->to_module(in, d);
    return;
  }
  TopicWriter* w = input_writer_[static_cast<size_t>(in)];
  eprosima::fastrtps::rtps::WriteParams params;
  WireTime time;
  WireTime::now(time);
  bool written = w && w->write(d.value, params);
  std::lock_guard<std::mutex> lock(acks_mutex_);
  ++sent_;
  // The runtime forgets a delivery once every event's lifetime has passed since it
  // (runtime/answered_deliveries.cc); so does this, or a module that never speaks would
  // make the list grow for ever.
  while (!pending_.empty() && pending_.front().at + longest_lifetime_ < d.time)
    pending_.pop_front();
  if (written) {
    const SampleIdentity& id = params.sample_identity();
    pending_.push_back({id.writer_guid(), id.sequence_number(), sent_, time, d.time});
  }
}

// An arbc process handles its inputs in the order they reach it, which is the order they
// were written here as long as samples on two topics do not overtake each other: a related
// sample answers every delivery written up to it (docs/distributed.md#known-limits). The
// reasoning is about the process that published the sample, whichever of its modules did:
// the runtime also counts the message being judged as an answer.
uint64_t DdsTransport::answered(const fdds::SampleInfo& info) {
  std::lock_guard<std::mutex> lock(acks_mutex_);
  const SampleIdentity& related = info.related_sample_identity;
  if (related == SampleIdentity::unknown()) {
    // Written in time order: those before the sample's source timestamp are a prefix.
    while (!pending_.empty() && pending_.front().time <= info.source_timestamp)
      pending_.pop_front();
  } else {
    uint64_t upto = 0;
    for (const Pending& p : pending_) {
      if (p.writer == related.writer_guid() && p.seq <= related.sequence_number()) upto = p.ticket;
    }
    while (!pending_.empty() && pending_.front().ticket <= upto) pending_.pop_front();
  }
  return pending_.empty() ? sent_ : pending_.front().ticket - 1;
}

void DdsTransport::post(std::function<void()> fn) {
  if (closing_ || !sink_) return;
  Executor& ex = sink_->executor();
  ex.post(ex.now(), [this, fn = std::move(fn)] {
    if (!closing_) fn();
  });
}

void DdsTransport::to_inbox(TopicReader* reader, std::optional<TopicReader::Buffered> sample) {
  if (inbox_.push({reader, std::move(sample)})) post([this] { drain_inbox(); });
}

void DdsTransport::drain_inbox() {
  bool more = false;
  Inbound in = inbox_.take(&more);
  if (in.sample) {
    in.reader->hand(*in.sample);
  } else {
    in.reader->report_losses();
  }
  // Posted after the runtime's tasks for this sample: they run before the next one.
  if (more) post([this] { drain_inbox(); });
}

void DdsTransport::report(std::string line) {
  post([this, line = std::move(line)] { sink_->report(line); });
}

// Deletes every DDS entity (remote peers see this process's endpoints go at once). Called at
// shutdown; after it no DDS thread reaches the runtime.
void DdsTransport::close() {
  if (closed_) return;
  closed_ = true;
  closing_ = true;
  if (!participant_) return;
  for (auto& r : readers_) r->reader->set_listener(nullptr);
  for (auto& w : writers_) w->writer->set_listener(nullptr);
  if (sim_clock_) sim_clock_->close();
  participant_->delete_contained_entities();
  fdds::DomainParticipantFactory::get_instance()->delete_participant(participant_);
  participant_ = nullptr;
}

TransportStatus DdsTransport::status() const {
  TransportStatus status;
  status.domain = options_.domain;
  for (const auto& r : readers_) {
    TransportTopicStatus t;
    t.topic = r->topic, t.port = r->port.qualified, t.type = r->wire->name, t.read = true;
    t.heard_peer = r->ever_matched, t.peers_now = r->publishers;
    t.expects_peer = expects_peer(r->port, r->input);
    t.received = r->received, t.lost = r->lost, t.undecodable = r->undecodable;
    status.topics.push_back(std::move(t));
  }
  for (const auto& w : writers_) {
    TransportTopicStatus t;
    t.topic = w->topic, t.port = w->port.qualified, t.type = w->wire->name, t.read = false;
    t.heard_peer = w->ever_matched, t.peers_now = w->subscribers;
    t.expects_peer = expects_peer(w->port, w->input);
    t.written = w->written, t.to_nobody = w->to_nobody, t.failed = w->failed;
    status.topics.push_back(std::move(t));
  }
  std::lock_guard<std::mutex> lock(mismatch_mutex_);
  status.notes.assign(mismatches_.begin(), mismatches_.end());
  return status;
}

std::string DdsTransport::summary() const {
  TransportStatus status = this->status();
  size_t read = 0;
  for (const auto& t : status.topics) read += t.read;
  std::string out = "dds: domain " + std::to_string(status.domain) + ", " + std::to_string(read) +
                    " topic(s) read, " + std::to_string(status.topics.size() - read) + " written\n";
  for (const auto& t : status.topics) {
    if (t.read) {
      out += "  read  " + t.topic + " (" + t.type + "): " + std::to_string(t.received) +
             " received, " + std::to_string(t.lost) + " lost, " + std::to_string(t.undecodable) +
             " undecodable\n";
    } else {
      out +=
          "  wrote " + t.topic + " (" + t.type + "): " + std::to_string(t.written) + " written" +
          (t.to_nobody ? ", " + std::to_string(t.to_nobody) + " to nobody (no subscriber)" : "") +
          (t.failed ? ", " + std::to_string(t.failed) + " failed" : "") + "\n";
    }
  }
  // What a run left alone says at the end too: a report long ago on stderr is easy to miss.
  // A topic both read and written is named once.
  std::string never;
  std::set<std::string> named;
  for (const auto& t : status.topics) {
    if (t.heard_peer || !t.expects_peer || !named.insert(t.topic).second) continue;
    bool heard_otherwise = false;
    for (const auto& u : status.topics) heard_otherwise |= u.topic == t.topic && u.heard_peer;
    if (heard_otherwise) continue;
    never += (never.empty() ? "" : ", ") + t.topic + " (" + t.port + ")";
  }
  if (!never.empty()) out += "  never heard a peer: " + never + "\n";
  for (const std::string& m : status.notes) out += "  " + m + "\n";
  if (sim_clock_) out += "  " + sim_clock_->summary() + "\n";
  return out;
}

}  // namespace arbc::dds
