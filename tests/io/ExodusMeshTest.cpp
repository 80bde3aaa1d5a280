/// \file ExodusMeshTest.cpp
/// Tests of the Exodus II mesh reader and result-series writer.
#include <sys/resource.h>

#include <csignal>

#include "signorini/core/Error.hpp"
#include "signorini/io/ExodusSeriesWriter.hpp"

#include <exodusII.h>
#include <gtest/gtest.h>
#include <netcdf.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

namespace signorini::io {
namespace {

namespace fs = std::filesystem;

/// A fresh, empty directory per test, removed afterwards.
class ExodusMeshTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(::testing::TempDir()) /
           ("signorini_exodus_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::vector<std::string> filesInDir() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  }

  fs::path dir_;
};

/// nx x 1 strip of unit quads; side set "contact" on the bottom edges (side 0).
QuadMesh stripMesh(int nx) {
  QuadMesh mesh;
  for (int j = 0; j <= 1; ++j) {
    for (int i = 0; i <= nx; ++i) {
      mesh.x.push_back(i);
      mesh.y.push_back(j);
    }
  }
  for (int i = 0; i < nx; ++i) {
    mesh.quads.push_back({i, i + 1, nx + 2 + i, nx + 1 + i});
    mesh.sideSets["contact"].push_back({i, 0});
  }
  return mesh;
}

std::vector<double> filled(std::size_t n, double value) { return std::vector<double>(n, value); }

/// Writes one step with u = v = time on nodes, level = 10 * time on cells, lambda = -time on sides.
void writeStep(ExodusSeriesWriter& writer, long meshId, const QuadMesh& mesh, double time) {
  const std::size_t sides =
      mesh.sideSets.count("contact") ? mesh.sideSets.at("contact").size() : 0;
  writer.write(meshId, mesh, time, {filled(mesh.x.size(), time), filled(mesh.x.size(), time)},
               {filled(mesh.quads.size(), 10 * time)}, {filled(sides, -time)});
}

ExodusSeriesWriter makeWriter(const std::string& base) {
  return ExodusSeriesWriter(base, {"u", "v"}, {"level"}, "contact", {"lambda"});
}

/// Opens an Exodus file read-only (fails the test on error); the caller must ex_close it.
int openForCheck(const std::string& file) {
  int cpu = 8, io = 0;
  float version = 0;
  ex_opts(0);
  const int exoid = ex_open(file.c_str(), EX_READ, &cpu, &io, &version);
  EXPECT_GE(exoid, 0) << file;
  return exoid;
}

std::vector<double> timeValues(const std::string& file) {
  const int exoid = openForCheck(file);
  if (exoid < 0) return {};
  std::vector<double> times(static_cast<std::size_t>(ex_inquire_int(exoid, EX_INQ_TIME)));
  if (!times.empty()) {
    EXPECT_GE(ex_get_all_times(exoid, times.data()), 0);
  }
  ex_close(exoid);
  return times;
}

/// Writes a mesh with the raw Exodus API: one element block of the given type.
void writeRawMesh(const std::string& file, int dim, const std::vector<double>& x,
                  const std::vector<double>& y, const std::vector<double>& z,
                  const char* elementType, int nodesPerElement, const std::vector<int>& connectivity,
                  const std::vector<int>& sideElements = {}, const std::vector<int>& sides = {},
                  const char* sideSetName = nullptr) {
  int cpu = 8, io = 8;
  ex_opts(0);
  const int exoid = ex_create(file.c_str(), EX_CLOBBER, &cpu, &io);
  ASSERT_GE(exoid, 0);
  const auto numElements = static_cast<int64_t>(connectivity.size()) / nodesPerElement;
  const int numSideSets = sideElements.empty() ? 0 : 1;
  ASSERT_GE(ex_put_init(exoid, "raw", dim, static_cast<int64_t>(x.size()), numElements, 1, 0,
                        numSideSets),
            0);
  ASSERT_GE(ex_put_block(exoid, EX_ELEM_BLOCK, 7, elementType, numElements, nodesPerElement, 0, 0,
                         0),
            0);
  if (numSideSets) {
    ASSERT_GE(ex_put_set_param(exoid, EX_SIDE_SET, 42, static_cast<int64_t>(sideElements.size()),
                               0),
              0);
    if (sideSetName) {
      ASSERT_GE(ex_put_name(exoid, EX_SIDE_SET, 42, sideSetName), 0);
    }
  }
  ASSERT_GE(ex_put_coord(exoid, x.data(), y.data(), dim == 3 ? z.data() : nullptr), 0);
  ASSERT_GE(ex_put_conn(exoid, EX_ELEM_BLOCK, 7, connectivity.data(), nullptr, nullptr), 0);
  if (numSideSets) {
    ASSERT_GE(ex_put_set(exoid, EX_SIDE_SET, 42, sideElements.data(), sides.data()), 0);
  }
  ASSERT_GE(ex_close(exoid), 0);
}

/// Expects readExodusQuadMesh(file) to throw a UserError whose message contains every fragment.
void expectReadError(const std::string& file, const std::vector<std::string>& fragments) {
  try {
    readExodusQuadMesh(file);
    ADD_FAILURE() << "no UserError for " << file;
  } catch (const core::UserError& error) {
    const std::string message = error.what();
    for (const auto& fragment : fragments) {
      EXPECT_NE(message.find(fragment), std::string::npos)
          << "'" << fragment << "' not in: " << message;
    }
  }
}

TEST_F(ExodusMeshTest, RoundTripKeepsMeshSideSetAndValues) {
  const QuadMesh mesh = stripMesh(2);
  std::vector<std::string> files;
  {
    auto writer = makeWriter(path("membrane"));
    for (double t : {0.0, 0.5, 1.0}) writeStep(writer, 1, mesh, t);
    files = writer.close();
  }
  ASSERT_EQ(files, std::vector<std::string>{path("membrane.e")});

  const QuadMesh back = readExodusQuadMesh(files[0]);
  EXPECT_EQ(back.x, mesh.x);
  EXPECT_EQ(back.y, mesh.y);
  EXPECT_EQ(back.quads, mesh.quads);
  EXPECT_EQ(back.sideSets, mesh.sideSets);
  EXPECT_EQ(timeValues(files[0]), (std::vector<double>{0.0, 0.5, 1.0}));

  // Values at the second step, by variable kind.
  const int exoid = openForCheck(files[0]);
  std::vector<double> u(mesh.x.size()), level(mesh.quads.size()), lambda(2);
  EXPECT_GE(ex_get_var(exoid, 2, EX_NODAL, 1, 1, static_cast<int64_t>(u.size()), u.data()), 0);
  EXPECT_GE(ex_get_var(exoid, 2, EX_ELEM_BLOCK, 1, 1, 2, level.data()), 0);
  EXPECT_GE(ex_get_var(exoid, 2, EX_SIDE_SET, 1, 1, 2, lambda.data()), 0);
  EXPECT_EQ(u, filled(mesh.x.size(), 0.5));
  EXPECT_EQ(level, filled(2, 5.0));
  EXPECT_EQ(lambda, filled(2, -0.5));
  char name[MAX_STR_LENGTH + 1] = {};
  EXPECT_GE(ex_get_variable_name(exoid, EX_NODAL, 2, name), 0);
  EXPECT_STREQ(name, "v");
  EXPECT_GE(ex_get_variable_name(exoid, EX_SIDE_SET, 1, name), 0);
  EXPECT_STREQ(name, "lambda");
  ex_close(exoid);
}

TEST_F(ExodusMeshTest, OtherSideSetsFollowTheContactSetWithoutVariables) {
  // "a" sorts before "contact": the set carrying the side variables is still side set 1.
  QuadMesh mesh = stripMesh(3);
  mesh.sideSets["a support"] = {{0, 3}};
  mesh.sideSets["load"] = {{0, 2}, {1, 2}, {2, 2}};
  mesh.sideSets["unused"] = {};
  std::vector<std::string> files;
  {
    auto writer = makeWriter(path("sets"));
    for (double t : {0.0, 0.5}) writeStep(writer, 1, mesh, t);
    files = writer.close();
  }
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(readExodusQuadMesh(files[0]).sideSets, mesh.sideSets);  // the empty set too

  const int exoid = openForCheck(files[0]);
  EXPECT_EQ(ex_inquire_int(exoid, EX_INQ_SIDE_SETS), 4);
  std::vector<int> ids(4);  // the file's ids are 32-bit
  ASSERT_GE(ex_get_ids(exoid, EX_SIDE_SET, ids.data()), 0);
  EXPECT_EQ(ids, (std::vector<int>{1, 2, 3, 4}));
  char name[MAX_STR_LENGTH + 1] = {};
  std::vector<std::string> names;
  for (const int id : ids) {
    EXPECT_GE(ex_get_name(exoid, EX_SIDE_SET, id, name), 0);
    names.emplace_back(name);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"contact", "a support", "load", "unused"}));
  std::vector<int> truth(4, -1);  // sets x side variables (lambda)
  ASSERT_GE(ex_get_truth_table(exoid, EX_SIDE_SET, 4, 1, truth.data()), 0);
  EXPECT_EQ(truth, (std::vector<int>{1, 0, 0, 0}));
  std::vector<double> lambda(3);
  EXPECT_GE(ex_get_var(exoid, 2, EX_SIDE_SET, 1, 1, 3, lambda.data()), 0);
  EXPECT_EQ(lambda, filled(3, -0.5));
  ex_close(exoid);
}

