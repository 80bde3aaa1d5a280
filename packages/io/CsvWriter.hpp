#pragma once
/// \file CsvWriter.hpp
/// Writing (CsvWriter) and reading (readCsv) the CSV tables of a run.
#include <fstream>
#include <string>
#include <vector>

#include "signorini/core/Interrupt.hpp"

namespace signorini::io {

/// A CSV table written under "\<path\>.part" and renamed to `path` by commit(), so an interrupted or failed run never
/// leaves a torn file under the final name. Rows are flushed as written. Owns the open file; not collective (the
/// caller chooses the writing rank).
class CsvWriter {
 public:
  /// Opens "<path>.part" and writes the header. Throws core::UserError naming the path if it
  /// cannot be created, core::Interrupted after a Ctrl-C (core::throwIfSignalled).
  CsvWriter(std::string path, std::vector<std::string> columns);
  ~CsvWriter();  ///< abandons the file unless committed
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  /// One row; values.size() must equal the number of columns. Each double as the shortest text
  /// that reads back to it (every bit kept).
  void row(const std::vector<double>& values);
  /// Publishes "<path>.part" as path (io::publish: at once, or at the commit of the run's
  /// io::OutputStaging).
  void commit();
  /// Removes the temporary file.
  void abandon();
  /// Removes the file, committed or not (a later failure of the run it belongs to).
  void remove();
  /// The header's column names.
  const std::vector<std::string>& columns() const { return columns_; }
  /// The final path (without ".part").
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::ofstream out_;
  core::RemovedOnSignal partRemovedOnSignal_;  ///< "<path>.part" goes with a Ctrl-C at once
  bool done_ = false;
  bool committed_ = false;
};

/// Reads a CSV file written by CsvWriter: header names and rows of numbers.
struct CsvTable {
  std::vector<std::string> columns;       ///< header names
  std::vector<std::vector<double>> rows;  ///< one vector per non-empty line after the header
  /// Index of a column; throws std::out_of_range if absent.
  size_t column(const std::string& name) const;
};
/// The table in \p path. Throws core::UserError if the file cannot be read or a field is not a number.
CsvTable readCsv(const std::string& path);

}  // namespace signorini::io
