#include "openfoam/case/case_properties.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <sstream>

#include "cosim/error.hpp"
#include "openfoam/foam/foam_application.hpp"
#include "openfoam/foam/foam_dictionary.hpp"

namespace openfoam {

namespace {

namespace fs = std::filesystem;

FluidProperties fluid(const DictionaryQuery& query, const std::string& phase) {
  const fs::path file = fs::path("constant") / "transportProperties";
  const double rho =
      scalar_value(dictionary_value(query, file, phase + "/rho"), file, phase + "/rho");
  const double nu = scalar_value(dictionary_value(query, file, phase + "/nu"), file, phase + "/nu");
  if (!(rho > 0.0) || !(nu > 0.0)) {
    throw cosim::InputError(cosim::SourceLocation{(query.case_dir / file).string(), 0, 0}, phase,
                            fmt::format("rho {} and nu {} must be positive", rho, nu));
  }
  return {rho, rho * nu};
}

// The numbers in the `which`-th (from 0) "(...)" after `label` in checkMesh's report.
std::vector<double> reported_vector(const std::string& report, const std::string& label,
                                    std::size_t which, const fs::path& log) {
  std::size_t begin = report.find(label);
  if (begin == std::string::npos) {
    throw cosim::Error(cosim::ExitCode::participant_failed,
                       fmt::format("checkMesh's report ({}) has no '{}'", log.string(), label));
  }
  begin += label.size();  // the label itself has parentheses
  for (std::size_t k = 0; k <= which; ++k) begin = report.find('(', begin) + 1;
  const std::size_t end = report.find(')', begin);
  std::istringstream in(report.substr(begin, end - begin));
  std::vector<double> v;
  for (double x = 0.0; in >> x;) v.push_back(x);
  return v;
}

}  // namespace

CaseProperties properties_of(const GeneratedCase& g) {
  CaseProperties p;
  p.dimension = g.dimension;
  p.thickness = g.dimension == 2 ? g.upper[2] - g.origin[2] : 1.0;
  p.water = g.water;
  p.air = g.air;
  p.gravity = g.gravity;
  return p;
}

CaseProperties read_case_properties(const Installation& installation, const fs::path& case_dir,
                                    const fs::path& log_dir) {
  const DictionaryQuery query{installation, case_dir, log_dir / "foamDictionary.log"};
  CaseProperties p;
  p.water = fluid(query, "water");
  p.air = fluid(query, "air");
  const fs::path g = fs::path("constant") / "g";
  p.gravity = vector_value(dictionary_value(query, g, "value"), g, "value");
  const fs::path h = fs::path("constant") / "hRef";
  if (fs::exists(case_dir / h)) {
    p.reference_height = scalar_value(dictionary_value(query, h, "value"), h, "value");
  }

  const fs::path log = log_dir / "checkMesh.log";
  const std::string report = application_output(installation, "checkMesh", {}, case_dir, log);
  const std::vector<double> directions =
      reported_vector(report, "solution (non-empty) directions", 0, log);
  const std::vector<double> lower = reported_vector(report, "Overall domain bounding box", 0, log);
  const std::vector<double> upper = reported_vector(report, "Overall domain bounding box", 1, log);
  if (directions.size() != 3 || lower.size() != 3 || upper.size() != 3) {
    throw cosim::Error(cosim::ExitCode::participant_failed,
                       fmt::format("checkMesh's report ({}) could not be read", log.string()));
  }
  int solved = 0;
  for (double d : directions) solved += d > 0.0 ? 1 : 0;
  if (solved == 3) {
    p.dimension = 3;
  } else if (solved == 2 && !(directions[2] > 0.0)) {
    p.dimension = 2;
    p.thickness = upper[2] - lower[2];
  } else {
    throw cosim::InputError(
        cosim::SourceLocation{(case_dir / "constant" / "polyMesh" / "boundary").string(), 0, 0},
        "empty",
        fmt::format("the mesh solves along ({} {} {}): a 2D case must be one cell thick along z "
                    "between empty patches (the soil's plane is x-y), a 3D case have none",
                    directions[0], directions[1], directions[2]));
  }
  if (report.find("Failed ") != std::string::npos) {
    spdlog::warn("checkMesh reports failed mesh checks on the case (see {})", log.string());
  }
  return p;
}

}  // namespace openfoam
