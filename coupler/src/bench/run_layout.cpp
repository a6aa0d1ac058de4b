#include "bench/run_layout.hpp"

#include <fmt/format.h>

#include "bench/pairing.hpp"
#include "cosim/config/document.hpp"
#include "cosim/error.hpp"

namespace cosim::bench {

namespace fs = std::filesystem;

fs::path RunLayout::participant(const std::string& name) const {
  return coupled && !name.empty() ? output / name : output;
}

fs::path RunLayout::fluid(const std::string& name) const {
  return participant(name.empty() ? std::string(fluid_participant) : name);
}

fs::path RunLayout::soil_case(const std::string& participant) const {
  if (!coupled) return input / "case.yaml";
  // The job names the participant's config (absolute in the run's copy).
  const auto job = config::Document::load_file(input / "job.yaml");
  const YAML::Node config = job.root().yaml()["participants"][participant]["config"];
  if (!config)
    throw Error(ExitCode::bad_input,
                fmt::format("{}: no participant '{}' with a config (give the soil's participant)",
                            (input / "job.yaml").string(), participant));
  return config.as<std::string>();
}

}  // namespace cosim::bench
