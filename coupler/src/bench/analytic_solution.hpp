#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cosim/config/node.hpp"

// The analytic solutions a bench metric can be compared with, selected by
// name in the suite (`reference: {analytic: <name>, parameters: {...}}`).
// A solution is a number (a steady velocity) or a curve: a value at an
// abscissa (a position along a profile, or a time) at a time.
namespace cosim::bench {

using Parameters = std::map<std::string, double>;

struct ParameterDoc {
  std::string name;
  std::string doc;
  std::optional<double> fallback;  // absent: required
};

class AnalyticSolution {
 public:
  virtual ~AnalyticSolution() = default;
  virtual std::string name() const = 0;
  // What it is and where it comes from (paper and equation).
  virtual std::string doc() const = 0;
  virtual std::vector<ParameterDoc> parameters() const = 0;
  // A curve takes its abscissa (and time); a number ignores both.
  virtual bool is_curve() const = 0;
  virtual double value(const Parameters& p, double abscissa, double time) const = 0;

  // Refuses unknown and missing parameters and values the solution cannot
  // use, located at the node (InputError).
  void check_parameters(const std::optional<config::Node>& given,
                        const config::Node& reference) const;
  // The given parameters with the defaults of the absent ones.
  Parameters with_defaults(const Parameters& given) const;

 protected:
  // Further checks of a complete set (e.g. a density must be positive);
  // returns an empty string or what is wrong.
  virtual std::string check_values(const Parameters&) const { return {}; }
};

// nullptr when there is none by that name.
const AnalyticSolution* find_analytic_solution(const std::string& name);
std::vector<const AnalyticSolution*> analytic_solutions();
std::string unknown_solution_message(const std::string& name);

// Every solution with its parameters, for `cosim bench --help-config`.
std::string analytic_solutions_help();

}  // namespace cosim::bench
