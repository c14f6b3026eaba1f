// tf2_msgs/TFMessage in ROS 1 serialization and CDR: geometry_msgs/TransformStamped[] transforms,
// each Header, string child_frame_id, Transform (Vector3 translation, Quaternion rotation).
#include "internal/cdr_reader.hpp"
#include "internal/ros1_reader.hpp"
#include "internal/ros_message_fields.hpp"
#include "tessera/io/ros_messages.hpp"

namespace tessera {
namespace {

/// The fewest bytes one TransformStamped takes (stamp, two string lengths, seven float64), so
/// that a corrupt count is refused before anything is allocated.
constexpr std::size_t kMinTransformBytes = 8 + 4 + 4 + 7 * 8;

template <typename Reader>
Result<TfMessage> decode(Reader r) {
  TfMessage m;
  const std::uint32_t n = r.sequence_count(kMinTransformBytes, "transforms");
  m.transforms.reserve(n);
  for (std::uint32_t i = 0; i < n && r.ok(); ++i) {
    m.transforms.push_back(io_internal::read_transform_stamped(r));
  }
  if (!r.ok()) return io_internal::decode_error(r, kTfMessageType);
  return m;
}

}  // namespace

Result<TfMessage> decode_tf_message(std::span<const std::uint8_t> bytes, RosEncoding encoding) {
  if (encoding == RosEncoding::kRos1) return decode(io_internal::Ros1Reader(bytes));
  return decode(io_internal::CdrReader(bytes));
}

}  // namespace tessera
