#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

// The one message format of every transport: a header and a raw
// little-endian payload.
namespace cosim::com {

// 2: implicit coupling (window_repeat; hello's `repeatable`, welcome's
// `implicit` and `time_interpolation`).
// 3: checkpoints (checkpoint_done; window_begin's payload naming the
// checkpoint directory; hello's `checkpointable` and `restart_window`).
// 4: participants on several ranks (mesh_part; hello's `part` and `parts`).
inline constexpr std::uint16_t protocol_version = 4;

enum class MessageType : std::uint8_t {
  hello = 1,        // participant -> coupler: name, job, declarations (JSON payload)
  welcome,          // coupler -> participant: schedule and the fields it will receive (JSON)
  refuse,           // coupler -> participant: why it is not admitted (text)
  mesh,             // participant -> coupler: a mesh's geometry (float64 payload)
  field,            // either way: one field's values on a mesh (float64 payload)
  window_end,       // participant -> coupler: all fields of this window are sent
  window_begin,     // coupler -> participant: all fields are sent; next window (JSON)
  finish,           // coupler -> participant: the run is over
  abort,            // either way: a fatal error; the payload says why (text)
  window_repeat,    // coupler -> participant: the window did not converge; run it again from its
                    // start with the fields just sent (implicit schemes)
  checkpoint_done,  // participant -> coupler: its part of the checkpoint the last window_begin
                    // asked for is written (architecture.md §14)
  mesh_part,        // participant rank -> coupler: the whole mesh's indices of the elements this
                    // rank holds (float64 payload), before the mesh's geometry whenever it changes
};

enum class ElementType : std::uint8_t { none = 0, float64 = 1, text = 2 };

struct Header {
  std::uint16_t version = protocol_version;
  MessageType type = MessageType::abort;
  ElementType element = ElementType::none;
  std::string job_id;
  std::string sender;
  std::uint64_t window = 0;
  double time = 0.0;
  std::string field;
  std::string mesh;
  std::uint64_t count = 0;       // elements (mesh entities) in the payload
  std::uint32_t components = 1;  // values per element
};

// Immutable, shareable payload bytes: transports send and receive it without
// copying where they can.
class Payload {
 public:
  Payload() = default;
  static Payload copy_of(std::span<const std::byte> bytes);
  static Payload from_doubles(std::span<const double> values);
  // Shares the values instead of copying them (on little-endian hosts): the
  // payload keeps them alive until the transport has sent them.
  static Payload share_doubles(std::shared_ptr<const std::vector<double>> values);
  static Payload from_text(std::string_view text);
  static Payload adopt(std::shared_ptr<const void> owner, const std::byte* data, std::size_t size);

  std::span<const std::byte> bytes() const { return {data_, size_}; }
  std::size_t size() const { return size_; }
  // Little-endian float64 values (copied out; aligned and byte-order safe).
  std::vector<double> doubles() const;
  void copy_doubles_to(std::span<double> out) const;
  std::string text() const;
  const std::shared_ptr<const void>& owner() const { return owner_; }

 private:
  std::shared_ptr<const void> owner_;
  const std::byte* data_ = nullptr;
  std::size_t size_ = 0;
};

struct Message {
  Header header;
  Payload payload;
};

const char* to_string(MessageType type);

// Header <-> bytes. decode_header throws ProtocolError naming `peer` on a
// malformed, truncated or foreign (bad magic / version) header.
std::vector<std::byte> encode_header(const Header& header);
Header decode_header(std::span<const std::byte> bytes, const std::string& peer);

// Checks the payload against the header: size = count * components * element
// size; float64 values finite unless `allow_nonfinite`. Throws ProtocolError.
void validate_payload(const Message& message, const std::string& peer, bool allow_nonfinite);

// Builders for the common messages.
Message make_field_message(const std::string& job_id, const std::string& sender,
                           std::uint64_t window, double time, const std::string& field,
                           const std::string& mesh, std::span<const double> values,
                           std::uint32_t components);
Message make_field_message(const std::string& job_id, const std::string& sender,
                           std::uint64_t window, double time, const std::string& field,
                           const std::string& mesh,
                           std::shared_ptr<const std::vector<double>> values,
                           std::uint32_t components);
Message make_text_message(MessageType type, const std::string& job_id, const std::string& sender,
                          std::uint64_t window, double time, std::string_view text);

}  // namespace cosim::com
