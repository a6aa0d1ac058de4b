#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace cosim::bench {

// A CSV file of numbers with one header row; lines starting with '#' and
// empty lines are skipped (the reference files' comments). Cells that are
// not numbers read as NaN.
class CsvTable {
 public:
  // Throws Error naming the file when it cannot be read or has no header.
  static CsvTable read(const std::filesystem::path& file);

  const std::vector<std::string>& header() const { return header_; }
  std::size_t rows() const { return rows_.size(); }
  const std::vector<double>& row(std::size_t r) const { return rows_[r]; }
  // The cell as written (for columns of names, e.g. Martin & Moyce's `kind`).
  const std::string& text(std::size_t r, std::size_t c) const { return text_[r][c]; }
  bool has(const std::string& column) const;
  // Throws Error naming the file, the column and the columns it has.
  std::size_t index(const std::string& column) const;
  std::vector<double> column(const std::string& name) const;
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::vector<std::string> header_;
  std::vector<std::vector<double>> rows_;
  std::vector<std::vector<std::string>> text_;
};

}  // namespace cosim::bench
