#include "window_iteration.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "cosim/error.hpp"

namespace cosim::cplscheme {

namespace {

// A residual counts as diverging only above this fraction of ||H(x)||.
constexpr double divergence_floor = 0.1;

const std::vector<double>& values_of(const FieldsByPeer& fields, const job::SentField& f) {
  const auto peer = fields.find(f.participant);
  if (peer != fields.end()) {
    const auto field = peer->second.find(f.field);
    if (field != peer->second.end()) return *field->second;
  }
  throw Error(ExitCode::internal_error,
              fmt::format("window iteration: no values of '{}' sent", f.label()));
}

double norm(std::span<const double> v) {
  return std::sqrt(std::inner_product(v.begin(), v.end(), v.begin(), 0.0));
}

double median(std::vector<std::size_t> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? static_cast<double>(v[n / 2]) : 0.5 * static_cast<double>(v[n / 2 - 1] + v[n / 2]);
}

std::vector<std::string> csv_columns(const job::CouplingSpec& spec,
                                     const std::map<std::string, std::string>& units) {
  std::vector<std::string> columns{"window", column_name("time", "s"), "iterations", "converged"};
  for (const job::ConvergenceMeasure& m : spec.convergence) {
    const std::string label = m.field.label();
    columns.push_back(column_name(label + " residual", units.at(label)));
    columns.push_back(column_name(label + " relative residual", "1"));
  }
  return columns;
}

}  // namespace

struct WindowIteration::Measure {
  const job::ConvergenceMeasure* spec;
  double residual = 0.0;           // ||r^k||
  double relative = 0.0;           // ||r^k|| / ||H(x^k)||
  double first_residual = 0.0;     // ||r^1|| of the window
  double previous_residual = 0.0;  // ||r^{k-1}||

  bool holds(std::size_t iteration, double answer_norm) const {
    return (spec->relative && residual <= *spec->relative * answer_norm) ||
           (spec->absolute && residual <= *spec->absolute) ||
           (spec->residual_relative && iteration >= 2 &&
            residual <= *spec->residual_relative * first_residual);
  }
};

WindowIteration::WindowIteration(const job::CouplingSpec& spec,
                                 const std::map<std::string, std::string>& units,
                                 const std::map<std::string, Bounds>& bounds,
                                 const std::filesystem::path& csv)
    : spec_(spec), bounds_(bounds), csv_(csv, csv_columns(spec, units)) {
  for (const job::ConvergenceMeasure& m : spec.convergence) measures_.push_back(Measure{&m});
}

WindowIteration::~WindowIteration() = default;

acceleration::Block WindowIteration::block_of(const job::SentField& f, std::size_t size) const {
  acceleration::Block block{f.label(), size};
  for (const job::ConvergenceMeasure& m : spec_.convergence) {
    if (m.field.label() != block.name) continue;
    block.relative = m.relative.value_or(0.0);
    block.absolute = m.absolute.value_or(0.0);
    block.residual_relative = m.residual_relative.value_or(0.0);
  }
  return block;
}

void WindowIteration::sent(const FieldsByPeer& x) {
  for (const auto& [participant, fields] : x)
    for (const auto& [field, values] : fields) sent_[participant][field] = values;
}

std::vector<double> WindowIteration::gather(const FieldsByPeer& fields) const {
  std::vector<double> out;
  for (const job::SentField& f : spec_.accelerated) {
    const auto& v = values_of(fields, f);
    out.insert(out.end(), v.begin(), v.end());
  }
  return out;
}

void WindowIteration::scatter(std::span<const double> values, FieldsByPeer& fields) const {
  std::size_t offset = 0;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    const job::SentField& f = spec_.accelerated[b];
    const auto first = values.begin() + static_cast<std::ptrdiff_t>(offset);
    auto field = std::make_shared<std::vector<double>>(
        first, first + static_cast<std::ptrdiff_t>(blocks_[b].size));
    // A quasi-Newton step may overshoot a bound (a density below zero): the
    // iterate is held within it, as a mapped field is.
    if (const auto bounds = bounds_.find(f.label()); bounds != bounds_.end())
      for (double& v : *field) v = std::clamp(v, bounds->second.first, bounds->second.second);
    fields[f.participant][f.field] = std::move(field);
    offset += blocks_[b].size;
  }
}

