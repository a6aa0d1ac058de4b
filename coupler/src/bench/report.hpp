#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench/metric.hpp"
#include "bench/run_plan.hpp"
#include "bench/runner.hpp"

namespace cosim::bench {

// Everything the report says of one run.
struct RunResult {
  const PlannedRun* run = nullptr;
  RunRecord record;
  std::optional<double> coupling_share;  // the coupler's own share of a coupled run's wall time
  std::vector<MetricResult> metrics;     // one per metric of the scenario, in its order
  // A coupled run's median attempts per window (1 with an explicit scheme).
  std::optional<double> iterations_per_window = std::nullopt;
};

struct ReportContext {
  std::string machine;  // CPU model and cores
  std::string started_at;
  Resolution resolution = Resolution::coarse;
  bool plots = false;  // plots/*.png were drawn
  std::string plots_note;
};

// <dir>/results.csv: one row per scenario x backend (x level) x metric.
void write_results_csv(const std::filesystem::path& file, const std::vector<RunResult>& results);

// <dir>/plots/plots.json: the curves, wall times and errors against
// resolution that bench_plots.py draws; returns the PNG files it will make.
std::vector<std::filesystem::path> write_plot_manifest(const std::filesystem::path& dir,
                                                       const Suite& suite,
                                                       const std::vector<RunResult>& results);

// <dir>/report.md: per scenario the backends side by side, the plots, and
// which pairing came closest to the reference and which was cheapest.
void write_report(const std::filesystem::path& file, const Suite& suite,
                  const std::vector<RunResult>& results, const ReportContext& context);

// The sentence of the report's summary for one scenario.
std::string scenario_summary(const Scenario& scenario, const std::vector<const RunResult*>& runs);

}  // namespace cosim::bench
