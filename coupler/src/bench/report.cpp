#include "bench/report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "cosim/io/files.hpp"

namespace cosim::bench {

namespace fs = std::filesystem;

namespace {

std::string number(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? fmt::format("{:.6g}", *v) : std::string();
}

std::string short_number(const std::optional<double>& v) {
  return v && std::isfinite(*v) ? fmt::format("{:.4g}", *v) : std::string("–");
}

// A CSV cell: quoted when it holds a comma, quote or line break.
std::string cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// A table cell of report.md: '|' would end the cell.
std::string md_cell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string first_line(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

// A failed run's message in one line: how it ended and the last line of its
// console (usually the error that ended it).
std::string failure_line(const std::string& message) {
  const std::string first = first_line(message);
  const auto last_break = message.find_last_of('\n');
  if (last_break == std::string::npos) return first;
  const auto start = message.find_first_not_of(' ', last_break + 1);
  return start == std::string::npos ? first : first + ": " + message.substr(start);
}

std::string run_label(const PlannedRun& run) {
  return run.level != nullptr ? fmt::format("{} ({})", run.backend_name(), run.level->label)
                              : run.backend_name();
}

// What a quantity measures, in a word (a plot's axis).
std::string quantity_name(const QuantitySpec& q) {
  for (const char* key : {"field", "variable", "measure", "column"})
    if (q.params[key]) return q.params[key].as<std::string>();
  return q.kind == "water_front" ? "front" : q.kind;
}

std::string plot_name(const std::string& scenario, const std::string& what) {
  return directory_name(scenario + "__" + what) + ".png";
}

// The figure of a metric's curves: the first metric measuring the same
// quantity names it.
std::string curve_plot(const Scenario& s, std::size_t index) {
  const auto text = [](const QuantitySpec& q) {
    YAML::Emitter out;
    out << q.params;
    return q.kind + out.c_str();
  };
  for (std::size_t i = 0; i < index; ++i)
    if (text(s.metrics[i].quantity) == text(s.metrics[index].quantity))
      return plot_name(s.name, s.metrics[i].name);
  return plot_name(s.name, s.metrics[index].name);
}

bool has_curve(const MetricSpec& m, const std::vector<const RunResult*>& runs, std::size_t index) {
  return std::any_of(runs.begin(), runs.end(), [&](const RunResult* r) {
    return index < r->metrics.size() && r->metrics[index].measured.is_curve();
  });
  (void)m;
}

bool has_levels(const std::vector<const RunResult*>& runs) {
  return std::any_of(runs.begin(), runs.end(),
                     [](const RunResult* r) { return r->run->level != nullptr; });
}

std::map<const Scenario*, std::vector<const RunResult*>> by_scenario(
    const std::vector<RunResult>& results) {
  std::map<const Scenario*, std::vector<const RunResult*>> out;
  for (const auto& r : results) out[r.run->scenario].push_back(&r);
  return out;
}

std::string percent_or_number(const MetricSpec& m, double error) {
  const bool relative = m.error.norm == "relative" || m.error.norm == "max_relative" ||
                        m.error.norm == "speed" || m.error.norm == "max_relative_offset_fitted";
  return relative && m.error.scale == 1.0 ? fmt::format("{:.3g} %", 100.0 * error)
                                          : fmt::format("{:.3g}", error);
}

std::string result_cell(const MetricSpec& m, const RunResult& r, const MetricResult& x) {
  if (!r.record.completed()) return fmt::format("run {}", r.record.state);
  if (x.verdict == Verdict::unavailable) return "unavailable";
  // A number shows itself and its error in brackets; a curve, its error.
  std::string text = x.value ? short_number(x.value) : std::string();
  if (x.error) {
    std::string error = fmt::format("error {}", percent_or_number(m, *x.error));
    if (x.tolerance) error += fmt::format(" ≤ {}", percent_or_number(m, *x.tolerance));
    text += text.empty() ? error : " (" + error + ")";
  }
  if (x.verdict == Verdict::pass) text += " ✓";
  if (x.verdict == Verdict::fail) text += " ✗";
  return text;
}

// The observed order of convergence between successive levels of a
// refinement study, log(e_1 / e_2) / log(n_2 / n_1), per backend and metric.
std::vector<std::string> convergence_notes(const Scenario& s,
                                           const std::vector<const RunResult*>& runs) {
  std::vector<std::string> notes;
  for (std::size_t i = 0; i < s.metrics.size(); ++i) {
    std::map<std::string, std::vector<std::pair<double, double>>> levels;
    for (const RunResult* r : runs) {
      const MetricResult& x = r->metrics[i];
      if (r->run->level == nullptr || !x.error || !std::isfinite(*x.error) || *x.error <= 0.0)
        continue;
      levels[r->run->backend_name()].emplace_back(r->run->level->cells, *x.error);
    }
    for (const auto& [backend, points] : levels) {
      if (points.size() < 2) continue;
      std::string orders;
      for (std::size_t k = 1; k < points.size(); ++k)
        orders += fmt::format("{}{:.2f} ({:g} to {:g} cells)", k > 1 ? ", " : "",
                              std::log(points[k - 1].second / points[k].second) /
                                  std::log(points[k].first / points[k - 1].first),
                              points[k - 1].first, points[k].first);
      notes.push_back(fmt::format("{}, {}: observed order of convergence {}", backend,
                                  s.metrics[i].name, orders));
    }
  }
  return notes;
}

}  // namespace

void write_results_csv(const fs::path& file, const std::vector<RunResult>& results) {
  std::string out =
      "scenario,backend,level,cells,metric,unit,value,reference,reference_label,error,"
      "tolerance,verdict,wall_time_s,coupling_share,iterations_per_window,run_state,note\n";
  for (const auto& r : results) {
    const PlannedRun& run = *r.run;
    const auto row = [&](const std::string& metric, const std::string& unit,
                         const MetricResult* x) {
      std::string note = x != nullptr ? x->note : std::string();
      if (!r.record.completed()) note = failure_line(r.record.message);
      out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
                         cell(run.scenario->name), run.backend_name(), cell(run.level_label()),
                         run.level != nullptr ? number(run.level->cells) : "", cell(metric),
                         cell(unit), x ? number(x->value) : "", x ? number(x->reference) : "",
                         x ? cell(x->reference_label) : "", x ? number(x->error) : "",
                         x ? number(x->tolerance) : "", x ? to_string(x->verdict) : "",
                         number(r.record.wall_time_s), number(r.coupling_share),
                         number(r.iterations_per_window), r.record.state, cell(note));
    };
    if (run.scenario->metrics.empty()) row("", "", nullptr);
    for (std::size_t i = 0; i < run.scenario->metrics.size(); ++i)
      row(run.scenario->metrics[i].name, run.scenario->metrics[i].unit, &r.metrics[i]);
  }
  write_file_atomically(file, out);
}

std::vector<fs::path> write_plot_manifest(const fs::path& dir, const Suite& suite,
                                          const std::vector<RunResult>& results) {
  using nlohmann::json;
  json figures = json::array();
  std::vector<fs::path> files;
  const auto grouped = by_scenario(results);
  for (const auto& s : suite.scenarios) {
    const auto it = grouped.find(&s);
    if (it == grouped.end()) continue;
    const auto& runs = it->second;
    std::set<std::string> drawn;  // metrics measuring the same curve share one figure
    for (std::size_t i = 0; i < s.metrics.size(); ++i) {
      const MetricSpec& m = s.metrics[i];
      if (has_curve(m, runs, i) && drawn.insert(curve_plot(s, i)).second) {
        json curves = json::array();
        json reference = nullptr;
        for (const RunResult* r : runs) {
          const MetricResult& x = r->metrics[i];
          if (!x.measured.is_curve()) continue;
          curves.push_back(
              {{"label", run_label(*r->run)}, {"x", x.measured.x}, {"y", x.measured.y}});
          if (reference.is_null() && !x.reference_x.empty())
            reference = {{"label", x.reference_label}, {"x", x.reference_x}, {"y", x.reference_y}};
        }
        const std::string file = curve_plot(s, i);
        figures.push_back({{"kind", "curves"},
                           {"file", file},
                           {"title", fmt::format("{}: {}", s.title, m.label)},
                           {"xlabel", runs.front()->metrics[i].measured.abscissa},
                           {"ylabel", fmt::format("{} [{}]", quantity_name(m.quantity), m.unit)},
                           {"curves", curves},
                           {"reference", reference}});
        files.push_back(dir / file);
      }
      if (has_levels(runs) && m.reference.kind != "none") {
        std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> series;
        for (const RunResult* r : runs) {
          const MetricResult& x = r->metrics[i];
          if (r->run->level == nullptr || !x.error || !std::isfinite(*x.error)) continue;
          series[r->run->backend_name()].first.push_back(r->run->level->cells);
          series[r->run->backend_name()].second.push_back(*x.error);
        }
        if (series.empty()) continue;
        json lines = json::array();
        for (const auto& [backend, xy] : series)
          lines.push_back({{"label", backend}, {"x", xy.first}, {"y", xy.second}});
        const std::string file = plot_name(s.name, m.name + "_convergence");
        figures.push_back(
            {{"kind", "convergence"},
             {"file", file},
             {"title", fmt::format("{}: error of {} against resolution", s.title, m.name)},
             {"xlabel", "cells"},
             {"ylabel", fmt::format("error ({})", m.error.norm)},
             {"curves", lines},
             {"tolerance", m.tolerance ? json(*m.tolerance) : json(nullptr)}});
        files.push_back(dir / file);
      }
    }
    json bars = json::array();
    for (const RunResult* r : runs) {
      if (!r->record.completed()) continue;
      bars.push_back(
          {{"label", run_label(*r->run)},
           {"wall_time_s", r->record.wall_time_s},
           {"coupling_share", r->coupling_share ? json(*r->coupling_share) : json(nullptr)}});
    }
    if (!bars.empty()) {
      const std::string file = plot_name(s.name, "wall_time");
      figures.push_back({{"kind", "wall_time"},
                         {"file", file},
                         {"title", fmt::format("{}: wall time per backend", s.title)},
                         {"bars", bars}});
      files.push_back(dir / file);
    }
  }
  create_output_directory(dir);
  write_file_atomically(dir / "plots.json",
                        json{{"suite", suite.name}, {"figures", figures}}.dump(1));
  return files;
}

namespace {

// Each backend's finest level (the last listed); runs without levels as they are.
std::vector<const RunResult*> finest_levels(const std::vector<const RunResult*>& runs) {
  std::map<std::string, const RunResult*> last;
  std::vector<std::string> order;
  for (const RunResult* r : runs) {
    const std::string b = r->run->backend_name();
    if (!last.count(b)) order.push_back(b);
    last[b] = r;
  }
  std::vector<const RunResult*> out;
  for (const auto& b : order) out.push_back(last[b]);
  return out;
}

}  // namespace

std::string scenario_summary(const Scenario& s, const std::vector<const RunResult*>& all_runs) {
  std::vector<std::string> sentences;
  const std::vector<const RunResult*> runs = finest_levels(all_runs);
  // Closest: the run with the most metrics where it has the smallest error,
  // then the smallest mean error over tolerance.
  std::map<const RunResult*, int> wins;
  std::map<const RunResult*, double> ratio_sum;
  std::map<const RunResult*, int> ratio_count;
  int compared = 0;
  for (std::size_t i = 0; i < s.metrics.size(); ++i) {
    const RunResult* best = nullptr;
    int candidates = 0;
    for (const RunResult* r : runs) {
      const MetricResult& x = r->metrics[i];
      if (!r->record.completed() || !x.error || !std::isfinite(*x.error)) continue;
      ++candidates;
      if (x.tolerance && *x.tolerance > 0.0) {
        ratio_sum[r] += *x.error / *x.tolerance;
        ++ratio_count[r];
      }
      if (best == nullptr || *x.error < *best->metrics[i].error) best = r;
    }
    if (best != nullptr && candidates > 1) {
      ++wins[best];
      ++compared;
    }
  }
  if (compared > 0) {
    const RunResult* closest = nullptr;
    for (const auto& [r, w] : wins) {
      const auto mean = [&](const RunResult* x) {
        return ratio_count[x] > 0 ? ratio_sum[x] / ratio_count[x] : 0.0;
      };
      if (closest == nullptr || w > wins[closest] ||
          (w == wins[closest] && mean(r) < mean(closest)))
        closest = r;
    }
    sentences.push_back(
        fmt::format("Closest to the reference: **{}** (smallest error on {} of {} "
                    "compared metrics).",
                    run_label(*closest->run), wins[closest], compared));
  }
  const RunResult* cheapest = nullptr;
  const RunResult* dearest = nullptr;
  int completed = 0;
  for (const RunResult* r : runs) {
    if (!r->record.completed()) continue;
    ++completed;
    if (cheapest == nullptr || r->record.wall_time_s < cheapest->record.wall_time_s) cheapest = r;
    if (dearest == nullptr || r->record.wall_time_s > dearest->record.wall_time_s) dearest = r;
  }
  if (completed > 1) {
    const double ratio = dearest->record.wall_time_s / cheapest->record.wall_time_s;
    sentences.push_back(fmt::format(
        "Cheapest: **{}** ({:.3g} s of wall time; {} took {:.3g} s, {} as long).",
        run_label(*cheapest->run), cheapest->record.wall_time_s, run_label(*dearest->run),
        dearest->record.wall_time_s,
        ratio >= 10.0 ? fmt::format("{:.0f} times", ratio) : fmt::format("{:.2g} times", ratio)));
  }
  for (const RunResult* r : all_runs) {
    if (!r->record.completed())
      sentences.push_back(fmt::format("**{}** did not finish ({}): {}", run_label(*r->run),
                                      r->record.state, failure_line(r->record.message)));
    int failing = 0;
    for (const auto& x : r->metrics) failing += x.verdict == Verdict::fail ? 1 : 0;
    if (failing > 0)
      sentences.push_back(fmt::format("{} is outside tolerance on {} metric{}.", run_label(*r->run),
                                      failing, failing > 1 ? "s" : ""));
  }
  std::string out;
  for (const auto& sentence : sentences) out += (out.empty() ? "" : " ") + sentence;
  return out;
}

void write_report(const fs::path& file, const Suite& suite, const std::vector<RunResult>& results,
                  const ReportContext& context) {
  std::ostringstream md;
  md << "# " << suite.title << "\n\n";
  if (!suite.about.empty()) md << suite.about << "\n";
  std::map<Verdict, int> verdicts;
  int reused = 0, failed = 0;
  for (const auto& r : results) {
    for (const auto& x : r.metrics) ++verdicts[x.verdict];
    reused += r.record.reused ? 1 : 0;
    failed += r.record.completed() ? 0 : 1;
  }
  md << fmt::format(
      "Suite `{}` ({}), resolution **{}**, run {} on {} with cosim {}. {} runs ({} kept from an "
      "earlier run with the same inputs, {} not finished); metrics: {} within tolerance, {} "
      "outside, {} measured without a tolerance, {} unavailable. Every number is in "
      "`results.csv`; each run's inputs, outputs and console are in "
      "`runs/<scenario>/<backend>/`.\n\n",
      suite.name, suite.file.string(), to_string(context.resolution), context.started_at,
      context.machine, COSIM_VERSION, results.size(), reused, failed, verdicts[Verdict::pass],
      verdicts[Verdict::fail], verdicts[Verdict::measured], verdicts[Verdict::unavailable]);
  if (!context.plots) md << "*No plots: " << context.plots_note << "*\n\n";

  const auto grouped = by_scenario(results);
  for (const auto& s : suite.scenarios) {
    const auto it = grouped.find(&s);
    if (it == grouped.end()) continue;
    const auto& runs = it->second;
    md << "## " << s.title << "\n\n";
    if (!s.about.empty()) md << s.about << "\n";
    const std::string summary = scenario_summary(s, runs);
    if (!summary.empty()) md << summary << "\n\n";
    md << "| metric | reference |";
    for (const RunResult* r : runs) md << " " << run_label(*r->run) << " |";
    md << "\n|---|---|";
    for (std::size_t k = 0; k < runs.size(); ++k) md << "---|";
    md << "\n";
    for (std::size_t i = 0; i < s.metrics.size(); ++i) {
      const MetricSpec& m = s.metrics[i];
      std::string reference = "–";
      for (const RunResult* r : runs) {
        const MetricResult& x = r->metrics[i];
        if (!x.reference_label.empty()) {
          reference = x.reference
                          ? fmt::format("{} ({})", short_number(x.reference), x.reference_label)
                          : x.reference_label;
          break;
        }
      }
      md << fmt::format("| {} [{}] | {} |", md_cell(m.label), m.unit, md_cell(reference));
      for (const RunResult* r : runs)
        md << " " << md_cell(result_cell(m, *r, r->metrics[i])) << " |";
      md << "\n";
    }
    md << "| wall time [s] | |";
    for (const RunResult* r : runs)
      md << " " << (r->record.completed() ? fmt::format("{:.3g}", r->record.wall_time_s) : "–")
         << " |";
    md << "\n| coupling share | |";
    for (const RunResult* r : runs)
      md << " " << (r->coupling_share ? fmt::format("{:.1f} %", 100.0 * *r->coupling_share) : "–")
         << " |";
    md << "\n| iterations per window (median) | |";
    for (const RunResult* r : runs)
      md << " " << (r->iterations_per_window ? fmt::format("{:g}", *r->iterations_per_window) : "–")
         << " |";
    md << "\n\n";
    std::vector<std::string> notes;
    for (const RunResult* r : runs)
      for (std::size_t i = 0; i < s.metrics.size(); ++i)
        if (!r->metrics[i].note.empty() && r->record.completed())
          notes.push_back(fmt::format("{}, {}: {}", run_label(*r->run), s.metrics[i].name,
                                      first_line(r->metrics[i].note)));
    for (const auto& n : convergence_notes(s, runs)) notes.push_back(n);
    for (const auto& n : s.not_represented)
      notes.push_back(fmt::format("**{}** not represented: {}", n.backend->name, n.reason));
    for (const auto& n : notes) md << "- " << n << "\n";
    if (!notes.empty()) md << "\n";
    if (context.plots) {
      std::set<std::string> shown;
      for (std::size_t i = 0; i < s.metrics.size(); ++i) {
        if (has_curve(s.metrics[i], runs, i) && shown.insert(curve_plot(s, i)).second)
          md << fmt::format("![{}](plots/{})\n", md_cell(s.metrics[i].label), curve_plot(s, i));
        if (has_levels(runs) && s.metrics[i].reference.kind != "none")
          md << fmt::format("![error of {} against resolution](plots/{})\n", s.metrics[i].name,
                            plot_name(s.name, s.metrics[i].name + "_convergence"));
      }
      md << fmt::format("![wall time](plots/{})\n\n", plot_name(s.name, "wall_time"));
    }
  }
  write_file_atomically(file, md.str());
}

}  // namespace cosim::bench
