// The type support Fast-DDS sees for one wire type: samples are WireSample objects holding the
// bytes to write (dds/cdr_write.h), and the value read from a received sample's bytes. Unlike
// Fast-DDS's own DynamicPubSubType it never fails a sample that does not decode (Fast-DDS would
// drop it without a trace, or an exception would escape into its threads): the sample arrives
// marked `bad`, so the transport counts it as a `bad-type` drop.
#pragma once

#include <fastrtps/types/DynamicData.h>
#include <fastrtps/types/DynamicPubSubType.h>

#include <fastdds/dds/topic/TopicDataType.hpp>
#include <memory>
#include <string>
#include <vector>

#include "core/value.h"
#include "dds/wire_types.h"

namespace arbc::dds {

struct WireSample {
  // What a writer sends: the sample's bytes, encapsulation included (dds/cdr_write.h). The
  // mediator fills it; Fast-DDS copies it into its payload.
  std::vector<uint8_t> bytes;
  // Without bytes, Fast-DDS's own encoding of this dynamic data is sent instead: the tests'
  // reference for the bytes above (to_wire fills it). Owned (DynamicDataFactory).
  eprosima::fastrtps::types::DynamicData* data = nullptr;
  // What the last deserialize read, straight from the bytes (dds/cdr_read.h); not `data`.
  Value value;
  bool bad = false;  // the last deserialize could not decode the bytes
  // Bytes the last sample had beyond what its decoded value takes (a program whose type has
  // the spec's fields and more); `bad` is set with it.
  uint32_t extra_bytes = 0;
};

class WireTopicType : public eprosima::fastdds::dds::TopicDataType {
 public:
  explicit WireTopicType(std::shared_ptr<const WireType> wire);
  const WireType& wire() const { return *wire_; }

  bool serialize(void* data, eprosima::fastrtps::rtps::SerializedPayload_t* payload) override;
  // Always true: a sample that does not decode is marked WireSample::bad instead, and so is one
  // longer than its decoded value (CDR decodes a prefix of a longer struct without a word).
  bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override;
  std::function<uint32_t()> getSerializedSizeProvider(void* data) override;
  void* createData() override;
  void deleteData(void* data) override;
  bool getKey(void* data, eprosima::fastrtps::rtps::InstanceHandle_t* handle,
              bool force_md5 = false) override;

 private:
  std::shared_ptr<const WireType> wire_;
  eprosima::fastrtps::types::DynamicPubSubType codec_;
};

}  // namespace arbc::dds
