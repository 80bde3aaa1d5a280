#include "DeckReader.hpp"

#include <cstdint>
#include <fstream>
#include <set>
#include <sstream>

#include <sys/stat.h>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_ParameterEntryXMLConverterDB.hpp>
#include <Teuchos_StringInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListReader.hpp>

#include "Error.hpp"
#include "MpiComm.hpp"
#include "ParameterTools.hpp"

namespace signorini::io {
namespace {

/// Numbers that convert in full, and no name twice in one list (Teuchos keeps the last silently).
void checkEntries(const Teuchos::XMLObject& node, const std::string& path, const std::string& file) {
  std::set<std::string> names;
  for (int i = 0; i < node.numChildren(); ++i) {
    const auto& child = node.getChild(i);
    const std::string name = child.hasAttribute("name") ? child.getAttribute("name") : "?";
    const std::string full = path.empty() ? name : path + "/" + name;
    if ((child.getTag() == "ParameterList" || child.getTag() == "Parameter") && child.hasAttribute("name") &&
        !names.insert(name).second)
      SIGNORINI_USER_ERROR(file << ": '" << full << "' is given twice");
    if (child.getTag() == "ParameterList") {
      checkEntries(child, full, file);
    } else if (child.getTag() == "Parameter" && child.hasAttribute("type") && child.hasAttribute("value")) {
      const std::string type = child.getAttribute("type"), value = child.getAttribute("value");
      try {
        Teuchos::ParameterEntryXMLConverterDB::getConverter(child);
      } catch (std::exception&) {  // Teuchos names neither the entry nor the line
        SIGNORINI_USER_ERROR(file << ": '" << full << "' has the type \"" << type
                                  << "\", which is not a parameter type (int, double, bool or string)");
      }
      double x;
      int i;
      if (type == "double" && core::readDouble(value, x) != core::NumberText::valid)
        SIGNORINI_USER_ERROR(file << ": '" << full << "' = \"" << value << "\" is not a number");
      const auto integer = type == "int" ? core::readInt(value, i) : core::NumberText::valid;
      if (integer == core::NumberText::notANumber)
        SIGNORINI_USER_ERROR(file << ": '" << full << "' = \"" << value << "\" is not an integer");
      if (integer == core::NumberText::outOfRange)
        SIGNORINI_USER_ERROR(file << ": '" << full << "' = \"" << value << "\" is out of the range of an int ("
                                  << INT32_MIN << " to " << INT32_MAX << ")");
    }
  }
}

/// The deck's text, read once (a deck from a pipe cannot be read a second time).
std::string readText(const std::string& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    SIGNORINI_USER_ERROR(path << ": is a directory, not a deck");
  std::ifstream in(path);
  if (!in) SIGNORINI_USER_ERROR(path << ": cannot open the deck (missing or unreadable file)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Teuchos::ParameterList parseDeck(const std::string& text, const std::string& path) {
  Teuchos::ParameterList deck;
  const std::string byteOrderMark = "\xEF\xBB\xBF";  // UTF-8, as some editors write it; the parser refuses it
  const bool marked = text.compare(0, byteOrderMark.size(), byteOrderMark) == 0;
  try {
    const Teuchos::XMLObject xml = Teuchos::StringInputSource(marked ? text.substr(byteOrderMark.size()) : text).getObject();
    checkEntries(xml, "", path);
    deck = Teuchos::XMLParameterListReader().toParameterList(xml);
  } catch (core::UserError&) {
    throw;
  } catch (std::exception& e) {
    std::string what = core::withoutSourceLocation(e.what());
    const auto pos = what.find_last_of('\n', what.size() > 1 ? what.size() - 2 : 0);
    if (what.size() > 300 && pos != std::string::npos) what = what.substr(pos + 1);
    SIGNORINI_USER_ERROR(path << ": malformed XML deck: " << what);
  }
  return deck;
}

}  // namespace

Teuchos::ParameterList readDeckFile(const std::string& path) { return parseDeck(readText(path), path); }

Teuchos::ParameterList readDeckFile(const std::string& path, const Comm& comm) {
  std::string text;
  core::onRootCollectively(comm, [&] { text = readText(path); });
  long long size = static_cast<long long>(text.size());
  Teuchos::broadcast(comm, 0, Teuchos::outArg(size));
  text.resize(static_cast<size_t>(size));
  if (size > 0) Teuchos::broadcast(comm, 0, static_cast<int>(size), &text[0]);
  return parseDeck(text, path);
}

}  // namespace signorini::io
