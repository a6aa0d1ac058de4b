#include <gtest/gtest.h>

#include <iostream>
#include <sstream>

#include "cosim/config/schema.hpp"
#include "example_job_schema.hpp"

namespace cosim::config {
namespace {

using testing::example_job_schema;

// The listing line that starts with `path` and the doc line under it.
std::pair<std::string, std::string> entry_of(const std::string& listing, const std::string& path) {
  std::istringstream lines(listing);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("  " + path + "  (", 0) == 0) {
      std::string doc;
      std::getline(lines, doc);
      return {line, doc};
    }
  }
  return {};
}

TEST(ConfigSchemaHelp, ListsEveryKeyPathWithItsTypeRequirementAndDoc) {
  const std::string listing = example_job_schema().help("job file");
  std::cout << listing;
  struct Row {
    std::string path, type, doc;
  };
  const std::vector<Row> rows{
      {"kind", "one of 'job'; required", "What this file is: always 'job'."},
      {"name", "non-empty string; required", "Run name."},
      {"end_time", "number > 0 [s]; required", "Simulated end time."},
      {"window", "number > 0 [s]; required", "Coupling window length."},
      {"transport", "one of 'zmq' | 'mpi'; optional; default: zmq",
       "How fields travel between processes."},
      {"gravity", "list of 1 to 3 numbers [m/s^2]; optional; default: [0, 0, -9.81]",
       "Gravitational acceleration vector."},
      {"relaxation", "number in [0, 1]; optional; default: 1",
       "Under-relaxation factor of implicit coupling."},
      {"max_iterations", "integer > 0; optional", "Coupling iterations per window."},
      {"restart", "true | false; optional; default: false", "Resume from a checkpoint."},
      {"participants", "mapping of at least 1 user-chosen names to: mapping; required",
       "The coupled processes, by name."},
      {"participants.<name>", "mapping", "One process of the coupled run."},
      {"participants.<name>.executable", "non-empty string; required", "Program to start."},
      {"participants.<name>.config", "path; required", "Its own YAML file, relative to this one."},
      {"exchange", "list of items: mapping; optional", "Fields that cross between participants."},
      {"exchange[]", "mapping", "One field sent from one participant to another."},
      {"exchange[].from", "string; required", "Writing participant."},
      {"exchange[].mapping", "one of 'consistent' | 'conservative', or mapping; required",
       "How the field moves between meshes."},
      {"exchange[].mapping.constraint", "required", "What the mapping preserves."},
      {"exchange[].mapping.kernel", "optional; default: linear", "Interpolation kernel."},
      {"momentum_exchange", "one of 'none', or mapping; optional",
       "Implicit momentum exchange, or none."},
      {"momentum_exchange.mesh", "string; required",
       "Participant whose mesh carries the exchange."},
      {"momentum_exchange.drag", "one of 'kozeny_carman' | 'forchheimer'; optional", "Drag law."},
  };
  for (const Row& row : rows) {
    const auto [line, doc] = entry_of(listing, row.path);
    EXPECT_NE(line.find(row.type), std::string::npos) << row.path << " listed as: " << line;
    EXPECT_NE(doc.find(row.doc), std::string::npos) << row.path << " doc: " << doc;
  }
}

TEST(ConfigSchemaHelp, StartsWithTitleAndTheFilesDoc) {
  const std::string listing = example_job_schema().help("job file");
  EXPECT_EQ(listing.rfind("job file\n========\nA coupled run of several participants.\n", 0), 0U);
}

TEST(ConfigSchemaHelp, EveryDeclaredKeyAppearsExactlyOnce) {
  const std::string listing = example_job_schema().help("job file");
  for (const char* path :
       {"  end_time  (", "  exchange[].to  (", "  participants.<name>.config  ("}) {
    const auto first = listing.find(path);
    ASSERT_NE(first, std::string::npos) << path;
    EXPECT_EQ(listing.find(path, first + 1), std::string::npos) << path << " listed twice";
  }
}

}  // namespace
}  // namespace cosim::config
