#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cosim {

// A CSV file with one header row, as the project's readers take them: blank
// lines and lines whose first non-blank character is '#' are skipped; cells
// are trimmed of blanks, except inside double quotes, where commas are kept
// and "" is a quote (RFC 4180, as results.csv writes them). Every row keeps
// its file line and the column where each cell starts, so that a reader's
// errors are cosim::InputErrors at file:line:column, naming the key path it
// was given (the YAML key that named the file, or empty) and the column.
class CsvTable {
 public:
  struct Cell {
    std::string text;
    int column = 1;  // 1-based, the first non-blank character
  };

  // Throws InputError naming the file when it cannot be read or has no
  // header row.
  static CsvTable read(const std::filesystem::path& file, std::string key_path = {});
  // `text` is the file's content; `file` and `key_path` locate errors.
  static CsvTable parse(std::string_view text, std::filesystem::path file,
                        std::string key_path = {});

  const std::vector<std::string>& header() const { return header_; }
  const std::vector<Cell>& header_cells() const { return header_cells_; }
  int header_line() const { return header_line_; }
  std::size_t rows() const { return rows_.size(); }
  // The last line read: a row's line, or the header's when there is none.
  int last_line() const { return rows_.empty() ? header_line_ : rows_.back().line; }

  // Row r as written: its line and its cells (any count).
  int line(std::size_t r) const { return rows_[r].line; }
  const std::vector<Cell>& cells(std::size_t r) const { return rows_[r].cells; }

  // Row r as wide as the header: numbers (NaN for a cell that is not one or
  // is missing) and the cells' text (empty where missing).
  const std::vector<double>& row(std::size_t r) const { return rows_[r].numbers; }
  const std::string& text(std::size_t r, std::size_t c) const { return rows_[r].texts[c]; }
  // The cell as a finite number; otherwise throws at its line and column.
  double number(std::size_t r, std::size_t c) const;

  bool has(const std::string& column) const;
  // Throws InputError at the header line, naming the column and those there.
  std::size_t index(const std::string& column) const;
  // Every row's number in the column (NaN where there is none).
  std::vector<double> column(const std::string& name) const;

  const std::filesystem::path& file() const { return file_; }
  const std::string& key_path() const { return key_path_; }
  // Throws an InputError at this file's `line` and `column`.
  [[noreturn]] void fail(int line, int column, const std::string& what) const;

 private:
  struct Row {
    int line = 0;
    std::vector<Cell> cells;
    std::vector<double> numbers;
    std::vector<std::string> texts;
  };

  std::filesystem::path file_;
  std::string key_path_;
  std::vector<std::string> header_;
  std::vector<Cell> header_cells_;
  int header_line_ = 0;
  std::vector<Row> rows_;
};

}  // namespace cosim
