#include "signorini/core/ParameterTools.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "signorini/core/Error.hpp"
#include "signorini/core/StringTools.hpp"

namespace signorini::core {
namespace {

const char* kPassThroughTag = "[pass-through] ";
const char* kNamedStringsTag = "[named strings] ";

bool hasTag(const Teuchos::ParameterEntry& e, const char* tag) {
  return e.docString().rfind(tag, 0) == 0;
}

std::string typeName(const Teuchos::any& a) {
  if (a.type() == typeid(double)) return "double";
  if (a.type() == typeid(int)) return "int";
  if (a.type() == typeid(bool)) return "bool";
  if (a.type() == typeid(std::string)) return "string";
  if (a.type() == typeid(ParameterList)) return "ParameterList";
  return a.typeName();
}

std::string join(const std::string& a, const std::string& b) { return a.empty() ? b : a + "/" + b; }

std::vector<std::string> names(const ParameterList& pl) {
  std::vector<std::string> out;
  for (auto it = pl.begin(); it != pl.end(); ++it) out.push_back(pl.name(it));
  return out;
}

size_t editDistance(std::string a, std::string b) {
  for (auto& c : a) c = std::tolower(static_cast<unsigned char>(c));
  for (auto& c : b) c = std::tolower(static_cast<unsigned char>(c));
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string describeValidator(const Teuchos::ParameterEntry& e) {
  auto v = e.validator();
  if (v.is_null()) return "";
  auto valid = v->validStringValues();
  if (!valid.is_null()) {
    std::string s;
    for (const auto& x : *valid) s += (s.empty() ? "" : ", ") + ("\"" + x + "\"");
    return "one of " + s;
  }
  if (auto d = Teuchos::rcp_dynamic_cast<const Teuchos::EnhancedNumberValidator<double>>(v); !d.is_null()) {
    std::ostringstream os;  // enough digits for bounds such as 0.4999999
    os << std::setprecision(10);
    // Infinite bounds are no bounds: every value must be finite (validateRecursive refuses inf).
    const bool lower = std::isfinite(d->getMin()), upper = std::isfinite(d->getMax());
    if (lower && upper) os << "in [" << d->getMin() << ", " << d->getMax() << "]";
    else if (lower) os << "finite, >= " << d->getMin();
    else if (upper) os << "finite, <= " << d->getMax();
    else os << "finite";
    return os.str();
  }
  if (auto i = Teuchos::rcp_dynamic_cast<const Teuchos::EnhancedNumberValidator<int>>(v); !i.is_null()) {
    std::ostringstream os;  // the int's own limits are no bounds
    const bool lower = i->getMin() != std::numeric_limits<int>::min();
    const bool upper = i->getMax() != std::numeric_limits<int>::max();
    if (lower && upper) os << "in [" << i->getMin() << ", " << i->getMax() << "]";
    else if (lower) os << ">= " << i->getMin();
    else if (upper) os << "<= " << i->getMax();
    else os << "an int";
    return os.str();
  }
  return "";
}

void validateRecursive(ParameterList& deck, const ParameterList& valid, const std::string& path,
                       const std::string& context) {
  const std::string where = path.empty() ? "the top level" : "sublist '" + path + "'";
  for (auto it = deck.begin(); it != deck.end(); ++it) {
    const std::string& key = deck.name(it);
    const std::string full = join(path, key);
    if (!valid.isParameter(key)) {
      std::string guess = closestName(key, names(valid));
      // a key given outside its sublist ("Time Step" at the top level for "Time Integration/Time Step")
      for (auto vt = valid.begin(); guess.empty() && !deck.entry(it).isList() && vt != valid.end(); ++vt)
        if (valid.entry(vt).isList() && valid.sublist(valid.name(vt)).isParameter(key) &&
            !valid.sublist(valid.name(vt)).getEntry(key).isList())
          guess = join(join(path, valid.name(vt)), key);
      SIGNORINI_USER_ERROR(context << ": unknown " << (deck.entry(it).isList() ? "sublist" : "parameter") << " '"
                                   << key << "' in " << where << (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
    }
    const auto& ventry = valid.getEntry(key);
    auto& dentry = deck.getEntry(key);
    const bool vIsList = ventry.isList(), dIsList = dentry.isList();
    if (vIsList != dIsList)
      SIGNORINI_USER_ERROR(context << ": '" << full << "' must be " << (vIsList ? "a sublist" : "a parameter, not a sublist"));
    if (vIsList) {
      if (hasTag(ventry, kPassThroughTag)) continue;
      if (hasTag(ventry, kNamedStringsTag)) {
        auto& sub = deck.sublist(key);
        for (auto jt = sub.begin(); jt != sub.end(); ++jt)
          if (sub.entry(jt).getAny().type() != typeid(std::string))
            SIGNORINI_USER_ERROR(context << ": '" << join(full, sub.name(jt)) << "' must be a string");
        continue;
      }
      validateRecursive(deck.sublist(key), valid.sublist(key), full, context);
      continue;
    }
    const auto& va = ventry.getAny();
    auto da = dentry.getAny();
    if (va.type() == typeid(double) && da.type() == typeid(int)) {  // an int is a fine double
      deck.set(key, static_cast<double>(Teuchos::any_cast<int>(da)));  // validated below
      da = deck.getEntry(key).getAny();
    }
    if (va.type() != da.type())
      SIGNORINI_USER_ERROR(context << ": '" << full << "' has type " << typeName(da) << " but must be "
                                   << typeName(va));
    if (da.type() == typeid(double) && !std::isfinite(Teuchos::any_cast<double>(da)))
      SIGNORINI_USER_ERROR(context << ": '" << full << "' is " << nonFiniteText(Teuchos::any_cast<double>(da))
                                   << "; a finite number is required");
    if (auto v = ventry.validator(); !v.is_null()) {
      try {
        v->validate(deck.getEntry(key), key, path);
      } catch (std::exception&) {
        std::ostringstream value;
        const auto& any = deck.getEntry(key).getAny();
        if (any.type() == typeid(double)) {
          value << shortestText(Teuchos::any_cast<double>(any));
        } else if (any.type() == typeid(std::string)) {  // quoted, so that blanks show; long ones cut
          const std::string& text = Teuchos::any_cast<std::string>(any);
          value << "\"" << (text.size() > 80 ? text.substr(0, 77) + "..." : text) << "\"";
        } else {
          value << any;
        }
        SIGNORINI_USER_ERROR(context << ": '" << full << "' = " << value.str() << " is not allowed; it must be "
                                     << describeValidator(ventry) << " (" << full << ": " << ventry.docString()
                                     << ")");
      }
    }
  }
}

void printRecursive(std::ostream& os, const ParameterList& valid, const std::string& path) {
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const auto& e = valid.entry(it);
    const std::string full = join(path, valid.name(it));
    if (e.isList()) {
      os << full << "/  (sublist)\n";
      if (!e.docString().empty()) os << "    " << e.docString() << "\n";
      if (!hasTag(e, kPassThroughTag) && !hasTag(e, kNamedStringsTag))
        printRecursive(os, valid.sublist(valid.name(it)), full);
      continue;
    }
    os << full << " : " << typeName(e.getAny()) << " = ";
    if (e.getAny().type() == typeid(std::string))
      os << "\"" << Teuchos::any_cast<std::string>(e.getAny()) << "\"";
    else if (e.getAny().type() == typeid(bool))
      os << (Teuchos::any_cast<bool>(e.getAny()) ? "true" : "false");  // as a deck writes it (not 1/0)
    else
      os << e.getAny();
    const std::string range = describeValidator(e);
    if (!range.empty()) os << "  (" << range << ")";
    os << "\n    " << e.docString() << "\n";
  }
}

}  // namespace

void addDouble(ParameterList& valid, const std::string& name, double def, const std::string& doc,
               double min, double max) {
  auto v = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>(min, max));
  valid.set(name, def, doc, v);
}

void addInt(ParameterList& valid, const std::string& name, int def, const std::string& doc, int min,
            int max) {
  auto v = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(min, max));
  valid.set(name, def, doc, v);
}

void addBool(ParameterList& valid, const std::string& name, bool def, const std::string& doc) {
  valid.set(name, def, doc);
}

void addString(ParameterList& valid, const std::string& name, const std::string& def,
               const std::string& doc) {
  valid.set(name, def, doc);
}

void addChoice(ParameterList& valid, const std::string& name, const std::string& def,
               const std::string& doc, const std::vector<std::string>& choices) {
  Teuchos::Array<std::string> arr(choices.begin(), choices.end());
  auto v = Teuchos::rcp(new Teuchos::StringValidator(arr));
  valid.set(name, def, doc, v);
}

ParameterList& addPassThrough(ParameterList& valid, const std::string& name, const std::string& doc) {
  auto& sub = valid.sublist(name, false, kPassThroughTag + doc);
  sub.disableRecursiveValidation();
  return sub;
}

ParameterList& addNamedStrings(ParameterList& valid, const std::string& name, const std::string& doc) {
  auto& sub = valid.sublist(name, false, kNamedStringsTag + doc);
  sub.disableRecursiveValidation();
  return sub;
}

void validateDeck(ParameterList& deck, const ParameterList& valid, const std::string& context) {
  validateRecursive(deck, valid, "", context);
  try {
    deck.validateParametersAndSetDefaults(valid);
  } catch (std::exception& e) {
    SIGNORINI_USER_ERROR(context << ": " << e.what());
  }
}

std::string closestName(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  size_t bestD = std::string::npos;
  for (const auto& c : candidates) {
    const size_t d = editDistance(name, c);
    if (d < bestD) bestD = d, best = c;
  }
  if (best.empty() || bestD > std::max<size_t>(3, name.size() / 2)) return "";
  return best;
}

bool isOverrideSpec(const std::string& spec) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos) return false;
  const std::string path = spec.substr(0, eq);
  return !path.empty() && path.front() != '/' && path.back() != '/' && path.find("//") == std::string::npos;
}