TEST_F(ExodusMeshTest, MeshChangeWritesSeriesParaViewGroups) {
  std::vector<std::string> files;
  {
    auto writer = makeWriter(path("run"));
    writeStep(writer, 5, stripMesh(1), 0.0);
    writeStep(writer, 5, stripMesh(1), 0.1);
    writeStep(writer, 6, stripMesh(2), 0.2);
    writeStep(writer, 9, stripMesh(4), 0.3);
    writeStep(writer, 9, stripMesh(4), 0.4);
    files = writer.close();
  }
  ASSERT_EQ(files, (std::vector<std::string>{path("run.e"), path("run.e-s.0001"),
                                             path("run.e-s.0002")}));
  EXPECT_EQ(filesInDir(), (std::vector<std::string>{"run.e", "run.e-s.0001", "run.e-s.0002"}));
  EXPECT_EQ(timeValues(files[0]), (std::vector<double>{0.0, 0.1}));
  EXPECT_EQ(timeValues(files[1]), (std::vector<double>{0.2}));
  EXPECT_EQ(timeValues(files[2]), (std::vector<double>{0.3, 0.4}));
  EXPECT_EQ(readExodusQuadMesh(files[2]).quads.size(), 4u);

  // The pattern ParaView's Exodus readers use to find the files of one series.
  const std::regex series(R"(^(.*\.[eg][^-.]*)(-s.[0-9]+)?(\.[0-9]+\.[0-9]+)?$)");
  for (const auto& file : files) {
    std::smatch match;
    const std::string name = fs::path(file).filename().string();
    ASSERT_TRUE(std::regex_match(name, match, series)) << name;
    EXPECT_EQ(match[1].str(), "run.e");
  }
  EXPECT_FALSE(std::regex_match(std::string("run.e-s.0003.part"), series));
}

