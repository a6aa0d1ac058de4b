#include "bench/metric.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "bench/analytic_solution.hpp"
#include "cosim/error.hpp"
#include "cosim/io/csv_table.hpp"

namespace cosim::bench {

std::string to_string(Verdict v) {
  switch (v) {
    case Verdict::pass:
      return "pass";
    case Verdict::fail:
      return "fail";
    case Verdict::measured:
      return "measured";
    case Verdict::unavailable:
      return "unavailable";
  }
  return "?";
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
  const std::size_t lo = hi - 1;
  const double w = (at - x[lo]) / (x[hi] - x[lo]);
  return y[lo] + w * (y[hi] - y[lo]);
}

namespace {

bool matches(const CsvTable& table, std::size_t row, const YAML::Node& where) {
  if (!where) return true;
  for (const auto& entry : where) {
    const std::size_t column = table.index(entry.first.as<std::string>());
    double wanted = 0.0;
    if (!YAML::convert<double>::decode(entry.second, wanted)) {
      if (table.text(row, column) != entry.second.Scalar()) return false;
      continue;
    }
    const double have = table.row(row)[column];
    if (!(std::abs(have - wanted) <= 1e-12 * std::max(1.0, std::abs(wanted)))) return false;
  }
  return true;
}

struct Reference {
  std::optional<double> value;
  std::vector<double> x, y;  // a curve from a file
  const AnalyticSolution* solution = nullptr;
  Parameters parameters;
  std::string label;
};

Reference read_reference(const ReferenceSpec& spec) {
  Reference r;
  const YAML::Node& p = spec.params;
  if (spec.kind == "value") {
    r.value = p["value"].as<double>();
    r.label = p["label"] ? p["label"].as<std::string>() : fmt::format("{:g}", *r.value);
  } else if (spec.kind == "analytic") {
    r.solution = find_analytic_solution(p["analytic"].as<std::string>());
    Parameters given;
    if (p["parameters"])
      for (const auto& e : p["parameters"])
        given[e.first.as<std::string>()] = e.second.as<double>();
    r.parameters = r.solution->with_defaults(given);
    r.label = p["label"] ? p["label"].as<std::string>() : r.solution->name();
    if (!r.solution->is_curve()) r.value = r.solution->value(r.parameters, 0.0, 0.0);
  } else if (spec.kind == "csv") {
    const auto table = CsvTable::read(spec.csv);
    r.label = p["label"] ? p["label"].as<std::string>() : spec.csv.filename().string();
    if (p["column"]) {
      const std::size_t c = table.index(p["column"].as<std::string>());
      for (std::size_t row = 0; row < table.rows() && !r.value; ++row)
        if (matches(table, row, p["where"])) r.value = table.row(row)[c];
      if (!r.value)
        throw Error(ExitCode::bad_input,
                    fmt::format("{}: no row matches the reference's `where`", spec.csv.string()));
    } else {
      const std::size_t cx = table.index(p["x"].as<std::string>());
      const std::size_t cy = table.index(p["y"].as<std::string>());
      for (std::size_t row = 0; row < table.rows(); ++row) {
        if (!matches(table, row, p["where"])) continue;
        if (std::isnan(table.row(row)[cx]) || std::isnan(table.row(row)[cy])) continue;
        r.x.push_back(table.row(row)[cx]);
        r.y.push_back(table.row(row)[cy]);
      }
      if (r.x.empty())
        throw Error(ExitCode::bad_input,
                    fmt::format("{}: no rows for the reference curve", spec.csv.string()));
    }
  }
  return r;
}

struct Pairs {
  std::vector<double> x, measured, reference;
};

bool in_window(const ErrorSpec& e, double x) {
  return !e.window || (x >= e.window->first - 1e-12 && x <= e.window->second + 1e-12);
}

// Measured and reference values at common abscissae: the measured curve's
// own points against an analytic or constant reference, or the measured
// curve interpolated at a file's points (shifted by `offset`).
Pairs pair_up(const Measurement& m, const Reference& r, const ErrorSpec& e, double offset) {
  Pairs p;
  if (!r.x.empty()) {
    for (std::size_t j = 0; j < r.x.size(); ++j) {
      if (!in_window(e, r.x[j])) continue;
      p.x.push_back(r.x[j]);
      p.measured.push_back(interpolate(m.x, m.y, r.x[j] - offset));
      p.reference.push_back(r.y[j]);
    }
    return p;
  }
  for (std::size_t i = 0; i < m.x.size(); ++i) {
    if (!in_window(e, m.x[i])) continue;
    p.x.push_back(m.x[i]);
    p.measured.push_back(m.y[i]);
    p.reference.push_back(
        r.value ? *r.value
                : r.solution->value(r.parameters, m.x[i],
                                    m.abscissa.rfind("t ", 0) == 0 ? m.x[i] : m.time));
  }
  return p;
}

double norm(const std::string& name, const Pairs& p, double scale) {
  if (p.x.empty()) return std::numeric_limits<double>::quiet_NaN();
  double worst = 0.0, sum = 0.0, squares = 0.0;
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    const double d = std::abs(p.measured[i] - p.reference[i]);
    const double relative = p.reference[i] != 0.0 ? d / std::abs(p.reference[i]) : d;
    const double v = name == "max_relative" || name == "max_relative_offset_fitted" ? relative : d;
    worst = std::max(worst, v);
    sum += d;
    squares += d * d;
  }
  const auto n = static_cast<double>(p.x.size());
  if (name == "mean_abs") return sum / n / scale;
  if (name == "relative_l1") {
    double reference = 0.0;
    for (double r : p.reference) reference += std::abs(r);
    return sum / reference / scale;
  }
  if (name == "rms") return std::sqrt(squares / n) / scale;
  return worst / scale;
}

double curve_error(const MetricSpec& spec, const Measurement& m, const Reference& r,
                   std::string& note) {
  const ErrorSpec& e = spec.error;
  if (e.norm == "speed") {
    const Pairs p = pair_up(m, r, e, 0.0);
    if (p.x.size() < 2) return std::numeric_limits<double>::quiet_NaN();
    const double dx = p.x.back() - p.x.front();
    const double measured = (p.measured.back() - p.measured.front()) / dx;
    const double reference = (p.reference.back() - p.reference.front()) / dx;
    note = fmt::format("slope {:.4g} against {:.4g} over [{:g}, {:g}]", measured, reference,
                       p.x.front(), p.x.back());
    return std::abs(measured / reference - 1.0) / e.scale;
  }
  if (e.norm == "max_relative_offset_fitted") {
    double best = std::numeric_limits<double>::infinity(), best_offset = e.offsets.first;
    const double step = (e.offsets.second - e.offsets.first) / 200.0;
    for (int k = 0; k <= 200; ++k) {
      const double offset = e.offsets.first + k * step;
      const double err = norm(e.norm, pair_up(m, r, e, offset), e.scale);
      if (err < best) {
        best = err;
        best_offset = offset;
      }
      if (step == 0.0) break;
    }
    note = fmt::format("abscissa offset {:.3g} fitted", best_offset);
    return best;
  }
  return norm(e.norm, pair_up(m, r, e, 0.0), e.scale);
}

double summarize(const std::string& how, const std::vector<double>& y) {
  if (y.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (how == "max") return *std::max_element(y.begin(), y.end());
  if (how == "min") return *std::min_element(y.begin(), y.end());
  if (how == "mean") {
    double s = 0.0;
    for (double v : y) s += v;
    return s / static_cast<double>(y.size());
  }
  return y.back();
}

}  // namespace

MetricResult unavailable(const MetricSpec& metric, const std::string& backend,
                         const std::string& why) {
  MetricResult r;
  r.tolerance = metric.tolerance_for(backend);
  r.verdict = Verdict::unavailable;
  r.note = why;
  return r;
}

MetricResult evaluate(const MetricSpec& spec, const std::string& backend,
                      const Measurement& measured) {
  MetricResult out;
  out.measured = measured;
  out.tolerance = spec.tolerance_for(backend);
  // A curve measured against a reference is summed up by its error; one
  // measured only, by the value `summarize` picks.
  out.value = !measured.is_curve() ? measured.value
              : spec.reference.kind == "none"
                  ? std::optional<double>(summarize(spec.summarize, measured.y))
                  : std::nullopt;
  if (spec.reference.kind == "none") {
    out.verdict = Verdict::measured;
    return out;
  }
  Reference r;
  try {
    r = read_reference(spec.reference);
  } catch (const Error& e) {
    return unavailable(spec, backend, e.what());
  }
  out.reference_label = r.label;
  out.reference_x = r.x;
  out.reference_y = r.y;
  if (measured.is_curve()) {
    out.error = curve_error(spec, measured, r, out.note);
    if (r.solution != nullptr && r.solution->is_curve()) {
      for (std::size_t i = 0; i < measured.x.size(); ++i) {
        out.reference_x.push_back(measured.x[i]);
        out.reference_y.push_back(r.solution->value(
            r.parameters, measured.x[i],
            measured.abscissa.rfind("t ", 0) == 0 ? measured.x[i] : measured.time));
      }
    }
  } else {
    if (!r.value) {
      // A number against a curve: the curve at the measurement's time.
      r.value = r.solution != nullptr
                    ? r.solution->value(r.parameters, measured.time, measured.time)
                    : interpolate(r.x, r.y, measured.time);
    }
    out.reference = r.value;
    const double v = *measured.value;
    const bool relative = spec.error.norm != "absolute" && *r.value != 0.0;
    out.error =
        (relative ? std::abs(v / *r.value - 1.0) : std::abs(v - *r.value)) / spec.error.scale;
  }
  if (!out.error || std::isnan(*out.error)) {
    out.verdict = Verdict::unavailable;
    out.note = "no points of the curves in the error's window";
    return out;
  }
  out.verdict = !out.tolerance ? Verdict::measured
                               : (*out.error <= *out.tolerance ? Verdict::pass : Verdict::fail);
  return out;
}

}  // namespace cosim::bench
