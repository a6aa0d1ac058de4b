#pragma once

#include <optional>
#include <string>

#include "com/handshake.hpp"
#include "job/job.hpp"

namespace cosim::cplscheme {

// Why a participant that said hello cannot take part in the job, or nothing
// when it can: another job or config, a name the job does not know, or
// declarations (meshes, fields, units, quantities) that contradict the job.
std::optional<std::string> admission_refusal(const job::Job& job, const std::string& job_id,
                                             const com::Header& header, const com::Hello& hello);

// Checks writer and reader of every exchange agree (components, units,
// quantity vs mapping constraint) once both have said hello.
std::optional<std::string> exchange_mismatch(const job::ExchangeSpec& exchange,
                                             const FieldSpec& written, const FieldSpec& read);

}  // namespace cosim::cplscheme