TEST_F(ExodusMeshTest, PartFileIsRenamedOnClose) {
  auto writer = makeWriter(path("out"));
  writeStep(writer, 1, stripMesh(2), 0.0);
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"out.e.part"});
  writer.close();
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"out.e"});
  EXPECT_EQ(writer.close(), std::vector<std::string>{path("out.e")});  // idempotent
  EXPECT_THROW(writeStep(writer, 1, stripMesh(2), 1.0), std::logic_error);
}

// A file that cannot grow (as on a full disk): a file size limit of 64 kB fails the file's first
// write beyond it (EFBIG; here netCDF's fill of the coordinates). The message gives a hint.
TEST_F(ExodusMeshTest, AFileThatCannotGrowIsNamedAsSuch) {
  auto writer = makeWriter(path("out"));
  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto previousHandler = std::signal(SIGXFSZ, SIG_IGN);  // the write fails instead of the process
  rlimit small = saved;
  small.rlim_cur = 64 * 1024;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    writeStep(writer, 1, stripMesh(20000), 0.0);  // 40,000 nodes: 320 kB per nodal field
    writer.close();
  } catch (const core::UserError& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previousHandler);
  writer.abandon();
  EXPECT_NE(message.find("(disk full, quota or file size limit exceeded?)"), std::string::npos) << message;
}

TEST_F(ExodusMeshTest, DestructorFinalisesFile) {
  {
    auto writer = makeWriter(path("out"));
    writeStep(writer, 1, stripMesh(2), 0.0);
  }
  EXPECT_EQ(filesInDir(), std::vector<std::string>{"out.e"});
}

