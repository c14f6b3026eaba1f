// The Cyclone DDS transport (dds_transport.hpp; decision 0021). One DDS participant per
// transport. A message crosses as CDR bytes: publish() checks them against the IDL type with
// Cyclone's own validator (dds_stream_normalize_data), reads them into the IDL-generated sample
// and writes it; poll() takes each received sample in its serialized form (dds_takecdr) and hands
// its bytes, encapsulation header included, to the handler. Cyclone's C API is wrapped in small
// owning handles; every entity is deleted with the participant.
#include "tessera/net/dds_transport.hpp"

#include <dds/dds.h>
#include <dds/ddsi/ddsi_cdrstream.h>
#include <dds/ddsi/ddsi_serdata.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "cyclone/dds_types.hpp"
#include "tessera/net/ros_names.hpp"

namespace tessera::net {
namespace {

using dds_internal::find_dds_type;

constexpr std::uint32_t kMaxDomainId = 232;  // DDS's port mapping leaves no room for more
constexpr std::uint32_t kXcdr1 = 1;

std::string dds_error(const char* what, dds_return_t rc) {
  return std::string(what) + ": " + dds_strretcode(rc);
}

// A DDS entity handle, deleted (with its children) when the owner goes.
class Entity {
 public:
  Entity() = default;
  explicit Entity(dds_entity_t handle) : handle_(handle) {}
  ~Entity() {
    if (handle_ > 0) dds_delete(handle_);
  }
  Entity(Entity&& other) noexcept : handle_(std::exchange(other.handle_, 0)) {}
  Entity& operator=(Entity&& other) noexcept {
    std::swap(handle_, other.handle_);
    return *this;
  }
  [[nodiscard]] dds_entity_t get() const { return handle_; }

 private:
  dds_entity_t handle_ = 0;
};

// A QoS object for the time of one create call.
class QosHandle {
 public:
  explicit QosHandle(const Qos& qos) : qos_(dds_create_qos()) {
    dds_qset_reliability(qos_,
                         qos.reliability == Qos::Reliability::kReliable
                             ? DDS_RELIABILITY_RELIABLE
                             : DDS_RELIABILITY_BEST_EFFORT,
                         DDS_MSECS(100));
    dds_qset_durability(qos_, qos.durability == Qos::Durability::kTransientLocal
                                  ? DDS_DURABILITY_TRANSIENT_LOCAL
                                  : DDS_DURABILITY_VOLATILE);
    dds_qset_history(qos_, DDS_HISTORY_KEEP_LAST, static_cast<int32_t>(std::max(qos.depth, 1U)));
  }
  ~QosHandle() { dds_delete_qos(qos_); }
  QosHandle(const QosHandle&) = delete;
  QosHandle& operator=(const QosHandle&) = delete;
  [[nodiscard]] const dds_qos_t* get() const { return qos_; }

 private:
  dds_qos_t* qos_;
};

// The loopback-only domain configuration: one interface, no multicast, unicast discovery of the
// participant indices 0..max-1 on 127.0.0.1.
std::string loopback_config(const DdsOptions& options) {
  return "<CycloneDDS><Domain id=\"any\"><General><Interfaces>"
         "<NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
         "<AllowMulticast>false</AllowMulticast></General>"
         "<Discovery><ParticipantIndex>auto</ParticipantIndex><MaxAutoParticipantIndex>" +
         std::to_string(std::max(options.max_participants, 2U) - 1) +
         "</MaxAutoParticipantIndex><Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>"
         "</Domain></CycloneDDS>";
}

// A process holds one DDS domain object per domain id, shared by its participants: Cyclone
// refuses a second dds_create_domain of the same id.
class Domains {
 public:
  static Result<std::shared_ptr<Entity>> acquire(const DdsOptions& options) {
    static Domains domains;
    const std::lock_guard lock(domains.mutex_);
    std::weak_ptr<Entity>& slot = domains.by_id_[options.domain_id];
    if (std::shared_ptr<Entity> existing = slot.lock()) return existing;
    const std::string config = options.loopback_only ? loopback_config(options) : "";
    const dds_entity_t domain = dds_create_domain(options.domain_id, config.c_str());
    if (domain < 0) return runtime_error(dds_error("DDS domain", domain));
    auto entity = std::make_shared<Entity>(domain);
    slot = entity;
    return entity;
  }

