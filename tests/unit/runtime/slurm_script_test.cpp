// The Slurm batch script of an MPI job and its srun multi-prog file: one
// task per rank, the programs and arguments of the mpirun line.

#include "runtime/slurm_script.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cosim/error.hpp"
#include "mpmd_job.hpp"
#include "runtime/mpi_launch.hpp"
#include "text_files.hpp"

namespace cosim::runtime {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;
using Words = std::vector<std::string>;

// A line of a multi-prog file as srun reads it (Slurm's multi_prog.c): the
// task range, then words split at blanks, a backslash keeping the next
// character, single quotes keeping everything up to the next quote. `%t` and
// `%o` outside quotes are srun's substitutions, and any other `%x` is
// dropped: the test refuses them all, since cosim's arguments are literal.
std::pair<std::string, Words> read_multi_prog_line(const std::string& line) {
  std::size_t at = line.find(' ');
  const std::string range = line.substr(0, at);
  Words words;
  std::string word;
  bool in_word = false;
  for (++at; at < line.size(); ++at) {
    const char c = line[at];
    if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(word);
      word.clear();
      in_word = false;
    } else if (c == '\\') {
      word += line.at(++at);
      in_word = true;
    } else if (c == '\'') {
      const std::size_t close = line.find('\'', at + 1);
      EXPECT_NE(close, std::string::npos) << line;
      word += line.substr(at + 1, close - at - 1);
      at = close;
      in_word = true;
    } else {
      EXPECT_NE(c, '%') << "srun would substitute it: " << line;
      word += c;
      in_word = true;
    }
  }
  if (in_word) words.push_back(word);
  return {range, words};
}

// The lines that are not comments.
Words task_lines(const std::string& multi_prog) {
  Words lines;
  std::istringstream in(multi_prog);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

class SlurmScriptTest : public cosim::testing::MpmdJob {
 protected:
  SlurmScript make(const fs::path& script) const {
    return slurm_script(job_, job_file_, scratch_ / "run", "job-42", 30.0, script);
  }
};

TEST_F(SlurmScriptTest, BatchScriptAsksForEveryRankAndRunsTheMultiProgFile) {
  const fs::path script = scratch_ / "run.slurm";
  const SlurmScript s = make(script);
  EXPECT_THAT(s.batch_script, StartsWith("#!/bin/bash\n#SBATCH --job-name=ranks_demo\n"));
  EXPECT_THAT(s.batch_script, HasSubstr("\n#SBATCH --ntasks=6\n"));  // 1 + 2 + 3
  EXPECT_THAT(s.batch_script, HasSubstr("#   sbatch " + script.string() + "\n"));
  EXPECT_THAT(s.batch_script, HasSubstr("\nset -euo pipefail\n"));
  EXPECT_THAT(s.batch_script, HasSubstr("\nsrun --kill-on-bad-exit=1 --multi-prog " +
                                        script.string() + ".multi-prog.conf\n"));
  EXPECT_EQ(multi_prog_path(script), fs::path(script.string() + ".multi-prog.conf"));
  // The set-up before srun stops on an error: set -e comes before srun.
  EXPECT_LT(s.batch_script.find("set -euo pipefail"), s.batch_script.find("\nsrun "));
}

// A participant whose program starts its solver's processes itself is one
// task; the script says how many cores its processes need beside it.
TEST_F(SlurmScriptTest, AProgramStartingItsSolverProcessesIsOneTaskAndSaysSo) {
  const job::Job job = job::load_job(job_file_, {"water_solver"});
  const SlurmScript s =
      slurm_script(job, job_file_, scratch_ / "run", "job-42", 30.0, scratch_ / "run.slurm");
  EXPECT_THAT(s.batch_script, HasSubstr("\n#SBATCH --ntasks=4\n"));  // 1 + 2 + 1
  EXPECT_THAT(s.batch_script,
              HasSubstr("participant 'water': 1 rank (tasks 3), which starts its solver on 3 "
                        "processes of its own"));
  const Words lines = task_lines(s.multi_prog);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_THAT(lines[2], StartsWith("3 env COSIM_APP_INDEX=2 "));
  EXPECT_THAT(lines[2], HasSubstr(" --cosim-solver-processes 3"));
}

TEST_F(SlurmScriptTest, MultiProgRunsEachApplicationOnItsTasksWithTheMpirunArguments) {
  const SlurmScript s = make(scratch_ / "run.slurm");
  const Words lines = task_lines(s.multi_prog);
  ASSERT_EQ(lines.size(), 3u) << s.multi_prog;
  const auto apps = mpmd_applications(job_, job_file_, scratch_ / "run", "job-42", 30.0);
  ASSERT_EQ(apps.size(), 3u);
  const Words ranges{"0", "1-2", "3-5"};
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const auto [range, words] = read_multi_prog_line(lines[i]);
    EXPECT_EQ(range, ranges[i]);
    ASSERT_GE(words.size(), 3u) << lines[i];
    EXPECT_EQ(words[0], "env");
    EXPECT_EQ(words[1], "COSIM_APP_INDEX=" + std::to_string(i));
    EXPECT_EQ(Words(words.begin() + 2, words.end()), apps[i].command) << lines[i];
  }
  EXPECT_THAT(lines[0], HasSubstr(" run " + fs::absolute(job_file_).string() + " --output " +
                                  fs::absolute(scratch_ / "run").string() +
                                  " --job-id job-42 --connect-timeout 30"));
  EXPECT_EQ(fs::path(read_multi_prog_line(lines[1]).second.at(2)).lexically_normal(),
            program("soil_solver"));
  EXPECT_THAT(lines[1], HasSubstr("--cosim-name soil "));
  EXPECT_THAT(lines[2], HasSubstr("--cosim-job job-42 "));
  EXPECT_THAT(lines[2], HasSubstr("--cosim-endpoint mpi:// "));

  // And the mpirun line gives the same applications the same words.
  const Words cmd = mpi_command(job_, job_file_, scratch_ / "run", "job-42", 30.0, 64);
  std::size_t np = 0;
  for (std::size_t i = 0; i < cmd.size(); ++i)
    if (cmd[i] == "-np") {
      ASSERT_LT(np, apps.size());
      EXPECT_EQ(cmd[i + 1], std::to_string(apps[np].ranks));
      EXPECT_EQ(cmd[i + 2], apps[np].command.front());
      ++np;
    }
  EXPECT_EQ(np, 3u);
}

