// The CSV tables keep every bit of every value in the shortest text that reads back to it.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "signorini/io/CsvWriter.hpp"
#include "signorini/core/Error.hpp"

using namespace signorini;

TEST(CsvWriter, WritesTheShortestTextThatReadsBackToEveryBit) {
  const std::string path = "/tmp/signorini-csv-" + std::to_string(::getpid()) + ".csv";
  const std::vector<double> values = {0.0975, 0.1, 1.0 / 3.0, 400, -0.0, 1e-300,
                                      std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::max(),
                                      0.1 + 0.2, 100000, 3e8, 9007199254740991.0, 1e16, 2.5e-5};
  std::vector<std::string> columns;
  for (size_t i = 0; i < values.size(); ++i) columns.push_back("c" + std::to_string(i));
  {
    io::CsvWriter csv(path, columns);
    csv.row(values);
    csv.commit();
  }
  std::ifstream in(path);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  // Whole numbers below 2^53 (steps, unknowns) without an exponent, others in the shorter form.
  EXPECT_EQ(line,
            "0.0975,0.1,0.3333333333333333,400,-0,1e-300,5e-324,1.7976931348623157e+308,0.30000000000000004,"
            "100000,300000000,9007199254740991,1e+16,2.5e-05");
  const auto table = io::readCsv(path);
  ASSERT_EQ(table.rows.size(), 1u);
  for (size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(std::memcmp(&table.rows[0][i], &values[i], sizeof(double)), 0) << columns[i] << " " << values[i];
  }
  std::remove(path.c_str());
}

// A full disk (the file is /dev/full, which refuses every write) fails the commit with a message
// naming the file, and nothing is published; the table used to be renamed with the rows it had.
TEST(CsvWriter, AWriteThatFailsFailsTheCommit) {
  const std::string path = "/tmp/signorini-csv-full-" + std::to_string(::getpid()) + ".csv";
  ASSERT_EQ(::symlink("/dev/full", (path + ".part").c_str()), 0);
  io::CsvWriter csv(path, {"step", "energy"});
  csv.row({1, 0.25});
  try {
    csv.commit();
    ADD_FAILURE() << "the commit succeeded";
  } catch (const core::UserError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write output file '" + path + ".part'"), std::string::npos) << e.what();
  }
  EXPECT_NE(::access(path.c_str(), F_OK), 0) << "published";
  csv.remove();
  EXPECT_NE(::access((path + ".part").c_str(), F_OK), 0) << "left behind";
  std::remove(path.c_str());
}
