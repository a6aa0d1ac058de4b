#include "cosim/io/run_size.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cosim/error.hpp"

namespace cosim {

namespace {

constexpr double gib = 1024.0 * 1024.0 * 1024.0;

std::string memory_text(double bytes) {
  if (bytes >= 1e6 * gib) return fmt::format("{:.3g} GiB", bytes / gib);
  if (bytes >= 10.0 * gib) return fmt::format("{:.0f} GiB", bytes / gib);
  if (bytes >= 0.1 * gib) return fmt::format("{:.1f} GiB", bytes / gib);
  return fmt::format("{:.0f} MiB", std::max(1.0, bytes / (1024.0 * 1024.0)));
}

std::string counts_text(const RunSize& size) {
  std::string text;
  for (const SizeCount& c : size.counts)
    text += fmt::format("{}{} {}", text.empty() ? "" : ", ", grouped(c.count), c.name);
  return text;
}

std::string json_key(std::string name) {
  for (char& ch : name)
    if (ch == ' ') ch = '_';
  return name;
}

}  // namespace

std::string grouped(double count) {
  if (!(count < 1e15)) return fmt::format("{:.3g}", count);
  const std::string digits = fmt::format("{:.0f}", std::max(0.0, count));
  std::string text;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text += ' ';
    text += digits[i];
  }
  return text;
}

RunSize& RunSize::add(SizeCount count) {
  counts.push_back(std::move(count));
  return *this;
}

double RunSize::count(std::string_view name) const {
  for (const SizeCount& c : counts)
    if (c.name == name) return c.count;
  return 0.0;
}

double RunSize::memory_bytes() const {
  double bytes = fixed_bytes;
  for (const SizeCount& c : counts) bytes += c.count * c.bytes_each;
  return bytes;
}

std::string RunSize::describe() const {
  const std::string listed = counts_text(*this);
  return fmt::format("{}{}about {}{}", listed, listed.empty() ? "" : ", ",
                     memory_text(memory_bytes()),
                     not_included.empty() ? "" : " without " + not_included);
}

nlohmann::json RunSize::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const SizeCount& c : counts) j[json_key(c.name)] = c.count;
  j["memory_bytes_estimate"] = memory_bytes();
  j["memory_limit_bytes"] = memory_limit_gib * gib;
  if (!not_included.empty()) j["not_included"] = not_included;
  return j;
}

config::Schema run_limits_schema() {
  config::Schema limits = config::Schema::object(
      "What the run may use. The solver estimates its memory from the case before it allocates "
      "anything (`--validate` prints the estimate) and refuses a case above the limit.");
  limits.optional("memory_gib",
                  config::Schema::number().positive().unit("GiB").default_value(
                      fmt::format("{:g}", RunLimits::default_memory_gib)),
                  "Most memory the run may need; raise it for a case the machine can hold.");
  return limits;
}

RunLimits read_run_limits(const config::Node& case_root) {
  RunLimits limits;
  if (auto node = case_root.find("limits"))
    limits.memory_gib = node->get<double>("memory_gib", limits.memory_gib);
  return limits;
}

void check_run_size(RunSize& size, const config::Node& case_root) {
  const double bytes = size.memory_bytes();
  for (const SizeCount& c : size.counts) {
    if (c.count <= c.most) continue;
    const std::string what = fmt::format(
        "the case makes {} {}, more than the solver's indices hold ({}); the run would need "
        "about {} ({})",
        grouped(c.count), c.name, grouped(c.most), memory_text(bytes), counts_text(size));
    if (c.set_by) c.set_by->fail(what);
    throw InputError(case_root.location(), "", what);
  }
  size.memory_limit_gib = read_run_limits(case_root).memory_gib;
  if (bytes <= size.memory_limit_gib * gib) return;
  const std::string what = fmt::format(
      "the run would need about {} ({}), more than the limit of {:g} GiB; make the case smaller "
      "or, if the machine has the memory, raise limits.memory_gib",
      memory_text(bytes), counts_text(size), size.memory_limit_gib);
  std::optional<config::Node> limit;
  if (auto limits = case_root.find("limits")) limit = limits->find("memory_gib");
  if (limit) limit->fail(what);
  throw InputError(case_root.location(), "limits.memory_gib", what);
}

}  // namespace cosim