 private:
  std::mutex mutex_;
  std::map<std::uint32_t, std::weak_ptr<Entity>> by_id_;
};

class DdsTransport final : public Transport {
 public:
  DdsTransport(std::shared_ptr<Entity> domain, Entity participant, Entity waitset)
      : domain_(std::move(domain)),
        participant_(std::move(participant)),
        waitset_(std::move(waitset)) {}

  ~DdsTransport() override {
    // Children first (dds_delete of the participant would do it too), then the domain reference.
    writers_.clear();
    readers_.clear();
    topics_.clear();
    waitset_ = Entity();
    participant_ = Entity();
  }

  std::size_t matched_readers(WriterId writer) const override {
    const auto w = writers_.find(writer);
    if (w == writers_.end()) return 0;
    dds_publication_matched_status_t status{};
    if (dds_get_publication_matched_status(w->second.entity.get(), &status) < 0) return 0;
    return status.current_count;
  }

  bool wait(double timeout_s) override {
    const auto timeout = static_cast<dds_duration_t>(std::max(timeout_s, 0.0) * 1e9);
    return dds_waitset_wait(waitset_.get(), nullptr, 0, timeout) > 0;
  }

 private:
  struct Writer {
    Entity entity;
    const dds_topic_descriptor_t* type = nullptr;
    std::string type_name;
  };
  struct Reader {
    Entity entity;
    Entity condition;
  };

  Result<dds_entity_t> topic(const TopicSpec& spec, const dds_topic_descriptor_t* type) {
    const std::string name = dds_topic_name(spec.name);
    auto found = topics_.find(name);
    if (found != topics_.end()) return found->second.get();
    const dds_entity_t t =
        dds_create_topic(participant_.get(), type, name.c_str(), nullptr, nullptr);
    if (t < 0) return runtime_error(dds_error(("DDS topic " + name).c_str(), t));
    return topics_.emplace(name, Entity(t)).first->second.get();
  }

  static Result<const dds_topic_descriptor_t*> type_of(const TopicSpec& spec) {
    const dds_topic_descriptor_t* type = find_dds_type(spec.type);
    if (type == nullptr) {
      return input_error("topic " + spec.name + ": type '" + spec.type +
                         "' is not one the DDS transport carries");
    }
    // The IDL's name must be ROS 2's mapping of the type name, or ROS 2 peers will not match.
    Result<std::string> dds_name = dds_type_name(spec.type);
    if (!dds_name.ok() || *dds_name != type->m_typename) {
      return runtime_error("topic " + spec.name + ": IDL type " + type->m_typename +
                           " is not ROS 2's name for " + spec.type);
    }
    return type;
  }

  Result<WriterId> do_advertise(const TopicSpec& spec) override {
    Result<const dds_topic_descriptor_t*> type = type_of(spec);
    if (!type.ok()) return type.error();
    Result<dds_entity_t> t = topic(spec, *type);
    if (!t.ok()) return t.error();
    const QosHandle qos(spec.qos);
    const dds_entity_t w = dds_create_writer(participant_.get(), *t, qos.get(), nullptr);
    if (w < 0) return runtime_error(dds_error(("DDS writer on " + spec.name).c_str(), w));
    const WriterId id = next_id_++;
    writers_.emplace(id, Writer{Entity(w), *type, spec.type});
    return id;
  }

  Status do_publish(WriterId id, std::span<const std::uint8_t> cdr) override {
    const auto found = writers_.find(id);
    if (found == writers_.end()) return input_error("publish: no writer " + std::to_string(id));
    const Writer& w = found->second;
    const std::string what = w.type_name + " of " + std::to_string(cdr.size()) + " bytes";
    if (cdr.size() < 4 || cdr[0] != 0x00 || (cdr[1] != 0x00 && cdr[1] != 0x01)) {
      return input_error(what + ": no plain CDR encapsulation header");
    }
    if (cdr.size() == 4) return input_error(what + ": no fields after the header");
    // Cyclone's validator checks every length and bound against the type and byte-swaps a big
    // endian message in place, so it works on a copy of the body.
    body_.assign(cdr.begin() + 4, cdr.end());
    const bool swap = cdr[1] == 0x00;  // 0x00 0x00: big endian
    std::uint32_t end = 0;
    if (dds_stream_normalize_data(body_.data(), &end, static_cast<std::uint32_t>(body_.size()),
                                  swap, kXcdr1, w.type->m_ops) == nullptr) {
      return input_error(what + ": does not fit the type (a length or count runs past the end)");
    }
    void* sample = dds_alloc(w.type->m_size);
    dds_istream_t in;
    dds_istream_init(&in, static_cast<std::uint32_t>(body_.size()), body_.data(), kXcdr1);
    dds_stream_read(&in, static_cast<char*>(sample), w.type->m_ops);
    dds_istream_fini(&in);
    const dds_return_t rc = dds_write(w.entity.get(), sample);
    dds_sample_free(sample, w.type, DDS_FREE_ALL);
    if (rc < 0) return runtime_error(dds_error(("DDS write of " + w.type_name).c_str(), rc));
    return Ok{};
  }

