#include "com/message.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>

#include "cosim/error.hpp"

namespace cosim::com {

namespace {

constexpr std::array<std::byte, 4> magic{std::byte{'C'}, std::byte{'S'}, std::byte{'I'},
                                         std::byte{'M'}};
constexpr std::size_t max_name_length = 4096;

template <class T>
T to_little_endian(T value) {
  if constexpr (std::endian::native == std::endian::big) {
    auto bytes = std::bit_cast<std::array<std::byte, sizeof(T)>>(value);
    std::reverse(bytes.begin(), bytes.end());
    return std::bit_cast<T>(bytes);
  }
  return value;
}

class HeaderWriter {
 public:
  template <class T>
  void put(T value) {
    const auto le = to_little_endian(value);
    const auto* p = reinterpret_cast<const std::byte*>(&le);
    out_.insert(out_.end(), p, p + sizeof(T));
  }
  void put(const std::string& s) {
    put(static_cast<std::uint32_t>(s.size()));
    const auto* p = reinterpret_cast<const std::byte*>(s.data());
    out_.insert(out_.end(), p, p + s.size());
  }
  void put_bytes(std::span<const std::byte> b) { out_.insert(out_.end(), b.begin(), b.end()); }
  std::vector<std::byte> take() { return std::move(out_); }

 private:
  std::vector<std::byte> out_;
};

class HeaderReader {
 public:
  HeaderReader(std::span<const std::byte> in, const std::string& peer) : in_(in), peer_(peer) {}

  template <class T>
  T get(const char* what) {
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, in_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return to_little_endian(value);
  }
  std::string get_string(const char* what) {
    const auto n = get<std::uint32_t>(what);
    if (n > max_name_length)
      throw ProtocolError(
          peer_, fmt::format("header {} is {} bytes long (limit {})", what, n, max_name_length));
    need(n, what);
    std::string s(reinterpret_cast<const char*>(in_.data() + pos_), n);
    pos_ += n;
    return s;
  }
  std::span<const std::byte> get_bytes(std::size_t n, const char* what) {
    need(n, what);
    auto s = in_.subspan(pos_, n);
    pos_ += n;
    return s;
  }
  bool done() const { return pos_ == in_.size(); }

