// The deck reader reads a deck once (a pipe gives its text only once) and refuses what Teuchos
// would accept silently.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

#include "signorini/io/DeckReader.hpp"
#include "signorini/core/Error.hpp"

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

// A shell's <(...) deck under mpirun: the ranks lack the shell's descriptor (/dev/fd/N). The
// message says why; a missing file keeps its own.
TEST(DeckReader, ADescriptorThisProcessLacksIsNamedAsSuch) {
  int unused = 900;
  while (::fcntl(unused, F_GETFD) != -1) ++unused;
  try {
    io::readDeckFile("/dev/fd/" + std::to_string(unused));
    FAIL() << "a descriptor that is not open was read";
  } catch (const core::UserError& e) {
    EXPECT_NE(std::string(e.what()).find("mpirun does not pass a shell's <(...) on to its ranks"), std::string::npos)
        << e.what();
  }
  try {
    io::readDeckFile(temporaryPath("missing.xml"));
    FAIL() << "a missing deck was read";
  } catch (const core::UserError& e) {
    EXPECT_NE(std::string(e.what()).find("missing or unreadable file"), std::string::npos) << e.what();
  }
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

namespace {

/// The message of the error io::readDeckFile gives for a deck with \p text, or "" if it reads it.
std::string errorReading(const std::string& text) {
  const std::string path = temporaryPath("numbers.xml");
  std::ofstream(path) << text;
  std::string message;
  try {
    io::readDeckFile(path);
  } catch (const core::UserError& e) {
    message = e.what();
  }
  std::remove(path.c_str());
  return message;
}

std::string deckWith(const std::string& type, const std::string& value) {
  return "<ParameterList name=\"deck\"><Parameter name=\"x\" type=\"" + type + "\" value=\"" + value +
         "\"/></ParameterList>\n";
}

}  // namespace

TEST(DeckReader, ReadsNumbersWithSurroundingBlanksAndNamesWhatIsWrongWithTheOthers) {
  const std::string path = temporaryPath("blanks.xml");
  std::ofstream(path) << "<ParameterList name=\"deck\"><Parameter name=\"k\" type=\"double\" value=\" 0.0025 \"/>"
                         "<Parameter name=\"n\" type=\"int\" value=\" 16\t\"/></ParameterList>\n";
  Teuchos::ParameterList deck;
  EXPECT_NO_THROW(deck = io::readDeckFile(path));
  std::remove(path.c_str());
  EXPECT_EQ(deck.get<double>("k"), 0.0025);
  EXPECT_EQ(deck.get<int>("n"), 16);
  for (const char* bad : {"", " ", "0.1 0.2", "0.1x", "x"})
    EXPECT_NE(errorReading(deckWith("double", bad)).find("is not a number"), std::string::npos) << "'" << bad << "'";
  for (const char* bad : {"", "4 5", "4.5", "1e3"})
    EXPECT_NE(errorReading(deckWith("int", bad)).find("is not an integer"), std::string::npos) << "'" << bad << "'";
  for (const char* big : {"2147483648", "-2147483649", "99999999999999999999"})
    EXPECT_NE(errorReading(deckWith("int", big)).find("is out of the range of an int (-2147483648 to 2147483647)"),
              std::string::npos)
        << big;
  EXPECT_EQ(errorReading(deckWith("int", "2147483647")), "");
  EXPECT_EQ(errorReading(deckWith("int", "-2147483648")), "");
}

TEST(DeckReader, ReadsADeckThatStartsWithAUtf8ByteOrderMark) {
  const std::string path = temporaryPath("bom.xml");
  std::ofstream(path) << "\xEF\xBB\xBF" << kDeck;
  Teuchos::ParameterList deck;
  EXPECT_NO_THROW(deck = io::readDeckFile(path));
  std::remove(path.c_str());
  EXPECT_EQ(deck.sublist("Time Integration").get<double>("Time Step"), 0.0025);
  // A cut byte-order mark is not UTF-8.
  EXPECT_NE(errorReading(std::string("\xEF\xBB") + kDeck).find("line 1 is not UTF-8 (byte 0xef)"), std::string::npos);
}
