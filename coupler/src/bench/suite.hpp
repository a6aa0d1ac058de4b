#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bench/backend_catalog.hpp"
#include "cosim/config/schema.hpp"
#include "cosim/error.hpp"

// A benchmark suite as its YAML `kind: bench_suite` file describes it: named
// scenarios, each one physical set-up run with several fluid backends, the
// reference it is measured against and the metrics that measure it. A
// coupled scenario writes its soil and its coupling once; each backend adds
// only its own fluid case (the job joining the two is built from the
// backend's pairing, pairing.hpp). Backends are those registered
// (backend_catalog.hpp), known by their descriptors.
namespace cosim::bench {

enum class Resolution { coarse, full };
std::string to_string(Resolution resolution);

// One value put at `key_path` (dotted; sequence items by index, e.g.
// `bodies.0.porous.porosity`) in one of a run's input files: `role` is
// `soil`, `fluid`, `case` or `job`.
struct Override {
  std::string role;
  std::string key_path;
  YAML::Node value;
  SourceLocation where;
};

// Overrides applied always, and those applied only at one resolution.
struct OverrideSet {
  std::vector<Override> always;
  std::vector<Override> coarse;
  std::vector<Override> full;
  std::vector<Override> at(Resolution r) const;
};

// One grid of a backend's refinement study: its overrides and the number the
// error-against-resolution plot puts on its axis (cells across the domain).
struct Level {
  std::string label;
  double cells = 0.0;
  std::vector<Override> set;
  std::optional<Resolution> only;  // runs at this resolution only
};

// How a backend gets its input: a standalone case (`case`), a fluid case
// coupled to the scenario's soil (`fluid`), or a ready job (`job`).
enum class InputForm { standalone_case, coupled_fluid, ready_job };

struct BackendRuns {
  const BackendDescriptor* backend = nullptr;
  InputForm form = InputForm::standalone_case;
  std::filesystem::path file;
  std::map<Resolution, std::filesystem::path> file_at;  // another file at one resolution
  OverrideSet overrides;
  std::vector<Level> levels;  // empty: one run
  SourceLocation where;
};

// The coupling settings a coupled scenario writes once for all its pairings.
struct Coupling {
  std::filesystem::path soil;                       // the MPM case
  const BackendDescriptor* soil_backend = nullptr;  // its solver
  double end_time = 0.0;
  double window = 0.0;
  YAML::Node drag;                          // the job's momentum_exchange.drag
  std::vector<std::string> optional_reads;  // e.g. solid_volume_flux, when a backend reads it
};

// What a metric measures in a finished run. `kind` selects the reader
// (quantity.hpp); `params` are its keys as written.
struct QuantitySpec {
  std::string kind;
  YAML::Node params;
  std::string key_path;
  SourceLocation where;
};

// What it is compared with: `value`, `analytic` (reference.hpp's registry)
// or `csv`; `none` when the metric is only measured.
struct ReferenceSpec {
  std::string kind = "none";
  YAML::Node params;
  std::filesystem::path csv;  // resolved from the suite file
  std::string key_path;
  SourceLocation where;
};

// How the two are compared. Scalars: relative or absolute. Curves (profiles
// and time series): the norm of their difference over the reference's points
// within `window`, divided by `scale`.
struct ErrorSpec {
  std::string norm = "relative";
  double scale = 1.0;
  std::optional<std::pair<double, double>> window;
  std::pair<double, double> offsets{0.0, 0.0};  // searched by max_relative_offset_fitted
};

struct MetricSpec {
  std::string name;
  std::string label;
  std::string unit;
  QuantitySpec quantity;
  ReferenceSpec reference;
  ErrorSpec error;
  // Largest error that passes; per backend when the suite gives a map (a
  // backend it leaves out is measured only).
  std::optional<double> tolerance;
  std::map<std::string, double> backend_tolerances;
  std::optional<Resolution> resolution;  // measured at this resolution only
  std::string summarize = "end";  // a curve's value without reference: end | max | min | mean
  std::string key_path;
  SourceLocation where;

  std::optional<double> tolerance_for(const std::string& backend) const;
};

// A backend the scenario cannot run, and why in one line (a measured
// reason): the report lists it beside the backends that ran.
struct NotRepresented {
  const BackendDescriptor* backend = nullptr;
  std::string reason;
  SourceLocation where;
};

struct Scenario {
  std::string name;
  std::string title;
  std::string about;
  std::optional<Coupling> coupling;
  OverrideSet overrides;  // soil and job overrides shared by every backend
  std::vector<BackendRuns> backends;
  std::vector<NotRepresented> not_represented;
  std::vector<MetricSpec> metrics;
  SourceLocation where;
};

struct Suite {
  std::filesystem::path file;
  std::string name;
  std::string title;
  std::string about;
  std::vector<Scenario> scenarios;
  std::string text;  // the file as read (part of every run's key)
};

// Reads and validates a suite file in full before anything runs: unknown
// keys, missing files, backends a scenario's form cannot use, metrics
// without a quantity. Errors are InputErrors at `file:line:col: key`. The
// backends a suite names are looked up in `backends`.
Suite load_suite(const std::filesystem::path& file,
                 const BackendCatalog& backends = registered_backends());

const config::Schema& suite_schema();

}  // namespace cosim::bench
