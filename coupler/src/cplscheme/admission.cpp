#include "admission.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace cosim::cplscheme {

namespace {

const FieldSpec* find_field(const std::vector<FieldSpec>& fields, const std::string& name) {
  auto it = std::find_if(fields.begin(), fields.end(), [&](auto& f) { return f.name == name; });
  return it == fields.end() ? nullptr : &*it;
}

std::optional<std::string> check_fields(const std::map<std::string, std::string>& in_job,
                                        const std::vector<FieldSpec>& declared, const char* verb,
                                        const std::string& participant) {
  for (const auto& [field, mesh] : in_job) {
    const FieldSpec* f = find_field(declared, field);
    if (!f)
      return fmt::format("the job says participant '{}' {} '{}', but it does not declare it",
                         participant, verb, field);
    if (f->mesh != mesh)
      return fmt::format("participant '{}' {} '{}' on mesh '{}', the job says mesh '{}'",
                         participant, verb, field, f->mesh, mesh);
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> admission_refusal(const job::Job& job, const std::string& job_id,
                                             const com::Header& header, const com::Hello& hello) {
  if (header.job_id != job_id)
    return fmt::format("participant '{}' was started for job '{}', this coupler runs job '{}'",
                       header.sender, header.job_id, job_id);
  if (hello.config_hash != job.config_hash)
    return fmt::format(
        "participant '{}' was started for a job config with hash {}, this job's "
        "config hash is {} (was the job or a participant config edited?)",
        header.sender, hello.config_hash, job.config_hash);
  if (hello.participant != header.sender)
    return fmt::format("hello from '{}' names participant '{}'", header.sender, hello.participant);
  const job::ParticipantSpec* spec = job.participant(header.sender);
  if (!spec) return fmt::format("job '{}' has no participant named '{}'", job.name, header.sender);
  for (const auto& [mesh_name, mesh] : spec->meshes) {
    auto it = std::find_if(hello.meshes.begin(), hello.meshes.end(),
                           [&](auto& m) { return m.name == mesh_name; });
    if (it == hello.meshes.end())
      return fmt::format("the job says participant '{}' declares mesh '{}', it does not",
                         spec->name, mesh_name);
    if (it->kind != mesh.kind || it->dim != mesh.dim)
      return fmt::format("participant '{}' declares mesh '{}' as a {}D {}, the job says {}D {}",
                         spec->name, mesh_name, it->dim, to_string(it->kind), mesh.dim,
                         to_string(mesh.kind));
  }
  if (auto r = check_fields(spec->writes, hello.writes, "writes", spec->name)) return r;
  if (auto r = check_fields(spec->reads, hello.reads, "reads", spec->name)) return r;
  for (const FieldSpec& f : hello.reads)
    if (!f.optional && !spec->reads.count(f.name))
      return fmt::format(
          "participant '{}' reads '{}', which the job does not send it (add it to "
          "its `reads` and to `exchange`)",
          spec->name, f.name);
  return std::nullopt;
}

std::optional<std::string> exchange_mismatch(const job::ExchangeSpec& x, const FieldSpec& written,
                                             const FieldSpec& read) {
  if (written.components != read.components)
    return fmt::format("'{}' has {} components as written by '{}' but {} as read by '{}'", x.field,
                       written.components, x.from, read.components, x.to);
  if (written.unit != read.unit)
    return fmt::format("'{}' is written by '{}' in [{}] but read by '{}' in [{}]", x.field, x.from,
                       written.unit, x.to, read.unit);
  if (written.quantity != read.quantity || written.time != read.time)
    return fmt::format("'{}' is {} {} for '{}' but {} {} for '{}'", x.field,
                       to_string(written.quantity), to_string(written.time), x.from,
                       to_string(read.quantity), to_string(read.time), x.to);
  if (mapping::constraint_for(written.quantity) != x.mapping.constraint)
    return fmt::format("'{}' is {}, so it maps {}, but the job ({}) says {}", x.field,
                       to_string(written.quantity),
                       mapping::to_string(mapping::constraint_for(written.quantity)), x.key_path,
                       mapping::to_string(x.mapping.constraint));
  return std::nullopt;
}

}  // namespace cosim::cplscheme
