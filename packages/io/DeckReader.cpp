#include "signorini/io/DeckReader.hpp"

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

#include "signorini/core/Error.hpp"
#include "signorini/core/MpiComm.hpp"
#include "signorini/core/ParameterTools.hpp"

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
    if (child.getTag() == "Parameter" && (!child.hasAttribute("type") || !child.hasAttribute("value")))
      SIGNORINI_USER_ERROR(file << ": '" << full << "' has no " << (child.hasAttribute("type") ? "value" : "type")
                                << " attribute (<Parameter name=\"...\" type=\"double\" value=\"...\"/>)");
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
      bool b;
      if (type == "bool") {  // Teuchos' message names neither the key nor the line, and it refuses blanks
        if (!core::readBool(value, b))
          SIGNORINI_USER_ERROR(file << ": '" << full << "' = \"" << value << "\" is not a bool (true or false)");
        Teuchos::XMLObject entry = child;  // a handle: the parsed tree itself gets the plain word
        entry.addAttribute("value", std::string(b ? "true" : "false"));
      }
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

/// Throws a user error naming the line if \p text is not UTF-8 (e.g. Latin-1 from an old editor):
/// the bytes would reach the Exodus records and CSV headers as they are.
void checkUtf8(const std::string& text, const std::string& path) {
  int line = 1;
  for (size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') ++line;
    // Length of the sequence and the smallest code point it may encode (no overlong forms).
    const int length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    bool valid = length > 0 && i + length <= text.size();
    unsigned long code = length == 1 ? c : length == 2 ? c & 0x1Fu : length == 3 ? c & 0x0Fu : c & 0x07u;
    for (int k = 1; valid && k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      valid = (next >> 6) == 0x2;
      code = (code << 6) | (next & 0x3Fu);
    }
    static const unsigned long smallest[5] = {0, 0, 0x80, 0x800, 0x10000};
    valid = valid && code >= smallest[length] && code <= 0x10FFFF && !(code >= 0xD800 && code <= 0xDFFF);
    if (!valid)
      SIGNORINI_USER_ERROR(path << ": line " << line << " is not UTF-8 (byte 0x" << std::hex << static_cast<int>(c)
                                << "); save the deck as UTF-8");
    i += static_cast<size_t>(length);
  }
}

/// The deck's text, read once (a deck from a pipe cannot be read a second time).
std::string readText(const std::string& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    SIGNORINI_USER_ERROR(path << ": is a directory, not a deck");
  std::ifstream in(path);
  if (!in) {
    // "<(...)" gives /dev/fd/N, a descriptor of the shell that mpirun does not pass on to its ranks.
    const bool descriptor = path.rfind("/dev/fd/", 0) == 0 || path.rfind("/proc/self/fd/", 0) == 0;
    if (descriptor)
      SIGNORINI_USER_ERROR(path << ": cannot open the deck (a file descriptor that this process does not have: "
                                   "mpirun does not pass a shell's <(...) on to its ranks; give a file, or the deck "
                                   "on stdin as /dev/stdin)");
    SIGNORINI_USER_ERROR(path << ": cannot open the deck (missing or unreadable file)");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Teuchos::ParameterList parseDeck(const std::string& text, const std::string& path) {
  Teuchos::ParameterList deck;
  const std::string byteOrderMark = "\xEF\xBB\xBF";  // UTF-8, as some editors write it; the parser refuses it
  const bool marked = text.compare(0, byteOrderMark.size(), byteOrderMark) == 0;
  checkUtf8(text, path);
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
    // A segment condition "x < 0.5" or an expression "a && b" inside a value: XML wants &lt; and &amp;.
    const bool inValue = what.find("attribute value") != std::string::npos || what.find("reference") != std::string::npos;
    SIGNORINI_USER_ERROR(path << ": malformed XML deck: " << what
                              << (inValue ? " (inside a value write < as &lt; and & as &amp;, e.g. \"bottom, x &lt;= "
                                            "0.5\")"
                                          : ""));
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
