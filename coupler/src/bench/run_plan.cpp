#include "bench/run_plan.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

#include "bench/input_file.hpp"
#include "bench/pairing.hpp"
#include "cosim/io/content_hash.hpp"
#include "cosim/io/files.hpp"

namespace cosim::bench {

namespace fs = std::filesystem;

std::string PlannedRun::id() const {
  std::string s = scenario->name + "/" + backend_name();
  if (level != nullptr) s += "@" + level->label;
  return s;
}

std::string PlannedRun::level_label() const {
  return level != nullptr ? level->label : std::string();
}

std::string directory_name(const std::string& label) {
  std::string out;
  for (unsigned char c : label)
    out += (std::isalnum(c) != 0 || c == '-' || c == '_' || c == '.') ? static_cast<char>(c) : '_';
  return out;
}

namespace {

// The simulated end time of a case or job, as its file gives it.
double end_time_of(const InputFile& f) {
  for (const char* key : {"end_time", "time.end_time"}) {
    const std::string text = scalar_at(f.root(), key);
    if (!text.empty()) {
      try {
        return std::stod(text);
      } catch (const std::exception&) {
        return 0.0;
      }
    }
  }
  return 0.0;
}

class RunKey {
 public:
  void add(const std::string& name, const InputFile& f) {
    hash_.update(name).update(f.text());
    for (const auto& referenced : f.referenced_files())
      hash_.update(referenced.string()).update(to_hex16(hash_file(referenced)));
  }
  std::string hex() const { return hash_.hex(); }

 private:
  ContentHash hash_;
};

void prepare(PlannedRun& run, Resolution resolution) {
  const Scenario& s = *run.scenario;
  const BackendRuns& b = *run.backend;
  std::vector<Override> overrides = s.overrides.at(resolution);
  const auto own = b.overrides.at(resolution);
  overrides.insert(overrides.end(), own.begin(), own.end());
  if (run.level != nullptr)
    overrides.insert(overrides.end(), run.level->set.begin(), run.level->set.end());

  const fs::path input = run.directory / "input";
  create_output_directory(input);
  const auto other = b.file_at.find(resolution);
  const fs::path file = other != b.file_at.end() ? other->second : b.file;
  RunKey key;
  const fs::path out = run.output();
  switch (b.form) {
    case InputForm::standalone_case: {
      InputFile c = InputFile::read(file);
      c.apply_all(overrides, "case");
      c.write(input / "case.yaml");
      key.add("case", c);
      run.end_time = end_time_of(c);
      run.executable = b.backend->executable;
      run.args = {"--config", (input / "case.yaml").string(), "--output", out.string()};
      break;
    }
    case InputForm::ready_job: {
      InputFile job = InputFile::read(file);
      job.apply_all(overrides, "job");
      job.write(input / "job.yaml");
      key.add("job", job);
      run.end_time = end_time_of(job);
      run.coupled = true;
      break;
    }
    case InputForm::coupled_fluid: {
      InputFile soil = InputFile::read(s.coupling->soil);
      InputFile fluid = InputFile::read(file);
      soil.apply_all(overrides, "soil");
      fluid.apply_all(overrides, "fluid");
      const fs::path soil_file = input / "soil.yaml";
      const fs::path fluid_file = input / "fluid.yaml";
      PairedJob paired = make_paired_job(*b.backend, s, std::move(soil), std::move(fluid),
                                         directory_name(s.name + "_" + b.backend->name),
                                         soil_file.string(), fluid_file.string());
      paired.job.apply_all(overrides, "job");
      paired.soil.write(soil_file);
      paired.fluid.write(fluid_file);
      paired.job.write(input / "job.yaml");
      key.add("soil", paired.soil);
      key.add("fluid", paired.fluid);
      key.add("job", paired.job);
      run.end_time = end_time_of(paired.job);
      run.coupled = true;
      break;
    }
  }
  if (run.coupled) {
    run.executable = "cosim";
    run.args = {"run", (input / "job.yaml").string(), "--output", out.string()};
  }
  run.key = key.hex();
}

}  // namespace

std::vector<PlannedRun> plan_runs(const Suite& suite, const BenchOptions& options) {
  for (const auto& name : options.only) {
    const bool found = std::any_of(suite.scenarios.begin(), suite.scenarios.end(),
                                   [&](const Scenario& s) { return s.name == name; });
    if (!found) {
      std::string names;
      for (const auto& s : suite.scenarios) names += (names.empty() ? "" : ", ") + s.name;
      throw InputError(fmt::format("--only {}: suite '{}' ({}) has no such scenario; it has: {}",
                                   name, suite.name, suite.file.string(), names));
    }
  }
  std::vector<PlannedRun> runs;
  for (const auto& s : suite.scenarios) {
    if (!options.only.empty() &&
        std::find(options.only.begin(), options.only.end(), s.name) == options.only.end())
      continue;
    for (const auto& b : s.backends) {
      const fs::path base = options.output / "runs" / directory_name(s.name);
      const auto add = [&](const Level* level) {
        PlannedRun run;
        run.scenario = &s;
        run.backend = &b;
        run.level = level;
        std::string dir = b.backend->name;
        if (level != nullptr) dir += "--" + directory_name(level->label);
        run.directory = base / dir;
        prepare(run, options.resolution);
        runs.push_back(std::move(run));
      };
      if (b.levels.empty()) {
        add(nullptr);
        continue;
      }
      for (const auto& level : b.levels)
        if (!level.only || *level.only == options.resolution) add(&level);
    }
  }
  return runs;
}

}  // namespace cosim::bench