TEST_F(ExodusMeshTest, AbandonLeavesNoFile) {
  {
    auto writer = makeWriter(path("out"));
    writeStep(writer, 1, stripMesh(2), 0.0);
    writeStep(writer, 1, stripMesh(2), 0.5);
    writer.abandon();
    EXPECT_TRUE(filesInDir().empty());
  }
  EXPECT_TRUE(filesInDir().empty());
}

// A failed run leaves nothing: the finished files of earlier meshes go with the open one.
TEST_F(ExodusMeshTest, AbandonRemovesTheCompletedFilesOfEarlierMeshesToo) {
  auto writer = makeWriter(path("out"));
  writeStep(writer, 1, stripMesh(2), 0.0);
  writeStep(writer, 2, stripMesh(3), 0.5);
  EXPECT_EQ(filesInDir(), (std::vector<std::string>{"out.e", "out.e-s.0001.part"}));
  writer.abandon();
  EXPECT_TRUE(filesInDir().empty());
}

TEST_F(ExodusMeshTest, StaleSeriesFilesOfEarlierRunAreRemoved) {
  for (const char* name : {"out.e-s.0001", "out.e-s.0007", "out.e-s.notes", "other.e-s.0001"}) {
    std::ofstream(path(name)) << "old";
  }
  auto writer = makeWriter(path("out"));
  writeStep(writer, 1, stripMesh(2), 0.0);
  writer.close();
  EXPECT_EQ(filesInDir(), (std::vector<std::string>{"other.e-s.0001", "out.e", "out.e-s.notes"}));
}

TEST_F(ExodusMeshTest, EmptySideSetIsOmitted) {
  QuadMesh mesh = stripMesh(2);
  mesh.sideSets.clear();
  {
    auto writer = makeWriter(path("out"));
    writer.write(1, mesh, 0.0, {filled(6, 1.0), filled(6, 2.0)}, {filled(2, 3.0)}, {});
    writer.write(1, mesh, 1.0, {filled(6, 1.0), filled(6, 2.0)}, {filled(2, 3.0)}, {{}});
  }
  const QuadMesh back = readExodusQuadMesh(path("out.e"));
  EXPECT_TRUE(back.sideSets.empty());
  EXPECT_EQ(back.quads, mesh.quads);
  EXPECT_EQ(timeValues(path("out.e")), (std::vector<double>{0.0, 1.0}));
}

TEST_F(ExodusMeshTest, WrongLengthsAreLogicErrors) {
  const QuadMesh mesh = stripMesh(2);
  auto writer = makeWriter(path("out"));
  const auto nodes = filled(6, 0.0), cells = filled(2, 0.0), sides = filled(2, 0.0);
  EXPECT_THROW(writer.write(1, mesh, 0.0, {nodes}, {cells}, {sides}), std::logic_error);
  EXPECT_THROW(writer.write(1, mesh, 0.0, {nodes, filled(5, 0.0)}, {cells}, {sides}),
               std::logic_error);
  EXPECT_THROW(writer.write(1, mesh, 0.0, {nodes, nodes}, {filled(3, 0.0)}, {sides}),
               std::logic_error);
  EXPECT_THROW(writer.write(1, mesh, 0.0, {nodes, nodes}, {cells}, {filled(1, 0.0)}),
               std::logic_error);
  writer.write(1, mesh, 0.0, {nodes, nodes}, {cells}, {sides});
  const QuadMesh bigger = stripMesh(3);
  EXPECT_THROW(writer.write(1, bigger, 1.0, {filled(8, 0.0), filled(8, 0.0)}, {filled(3, 0.0)},
                            {filled(3, 0.0)}),
               std::logic_error);
}

TEST_F(ExodusMeshTest, LongNamesSurvive) {
  const std::string longName = "contact_surface_of_the_membrane_with_the_obstacle";
  QuadMesh mesh = stripMesh(2);
  mesh.sideSets[longName] = mesh.sideSets["contact"];
  {
    ExodusSeriesWriter writer(path("out"), {"displacement_normal_to_the_membrane_plane"}, {},
                              longName, {"lagrange_multiplier_of_the_contact_constraint"});
    writer.write(1, mesh, 0.0, {filled(6, 1.0)}, {}, {filled(2, 2.0)});
  }
  const QuadMesh back = readExodusQuadMesh(path("out.e"));
  ASSERT_EQ(back.sideSets.count(longName), 1u);
  EXPECT_EQ(back.sideSets.at(longName), mesh.sideSets.at("contact"));
}

