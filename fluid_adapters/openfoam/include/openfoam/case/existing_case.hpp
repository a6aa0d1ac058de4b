#pragma once

#include <filesystem>

#include "openfoam/case/case_description.hpp"
#include "openfoam/foam/foam_dictionary.hpp"

namespace openfoam {

// Checks a user's interFoam case up front for what the restart-per-window
// recipe needs, and throws cosim::InputError (exit 2) naming the file and
// the entry that is missing: a mesh (constant/polyMesh, or
// system/blockMeshDict to make one), the phases and gravity, the solvers of
// alpha.water, pcorr (run at every start), p_rgh and p_rghFinal, the
// divergence schemes of the VOF solver, Euler in time (a restart restores no
// older time level) and the viscous stress, and 0/ with alpha.water, U and
// p_rgh. MPPICInterFoam needs nothing more: an interFoam case is completed
// for it in the run's copy (prepare_cloud_in_copy).
void check_existing_case(const std::filesystem::path& case_dir);

// Copies the case's system/, constant/ and 0/ into `run_case_dir`.
void copy_existing_case(const std::filesystem::path& case_dir,
                        const std::filesystem::path& run_case_dir);

// Completes the copy of an interFoam case for MPPICInterFoam with the soil
// as parcels: the recipe's constant/kinematicCloudProperties (replacing the
// case's, as the soil's parcels need it), and MPPICInterFoam's stress scheme
// (div((((alphac*rho)*nuEff)*dev2(T(grad(U)))))) when missing, as the case's
// interFoam one.
void prepare_cloud_in_copy(const DictionaryQuery& query, const SoilSettings& soil);

// The copy's mesh and initial fields in ASCII (the adapter reads ASCII
// only): binary or compressed files are converted by foamFormatConvert.
void convert_copy_to_ascii(const DictionaryQuery& query);

}  // namespace openfoam
