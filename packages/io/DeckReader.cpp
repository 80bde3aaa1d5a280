#include "DeckReader.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>

#include <sys/stat.h>

#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListReader.hpp>

#include "Error.hpp"

namespace signorini::io {
namespace {

bool isWholeDouble(const std::string& v) {
  if (v.empty()) return false;
  char* end = nullptr;
  std::strtod(v.c_str(), &end);
  return *end == '\0';
}

bool isWholeInt(const std::string& v) {
  if (v.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const long l = std::strtol(v.c_str(), &end, 10);
  return *end == '\0' && errno != ERANGE && l >= INT32_MIN && l <= INT32_MAX;
}

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
      if (type == "double" && !isWholeDouble(value))
        SIGNORINI_USER_ERROR(file << ": '" << full << "' = \"" << value << "\" is not a number");
      if (type == "int" && !isWholeInt(value))
        SIGNORINI_USER_ERROR(file << ": '" << full << "' = \"" << value << "\" is not an integer");
    }
  }
}

}  // namespace

Teuchos::ParameterList readDeckFile(const std::string& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    SIGNORINI_USER_ERROR(path << ": is a directory, not a deck");
  if (!std::ifstream(path)) SIGNORINI_USER_ERROR(path << ": cannot open the deck (missing or unreadable file)");
  Teuchos::ParameterList deck;
  try {
    // Read once: a deck from a pipe ("<(...)", /dev/stdin) cannot be read a second time.
    const Teuchos::XMLObject xml = Teuchos::FileInputSource(path).getObject();
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

}  // namespace signorini::io
