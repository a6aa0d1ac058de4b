#pragma once

#include <string>

// `cosim validate <job.yaml>`: checks a job without running it: the job
// file itself, then every participant's own config through its solver
// (`<executable> --validate --config <file>`), so that a mistake anywhere in
// the job is reported before a run starts, with its file, key and line.
namespace cosim::app {

// Returns the exit code: 0 when everything is valid, 2 when something is
// not (each problem printed), 3 when interrupted or a solver misbehaved.
int validate_job(const std::string& job_file);

}  // namespace cosim::app
