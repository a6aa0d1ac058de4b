#include "bench/bench.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "bench/quantity.hpp"
#include "bench/report.hpp"
#include "bench/runner.hpp"
#include "cosim/io/content_hash.hpp"
#include "cosim/io/files.hpp"
#include "cosim/io/logging.hpp"
#include "cosim/io/run_summary.hpp"
#include "cosim/runtime/supervisor.hpp"

namespace cosim::bench {

namespace fs = std::filesystem;

namespace {

std::string machine_description() {
  std::ifstream cpu("/proc/cpuinfo");
  std::string line, model;
  while (std::getline(cpu, line)) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return fmt::format("{}, {} cores", model.empty() ? "unknown CPU" : model,
                     std::thread::hardware_concurrency());
}

// The coupler's summary.json of a coupled run, if it reads.
std::optional<nlohmann::json> coupler_summary(const PlannedRun& run) {
  if (!run.coupled) return std::nullopt;
  std::ifstream in(run.output() / "summary.json");
  if (!in) return std::nullopt;
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The coupler's own share of a coupled run's wall time: transport, mapping,
// exchange and output, against the total (the rest is waiting for the
// participants to compute).
std::optional<double> coupling_share(const nlohmann::json& summary) {
  try {
    const double total = summary.at("wall_time_s").at("total").get<double>();
    double own = 0.0;
    for (const auto& [phase, seconds] : summary.at("wall_time_s").at("phases").items())
      if (phase != "waiting") own += seconds.get<double>();
    return total > 0.0 ? std::optional<double>(own / total) : std::nullopt;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// A coupled run's median iterations per window: its summary's `coupling`
// section under an implicit scheme, 1 under an explicit one.
std::optional<double> iterations_per_window(const nlohmann::json& summary) {
  try {
    if (!summary.contains("coupling")) return 1.0;
    return summary.at("coupling").at("median_iterations_per_window").get<double>();
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

RunResult evaluate_run(const PlannedRun& run, const RunRecord& record) {
  RunResult result{&run, record, std::nullopt, {}, std::nullopt};
  if (const auto summary = coupler_summary(run)) {
    result.coupling_share = coupling_share(*summary);
    result.iterations_per_window = iterations_per_window(*summary);
  }
  const RunLayout layout{run.backend->backend, run.coupled, run.directory / "input", run.output()};
  for (const auto& m : run.scenario->metrics) {
    if (!record.completed()) {
      result.metrics.push_back(
          unavailable(m, run.backend_name(), fmt::format("the run {}", record.state)));
      continue;
    }
    try {
      result.metrics.push_back(evaluate(m, run.backend_name(), measure(m.quantity, layout)));
    } catch (const std::exception& e) {
      result.metrics.push_back(unavailable(m, run.backend_name(), e.what()));
    }
    const MetricResult& x = result.metrics.back();
    spdlog::info("{} {}: {} {}{}{}", run.id(), m.name,
                 x.value ? fmt::format("{:.6g}", *x.value) : "-", m.unit,
                 x.error ? fmt::format(", error {:.4g}", *x.error) : "",
                 fmt::format(" ({}{})", to_string(x.verdict), x.note.empty() ? "" : ": " + x.note));
  }
  return result;
}

// bench_plots.py next to the build's share directory, or in the source tree.
std::optional<fs::path> plot_script() {
  for (const fs::path& candidate :
       {runtime::self_directory() / ".." / "share" / "cosim" / "bench_plots.py",
        fs::path(COSIM_BENCH_SHARE_DIR) / "bench_plots.py"}) {
    if (fs::exists(candidate)) return fs::weakly_canonical(candidate);
  }
  return std::nullopt;
}

// Draws the manifest's figures with Debian's matplotlib; says why not when it cannot.
bool draw_plots(const fs::path& plots, std::string& why) {
  const auto script = plot_script();
  if (!script) {
    why = "bench_plots.py was not found next to the cosim executable";
    return false;
  }
  const fs::path python = "/usr/bin/python3";
  if (!fs::exists(python)) {
    why = "/usr/bin/python3 is missing (apt-get install python3-matplotlib)";
    return false;
  }
  runtime::Supervisor supervisor;
  runtime::ChildSpec child{
      "bench_plots", python, {script->string(), plots.string()}, plots / "bench_plots.log"};
  supervisor.start(child);
  const auto exits = supervisor.wait_all(std::chrono::milliseconds(600000));
  if (exits.empty() || !exits.front().success()) {
    supervisor.stop_all(std::chrono::milliseconds(1000));
    why = fmt::format("bench_plots.py failed (see {})", (plots / "bench_plots.log").string());
    return false;
  }
  return true;
}

}  // namespace

int run_bench(const BenchRunOptions& o) {
  Suite suite = load_suite(o.bench.suite_file);
  // Metrics of the other resolution are dropped. (Copied, not erased in
  // place: assigning a YAML::Node rebinds the storage it shares.)
  for (auto& s : suite.scenarios) {
    std::vector<MetricSpec> kept;
    for (const auto& m : s.metrics)
      if (!m.resolution || *m.resolution == o.bench.resolution) kept.push_back(m);
    s.metrics = std::move(kept);
  }
  const fs::path output = fs::absolute(o.bench.output);
  if (o.reuse == OutputReuse::overwrite && is_inside(o.bench.suite_file, output))
    throw InputError(fmt::format("--overwrite would clear '{}', which holds the suite file '{}'",
                                 output.string(), o.bench.suite_file.string()));
  // A dry run clears nothing: with --overwrite it lists every run as to run.
  prepare_output_directory(
      output, o.dry_run && o.reuse == OutputReuse::overwrite ? OutputReuse::resume : o.reuse,
      {"summary.json"}, true);
  init_logging(output, "cosim", parse_verbosity(o.verbosity));
  RunSummary summary(output, "cosim bench");
  summary.set_config(fs::absolute(o.bench.suite_file), hash_bytes(suite.text));
  summary.set_section("bench", {{"suite", suite.name},
                                {"resolution", to_string(o.bench.resolution)},
                                {"jobs", o.bench.jobs},
                                {"only", o.bench.only}});
  summary.write();
  return run_and_finish(summary, [&] {
    BenchOptions options = o.bench;
    options.output = output;
    const auto runs = plan_runs(suite, options);
    spdlog::info("suite '{}' ({}): {} runs at resolution {}, up to {} at a time; outputs in {}",
                 suite.name, o.bench.suite_file.string(), runs.size(),
                 to_string(o.bench.resolution), o.bench.jobs, output.string());
    if (o.dry_run) {
      for (const auto& run : runs) {
        const RunRecord previous = read_record(run);
        const bool kept =
            o.reuse == OutputReuse::resume && previous.completed() && previous.key == run.key;
        std::printf("%-40s %-12s %s %s\n", run.id().c_str(), kept ? "(kept)" : "(to run)",
                    run.executable.c_str(), fmt::format("{}", fmt::join(run.args, " ")).c_str());
      }
      return;
    }
    const std::string started_at = iso8601_utc(std::chrono::system_clock::now());
    const auto records = [&] {
      auto scope = summary.phases().measure("runs");
      return run_all(runs, {o.bench.jobs, o.terminal, o.interrupted});
    }();
    std::vector<RunResult> results;
    {
      auto scope = summary.phases().measure("evaluation");
      for (std::size_t i = 0; i < runs.size(); ++i)
        results.push_back(evaluate_run(runs[i], records[i]));
    }
    auto scope = summary.phases().measure("report");
    write_results_csv(output / "results.csv", results);
    ReportContext context{machine_description(), started_at, o.bench.resolution, false, {}};
    write_plot_manifest(output / "plots", suite, results);
    context.plots = draw_plots(output / "plots", context.plots_note);
    if (!context.plots) spdlog::warn("no plots: {}", context.plots_note);
    write_report(output / "report.md", suite, results, context);

    std::map<Verdict, int> verdicts;
    int failed = 0;
    for (const auto& r : results) {
      failed += r.record.completed() ? 0 : 1;
      for (const auto& x : r.metrics) ++verdicts[x.verdict];
    }
    summary.set_metric("runs", static_cast<double>(results.size()), "1");
    summary.set_metric("runs_not_finished", failed, "1");
    summary.set_metric("metrics_within_tolerance", verdicts[Verdict::pass], "1");
    summary.set_metric("metrics_outside_tolerance", verdicts[Verdict::fail], "1");
    summary.set_metric("metrics_unavailable", verdicts[Verdict::unavailable], "1");
    spdlog::info(
        "{} runs, {} not finished; metrics: {} within tolerance, {} outside, {} measured, "
        "{} unavailable; report: {}",
        results.size(), failed, verdicts[Verdict::pass], verdicts[Verdict::fail],
        verdicts[Verdict::measured], verdicts[Verdict::unavailable],
        (output / "report.md").string());
    if (failed > 0)
      throw Error(
          ExitCode::participant_failed,
          fmt::format("{} of {} runs did not finish (see report.md)", failed, results.size()));
  });
}

}  // namespace cosim::bench
