// The deck reader reads a deck once (a pipe gives its text only once) and refuses what Teuchos
// would accept silently.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include "DeckReader.hpp"
#include "Error.hpp"

using namespace signorini;

namespace {

const char* kDeck =
    "<ParameterList name=\"deck\">\n"
    "  <ParameterList name=\"Time Integration\">\n"
    "    <Parameter name=\"Time Step\" type=\"double\" value=\"0.0025\"/>\n"
    "  </ParameterList>\n"
    "</ParameterList>\n";

std::string temporaryPath(const std::string& name) {
  return "/tmp/signorini-deck-reader-" + std::to_string(::getpid()) + "-" + name;
}

}  // namespace

TEST(DeckReader, ReadsADeckFromAPipe) {
  const std::string fifo = temporaryPath("fifo");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer([&] { std::ofstream(fifo) << kDeck; });  // the pipe's text, once
  Teuchos::ParameterList deck;
  EXPECT_NO_THROW(deck = io::readDeckFile(fifo));
  writer.join();
  std::remove(fifo.c_str());
  EXPECT_EQ(deck.sublist("Time Integration").get<double>("Time Step"), 0.0025);
}

TEST(DeckReader, RefusesAKeyGivenTwiceButNotTheSameNameInTwoLists) {
  const std::string path = temporaryPath("twice.xml");
  std::ofstream(path) << "<ParameterList name=\"deck\">\n"
                         "  <ParameterList name=\"A\"><Parameter name=\"x\" type=\"int\" value=\"1\"/></ParameterList>\n"
                         "  <ParameterList name=\"B\"><Parameter name=\"x\" type=\"int\" value=\"2\"/></ParameterList>\n"
                         "</ParameterList>\n";
  EXPECT_NO_THROW(io::readDeckFile(path));
  std::ofstream(path) << "<ParameterList name=\"deck\">\n"
                         "  <ParameterList name=\"A\"><Parameter name=\"x\" type=\"int\" value=\"1\"/>\n"
                         "    <Parameter name=\"x\" type=\"int\" value=\"2\"/></ParameterList>\n"
                         "</ParameterList>\n";
  try {
    io::readDeckFile(path);
    ADD_FAILURE() << "a key given twice was accepted";
  } catch (const core::UserError& e) {
    EXPECT_NE(std::string(e.what()).find("'A/x' is given twice"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}