/// The records of an Exodus file: its title, QA record and info records.
struct Records {
  std::string title;
  std::vector<std::string> qa, info;
};
Records recordsOf(const std::string& file) {
  Records r;
  const int exoid = openForCheck(file);
  if (exoid < 0) return r;
  ex_init_params params{};
  EXPECT_GE(ex_get_init_ext(exoid, &params), 0);
  r.title = params.title;
  EXPECT_EQ(ex_inquire_int(exoid, EX_INQ_QA), 1);
  char fields[4][MAX_STR_LENGTH + 1];
  char* qa[1][4] = {{fields[0], fields[1], fields[2], fields[3]}};
  EXPECT_GE(ex_get_qa(exoid, qa), 0);
  r.qa.assign(fields, fields + 4);
  const auto n = static_cast<std::size_t>(ex_inquire_int(exoid, EX_INQ_INFO));
  std::vector<std::vector<char>> buffers(n, std::vector<char>(MAX_LINE_LENGTH + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& b : buffers) pointers.push_back(b.data());
  if (n > 0) { EXPECT_GE(ex_get_info(exoid, pointers.data()), 0); }
  for (auto& b : buffers) r.info.emplace_back(b.data());
  ex_close(exoid);
  return r;
}

std::vector<double> globalsAt(const std::string& file, int step, int count) {
  std::vector<double> values(static_cast<std::size_t>(count));
  const int exoid = openForCheck(file);
  if (exoid < 0) return {};
  EXPECT_GE(ex_get_var(exoid, step, EX_GLOBAL, 1, 0, count, values.data()), 0);
  ex_close(exoid);
  return values;
}

TEST_F(ExodusMeshTest, EveryFileOfASeriesCarriesTitleRecordsAndGlobals) {
  const std::string longLine = std::string(79, 'a') + std::string(79, 'b') + "cd";  // 160 characters
  ExodusDescription description;
  description.title = "signorini: membrane";
  description.info = {"deck: membrane.xml", longLine, std::string(80, 'e'), ""};
  description.globalNames = {"energy", "eta"};
  {
    ExodusSeriesWriter writer(path("out"), {"u", "v"}, {"level"}, "contact", {"lambda"}, description);
    const QuadMesh a = stripMesh(2), b = stripMesh(3);
    writer.write(1, a, 0.0, {filled(6, 0.0), filled(6, 0.0)}, {filled(2, 0.0)}, {filled(2, 0.0)}, {1.0, 0.5});
    writer.write(1, a, 0.1, {filled(6, 0.0), filled(6, 0.0)}, {filled(2, 0.0)}, {filled(2, 0.0)}, {0.9, 0.25});
    writer.write(2, b, 0.2, {filled(8, 0.0), filled(8, 0.0)}, {filled(3, 0.0)}, {filled(3, 0.0)}, {0.8, 0.125});
    EXPECT_THROW(writer.write(2, b, 0.3, {filled(8, 0.0), filled(8, 0.0)}, {filled(3, 0.0)}, {filled(3, 0.0)}, {1.0}),
                 std::logic_error);
  }
  for (const std::string& file : {path("out.e"), path("out.e-s.0001")}) {
    const Records r = recordsOf(file);
    EXPECT_EQ(r.title, "signorini: membrane") << file;
    ASSERT_EQ(r.qa.size(), 4u);
    EXPECT_EQ(r.qa[0], "signorini");
    EXPECT_TRUE(std::regex_match(r.qa[1], std::regex("[0-9]+[.][0-9]+[.][0-9]+"))) << r.qa[1];
    EXPECT_TRUE(std::regex_match(r.qa[2], std::regex("[0-9]{4}-[0-9]{2}-[0-9]{2}"))) << r.qa[2];
    EXPECT_TRUE(std::regex_match(r.qa[3], std::regex("[0-9]{2}:[0-9]{2}:[0-9]{2} UTC"))) << r.qa[3];
    // The long line continues on the next records; a line of exactly 80 characters fits in one.
    EXPECT_EQ(r.info, (std::vector<std::string>{"deck: membrane.xml", std::string(79, 'a') + "\\",
                                                std::string(79, 'b') + "\\", "cd", std::string(80, 'e'), ""}))
        << file;
  }
  EXPECT_EQ(globalsAt(path("out.e"), 1, 2), (std::vector<double>{1.0, 0.5}));
  EXPECT_EQ(globalsAt(path("out.e"), 2, 2), (std::vector<double>{0.9, 0.25}));
  EXPECT_EQ(globalsAt(path("out.e-s.0001"), 1, 2), (std::vector<double>{0.8, 0.125}));
}

TEST_F(ExodusMeshTest, UncreatableFileIsUserErrorNamingPath) {
  const std::string base = path("no/such/dir/out");
  auto writer = makeWriter(base);
  try {
    writeStep(writer, 1, stripMesh(1), 0.0);
    FAIL() << "no UserError";
  } catch (const core::UserError& error) {
    EXPECT_NE(std::string(error.what()).find(base + ".e"), std::string::npos) << error.what();
  }
}

TEST_F(ExodusMeshTest, MissingFileIsUserErrorNamingPath) {
  expectReadError(path("missing.exo"), {path("missing.exo")});
}

TEST_F(ExodusMeshTest, NonExodusFileIsUserErrorNamingPath) {
  std::ofstream(path("notes.exo")) << "this is not a netCDF file\n";
  expectReadError(path("notes.exo"), {path("notes.exo")});
}

TEST_F(ExodusMeshTest, NetcdfFileWithoutMeshIsUserError) {
  // A valid Exodus file with no elements at all.
  int cpu = 8, io = 8;
  ex_opts(0);
  const int exoid = ex_create(path("empty.exo").c_str(), EX_CLOBBER, &cpu, &io);
  ASSERT_GE(exoid, 0);
  ASSERT_GE(ex_put_init(exoid, "empty", 2, 0, 0, 0, 0, 0), 0);
  ASSERT_GE(ex_close(exoid), 0);
  expectReadError(path("empty.exo"), {path("empty.exo")});
}

TEST_F(ExodusMeshTest, TriangleBlockIsUserError) {
  writeRawMesh(path("tri.exo"), 2, {0, 1, 0}, {0, 0, 1}, {}, "TRI3", 3, {1, 2, 3});
  expectReadError(path("tri.exo"), {path("tri.exo"), "block 7", "TRI3"});
}

// A bowtie whose two triangles have equal areas of opposite sign: zero area, and the message says
// what such a cell may be (a user review found "zero area" alone puzzling for a crossed cell).
TEST_F(ExodusMeshTest, ACellThatCrossesItselfIsNamed) {
  writeRawMesh(path("bowtie.exo"), 2, {0, 1, 1, 0}, {0, 1, 0, 1}, {}, "QUAD4", 4, {1, 2, 3, 4});
  expectReadError(path("bowtie.exo"), {path("bowtie.exo"), "element 1 has zero area", "crosses itself"});
}

TEST_F(ExodusMeshTest, ThreeDimensionalMeshIsUserError) {
  writeRawMesh(path("hex.exo"), 3, {0, 1, 1, 0, 0, 1, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1},
               {0, 0, 0, 0, 1, 1, 1, 1}, "HEX8", 8, {1, 2, 3, 4, 5, 6, 7, 8});
  expectReadError(path("hex.exo"), {path("hex.exo"), "3-dimensional and not a plane z = const (node 5 has z = 1"});
}

TEST_F(ExodusMeshTest, PlanarMeshWithThreeCoordinatesIsRead) {
  // A quad in the plane z = 2, as generators write 2D meshes with three coordinates.
  writeRawMesh(path("plane.exo"), 3, {0, 1, 1, 0}, {0, 0, 1, 1}, {2, 2, 2, 2}, "QUAD4", 4, {1, 2, 3, 4});
  const QuadMesh mesh = readExodusQuadMesh(path("plane.exo"));
  EXPECT_EQ(mesh.x, (std::vector<double>{0, 1, 1, 0}));
  EXPECT_EQ(mesh.y, (std::vector<double>{0, 0, 1, 1}));
  ASSERT_EQ(mesh.quads.size(), 1u);
}

TEST_F(ExodusMeshTest, AZeroNodeSaysTheFileMayBeTruncated) {
  // netCDF reads the data missing from a cut-off file as zeros; Exodus numbers nodes from 1.
  writeRawMesh(path("zero.exo"), 2, {0, 1, 1, 0}, {0, 0, 1, 1}, {}, "QUAD4", 4, {1, 2, 0, 4});
  expectReadError(path("zero.exo"), {path("zero.exo"), "refers to node 0 which does not exist",
                                     "the file may be truncated or corrupt"});
}

TEST_F(ExodusMeshTest, ARepeatedSideSetIdIsUserError) {
  // Written as side sets 42 ("bottom") and 43 ("top") by the Exodus API, which refuses a repeated
  // id, then 43 changed to 42 in the netCDF variable, as a writer without the API could leave it:
  // the library would read the bottom's sides for the top.
  const std::string file = path("twice.exo");
  {
    int cpu = 8, io = 8;
    ex_opts(0);
    const int exoid = ex_create(file.c_str(), EX_CLOBBER, &cpu, &io);
    ASSERT_GE(exoid, 0);
    ASSERT_GE(ex_put_init(exoid, "raw", 2, 4, 1, 1, 0, 2), 0);
    ASSERT_GE(ex_put_block(exoid, EX_ELEM_BLOCK, 7, "QUAD4", 1, 4, 0, 0, 0), 0);
    const std::vector<double> x{0, 1, 1, 0}, y{0, 0, 1, 1};
    const std::vector<int> connectivity{1, 2, 3, 4}, element{1}, bottom{1}, top{3};
    ASSERT_GE(ex_put_coord(exoid, x.data(), y.data(), nullptr), 0);
    ASSERT_GE(ex_put_conn(exoid, EX_ELEM_BLOCK, 7, connectivity.data(), nullptr, nullptr), 0);
    for (const auto& [id, name, side] : {std::tuple{42, "bottom", &bottom}, std::tuple{43, "top", &top}}) {
      ASSERT_GE(ex_put_set_param(exoid, EX_SIDE_SET, id, 1, 0), 0);
      ASSERT_GE(ex_put_name(exoid, EX_SIDE_SET, id, name), 0);
      ASSERT_GE(ex_put_set(exoid, EX_SIDE_SET, id, element.data(), side->data()), 0);
    }
    ASSERT_GE(ex_close(exoid), 0);
  }
  EXPECT_EQ(readExodusQuadMesh(file).sideSets.size(), 2u);  // the control: two sets as written
  int ncid = 0, varid = 0;
  ASSERT_EQ(nc_open(file.c_str(), NC_WRITE, &ncid), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(ncid, "ss_prop1", &varid), NC_NOERR);
  const int ids[2] = {42, 42};
  ASSERT_EQ(nc_put_var_int(ncid, varid, ids), NC_NOERR);
  ASSERT_EQ(nc_close(ncid), NC_NOERR);
  expectReadError(file, {file, "two side sets have the id 42"});
}

TEST_F(ExodusMeshTest, UnnamedSideSetAndClockwiseQuad) {
  // Quad 1 is counter-clockwise, quad 2 clockwise; both have their bottom edge in the set:
  // Exodus side 1 of quad 1 (nodes 1-2) and side 4 of quad 2 (nodes 3-2 in its clockwise order).
  writeRawMesh(path("mixed.exo"), 2, {0, 1, 2, 0, 1, 2}, {0, 0, 0, 1, 1, 1}, {}, "quad", 4,
               {1, 2, 5, 4, 2, 5, 6, 3}, {1, 2}, {1, 4});
  const QuadMesh mesh = readExodusQuadMesh(path("mixed.exo"));
  ASSERT_EQ(mesh.quads.size(), 2u);
  EXPECT_EQ(mesh.quads[0], (std::array<int, 4>{0, 1, 4, 3}));
  EXPECT_EQ(mesh.quads[1], (std::array<int, 4>{1, 2, 5, 4}));
  ASSERT_EQ(mesh.sideSets.count("sideset_42"), 1u);
  const auto& sides = mesh.sideSets.at("sideset_42");
  ASSERT_EQ(sides.size(), 2u);
  for (const auto& [quad, side] : sides) {
    const auto& q = mesh.quads[quad];
    EXPECT_EQ(mesh.y[q[side]], 0.0);
    EXPECT_EQ(mesh.y[q[(side + 1) % 4]], 0.0);
  }
}

}  // namespace
}  // namespace signorini::io
