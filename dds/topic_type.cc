#include "dds/topic_type.h"

#include <fastrtps/types/DynamicDataFactory.h>

#include <cstring>

#include "dds/cdr_read.h"

namespace arbc::dds {

namespace ft = eprosima::fastrtps::types;

WireTopicType::WireTopicType(std::shared_ptr<const WireType> wire)
    : wire_(std::move(wire)), codec_(wire_->dynamic) {
  setName(wire_->name.c_str());
  // Unbounded strings and sequences: no useful maximum. Payloads start at this size and grow
  // (the endpoints use a reallocating memory policy).
  m_typeSize = 512;
  m_isGetKeyDefined = false;
  // Matching is by type name, as ROS 2 does; no TypeObject is built for dynamic types.
  auto_fill_type_object(false);
  auto_fill_type_information(false);
}

bool WireTopicType::serialize(void* data, eprosima::fastrtps::rtps::SerializedPayload_t* payload) {
  auto* sample = static_cast<WireSample*>(data);
  if (!sample->bytes.empty()) {
    // The size provider reserved this much; a payload from a pool may be larger.
    if (payload->max_size < sample->bytes.size()) return false;
    std::memcpy(payload->data, sample->bytes.data(), sample->bytes.size());
    payload->length = static_cast<uint32_t>(sample->bytes.size());
    payload->encapsulation = sample->bytes[1] == 1 ? CDR_LE : CDR_BE;
    return true;
  }
  try {
    return codec_.serialize(sample->data, payload);
  } catch (...) {  // Fast-DDS throws ReturnCode values and fastcdr exceptions
    return false;
  }
}

// Reads the bytes into sample->value (dds/cdr_read.h), not into the dynamic data, which cost a
// LaserScan a hundred times more (docs/benchmarks.md "ROS 2 messages").
bool WireTopicType::deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload,
                                void* data) {
  auto* sample = static_cast<WireSample*>(data);
  sample->extra_bytes = 0;
  CdrRead r = cdr_read(*wire_->type, payload->data, payload->length, &sample->value);
  sample->bad = !r.ok;
  // A struct with more fields than the spec's decodes as its first fields and the rest is
  // ignored: the mediator would pass on a shorter message, which the program's subscribers
  // drop without a trace. Up to 3 bytes are the padding a writer may add to a multiple of 4.
  if (r.ok && payload->length > r.used + 3) {
    sample->extra_bytes = payload->length - r.used;
    sample->bad = true;
  }
  return true;
}

std::function<uint32_t()> WireTopicType::getSerializedSizeProvider(void* data) {
  auto* sample = static_cast<WireSample*>(data);
  if (!sample->bytes.empty()) {
    uint32_t size = static_cast<uint32_t>(sample->bytes.size());
    return [size] { return size; };
  }
  return codec_.getSerializedSizeProvider(sample->data);
}

void* WireTopicType::createData() {
  auto* sample = new WireSample;
  sample->data = ft::DynamicDataFactory::get_instance()->create_data(wire_->dynamic);
  return sample;
}

void WireTopicType::deleteData(void* data) {
  auto* sample = static_cast<WireSample*>(data);
  ft::DynamicDataFactory::get_instance()->delete_data(sample->data);
  delete sample;
}

bool WireTopicType::getKey(void*, eprosima::fastrtps::rtps::InstanceHandle_t*, bool) {
  return false;  // keyless topics, as ROS 2 messages are
}

}  // namespace arbc::dds
