#include "openfoam/case/existing_case.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cosim/error.hpp"

namespace openfoam {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void missing(const fs::path& file, const std::string& entry, const std::string& why) {
  throw cosim::InputError(cosim::SourceLocation{file.string(), 0, 0}, entry,
                          fmt::format("missing: {}", why));
}

// The file's text without comments, so that a commented-out entry does not
// count.
std::string text_without_comments(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "//") == 0) {
      i = text.find('\n', i);
      if (i == std::string::npos) break;
      out += '\n';
    } else if (text.compare(i, 2, "/*") == 0) {
      i = text.find("*/", i + 2);
      if (i == std::string::npos) break;
      ++i;
    } else {
      out += text[i];
    }
  }
  return out;
}

const fs::path& require_file(const fs::path& file, const std::string& why) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) missing(file, file.filename().string(), why);
  return file;
}

void require_entries(const fs::path& file, std::initializer_list<const char*> entries,
                     const std::string& why) {
  const std::string text = text_without_comments(require_file(file, why));
  for (const char* entry : entries) {
    if (text.find(entry) == std::string::npos) missing(file, entry, why);
  }
}

}  // namespace

void check_existing_case(const fs::path& c, bool cloud) {
  std::error_code ec;
  if (!fs::is_directory(c / "constant" / "polyMesh", ec)) {
    require_file(c / "system" / "blockMeshDict",
                 "a mesh: constant/polyMesh, or system/blockMeshDict for blockMesh to make one");
  }
  require_entries(c / "constant" / "transportProperties", {"phases", "water", "air", "sigma"},
                  "the two phases (water air) with their nu and rho, and sigma");
  require_file(c / "constant" / "g", "gravity");
  require_file(c / "constant" / "turbulenceProperties", "the turbulence model (laminar)");
  require_entries(c / "system" / "fvSolution",
                  {"\"alpha.water.*\"", "\"pcorr.*\"", "p_rgh", "p_rghFinal", "PIMPLE"},
                  "interFoam's solvers; pcorr runs at every start of the solver");
  require_entries(c / "system" / "fvSchemes",
                  {"div(rhoPhi,U)", "div(phi,alpha)", "div(phirb,alpha)", "Euler"},
                  "interFoam's divergence schemes and Euler in time (a restart restores no older "
                  "time level)");
  for (const char* field : {"alpha.water", "U", "p_rgh"}) {
    require_file(c / "0" / field, "the initial fields alpha.water, U and p_rgh in 0/");
  }
  if (!cloud) return;
  require_entries(c / "constant" / "kinematicCloudProperties",
                  {"ErgunWenYuDrag", "alphac", "rho0", "alphaMax", "semiImplicit"},
                  "MPPICInterFoam's cloud for the soil's parcels: Ergun-Wen-Yu drag on alphac, "
                  "rho0, alphaMax, the semi-implicit momentum source");
  require_entries(c / "system" / "fvSchemes", {"div((((alphac*rho)*nuEff)*dev2(T(grad(U)))))"},
                  "MPPICInterFoam's viscous stress scheme");
}

void copy_existing_case(const fs::path& case_dir, const fs::path& run_case_dir) {
  fs::create_directories(run_case_dir);
  for (const char* sub : {"system", "constant", "0"}) {
    fs::copy(case_dir / sub, run_case_dir / sub,
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  }
}

}  // namespace openfoam
