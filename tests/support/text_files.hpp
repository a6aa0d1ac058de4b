#pragma once

#include <filesystem>
#include <string>
#include <vector>

// Whole text files read and written in one call, and numeric CSV files read.
namespace cosim::testing {

// The file's bytes; empty when it cannot be read.
std::string read_text(const std::filesystem::path& file);
// Makes the file's directories first.
void write_text(const std::filesystem::path& file, const std::string& text);

// Rows of a CSV file after its header row (all values numeric).
std::vector<std::vector<double>> read_csv(const std::filesystem::path& file);

}  // namespace cosim::testing