WindowIteration::Verdict WindowIteration::judge(std::size_t window, double time,
                                                const FieldsByPeer& answer) {
  ++iteration_;
  bool all_hold = true;
  for (Measure& m : measures_) {
    const auto& x = values_of(sent_, m.spec->field);
    const auto& h = values_of(answer, m.spec->field);
    std::vector<double> r(h.size());
    for (std::size_t i = 0; i < h.size(); ++i) r[i] = h[i] - x[i];
    m.previous_residual = m.residual;
    m.residual = norm(r);
    const double answer_norm = norm(h);
    m.relative = answer_norm > 0.0
                     ? m.residual / answer_norm
                     : (m.residual > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
    if (iteration_ == 1) m.first_residual = m.residual;
    if (!std::isfinite(m.residual))
      throw NumericalError(
          fmt::format("window {} (t = {:.6g} s), iteration {}: the residual of '{}' is not finite",
                      window, time, iteration_, m.spec->field.label()));
    // Growth from a residual already at round-off or at the tolerance is
    // not divergence: the iterate must also change by a tenth of itself.
    if (iteration_ >= 2 && m.previous_residual > 0.0 &&
        m.residual > spec_.divergence_factor * m.previous_residual &&
        m.residual > divergence_floor * answer_norm)
      throw NumericalError(fmt::format(
          "window {} (t = {:.6g} s): the implicit coupling diverges: the residual of '{}' grew "
          "from {:.4g} to {:.4g} over iteration {} (more than coupling.divergence_factor = {:g} "
          "times); a shorter window or another acceleration may converge",
          window, time, m.spec->field.label(), m.previous_residual, m.residual, iteration_,
          spec_.divergence_factor));
    all_hold = m.holds(iteration_, answer_norm) && all_hold;
  }
  spdlog::debug("window {} (t = {:.6g} s), iteration {}: {}", window, time, iteration_,
                residuals_text());

  std::vector<double> x = gather(sent_);
  std::vector<double> h = gather(answer);
  if (!accelerator_ && !spec_.accelerated.empty()) {
    for (const job::SentField& f : spec_.accelerated)
      blocks_.push_back(block_of(f, values_of(answer, f).size()));
    accelerator_ = acceleration::make_accelerator(spec_.acceleration, blocks_);
  }
  if (all_hold) {
    if (accelerator_) accelerator_->window_converged(x, h);
    window_done(true, window, time);
    return Verdict::converged;
  }
  if (iteration_ >= spec_.max_iterations) {
    const std::string what = fmt::format(
        "window {} (t = {:.6g} s) has not converged in {} iterations (coupling.max_iterations): "
        "{}",
        window, time, iteration_, residuals_text());
    if (spec_.on_max_iterations == job::OnMaxIterations::stop)
      throw NumericalError(what + " (coupling.on_max_iterations: continue takes the last iterate)");
    spdlog::warn("{}; the last iterate is taken (coupling.on_max_iterations: continue)", what);
    if (accelerator_) accelerator_->window_converged(x, h);
    window_done(false, window, time);
    return Verdict::gave_up;
  }
  next_ = answer;
  if (accelerator_) {
    std::vector<double> accelerated(x.size());
    accelerator_->accelerate(x, h, accelerated);
    scatter(accelerated, next_);
  }
  return Verdict::repeat;
}

std::string WindowIteration::residuals_text() const {
  std::string out;
  for (const Measure& m : measures_)
    out += fmt::format("{}'{}' residual {:.4g} (relative {:.4g})", out.empty() ? "" : ", ",
                       m.spec->field.label(), m.residual, m.relative);
  return out;
}

void WindowIteration::window_done(bool converged, std::size_t window, double time) {
  std::vector<double> row{static_cast<double>(window), time, static_cast<double>(iteration_),
                          converged ? 1.0 : 0.0};
  for (const Measure& m : measures_) {
    row.push_back(m.residual);
    row.push_back(m.relative);
  }
  csv_.append(row);
  iterations_per_window_.push_back(iteration_);
  if (!converged) ++not_converged_;
  last_iterations_ = iteration_;
  iteration_ = 0;
  for (Measure& m : measures_) m.residual = m.previous_residual = m.first_residual = 0.0;
}

nlohmann::json WindowIteration::summary() const {
  const auto& v = iterations_per_window_;
  nlohmann::json residuals = nlohmann::json::object();
  for (const Measure& m : measures_) residuals[m.spec->field.label()] = m.relative;
  return {{"scheme", spec_.is_serial() ? "serial-implicit" : "parallel-implicit"},
          {"windows", v.size()},
          {"iterations", std::accumulate(v.begin(), v.end(), std::size_t{0})},
          {"median_iterations_per_window", median(v)},
          {"max_iterations_per_window", v.empty() ? 0 : *std::max_element(v.begin(), v.end())},
          {"windows_not_converged", not_converged_},
          {"accelerator_columns", accelerator_ ? accelerator_->columns() : 0},
          {"csv", csv_.path().filename().string()}};
}

}  // namespace cosim::cplscheme

