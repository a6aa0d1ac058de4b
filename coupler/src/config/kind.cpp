#include "cosim/config/kind.hpp"

#include <fmt/format.h>

namespace cosim::config {

void expect_kind(const Node& root, const std::string& kind) {
  if (!root.is_map()) {
    root.fail(fmt::format("expected a mapping that starts with 'kind: {}', got {}", kind,
                          root.describe()));
  }
  auto declared = root.find("kind");
  if (!declared) {
    throw InputError(
        root.location(), "kind",
        fmt::format("missing 'kind: {}'; every cosim YAML file says what it is", kind));
  }
  if (!declared->is_scalar()) {
    declared->fail(
        fmt::format("expected a file kind such as '{}', got {}", kind, declared->describe()));
  }
  const std::string& actual = declared->yaml().Scalar();
  if (actual != kind) {
    declared->fail(
        fmt::format("this is a '{}' file, but a '{}' file is expected here", actual, kind));
  }
}

}  // namespace cosim::config
