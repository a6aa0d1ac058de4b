#pragma once

#include <filesystem>

namespace openfoam {

// Checks a user's interFoam case up front for what the restart-per-window
// recipe needs, and throws cosim::InputError (exit 2) naming the file and
// the entry that is missing: a mesh (constant/polyMesh, or
// system/blockMeshDict to make one), the phases and gravity, the solvers of
// alpha.water, pcorr (run at every start), p_rgh and p_rghFinal, the
// divergence schemes of the VOF solver, Euler in time (a restart restores no
// older time level), and 0/ with alpha.water, U and p_rgh; with `cloud`
// (MPPICInterFoam) also the cloud's properties (Ergun-Wen-Yu drag on alphac,
// rho0, alphaMax, semi-implicit source) and the solver's stress scheme.
void check_existing_case(const std::filesystem::path& case_dir, bool cloud = false);

// Copies the case's system/, constant/ and 0/ into `run_case_dir`.
void copy_existing_case(const std::filesystem::path& case_dir,
                        const std::filesystem::path& run_case_dir);

}  // namespace openfoam