void applyOverride(ParameterList& deck, const std::string& spec, const ParameterList& valid) {
  const auto eq = spec.find('=');
  if (!isOverrideSpec(spec))
    SIGNORINI_USER_ERROR("--set '" << spec << "': expected 'Sublist/key=value'");
  const std::string path = spec.substr(0, eq), value = spec.substr(eq + 1);
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const auto slash = path.find('/', start);
    parts.push_back(path.substr(start, slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  ParameterList* d = &deck;
  const ParameterList* v = &valid;
  std::string walked;
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    walked = join(walked, parts[i]);
    if (v) {
      if (!v->isSublist(parts[i])) {
        const std::string guess = closestName(parts[i], names(*v));
        SIGNORINI_USER_ERROR("--set '" << spec << "': no sublist '" << walked << "'"
                                       << (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
      }
      const auto& e = v->getEntry(parts[i]);
      if (hasTag(e, kNamedStringsTag)) {  // user-chosen names, string values
        if (i + 2 != parts.size())
          SIGNORINI_USER_ERROR("--set '" << spec << "': '" << walked << "' holds named strings, not sublists");
        ParameterList* target = &deck;
        for (size_t k = 0; k <= i; ++k) target = &target->sublist(parts[k]);
        target->set(parts.back(), value);
        return;
      }
      v = hasTag(e, kPassThroughTag) ? nullptr : &v->sublist(parts[i]);
    }
    d = &d->sublist(parts[i]);
  }
  const std::string& key = parts.back();
  auto fail = [&](const std::string& type) {
    SIGNORINI_USER_ERROR("--set '" << spec << "': '" << value << "' is not a valid " << type);
  };
  // Numbers and bools may have blanks around them, as in a deck.
  auto parseDouble = [&](double& out) { return readDouble(value, out) == NumberText::valid; };
  bool intOutOfRange = false;  // set by parseInt for an integer that an int cannot hold
  auto parseInt = [&](int& out) {
    const auto read = readInt(value, out);
    intOutOfRange = read == NumberText::outOfRange;
    return read == NumberText::valid;
  };
  auto parseBool = [&](bool& out) {
    const auto first = value.find_first_not_of(" \t"), last = value.find_last_not_of(" \t");
    const std::string word = first == std::string::npos ? "" : value.substr(first, last - first + 1);
    if (word == "true" || word == "1") return out = true, true;
    if (word == "false" || word == "0") return out = false, true;
    return false;
  };
  if (!v) {  // pass-through or named strings: infer the type
    int i;
    double x;
    bool b;
    if (parseInt(i)) d->set(key, i);
    else if (parseDouble(x)) d->set(key, x);
    else if (parseBool(b)) d->set(key, b);
    else d->set(key, value);
    return;
  }
  if (v->isSublist(key))
    SIGNORINI_USER_ERROR("--set '" << spec << "': '" << join(walked, key) << "' is a sublist: set one of its entries, e.g. --set '"
                                   << join(walked, key) << "/<key>=value' (--print-parameters lists them)");
  if (!v->isParameter(key)) {
    std::string guess = closestName(key, names(*v));
    if (walked.empty())  // a key given without its sublist ("Refinement Level" for "Mesh/Refinement Level")
      for (auto it = v->begin(); guess.empty() && it != v->end(); ++it)
        if (v->entry(it).isList() && v->sublist(v->name(it)).isParameter(key)) guess = v->name(it) + "/" + key;
    SIGNORINI_USER_ERROR("--set '" << spec << "': unknown parameter '" << key << "' "
                                   << (walked.empty() ? std::string("at the top level") : "in sublist '" + walked + "'")
                                   << (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
  }
  const auto& t = v->getEntry(key).getAny().type();
  if (t == typeid(double)) {
    double x;
    if (!parseDouble(x)) fail("double");
    d->set(key, x);
  } else if (t == typeid(int)) {
    int i;
    if (!parseInt(i) && intOutOfRange)
      SIGNORINI_USER_ERROR("--set '" << spec << "': '" << value << "' is out of the range of an int ("
                                     << std::numeric_limits<int>::min() << " to " << std::numeric_limits<int>::max() << ")");
    if (!parseInt(i)) fail("int");
    d->set(key, i);
  } else if (t == typeid(bool)) {
    bool b;
    if (!readBool(value, b)) fail("bool (true/false)");
    d->set(key, b);
  } else {
    d->set(key, value);
  }
}

void printParameters(std::ostream& os, const ParameterList& valid) { printRecursive(os, valid, ""); }

namespace {

bool onlyBlanks(const char* text) { return std::string(text).find_first_not_of(" \t\r\n") == std::string::npos; }

}  // namespace

NumberText readDouble(const std::string& text, double& value) {
  char* end = nullptr;
  const double read = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !onlyBlanks(end)) return NumberText::notANumber;
  value = read;
  return NumberText::valid;
}

std::string keysSetOtherThanDefaults(const ParameterList& list, const ParameterList& defaults, const std::string& path,
                                     const std::function<bool(const std::string&)>& filter) {
  std::string keys;
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    if ((!filter || filter(name)) && defaults.isParameter(name) &&
        !(list.entry(it).getAny() == defaults.getEntry(name).getAny()))
      keys += (keys.empty() ? "" : ", ") + path + "/" + name;
  }
  return keys;
}

std::string shortestText(double value) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

NumberText readInt(const std::string& text, int& value) {
  char* end = nullptr;
  errno = 0;
  const long read = std::strtol(text.c_str(), &end, 10);
  if (end == text.c_str() || !onlyBlanks(end)) return NumberText::notANumber;
  if (errno == ERANGE || read < std::numeric_limits<int>::min() || read > std::numeric_limits<int>::max())
    return NumberText::outOfRange;
  value = static_cast<int>(read);
  return NumberText::valid;
}

bool readBool(const std::string& text, bool& value) {
  const auto first = text.find_first_not_of(" \t"), last = text.find_last_not_of(" \t");
  std::string word = first == std::string::npos ? "" : text.substr(first, last - first + 1);
  for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (word == "true" || word == "yes" || word == "1") return value = true, true;
  if (word == "false" || word == "no" || word == "0") return value = false, true;
  return false;
}

namespace {

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else if (c == '\n') out += "&#10;";  // every line of the deck ends in '>'
    else if (c == '\r') out += "&#13;";
    else out += c;
  }
  return out;
}

void writeXml(std::ostream& os, const ParameterList& list, const std::string& name, int depth) {
  const std::string indent(static_cast<size_t>(2 * depth), ' ');
  os << indent << "<ParameterList name=\"" << xmlEscaped(name) << "\">\n";
  for (auto it = list.begin(); it != list.end(); ++it) {
    const auto& entry = list.entry(it);
    const std::string& key = list.name(it);
    if (entry.isList()) {
      writeXml(os, Teuchos::getValue<ParameterList>(entry), key, depth + 1);
      continue;
    }
    const auto& any = entry.getAny();
    std::ostringstream value;
    if (any.type() == typeid(double))
      value << shortestText(Teuchos::any_cast<double>(any));  // 0.3, not 0.29999999999999999
    else if (any.type() == typeid(bool))
      value << (Teuchos::any_cast<bool>(any) ? "true" : "false");
    else
      value << std::setprecision(17) << any;  // arrays of doubles and the like
    os << indent << "  <Parameter name=\"" << xmlEscaped(key) << "\" type=\"" << typeName(any) << "\" value=\""
       << xmlEscaped(value.str()) << "\"/>\n";
  }
  os << indent << "</ParameterList>\n";
}

}  // namespace

std::string deckAsXml(const ParameterList& deck) {
  std::ostringstream os;
  writeXml(os, deck, deck.name(), 0);
  return os.str();
}

}  // namespace signorini::core
