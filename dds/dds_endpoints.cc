// The DDS transport's readers and writers: QoS, samples <-> values, the buffer between DDS's
// threads and the executor, and what they count.
#include <fastrtps/types/DynamicDataFactory.h>

#include "core/join.h"
#include "dds/cdr_write.h"
#include "dds/dds_transport_internal.h"
#include "dds/wire_values.h"
#include "runtime/executor.h"

namespace arbc::dds {

namespace {

// What `arbc` endpoints announce in their USER_DATA: the port's spec type, so that two arbc
// processes that disagree on a type under one name find out at discovery.
std::vector<eprosima::fastrtps::rtps::octet> user_data(const WireType& wire) {
  std::string text = "arbc-type=" + wire.type->to_string();
  return {text.begin(), text.end()};
}

// Reliable, volatile, keep-last `depth`: what ROS 2's default profile is, with a deeper history
// (dds/deployment.h says why), unless the deployment gives the port best effort or transient
// local (the QoS of the program at the other end). Payloads grow as needed: types are unbounded.
template <class Qos>
void set_common_qos(Qos& qos, int depth, const WireType& wire, const PortQos& port) {
  qos.reliability().kind =
      port.best_effort ? fdds::BEST_EFFORT_RELIABILITY_QOS : fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind =
      port.transient_local ? fdds::TRANSIENT_LOCAL_DURABILITY_QOS : fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = depth;
  qos.endpoint().history_memory_policy =
      eprosima::fastrtps::rtps::PREALLOCATED_WITH_REALLOC_MEMORY_MODE;
  qos.user_data().data_vec(user_data(wire));
}

WireSample* new_sample(const WireType& wire) {
  auto* s = new WireSample;
  s->data =
      eprosima::fastrtps::types::DynamicDataFactory::get_instance()->create_data(wire.dynamic);
  return s;
}

void delete_sample(WireSample* s) {
  if (!s) return;
  eprosima::fastrtps::types::DynamicDataFactory::get_instance()->delete_data(s->data);
  delete s;
}

}  // namespace

// --- DdsTransport: creating endpoints ------------------------------------------------------

bool DdsTransport::add_reader(const Endpoint& e, std::string* error) {
  fdds::Topic* t = topic_for(e.topic, e.wire, error);
  if (!t) return false;
  auto r = std::make_unique<TopicReader>(this, e.port, e.input, e.topic, e.wire);
  fdds::DataReaderQos qos = subscriber_->get_default_datareader_qos();
  set_common_qos(qos, depth(), *e.wire, options_.deployment.qos_of(e.port.qualified));
  fdds::StatusMask mask = fdds::StatusMask::data_available()
                          << fdds::StatusMask::sample_lost()
                          << fdds::StatusMask::subscription_matched()
                          << fdds::StatusMask::requested_incompatible_qos();
  r->reader = subscriber_->create_datareader(t, qos, r.get(), mask);
  if (!r->reader) {
    *error = "DDS: cannot create a reader on topic " + e.topic;
    return false;
  }
  readers_.push_back(std::move(r));
  return true;
}

bool DdsTransport::add_writer(const Endpoint& e, std::string* error) {
  fdds::Topic* t = topic_for(e.topic, e.wire, error);
  if (!t) return false;
  const PortQos& port_qos = options_.deployment.qos_of(e.port.qualified);
  auto w = std::make_unique<TopicWriter>(this, e.port, e.input, e.topic, e.wire,
                                         port_qos.transient_local ? depth() : 0);
  fdds::DataWriterQos qos = publisher_->get_default_datawriter_qos();
  set_common_qos(qos, depth(), *e.wire, port_qos);
  w->writer = publisher_->create_datawriter(t, qos, w.get(),
                                            fdds::StatusMask::publication_matched()
                                                << fdds::StatusMask::offered_incompatible_qos());
  if (!w->writer) {
    *error = "DDS: cannot create a writer on topic " + e.topic;
    return false;
  }
  (e.input ? input_writer_ : output_writer_)[static_cast<size_t>(e.port.index)] = w.get();
  if (e.input) {  // the mediator of a module elsewhere: its only publisher (dds_discovery.cc)
    std::optional<bool> other_arbc;
    {
      std::lock_guard<std::mutex> lock(mismatch_mutex_);
      mediated_input_of_topic_[e.topic] = e.port.qualified;
      if (auto it = remote_writers_.find(e.topic); it != remote_writers_.end())
        other_arbc = it->second;
    }
    if (other_arbc) report_other_writer(e.topic, e.port.qualified, *other_arbc);
  }
  writers_.push_back(std::move(w));
  return true;
}

// --- TopicReader -----------------------------------------------------------------------------

TopicReader::TopicReader(DdsTransport* transport, const TransportPort& port, bool input,
                         std::string topic, std::shared_ptr<const WireType> wire)
    : port(port),
      input(input),
      topic(std::move(topic)),
      wire(std::move(wire)),
      transport_(transport),
      sample_(new_sample(*this->wire)) {}

TopicReader::~TopicReader() { delete_sample(sample_); }

// Takes exactly the samples DDS counts as unread, one at a time (a loaned batch `take` cost
// more here). Never "take until there is no data": in Fast-DDS 2.9 a take that finds nothing
// walks the whole reader history, and after a lost sample that history holds every later sample
// until the repair comes, hundreds during a burst. That last, empty take cost about 1 ms per
// call, slowed this (receive) thread, which lost more samples: docs/benchmarks.md, the DDS
// section, has the figures.
void TopicReader::on_data_available(fdds::DataReader* r) {
  std::lock_guard<std::mutex> take(take_mutex_);
  fdds::SampleInfo info;
  for (uint64_t n = r->get_unread_count(); n > 0 && !transport_->closing();
       n = r->get_unread_count()) {
    for (; n > 0; --n) {
      if (r->take_next_sample(sample_, &info) != ReturnCode_t::RETCODE_OK) return;
      if (info.valid_data) take_one(*sample_, info);  // else a lifecycle notice
    }
  }
}

void TopicReader::take_one(WireSample& sample, const fdds::SampleInfo& info) {
  ++received;
  Buffered b;
  std::string why;
  bool bad = sample.bad;
  if (bad && sample.extra_bytes > 0) {
    why = "a sample on " + topic + " has " + std::to_string(sample.extra_bytes) +
          " bytes more than " + wire->name + " as the spec declares it";
  } else if (bad) {
    why = "a sample on " + topic + " does not decode as " + wire->name;
  } else {
    b.value = std::move(sample.value);
  }
  if (input) {
    b.identity = info.sample_identity;
  } else if (!bad) {
    b.answered = transport_->answered(info);
  }
  buffer(std::move(b), bad, why);
}

void TopicReader::buffer(Buffered b, bool bad, const std::string& why) {
  if (!bad && queued_.load() < transport_->depth()) {
    ++queued_;
    transport_->to_inbox(this, std::move(b));
    return;
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (bad) {
      ++undecodable;
      count_loss(DropReason::BadType, why, 1);
    } else {
      ++lost;
      count_loss(DropReason::QueueFull,
                 "DDS: " + topic + ": this process's queue of the topic's samples was full (" +
                     std::to_string(transport_->depth()) + ", the deployment's depth)",
                 1);
    }
  }
  transport_->to_inbox(this, std::nullopt);
}

void TopicReader::count_loss(DropReason reason, const std::string& detail, uint64_t count) {
  if (!losses_.empty() && losses_.back().reason == reason && losses_.back().detail == detail) {
    losses_.back().count += count;
  } else {
    losses_.push_back({reason, detail, count});
  }
}

// Samples DDS reports lost before they reached this reader: a gap in the writer's sequence
// numbers, which this process cannot tell apart (Fast-DDS 2.9 gives only a count): a sample the
// network lost, one that came after a later one (a best-effort reader drops it), or one the
// writer's keep-last history dropped before sending it. Never this process's own queue.
void TopicReader::on_sample_lost(fdds::DataReader*, const fdds::SampleLostStatus& status) {
  if (status.total_count_change <= 0) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    lost += static_cast<uint64_t>(status.total_count_change);
    count_loss(DropReason::LostInTransit,
               "DDS: " + topic +
                   ": DDS reports samples lost before they reached this process (lost or "
                   "reordered on the network, or dropped by the writer)",
               static_cast<uint64_t>(status.total_count_change));
  }
  transport_->to_inbox(this, std::nullopt);
}