TEST_F(SlurmScriptTest, ArgumentsSrunWouldReadOtherwiseAreQuoted) {
  job_file_ = scratch_.write("job.yaml", job_text(R"([--title, "it's 100% a test"])"));
  job_ = job::load_job(job_file_);
  const Words lines = task_lines(make(scratch_ / "run.slurm").multi_prog);
  ASSERT_EQ(lines.size(), 3u);
  const auto [range, words] = read_multi_prog_line(lines[1]);
  EXPECT_EQ(range, "1-2");
  ASSERT_GE(words.size(), 2u);
  EXPECT_EQ(words.back(), "it's 100% a test");
  EXPECT_EQ(words[words.size() - 2], "--title");
}

TEST_F(SlurmScriptTest, AnArgumentWithALineBreakIsRefused) {
  job_file_ = scratch_.write("job.yaml", job_text(R"(["two\nlines"])"));
  job_ = job::load_job(job_file_);
  try {
    make(scratch_ / "run.slurm");
    ADD_FAILURE() << "a line break went into the multi-prog file";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_input);
    EXPECT_THAT(e.what(), HasSubstr("line break"));
  }
}

TEST_F(SlurmScriptTest, WritesBothFilesAndRefusesToOverwriteThemUnlessAsked) {
  const fs::path script = scratch_ / "run.slurm";
  const fs::path conf = multi_prog_path(script);
  write_slurm_script(job_, job_file_, scratch_ / "run", "job-42", 30.0, script, false);
  const SlurmScript expected = make(script);
  EXPECT_EQ(cosim::testing::read_text(script), expected.batch_script);
  EXPECT_EQ(cosim::testing::read_text(conf), expected.multi_prog);
  EXPECT_FALSE(fs::exists(scratch_ / "run")) << "the output directory is the job's to make";

  cosim::testing::write_text(script, "mine\n");
  try {
    write_slurm_script(job_, job_file_, scratch_ / "run", "job-43", 30.0, script, false);
    ADD_FAILURE() << "an existing script was replaced";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr(script.string()));
    EXPECT_THAT(e.what(), HasSubstr("--overwrite"));
  }
  EXPECT_EQ(cosim::testing::read_text(script), "mine\n");
  EXPECT_THAT(cosim::testing::read_text(conf), HasSubstr("job-42"));  // untouched too

  write_slurm_script(job_, job_file_, scratch_ / "run", "job-43", 30.0, script, true);
  EXPECT_THAT(cosim::testing::read_text(script), HasSubstr("#SBATCH --ntasks=6"));
  EXPECT_THAT(cosim::testing::read_text(conf), HasSubstr("--job-id job-43"));
}

}  // namespace
}  // namespace cosim::runtime
