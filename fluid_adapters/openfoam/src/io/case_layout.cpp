#include "openfoam/io/case_layout.hpp"

#include <fmt/format.h>

#include <cmath>

#include "cosim/error.hpp"
#include "openfoam/foam/field_file.hpp"

namespace openfoam {

namespace fs = std::filesystem;

namespace {

fs::path processor_dir(const fs::path& case_dir, int p) {
  return case_dir / fmt::format("processor{}", p);
}

// The entries of a field gathered from its processors' parts.
void gather(std::vector<double>& whole, const std::vector<double>& part,
            const std::vector<std::int64_t>& addressing, std::size_t components) {
  for (std::size_t local = 0; local < addressing.size(); ++local) {
    const auto global = static_cast<std::size_t>(addressing[local]);
    for (std::size_t k = 0; k < components; ++k)
      whole[global * components + k] = part[local * components + k];
  }
}

}  // namespace

CaseLayout::CaseLayout(fs::path case_dir, int processes, std::size_t cells)
    : case_dir_(std::move(case_dir)), processes_(processes), cells_(cells) {
  if (processes_ <= 1) return;
  owner_.assign(cells_, -1);
  local_.assign(cells_, -1);
  for (int p = 0; p < processes_; ++p) {
    const fs::path file =
        processor_dir(case_dir_, p) / "constant" / "polyMesh" / "cellProcAddressing";
    addressing_.push_back(read_label_list(file));
    const auto& labels = addressing_.back();
    for (std::size_t local = 0; local < labels.size(); ++local) {
      const std::int64_t global = labels[local];
      if (global < 0 || static_cast<std::size_t>(global) >= cells_ ||
          owner_[static_cast<std::size_t>(global)] >= 0) {
        throw cosim::Error(cosim::ExitCode::participant_failed,
                           fmt::format("{}: cell {} of processor {} is {} (the mesh has {} cells, "
                                       "each on one processor)",
                                       file.string(), local, p, global, cells_));
      }
      owner_[static_cast<std::size_t>(global)] = p;
      local_[static_cast<std::size_t>(global)] = static_cast<std::int64_t>(local);
    }
  }
  for (std::size_t c = 0; c < cells_; ++c) {
    if (owner_[c] < 0) {
      throw cosim::Error(cosim::ExitCode::participant_failed,
                         fmt::format("the decomposed case {} has no processor for cell {}",
                                     case_dir_.string(), c));
    }
  }
}

std::vector<fs::path> CaseLayout::roots() const {
  if (processes_ <= 1) return {case_dir_};
  std::vector<fs::path> r;
  for (int p = 0; p < processes_; ++p) r.push_back(processor_dir(case_dir_, p));
  return r;
}

void CaseLayout::copy_time_out(const std::string& name, const fs::path& into) const {
  for (const fs::path& root : roots()) {
    const fs::path target = into / fs::relative(root, case_dir_) / name;
    fs::create_directories(target.parent_path());
    fs::copy(root / name, target, fs::copy_options::recursive);
  }
}

void CaseLayout::copy_times_in(const fs::path& from) const {
  for (const fs::path& root : roots()) {
    const fs::path source = from / fs::relative(root, case_dir_);
    if (!fs::is_directory(source))
      throw cosim::InputError(
          fmt::format("{}: the checkpoint has no time directory of {} (a "
                      "case decomposed otherwise?)",
                      from.string(), fs::relative(root, case_dir_).string()));
    for (const auto& time : fs::directory_iterator(source))
      fs::copy(time.path(), root / time.path().filename(),
               fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  }
}

std::optional<TimeDirectory> CaseLayout::latest() const {
  return latest_time_directory(roots().front());
}

FoamFields CaseLayout::read(const std::string& name, int dim) const {
  if (processes_ <= 1) return read_foam_fields(case_dir_ / name, cells_, dim);
  const auto components = static_cast<std::size_t>(dim);
  FoamFields whole;
  for (int p = 0; p < processes_; ++p) {
    const auto& addressing = addressing_[static_cast<std::size_t>(p)];
    const FoamFields part =
        read_foam_fields(processor_dir(case_dir_, p) / name, addressing.size(), dim);
    const auto sized = [&](std::vector<double>& v, const std::vector<double>& from, std::size_t k) {
      if (from.empty()) return;
      if (v.empty()) v.assign(cells_ * k, 0.0);
      gather(v, from, addressing, k);
    };
    sized(whole.alpha_water, part.alpha_water, 1);
    sized(whole.p_rgh, part.p_rgh, 1);
    sized(whole.p, part.p, 1);
    sized(whole.velocity, part.velocity, components);
    sized(whole.alphac, part.alphac, 1);
    sized(whole.cloud_momentum, part.cloud_momentum, components);
  }
  return whole;
}

std::vector<double> CaseLayout::read_scalar(const std::string& name,
                                            const std::string& field) const {
  return read_gathered(name, field, FieldType::scalar);
}

std::vector<double> CaseLayout::read_vector(const std::string& name,
                                            const std::string& field) const {
  return read_gathered(name, field, FieldType::vector);
}

std::vector<double> CaseLayout::read_gathered(const std::string& name, const std::string& field,
                                              FieldType type) const {
  if (processes_ <= 1) return read_internal_field(case_dir_ / name / field, type, cells_);
  const std::size_t k = components(type);
  std::vector<double> whole(cells_ * k, 0.0);
  for (int p = 0; p < processes_; ++p) {
    const auto& addressing = addressing_[static_cast<std::size_t>(p)];
    gather(whole,
           read_internal_field(processor_dir(case_dir_, p) / name / field, type, addressing.size()),
           addressing, k);
  }
  return whole;
}

bool CaseLayout::has(const std::string& name, const std::string& field) const {
  return fs::is_regular_file(roots().front() / name / field);
}

std::optional<TimeDirectory> CaseLayout::at(double time, double tolerance) const {
  for (const TimeDirectory& t : time_directories(roots().front())) {
    if (std::abs(t.time - time) <= tolerance) return t;
  }
  return std::nullopt;
}

void CaseLayout::write_cloud(const std::string& name, const SoilParcels& parcels,
                             double parcel_density) const {
  if (processes_ <= 1) {
    write_soil_cloud(case_dir_ / name, name, parcels, parcel_density);
    return;
  }
  std::vector<SoilParcels> parts(static_cast<std::size_t>(processes_));
  for (std::size_t i = 0; i < parcels.size(); ++i) {
    const auto global = static_cast<std::size_t>(parcels.cell[i]);
    SoilParcels& part = parts[static_cast<std::size_t>(owner_[global])];
    part.add(&parcels.position[3 * i], local_[global], &parcels.velocity[3 * i],
             parcels.diameter[i], parcels.grains[i]);
  }
  for (int p = 0; p < processes_; ++p)
    write_soil_cloud(processor_dir(case_dir_, p) / name, name, parts[static_cast<std::size_t>(p)],
                     parcel_density);
}

void CaseLayout::write_scalar_field(const std::string& name, const std::string& field,
                                    const std::string& dimensions,
                                    std::span<const double> values) const {
  // The constraint patches as their type; a processor patch's value is not
  // `$internalField` (a nonuniform list cannot be expanded twice): OpenFOAM
  // takes it from the neighbouring processor when it evaluates the patch.
  const std::string boundary =
      "    \".*\"\n    {\n        type zeroGradient;\n    }\n"
      "    #includeEtc \"caseDicts/setConstraintTypes\"\n"
      "    processor\n    {\n        type processor;\n        value uniform 0;\n    }\n"
      "    processorCyclic\n    {\n        type processorCyclic;\n        value uniform 0;\n    "
      "}\n";
  if (processes_ <= 1) {
    write_vol_field(case_dir_ / name / field, name,
                    {FieldType::scalar, dimensions, values, boundary});
    return;
  }
  for (int p = 0; p < processes_; ++p) {
    const auto& addressing = addressing_[static_cast<std::size_t>(p)];
    std::vector<double> part(addressing.size());
    for (std::size_t local = 0; local < addressing.size(); ++local)
      part[local] = values[static_cast<std::size_t>(addressing[local])];
    write_vol_field(processor_dir(case_dir_, p) / name / field, name,
                    {FieldType::scalar, dimensions, part, boundary});
  }
}

void CaseLayout::remove_time(const std::string& name) const {
  for (const fs::path& root : roots()) {
    std::error_code ec;
    fs::remove_all(root / name, ec);
    if (ec) {
      throw cosim::Error(cosim::ExitCode::participant_failed,
                         fmt::format("cannot remove {}: {}", (root / name).string(), ec.message()));
    }
  }
}

void CaseLayout::remove_times_except(std::span<const std::string> keep) const {
  for (const fs::path& root : roots()) remove_time_directories_except(root, keep);
}

}  // namespace openfoam
