#include <fmt/format.h>

#include <set>

#include "bench/analytic_solution.hpp"
#include "bench/suite.hpp"
#include "cosim/config/document.hpp"

namespace cosim::bench {

std::string to_string(Resolution resolution) {
  return resolution == Resolution::coarse ? "coarse" : "full";
}

std::optional<double> MetricSpec::tolerance_for(const std::string& backend) const {
  if (tolerance) return tolerance;
  const auto it = backend_tolerances.find(backend);
  return it != backend_tolerances.end() ? std::optional<double>(it->second) : std::nullopt;
}

std::vector<Override> OverrideSet::at(Resolution r) const {
  std::vector<Override> out = always;
  const auto& extra = r == Resolution::coarse ? coarse : full;
  out.insert(out.end(), extra.begin(), extra.end());
  return out;
}

namespace {

const std::set<std::string> roles{"soil", "fluid", "case", "job"};

// A report's line, with the backend's name in front.
constexpr std::size_t max_reason_length = 300;

const BackendDescriptor& backend_from(const std::string& name, const config::Node& where,
                                      const BackendCatalog& backends) {
  if (const auto* b = backends.find(name)) return *b;
  where.fail_at_key(fmt::format("unknown backend '{}' (registered in {}: {})", name,
                                backends.directory().string(), backends.names_text()));
}

std::vector<Override> read_overrides(const config::Node& parent,
                                     const std::set<std::string>& allowed) {
  std::vector<Override> out;
  auto set = parent.find("set");
  if (!set) return out;
  for (const auto& [role, keys] : set->entries()) {
    if (!allowed.count(role)) {
      std::string names;
      for (const auto& r : allowed) names += (names.empty() ? "" : ", ") + r;
      keys.fail_at_key(fmt::format("'{}' is not an input of this run (here: {})", role, names));
    }
    for (const auto& [key_path, value] : keys.entries()) {
      if (key_path.empty() || key_path.front() == '.' || key_path.back() == '.' ||
          key_path.find("..") != std::string::npos)
        value.fail_at_key(fmt::format("'{}' is not a dotted key path", key_path));
      out.push_back({role, key_path, YAML::Clone(value.yaml()), value.key_location()});
    }
  }
  return out;
}

OverrideSet read_override_set(const config::Node& parent, const std::set<std::string>& allowed) {
  OverrideSet set;
  set.always = read_overrides(parent, allowed);
  if (auto c = parent.find("coarse")) set.coarse = read_overrides(*c, allowed);
  if (auto f = parent.find("full")) set.full = read_overrides(*f, allowed);
  return set;
}

std::set<std::string> roles_of(InputForm form) {
  switch (form) {
    case InputForm::standalone_case:
      return {"case"};
    case InputForm::coupled_fluid:
      return {"soil", "fluid", "job"};
    case InputForm::ready_job:
      return {"job"};
  }
  return {};
}

BackendRuns read_backend(const std::string& name, const config::Node& node, bool coupled,
                         const BackendCatalog& backends) {
  BackendRuns b;
  b.backend = &backend_from(name, node, backends);
  b.where = node.key_location();
  int forms = 0;
  for (const auto& [key, form] :
       {std::pair{"case", InputForm::standalone_case}, std::pair{"fluid", InputForm::coupled_fluid},
        std::pair{"job", InputForm::ready_job}}) {
    if (auto f = node.find(key)) {
      b.form = form;
      b.file = f->as_path();
      ++forms;
    }
  }
  if (forms != 1) node.fail("give exactly one of case, fluid and job");
  if (b.form == InputForm::coupled_fluid && !coupled)
    node["fluid"].fail(
        "a fluid case is coupled to the scenario's soil: give `soil` and "
        "`coupling` in the scenario, or run the case standalone with `case`");
  if (b.form == InputForm::coupled_fluid && !b.backend->is_fluid()) {
    std::vector<std::string> fluids;
    for (const auto& other : backends.names())
      if (backends.find(other)->is_fluid()) fluids.push_back(other);
    node["fluid"].fail(fmt::format("backend '{}' is not a fluid; the pairings are {}", name,
                                   fmt::join(fluids, ", ")));
  }
  if (b.form == InputForm::standalone_case && !b.backend->has_standalone_case())
    node["case"].fail(fmt::format("the {} has no standalone case: give a `job`", name));
  b.overrides = read_override_set(node, roles_of(b.form));
  const char* form_key = b.form == InputForm::standalone_case ? "case"
                         : b.form == InputForm::coupled_fluid ? "fluid"
                                                              : "job";
  for (const auto& [key, resolution] :
       {std::pair{"coarse", Resolution::coarse}, std::pair{"full", Resolution::full}}) {
    const auto block = node.find(key);
    if (!block) continue;
    for (const char* other : {"case", "fluid", "job"})
      if (block->has(other) && std::string(other) != form_key)
        (*block)[other].fail_at_key(fmt::format(
            "this backend runs a `{}`; give another {} here, not a {}", form_key, form_key, other));
    if (auto f = block->find(form_key)) b.file_at[resolution] = f->as_path();
  }
  if (auto levels = node.find("levels")) {
    std::set<std::string> labels;
    for (const auto& l : levels->items()) {
      Level level;
      level.label = l["label"].as<std::string>();
      if (!labels.insert(level.label).second)
        l["label"].fail(fmt::format("a second level labelled '{}'", level.label));
      level.cells = l["cells"].as<double>();
      level.set = read_overrides(l, roles_of(b.form));
      if (auto r = l.find("resolution"))
        level.only = r->as<std::string>() == "coarse" ? Resolution::coarse : Resolution::full;
      b.levels.push_back(std::move(level));
    }
  }
  return b;
}

QuantitySpec read_quantity(const config::Node& node) {
  QuantitySpec q;
  q.where = node.location();
  int kinds = 0;
  for (const auto& [kind, params] : node.entries()) {
    q.kind = kind;
    q.params = YAML::Clone(params.yaml());
    q.key_path = params.key_path();
    q.where = params.key_location();
    ++kinds;
    // `at` is a reduction's name or a time.
    if (auto at = params.find("at")) {
      const auto text = at->yaml().Scalar();
      if (!(text == "end" || text == "max" || text == "min" || text == "series" ||
            text == "first_above") &&
          at->as<double>() < 0.0)
        at->fail("a time must not be negative");
    }
  }
  if (kinds != 1)
    node.fail(
        "give exactly one kind: gauge, time_series, profile, water_front, soil, summary "
        "or wall_gradient");
  return q;
}

ReferenceSpec read_reference(const config::Node& node) {
  ReferenceSpec r;
  r.where = node.location();
  r.key_path = node.key_path();
  r.params = YAML::Clone(node.yaml());
  int kinds = 0;
  if (node.has("value")) {
    r.kind = "value";
    ++kinds;
  }
  if (auto a = node.find("analytic")) {
    r.kind = "analytic";
    ++kinds;
    // The solution's name and parameters are checked here, before anything runs.
    const auto name = a->as<std::string>();
    const AnalyticSolution* solution = find_analytic_solution(name);
    if (solution == nullptr) a->fail(unknown_solution_message(name));
    solution->check_parameters(node.find("parameters"), node);
  }
  if (auto c = node.find("csv")) {
    r.kind = "csv";
    r.csv = c->as_path();
    ++kinds;
    const bool one_number = node.has("column");
    const bool curve = node.has("x") && node.has("y");
    if (one_number == curve)
      node.fail("a csv reference takes either `column` (one number) or `x` and `y` (a curve)");
  }
  if (kinds != 1) node.fail("give exactly one of value, analytic and csv");
  for (const char* key : {"column", "x", "y", "where"})
    if (node.has(key) && r.kind != "csv") node[key].fail_at_key("only a csv reference takes it");
  if (node.has("parameters") && r.kind != "analytic")
    node["parameters"].fail_at_key("only an analytic reference takes parameters");
  return r;
}

ErrorSpec read_error(const config::Node& node) {
  ErrorSpec e;
  if (node.is_scalar()) {
    e.norm = node.as<std::string>();
    return e;
  }
  e.norm = node["norm"].as<std::string>();
  e.scale = node.get<double>("scale");
  if (auto w = node.find("window")) {
    const auto v = w->as<std::vector<double>>();
    if (!(v[0] <= v[1])) w->fail("a window is [a, b] with a <= b");
    e.window = std::make_pair(v[0], v[1]);
  }
  if (auto o = node.find("offsets")) {
    const auto v = o->as<std::vector<double>>();
    if (!(v[0] <= v[1])) o->fail("offsets are [a, b] with a <= b");
    e.offsets = {v[0], v[1]};
  }
  return e;
}

MetricSpec read_metric(const config::Node& node, const BackendCatalog& backends) {
  MetricSpec m;
  m.name = node["name"].as<std::string>();
  m.key_path = node.key_path();
  m.where = node.location();
  m.label = node.get("label", m.name.c_str());
  m.unit = node.get<std::string>("unit");
  m.quantity = read_quantity(node["quantity"]);
  if (auto r = node.find("reference")) m.reference = read_reference(*r);
  if (auto e = node.find("error")) m.error = read_error(*e);
  if (auto t = node.find("tolerance")) {
    if (m.reference.kind == "none") t->fail_at_key("a tolerance needs a reference");
    if (t->is_map()) {
      for (const auto& [backend, value] : t->entries()) {
        backend_from(backend, value, backends);
        m.backend_tolerances[backend] = value.as<double>();
      }
    } else {
      m.tolerance = t->as<double>();
    }
  }
  if (auto r = node.find("resolution"))
    m.resolution = r->as<std::string>() == "coarse" ? Resolution::coarse : Resolution::full;
  m.summarize = node.get<std::string>("summarize");
  return m;
}

Scenario read_scenario(const config::Node& node, const BackendCatalog& backends) {
  Scenario s;
  s.name = node["name"].as<std::string>();
  s.where = node.location();
  s.title = node.get("title", s.name.c_str());
  s.about = node.get("about", "");
  const bool has_soil = node.has("soil");
  const bool has_coupling = node.has("coupling");
  if (has_soil != has_coupling)
    node[has_soil ? "soil" : "coupling"].fail_at_key(
        "a coupled scenario gives both `soil` and `coupling`");
  if (has_soil) {
    Coupling c;
    c.soil = node["soil"].as_path();
    c.soil_backend = backends.soil();
    if (c.soil_backend == nullptr)
      node["soil"].fail(
          fmt::format("no registered backend takes the soil's side of a pairing "
                      "(registered in {}: {})",
                      backends.directory().string(), backends.names_text()));
    const auto coupling = node["coupling"];
    c.end_time = coupling["end_time"].as<double>();
    c.window = coupling["window"].as<double>();
    if (c.window > c.end_time) coupling["window"].fail("the window is longer than the run");
    if (auto drag = coupling.find("drag")) c.drag = YAML::Clone(drag->yaml());
    if (auto o = coupling.find("optional_reads"))
      c.optional_reads = o->as<std::vector<std::string>>();
    s.coupling = std::move(c);
  }
  s.overrides = read_override_set(node, {"soil", "job"});
  if (!has_soil)
    for (const auto* list : {&s.overrides.always, &s.overrides.coarse, &s.overrides.full})
      for (const auto& o : *list)
        if (o.role == "soil")
          throw InputError(o.where, node.key_path() + ".set",
                           "soil overrides need a coupled scenario (`soil`)");
  for (const auto& [name, b] : node["backends"].entries())
    s.backends.push_back(read_backend(name, b, has_soil, backends));
  if (auto absent = node.find("not_represented")) {
    for (const auto& [name, reason] : absent->entries()) {
      NotRepresented n{&backend_from(name, reason, backends), reason.as<std::string>(),
                       reason.key_location()};
      for (const auto& b : s.backends)
        if (b.backend == n.backend)
          reason.fail_at_key(fmt::format("'{}' runs the scenario (under `backends`)", name));
      if (n.reason.find('\n') != std::string::npos || n.reason.size() > max_reason_length)
        reason.fail(fmt::format("say why in one line of at most {} characters (here {})",
                                max_reason_length, n.reason.size()));
      s.not_represented.push_back(std::move(n));
    }
  }
  std::set<std::string> names;
  if (auto metrics = node.find("metrics")) {
    for (const auto& m : metrics->items()) {
      s.metrics.push_back(read_metric(m, backends));
      if (!names.insert(s.metrics.back().name).second)
        m["name"].fail(fmt::format("a second metric named '{}'", s.metrics.back().name));
    }
  }
  return s;
}

}  // namespace

Suite load_suite(const std::filesystem::path& file, const BackendCatalog& backends) {
  const auto doc = config::Document::load_file(file);
  const config::Node root = doc.root();
  suite_schema().validate(root);
  suite_schema().add_defaults(root);
  Suite suite;
  suite.file = file;
  suite.text = doc.text();
  suite.name = root["name"].as<std::string>();
  suite.title = root.get("title", suite.name.c_str());
  suite.about = root.get("about", "");
  std::set<std::string> names;
  for (const auto& s : root["scenarios"].items()) {
    suite.scenarios.push_back(read_scenario(s, backends));
    if (!names.insert(suite.scenarios.back().name).second)
      s["name"].fail(fmt::format("a second scenario named '{}'", suite.scenarios.back().name));
  }
  return suite;
}

}  // namespace cosim::bench
