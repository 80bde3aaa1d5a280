#include "signorini/io/CsvWriter.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "signorini/core/Error.hpp"
#include "signorini/io/OutputStaging.hpp"

namespace signorini::io {

CsvWriter::CsvWriter(std::string path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)) {
  partRemovedOnSignal_ = core::RemovedOnSignal(path_ + ".part");
  errno = 0;
  out_.open(path_ + ".part", std::ios::out | std::ios::trunc);
  if (!out_) {  // the reason, e.g. "File name too long" for a long Output/Basename
    const int reason = errno;
    SIGNORINI_USER_ERROR("cannot create output file '" << path_ << ".part': "
                                                       << (reason ? std::strerror(reason) : "reason unknown"));
  }
  for (size_t i = 0; i < columns_.size(); ++i) out_ << (i ? "," : "") << columns_[i];
  out_ << "\n";
  out_.flush();
  if (core::stopSignal()) {  // the signal's handler may have run before the file existed
    abandon();
    core::throwIfSignalled();
  }
}

CsvWriter::~CsvWriter() {
  if (!done_) abandon();
}

void CsvWriter::row(const std::vector<double>& values) {
  if (values.size() != columns_.size()) throw std::logic_error("CsvWriter::row: wrong number of values");
  // The shortest text that reads back to the same double (0.0975, not 0.097500000000000003):
  // equal text is equal bits.
  std::string line;
  char number[32];
  for (size_t i = 0; i < values.size(); ++i) {
    if (i) line += ',';
    // Whole numbers below 2^53 (steps, unknowns, cells) without an exponent: 100000, not 1e+05.
    const double v = values[i];
    const bool whole = std::fabs(v) < 9007199254740992.0 && v == std::trunc(v);
    const auto end = whole ? std::to_chars(number, number + sizeof number, v, std::chars_format::fixed).ptr
                           : std::to_chars(number, number + sizeof number, v).ptr;
    line.append(number, end);
  }
  out_ << line << "\n";
  out_.flush();
}

void CsvWriter::commit() {
  if (done_) return;
  out_.close();  // a failed write (disk full) leaves the stream failed; the rows were flushed as they came
  if (!out_) SIGNORINI_USER_ERROR("cannot write output file '" << path_ << ".part' (disk full or quota exceeded?)");
  publish(path_ + ".part", path_);
  partRemovedOnSignal_ = {};  // published: renamed, or staged (the staging removes it on a signal)
  done_ = committed_ = true;
}

void CsvWriter::remove() {
  if (committed_) unpublish(path_);
  abandon();
}

void CsvWriter::abandon() {
  if (done_) return;
  out_.close();
  std::remove((path_ + ".part").c_str());
  partRemovedOnSignal_ = {};
  done_ = true;
}

size_t CsvTable::column(const std::string& name) const {
  for (size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return i;
  throw std::out_of_range("CSV column '" + name + "' not found");
}

CsvTable readCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) SIGNORINI_USER_ERROR("cannot read '" << path << "'");
  CsvTable t;
  std::string line;
  if (std::getline(in, line)) {
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) t.columns.push_back(c);
  }
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::stringstream ss(line);
    std::vector<double> row;
    for (std::string c; std::getline(ss, c, ',');) {
      char* end = nullptr;
      row.push_back(std::strtod(c.c_str(), &end));  // (std::stod refuses subnormal numbers)
      if (c.empty() || *end != '\0') SIGNORINI_USER_ERROR("'" << path << "': '" << c << "' is not a number");
    }
    t.rows.push_back(row);
  }
  return t;
}

}  // namespace signorini::io