  Result<ReaderId> do_subscribe(const TopicSpec& spec) override {
    Result<const dds_topic_descriptor_t*> type = type_of(spec);
    if (!type.ok()) return type.error();
    Result<dds_entity_t> t = topic(spec, *type);
    if (!t.ok()) return t.error();
    const QosHandle qos(spec.qos);
    const dds_entity_t r = dds_create_reader(participant_.get(), *t, qos.get(), nullptr);
    if (r < 0) return runtime_error(dds_error(("DDS reader on " + spec.name).c_str(), r));
    Entity reader(r);
    const dds_entity_t c = dds_create_readcondition(r, DDS_ANY_STATE);
    if (c < 0) return runtime_error(dds_error("DDS read condition", c));
    Entity condition(c);
    if (const dds_return_t rc = dds_waitset_attach(waitset_.get(), c, c); rc < 0) {
      return runtime_error(dds_error("DDS waitset", rc));
    }
    const ReaderId id = next_id_++;
    readers_.emplace(id, Reader{std::move(reader), std::move(condition)});
    return id;
  }

  std::size_t do_poll(
      const std::function<void(ReaderId, std::span<const std::uint8_t>)>& deliver) override {
    std::size_t n = 0;
    for (const auto& [id, reader] : readers_) {
      for (;;) {
        ddsi_serdata* data = nullptr;
        dds_sample_info_t info;
        if (dds_takecdr(reader.entity.get(), &data, 1, &info, DDS_ANY_STATE) <= 0) break;
        if (info.valid_data) {
          const std::uint32_t size = ddsi_serdata_size(data);
          received_.resize(size);
          ddsi_serdata_to_ser(data, 0, size, received_.data());
        }
        ddsi_serdata_unref(data);
        if (!info.valid_data) continue;  // a dispose or unregister, no message
        deliver(id, received_);
        ++n;
      }
    }
    return n;
  }

  std::shared_ptr<Entity> domain_;
  Entity participant_;
  Entity waitset_;
  std::map<std::string, Entity> topics_;
  std::map<WriterId, Writer> writers_;
  std::map<ReaderId, Reader> readers_;
  std::uint32_t next_id_ = 1;
  std::vector<char> body_;              // publish's working copy
  std::vector<std::uint8_t> received_;  // poll's working copy
};

}  // namespace

Result<std::unique_ptr<Transport>> make_dds_transport(const DdsOptions& options) {
  if (options.domain_id > kMaxDomainId) {
    return input_error("DDS domain id " + std::to_string(options.domain_id) +
                       " is out of range (0.." + std::to_string(kMaxDomainId) + ")");
  }
  Result<std::shared_ptr<Entity>> domain = Domains::acquire(options);
  if (!domain.ok()) return domain.error();
  const dds_entity_t participant = dds_create_participant(options.domain_id, nullptr, nullptr);
  if (participant < 0) return runtime_error(dds_error("DDS participant", participant));
  Entity owned(participant);
  const dds_entity_t waitset = dds_create_waitset(participant);
  if (waitset < 0) return runtime_error(dds_error("DDS waitset", waitset));
  return std::unique_ptr<Transport>(
      std::make_unique<DdsTransport>(std::move(*domain), std::move(owned), Entity(waitset)));
}

std::vector<std::string> dds_transport_types() {
  std::vector<std::string> out;
  for (const std::string_view name : dds_internal::dds_type_names()) out.emplace_back(name);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace tessera::net
