#include "demo_job.hpp"

#include <fmt/format.h>

#include "text_files.hpp"

namespace cosim::testing {

namespace fs = std::filesystem;

fs::path write_job(const fs::path& dir, const JobOptions& o) {
  const fs::path demo = fs::path(COSIM_SOURCE_DIR) / "configs" / "demo";
  fs::copy_file(demo / "left.yaml", dir / "left.yaml", fs::copy_options::overwrite_existing);
  fs::copy_file(demo / "right.yaml", dir / "right.yaml", fs::copy_options::overwrite_existing);
  const std::string job = fmt::format(R"(kind: job
name: {}
end_time: {}
window: 2.5e-3
transport: {}
extrapolation: {}
zmq: {{scheme: {}, host: '{}'}}
window_timeout: {}
output: {{every: {}}}
participants:
  left:
    executable: cosim_test_participant
    config: left.yaml
    ranks: {}
    args: {}
    meshes: {{grid: {{kind: uniform_grid, dim: 2}}}}
    writes: {{temperature: grid, heat: grid}}
    reads: {{pressure: grid}}
  right:
    executable: cosim_test_participant
    config: right.yaml
    ranks: {}
    args: {}
    meshes: {{grid: {{kind: uniform_grid, dim: 2}}}}
    writes: {{pressure: grid}}
    reads: {{temperature: grid, heat: grid}}
exchange:
  - {{field: temperature, from: left, to: right, mapping: consistent}}
  - {{field: heat, from: left, to: right, mapping: conservative}}
  - {{field: pressure, from: right, to: left, mapping: consistent}}
)",
                                      o.name, o.end_time, o.transport, o.extrapolation, o.scheme,
                                      o.host, o.window_timeout, o.output_every, o.left_ranks,
                                      o.left_args, o.right_ranks, o.right_args);
  write_text(dir / "job.yaml", job);
  return dir / "job.yaml";
}

ProcessResult cosim_run(const fs::path& job, const fs::path& output, int timeout_s,
                        const std::vector<std::string>& extra) {
  std::vector<std::string> args{binary("cosim").string(), "run", job.string(), "--output",
                                output.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return run(args, std::chrono::seconds(timeout_s));
}

}  // namespace cosim::testing