// What a mediated output's silence does here: its rules get nothing, and the events its
// monitors set are not refreshed (each lapses by its lifetime, if it has one).
static std::string silence_effect(const TransportPort& port) {
  std::string effect;
  if (!port.connections.empty())
    effect = join(port.connections) + " get" + (port.connections.size() == 1 ? "s" : "") +
             " nothing until one is back";
  if (!port.events.empty())
    effect += std::string(effect.empty() ? "" : "; ") + join(port.events) +
              (port.events.size() == 1 ? " is" : " are") + " no longer refreshed and lapse" +
              (port.events.size() == 1 ? "s" : "") + " by " +
              (port.events.size() == 1 ? "its lifetime" : "their lifetimes");
  return effect.empty() ? "nothing here reads it" : effect;
}

void TopicReader::on_subscription_matched(fdds::DataReader*,
                                          const fdds::SubscriptionMatchedStatus& status) {
  publishers = status.current_count;
  if (status.current_count_change > 0 && status.current_count == 1 && ever_matched) {
    transport_->report("DDS: topic " + topic + ": a publisher is back; traffic resumes");
  }
  if (status.current_count_change > 0) ever_matched = true;
  if (status.current_count_change < 0 && status.current_count == 0) {
    transport_->report(
        "DDS: topic " + topic + " (" + port.qualified + ") has no publisher any more; " +
        (input ? "nothing reaches the module until one is back" : silence_effect(port)));
  }
}

