#include "openfoam/case/existing_case.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cosim/error.hpp"
#include "cosim/io/files.hpp"
#include "openfoam/case/generated_case.hpp"
#include "openfoam/foam/foam_application.hpp"

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

void check_existing_case(const fs::path& c) {
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
                  {"div(rhoPhi,U)", "div(phi,alpha)", "div(phirb,alpha)",
                   "div(((rho*nuEff)*dev2(T(grad(U)))))", "Euler"},
                  "interFoam's divergence schemes and Euler in time (a restart restores no older "
                  "time level)");
  for (const char* field : {"alpha.water", "U", "p_rgh"}) {
    require_file(c / "0" / field, "the initial fields alpha.water, U and p_rgh in 0/");
  }
}

void copy_existing_case(const fs::path& case_dir, const fs::path& run_case_dir) {
  fs::create_directories(run_case_dir);
  for (const char* sub : {"system", "constant", "0"}) {
    fs::copy(case_dir / sub, run_case_dir / sub,
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  }
}

namespace {

// Whether an OpenFOAM file of the copy is written in binary or compressed.
bool is_binary_or_compressed(const fs::path& file) {
  if (file.extension() == ".gz") return true;
  std::ifstream in(file);
  std::string head(2048, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const auto at = head.find("format");
  return at != std::string::npos && head.find("binary", at) < head.find(';', at);
}

bool has_binary_files(const fs::path& directory) {
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) return false;
  for (const auto& entry : fs::directory_iterator(directory)) {
    if (entry.is_regular_file() && is_binary_or_compressed(entry.path())) return true;
  }
  return false;
}

}  // namespace

void prepare_cloud_in_copy(const DictionaryQuery& query, const SoilSettings& soil) {
  const fs::path properties = query.case_dir / "constant" / "kinematicCloudProperties";
  if (fs::exists(properties)) {
    spdlog::info(
        "the case's constant/kinematicCloudProperties is replaced by the soil's parcels' "
        "(one per cell, Ergun-Wen-Yu drag, no injection)");
  }
  cosim::write_file_atomically(properties, soil_cloud_properties(soil));
  const std::string stress = "div((((alphac*rho)*nuEff)*dev2(T(grad(U)))))";
  if (text_without_comments(query.case_dir / "system" / "fvSchemes").find(stress) ==
      std::string::npos) {
    const fs::path schemes = fs::path("system") / "fvSchemes";
    const std::string scheme =
        dictionary_value(query, schemes, "divSchemes/div(((rho*nuEff)*dev2(T(grad(U)))))");
    set_dictionary_entry(query, schemes, "divSchemes/" + stress, scheme);
    spdlog::info(
        "MPPICInterFoam's stress scheme {} is added to the case's system/fvSchemes as "
        "interFoam's: {}",
        stress, scheme);
  }
}

void convert_copy_to_ascii(const DictionaryQuery& query) {
  const fs::path& c = query.case_dir;
  if (!has_binary_files(c / "constant" / "polyMesh") && !has_binary_files(c / "0")) return;
  spdlog::info(
      "the case's mesh or initial fields are binary or compressed: converted to ASCII "
      "(foamFormatConvert) in the run's copy");
  run_application(query.installation, "foamFormatConvert", {"-constant"}, c,
                  query.log_file.parent_path() / "foamFormatConvert.log");
  for (const fs::path& dir : {c / "constant" / "polyMesh", c / "0"}) {
    if (has_binary_files(dir)) {
      throw cosim::InputError(
          cosim::SourceLocation{dir.string(), 0, 0}, "format",
          "binary or compressed files remain after foamFormatConvert; write the case in ASCII "
          "(writeFormat ascii, writeCompression off)");
    }
  }
}

}  // namespace openfoam