namespace cosim::cplscheme {

void WindowIteration::save(StateFileWriter& out) const {
  for (const auto& [participant, fields] : sent_)
    for (const auto& [field, values] : fields)
      out.numbers("iteration.sent." + participant + "." + field, *values);
  std::vector<std::int64_t> counts(iterations_per_window_.begin(), iterations_per_window_.end());
  out.integers("iteration.iterations_per_window", counts);
  out.integer("iteration.windows_not_converged", static_cast<std::int64_t>(not_converged_));
  out.integer("iteration.last_window_iterations", static_cast<std::int64_t>(last_iterations_));
  if (!accelerator_) return;
  std::vector<std::int64_t> sizes;
  for (const acceleration::Block& b : blocks_) sizes.push_back(static_cast<std::int64_t>(b.size));
  out.integers("iteration.accelerator.block_sizes", sizes);
  const acceleration::AcceleratorState state = accelerator_->state();
  out.numbers("iteration.accelerator.scalars", state.scalars);
  out.integer("iteration.accelerator.vectors", static_cast<std::int64_t>(state.vectors.size()));
  for (std::size_t i = 0; i < state.vectors.size(); ++i)
    out.numbers(fmt::format("iteration.accelerator.vector.{}", i), state.vectors[i]);
}

void WindowIteration::restore(const StateFileReader& in,
                              const std::vector<std::pair<std::string, std::string>>& sent_fields) {
  sent_.clear();
  for (const auto& [participant, field] : sent_fields) {
    const std::string key = "iteration.sent." + participant + "." + field;
    if (in.has(key))
      sent_[participant][field] = std::make_shared<const std::vector<double>>(in.numbers(key));
  }
  iterations_per_window_.clear();
  for (std::int64_t n : in.integers("iteration.iterations_per_window"))
    iterations_per_window_.push_back(static_cast<std::size_t>(n));
  not_converged_ = static_cast<std::size_t>(in.integer("iteration.windows_not_converged"));
  last_iterations_ = static_cast<std::size_t>(in.integer("iteration.last_window_iterations"));
  iteration_ = 0;
  if (!in.has("iteration.accelerator.block_sizes")) return;
  const std::vector<std::int64_t> sizes = in.integers("iteration.accelerator.block_sizes");
  if (sizes.size() != spec_.accelerated.size())
    throw Error(ExitCode::bad_input,
                fmt::format("{}: the accelerator had {} fields, the job accelerates {}",
                            in.file().string(), sizes.size(), spec_.accelerated.size()));
  blocks_.clear();
  for (std::size_t b = 0; b < sizes.size(); ++b)
    blocks_.push_back(block_of(spec_.accelerated[b], static_cast<std::size_t>(sizes[b])));
  accelerator_ = acceleration::make_accelerator(spec_.acceleration, blocks_);
  acceleration::AcceleratorState state;
  state.scalars = in.numbers("iteration.accelerator.scalars");
  const auto vectors = in.integer("iteration.accelerator.vectors");
  for (std::int64_t i = 0; i < vectors; ++i)
    state.vectors.push_back(in.numbers(fmt::format("iteration.accelerator.vector.{}", i)));
  try {
    accelerator_->restore(state);
  } catch (const std::invalid_argument& e) {
    throw Error(ExitCode::bad_input, fmt::format("{}: the accelerator's state does not fit: {}",
                                                 in.file().string(), e.what()));
  }
}

}  // namespace cosim::cplscheme
