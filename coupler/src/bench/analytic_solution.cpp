#include "bench/analytic_solution.hpp"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "builtin_solutions.hpp"

namespace cosim::bench {

void AnalyticSolution::check_parameters(const std::optional<config::Node>& given,
                                        const config::Node& reference) const {
  Parameters values;
  std::set<std::string> known;
  for (const auto& p : parameters()) known.insert(p.name);
  if (given) {
    for (const auto& [key, value] : given->entries()) {
      if (!known.count(key)) {
        std::string names;
        for (const auto& p : parameters()) names += (names.empty() ? "" : ", ") + p.name;
        value.fail_at_key(
            fmt::format("'{}' is not a parameter of '{}' (it takes: {})", key, name(), names));
      }
      values[key] = value.as<double>();
    }
  }
  for (const auto& p : parameters()) {
    if (!p.fallback && !values.count(p.name))
      reference.fail(fmt::format("'{}' needs the parameter '{}': {}", name(), p.name, p.doc));
  }
  const std::string wrong = check_values(with_defaults(values));
  if (!wrong.empty()) (given ? *given : reference).fail(fmt::format("'{}': {}", name(), wrong));
}

Parameters AnalyticSolution::with_defaults(const Parameters& given) const {
  Parameters out = given;
  for (const auto& p : parameters())
    if (p.fallback && !out.count(p.name)) out[p.name] = *p.fallback;
  return out;
}

std::vector<const AnalyticSolution*> analytic_solutions() {
  static const std::vector<std::unique_ptr<AnalyticSolution>> all = builtin_solutions();
  std::vector<const AnalyticSolution*> out;
  for (const auto& s : all) out.push_back(s.get());
  return out;
}

const AnalyticSolution* find_analytic_solution(const std::string& name) {
  for (const auto* s : analytic_solutions())
    if (s->name() == name) return s;
  return nullptr;
}

std::string unknown_solution_message(const std::string& name) {
  std::string names;
  for (const auto* s : analytic_solutions()) names += (names.empty() ? "" : ", ") + s->name();
  return fmt::format("no analytic solution '{}' (there are: {})", name, names);
}

std::string analytic_solutions_help() {
  std::string out = "Analytic solutions (reference: {analytic: <name>, parameters: {...}}):\n";
  for (const auto* s : analytic_solutions()) {
    out += fmt::format("\n  {} ({})\n    {}\n", s->name(), s->is_curve() ? "curve" : "number",
                       s->doc());
    for (const auto& p : s->parameters()) {
      out += fmt::format("    {:<26} {}{}\n", p.name, p.doc,
                         p.fallback ? fmt::format(" (default {})", *p.fallback) : "; required");
    }
  }
  return out;
}

}  // namespace cosim::bench
