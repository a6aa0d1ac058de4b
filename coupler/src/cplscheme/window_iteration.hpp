#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "acceleration/accelerator.hpp"
#include "cosim/io/state_file.hpp"
#include "cosim/io/time_series_writer.hpp"
#include "fields_by_peer.hpp"
#include "job/coupling_spec.hpp"

namespace cosim::cplscheme {

// The iterations of an implicit scheme's window (preCICE's implicit coupling
// scheme): x^k is what the coupler sent the participants for the window,
// H(x^k) what their run of the window from its start gives back; the window
// has converged when every convergence measure of r^k = H(x^k) - x^k holds,
// and otherwise runs again with x^{k+1} from the accelerator (its fields;
// the others take H(x^k)).
//
// Each window's last iteration is one row of coupling_iterations.csv:
// window, time [s], iterations, converged, then per measured field its
// residual ||r|| [unit] and relative residual ||r|| / ||H(x)|| [1].
class WindowIteration {
 public:
  // The bounds the reader declared for a field (FieldSpec's lower and upper).
  using Bounds = std::pair<double, double>;
  // `units`: each measured field's unit, by `<participant>.<field>`;
  // `bounds`: each accelerated field's, by the same label (an accelerated
  // iterate is held within them, as a mapped field is).
  WindowIteration(const job::CouplingSpec& spec, const std::map<std::string, std::string>& units,
                  const std::map<std::string, Bounds>& bounds, const std::filesystem::path& csv);
  ~WindowIteration();

  // The iterate the participants run the window with next (what the coupler
  // has just sent them), field by field: fields not in `x` keep theirs.
  void sent(const FieldsByPeer& x);

  enum class Verdict {
    converged,  // every measure holds: H(x^k) begins the next window
    repeat,     // run the window again with next()
    gave_up,    // max_iterations reached with on_max_iterations: continue
  };
  // Judges the participants' answer to the current iterate; throws
  // NumericalError (exit 4) naming the window, the field and its residual
  // when a residual diverges, or at max_iterations with `stop`.
  Verdict judge(std::size_t window, double time, const FieldsByPeer& answer);
  // After `repeat`: x^{k+1}, every field of the answer with the accelerated
  // ones replaced.
  const FieldsByPeer& next() const { return next_; }

  std::size_t iteration() const { return iteration_; }  // of the window being judged
  std::size_t last_window_iterations() const { return last_iterations_; }
  // The `coupling` section of summary.json: iterations per window (total,
  // median, max), windows not converged, the last residuals.
  nlohmann::json summary() const;

  // A checkpoint's part of the iteration, between windows: the last iterate
  // sent (the next window's first), the accelerator's history and the
  // tallies. `sent_fields` lists every (participant, field) the coupler
  // sends, as the restore needs the names.
  void save(StateFileWriter& out) const;
  void restore(const StateFileReader& in,
               const std::vector<std::pair<std::string, std::string>>& sent_fields);

 private:
  struct Measure;
  acceleration::Block block_of(const job::SentField& f, std::size_t size) const;
  void window_done(bool converged, std::size_t window, double time);
  std::vector<double> gather(const FieldsByPeer& fields) const;
  void scatter(std::span<const double> values, FieldsByPeer& fields) const;
  std::string residuals_text() const;

  const job::CouplingSpec& spec_;
  std::vector<Measure> measures_;
  std::vector<acceleration::Block> blocks_;  // the accelerated fields, in spec order
  std::map<std::string, Bounds> bounds_;
  std::unique_ptr<acceleration::Accelerator> accelerator_;
  TimeSeriesWriter csv_;
  FieldsByPeer sent_, next_;
  std::size_t iteration_ = 0;
  std::size_t last_iterations_ = 0;
  std::vector<std::size_t> iterations_per_window_;
  std::size_t not_converged_ = 0;
};

}  // namespace cosim::cplscheme