 private:
  void need(std::size_t n, const char* what) const {
    if (in_.size() - pos_ < n)
      throw ProtocolError(peer_, fmt::format("truncated message header (reading {})", what));
  }
  std::span<const std::byte> in_;
  const std::string& peer_;
  std::size_t pos_ = 0;
};

std::size_t element_size(ElementType type) {
  switch (type) {
    case ElementType::float64:
      return sizeof(double);
    case ElementType::text:
      return 1;
    case ElementType::none:
      return 0;
  }
  return 0;
}

}  // namespace

Payload Payload::copy_of(std::span<const std::byte> bytes) {
  auto storage = std::make_shared<std::vector<std::byte>>(bytes.begin(), bytes.end());
  Payload p;
  p.data_ = storage->data();
  p.size_ = storage->size();
  p.owner_ = std::move(storage);
  return p;
}

Payload Payload::from_doubles(std::span<const double> values) {
  auto storage = std::make_shared<std::vector<double>>(values.begin(), values.end());
  if constexpr (std::endian::native == std::endian::big)
    for (double& v : *storage) v = to_little_endian(v);
  Payload p;
  p.data_ = reinterpret_cast<const std::byte*>(storage->data());
  p.size_ = storage->size() * sizeof(double);
  p.owner_ = std::move(storage);
  return p;
}

Payload Payload::share_doubles(std::shared_ptr<const std::vector<double>> values) {
  if constexpr (std::endian::native == std::endian::big) return from_doubles(*values);
  Payload p;
  p.data_ = reinterpret_cast<const std::byte*>(values->data());
  p.size_ = values->size() * sizeof(double);
  p.owner_ = std::move(values);
  return p;
}

Payload Payload::from_text(std::string_view text) {
  return copy_of(std::as_bytes(std::span<const char>(text.data(), text.size())));
}

Payload Payload::adopt(std::shared_ptr<const void> owner, const std::byte* data, std::size_t size) {
  Payload p;
  p.owner_ = std::move(owner);
  p.data_ = data;
  p.size_ = size;
  return p;
}

std::vector<double> Payload::doubles() const {
  std::vector<double> out(size_ / sizeof(double));
  copy_doubles_to(out);
  return out;
}

void Payload::copy_doubles_to(std::span<double> out) const {
  const std::size_t n = std::min(out.size(), size_ / sizeof(double));
  if (n > 0) std::memcpy(out.data(), data_, n * sizeof(double));
  if constexpr (std::endian::native == std::endian::big)
    for (std::size_t i = 0; i < n; ++i) out[i] = to_little_endian(out[i]);
}

std::string Payload::text() const {
  return std::string(reinterpret_cast<const char*>(data_), size_);
}

const char* to_string(MessageType type) {
  switch (type) {
    case MessageType::hello:
      return "hello";
    case MessageType::welcome:
      return "welcome";
    case MessageType::refuse:
      return "refuse";
    case MessageType::mesh:
      return "mesh";
    case MessageType::field:
      return "field";
    case MessageType::window_end:
      return "window_end";
    case MessageType::window_begin:
      return "window_begin";
    case MessageType::finish:
      return "finish";
    case MessageType::abort:
      return "abort";
    case MessageType::window_repeat:
      return "window_repeat";
    case MessageType::checkpoint_done:
      return "checkpoint_done";
    case MessageType::mesh_part:
      return "mesh_part";
  }
  return "unknown";
}

std::vector<std::byte> encode_header(const Header& h) {
  HeaderWriter w;
  w.put_bytes(magic);
  w.put(h.version);
  w.put(static_cast<std::uint8_t>(h.type));
  w.put(static_cast<std::uint8_t>(h.element));
  w.put(h.window);
  w.put(h.time);
  w.put(h.count);
  w.put(h.components);
  w.put(h.job_id);
  w.put(h.sender);
  w.put(h.field);
  w.put(h.mesh);
  return w.take();
}

Header decode_header(std::span<const std::byte> bytes, const std::string& peer) {
  HeaderReader r(bytes, peer);
  const auto m = r.get_bytes(magic.size(), "magic");
  if (!std::equal(m.begin(), m.end(), magic.begin()))
    throw ProtocolError(peer, "not a cosim message (bad magic bytes)");
  Header h;
  h.version = r.get<std::uint16_t>("version");
  if (h.version != protocol_version)
    throw ProtocolError(peer, fmt::format("speaks cosim protocol version {}, this side speaks {}",
                                          h.version, protocol_version));
  const auto type = r.get<std::uint8_t>("type");
  if (type < static_cast<std::uint8_t>(MessageType::hello) ||
      type > static_cast<std::uint8_t>(MessageType::mesh_part))
    throw ProtocolError(peer, fmt::format("unknown message type {}", type));
  h.type = static_cast<MessageType>(type);
  const auto element = r.get<std::uint8_t>("element type");
  if (element > static_cast<std::uint8_t>(ElementType::text))
    throw ProtocolError(peer, fmt::format("unknown element type {}", element));
  h.element = static_cast<ElementType>(element);
  h.window = r.get<std::uint64_t>("window");
  h.time = r.get<double>("time");
  h.count = r.get<std::uint64_t>("count");
  h.components = r.get<std::uint32_t>("components");
  h.job_id = r.get_string("job id");
  h.sender = r.get_string("sender");
  h.field = r.get_string("field");
  h.mesh = r.get_string("mesh");
  if (!r.done()) throw ProtocolError(peer, "trailing bytes after the message header");
  if (!std::isfinite(h.time)) throw ProtocolError(peer, "non-finite simulated time in header");
  return h;
}

void validate_payload(const Message& message, const std::string& peer, bool allow_nonfinite) {
  const Header& h = message.header;
  if ((h.type == MessageType::field || h.type == MessageType::mesh) &&
      h.element != ElementType::float64)
    throw ProtocolError(peer, fmt::format("{} '{}' on mesh '{}' does not carry float64 values",
                                          to_string(h.type), h.field, h.mesh));
  const std::size_t esize = element_size(h.element);
  const std::uint64_t components = h.element == ElementType::float64 ? h.components : 1;
  if (h.element == ElementType::float64 && h.components == 0)
    throw ProtocolError(
        peer, fmt::format("{} '{}' declares zero components", to_string(h.type), h.field));
  // Bounded before multiplying: a product past 2^64 wraps to a size that a
  // short payload matches, and the values would be read far beyond it.
  constexpr std::uint64_t max_values = std::uint64_t{1} << 40;
  if (h.count > max_values || components > max_values / std::max<std::uint64_t>(h.count, 1))
    throw ProtocolError(peer, fmt::format("{} '{}' on mesh '{}': the header announces {} x {} "
                                          "values, more than 2^40",
                                          to_string(h.type), h.field, h.mesh, h.count, components));
  const std::uint64_t expected = h.count * components * esize;
  if (message.payload.size() != expected)
    throw ProtocolError(
        peer, fmt::format("{} '{}' on mesh '{}': payload has {} bytes, the header "
                          "announces {} x {} x {} = {}",
                          to_string(h.type), h.field, h.mesh, message.payload.size(), h.count,
                          components, esize, expected));
  if (h.element == ElementType::float64 && !allow_nonfinite) {
    const auto bytes = message.payload.bytes();
    for (std::size_t i = 0; i < h.count * components; ++i) {
      double v;
      std::memcpy(&v, bytes.data() + i * sizeof(double), sizeof(double));
      if (!std::isfinite(to_little_endian(v)))
        throw ProtocolError(peer, fmt::format("field '{}' on mesh '{}' has a non-finite value at "
                                              "element {} component {}",
                                              h.field, h.mesh, i / components, i % components));
    }
  }
}

namespace {

Message field_message(const std::string& job_id, const std::string& sender, std::uint64_t window,
                      double time, const std::string& field, const std::string& mesh,
                      std::size_t values, std::uint32_t components) {
  Message m;
  m.header.type = MessageType::field;
  m.header.element = ElementType::float64;
  m.header.job_id = job_id;
  m.header.sender = sender;
  m.header.window = window;
  m.header.time = time;
  m.header.field = field;
  m.header.mesh = mesh;
  m.header.components = components;
  m.header.count = components == 0 ? 0 : values / components;
  return m;
}

}  // namespace

Message make_field_message(const std::string& job_id, const std::string& sender,
                           std::uint64_t window, double time, const std::string& field,
                           const std::string& mesh, std::span<const double> values,
                           std::uint32_t components) {
  Message m = field_message(job_id, sender, window, time, field, mesh, values.size(), components);
  m.payload = Payload::from_doubles(values);
  return m;
}

Message make_field_message(const std::string& job_id, const std::string& sender,
                           std::uint64_t window, double time, const std::string& field,
                           const std::string& mesh,
                           std::shared_ptr<const std::vector<double>> values,
                           std::uint32_t components) {
  Message m = field_message(job_id, sender, window, time, field, mesh, values->size(), components);
  m.payload = Payload::share_doubles(std::move(values));
  return m;
}

Message make_text_message(MessageType type, const std::string& job_id, const std::string& sender,
                          std::uint64_t window, double time, std::string_view text) {
  Message m;
  m.header.type = type;
  m.header.element = ElementType::text;
  m.header.job_id = job_id;
  m.header.sender = sender;
  m.header.window = window;
  m.header.time = time;
  m.header.count = text.size();
  m.payload = Payload::from_text(text);
  return m;
}

}  // namespace cosim::com