void TopicReader::on_requested_incompatible_qos(
    fdds::DataReader*, const fdds::RequestedIncompatibleQosStatus& status) {
  if (status.total_count_change > 0)
    transport_->report_qos_mismatch(topic, port.qualified, true, status.last_policy_id);
}

void TopicReader::report_losses() {
  std::vector<Loss> losses;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::swap(losses, losses_);
  }
  TransportSink& sink = transport_->sink();
  for (const Loss& loss : losses) {
    sink.lost(input, port.index, loss.reason, loss.count, loss.detail);
    if (loss.reason == DropReason::BadType) report_bad_type(loss.detail);
  }
}

// Said once, when it first happens: the counters alone show it only at the end of the run.
// A program without arbc in it announces no spec type, so this is the first sign that its
// type has the name this process expects and another layout.
void TopicReader::report_bad_type(const std::string& why) {
  if (bad_reported_) return;
  bad_reported_ = true;
  transport_->sink().report(
      "DDS: topic " + topic + " (" + port.qualified + "): " + why +
      "; the remote program's type has this name but other fields, or another order: give " +
      port.qualified +
      "'s type in the spec the program's fields, in the program's order "
      "(docs/distributed.md#types-on-the-wire); until then every sample is dropped as bad-type");
}

void TopicReader::hand(const Buffered& b) {
  --queued_;
  TransportSink& sink = transport_->sink();
  if (input) {
    // Before the module sees it: what it publishes from now on answers this sample.
    transport_->received(b.identity);
    sink.to_module(port.index,
                   Delivery{port.port, b.value, topic, topic, seconds_of(sink.executor().now())});
  } else {
    sink.from_source(port.index, b.value, b.answered);
  }
}

// --- TopicWriter -----------------------------------------------------------------------------

TopicWriter::TopicWriter(DdsTransport* transport, const TransportPort& port, bool input,
                         std::string topic, std::shared_ptr<const WireType> wire, int kept)
    : port(port),
      input(input),
      topic(std::move(topic)),
      wire(std::move(wire)),
      transport_(transport),
      sample_(new_sample(*this->wire)),
      kept_(kept) {}

TopicWriter::~TopicWriter() { delete_sample(sample_); }

bool TopicWriter::write(const Value& v, eprosima::fastrtps::rtps::WriteParams& params) {
  std::string error;
  if (cdr_write(*wire->type, v, &sample_->bytes, &error) && writer->write(sample_, params)) {
    ++written;
    if (subscribers.load() == 0) wrote_to_nobody();
    return true;
  }
  ++failed;
  if (!reported_) {
    reported_ = true;
    transport_->sink().report("DDS: topic " + topic + ": a message could not be written" +
                              (error.empty() ? "" : " (" + error + ")") +
                              "; such failures are counted in the summary");
  }
  return false;
}

// DDS accepted the sample, but no reader had matched: it reaches nobody, although the runtime
// counts the connection's delivery (issue 39: a restarted mediator "delivered" 1,486 commands
// before the base's subscriber matched). Counted apart and said, in the summary and here. A
// transient-local writer keeps its last `kept_` samples for a subscriber that joins later: only
// the writes that push one out of that history reach nobody.
void TopicWriter::wrote_to_nobody() {
  if (unmatched_writes_.fetch_add(1) < static_cast<uint64_t>(kept_)) return;
  ++to_nobody;
  if (nobody_reported_.exchange(true)) return;
  transport_->sink().report("DDS: topic " + topic + " (" + port.qualified +
                            "): written with no subscriber matched " +
                            (ever_matched ? "(since the last one left)" : "(none yet)") + ": " +
                            (input ? port.module + " does not receive it" : "nobody receives it") +
                            (kept_ ? " (beyond the last " + std::to_string(kept_) +
                                         " the writer keeps for a late subscriber)"
                                   : "") +
                            "; such writes are counted as 'to nobody' in the summary");
}

void TopicWriter::on_publication_matched(fdds::DataWriter*,
                                         const fdds::PublicationMatchedStatus& status) {
  subscribers = status.current_count;
  if (status.current_count_change > 0) {
    ever_matched = true;
    nobody_reported_ = false;
    unmatched_writes_ = 0;
  }
  if (input && status.current_count_change < 0 && status.current_count == 0) {
    transport_->report("DDS: topic " + topic + " (" + port.qualified +
                       ") has no subscriber any more: the process that hosts " + port.module +
                       " is gone; what is delivered to it is lost until it is back");
  }
}

void TopicWriter::on_offered_incompatible_qos(fdds::DataWriter*,
                                              const fdds::OfferedIncompatibleQosStatus& status) {
  if (status.total_count_change > 0)
    transport_->report_qos_mismatch(topic, port.qualified, false, status.last_policy_id);
}

}  // namespace arbc::dds
