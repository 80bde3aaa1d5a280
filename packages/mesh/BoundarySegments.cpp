#include "signorini/mesh/BoundarySegments.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "signorini/core/Error.hpp"
#include "signorini/core/StringTools.hpp"

namespace signorini::mesh {
namespace {
using core::trim;
}  // namespace

BoundarySegments::BoundarySegments(const core::ParameterList& specs, const CoarseMesh& coarse) {
  for (auto it = specs.begin(); it != specs.end(); ++it)
    add(specs.name(it), Teuchos::any_cast<std::string>(specs.entry(it).getAny()), coarse);
}

BoundarySegments::BoundarySegments(const std::vector<std::pair<std::string, std::string>>& specs,
                                   const CoarseMesh& coarse) {
  for (const auto& [n, s] : specs) add(n, s, coarse);
}

void BoundarySegments::add(const std::string& name, const std::string& spec, const CoarseMesh& coarse) {
  const std::string key = "Mesh/Boundary Segments/" + name;
  // The lists of Problem name segments by their names (blanks around an item dropped): a blank name
  // could never be named.
  if (trim(name).empty())
    SIGNORINI_USER_ERROR("Mesh/Boundary Segments: a segment with an empty name ('" << spec
                                                                                   << "'), which no list can name");
  // The lists split at commas and drop the blanks around each item: such names could never be named either.
  if (name.find(',') != std::string::npos || trim(name) != name)
    SIGNORINI_USER_ERROR(key << ": a segment name with a comma or with blanks at either end, which the Problem "
                               "lists (comma-separated, blanks dropped) cannot name; rename it");
  if (segments_.size() >= 32) SIGNORINI_USER_ERROR(key << ": at most 32 boundary segments are supported");
  Segment seg;
  seg.name = name;
  const std::vector<std::string> parts = core::splitTrimmed(spec, ',');  // "left," has two, the second empty
  if (parts[0].empty()) SIGNORINI_USER_ERROR(key << ": empty segment; expected \"<side set>[, x >= value]...\"");
  seg.set = parts[0];
  if (coarse.isEmptySet(seg.set))
    SIGNORINI_USER_ERROR(key << ": side set '" << seg.set << "' in " << coarse.source() << " is empty (it has no sides)");
  if (!coarse.hasSet(seg.set)) {
    std::string list;
    for (const auto& s : coarse.setNames()) list += (list.empty() ? "" : ", ") + s;
    SIGNORINI_USER_ERROR(key << ": side set '" << seg.set << "' does not exist in " << coarse.source()
                             << " (its side sets: " << (list.empty() ? "none" : list) << ")");
  }
  static const char* ops[4] = {">=", "<=", ">", "<"};
  for (size_t i = 1; i < parts.size(); ++i) {
    const std::string& c = parts[i];
    Condition cond{};
    if (c.empty())
      SIGNORINI_USER_ERROR(key << ": empty condition in '" << spec
                               << "' (a comma at the end, or two commas in a row); expected \"<side set>[, x >= value]...\"");
    if (coarse.hasSet(c))  // "top, bottom" (or "left, xmax"): a second side set where a condition belongs
      SIGNORINI_USER_ERROR(key << ": '" << c << "' is a second side set; a segment is one side set followed by "
                               "conditions on x or y (\"<side set>[, x >= value]...\"): make one segment per side "
                               "set and name all of them in the Problem list (e.g. \"" << name << "_" << c << "\")");
    if (c[0] != 'x' && c[0] != 'y') {
      SIGNORINI_USER_ERROR(key << ": condition '" << c << "' must start with x or y (a segment is \"<side set>[, "
                               "x >= value]...\": one side set, then conditions)");
    }
    cond.coord = c[0] == 'x' ? 0 : 1;
    std::string rest = trim(c.substr(1));
    int op = -1;
    for (int k = 0; k < 4 && op < 0; ++k)
      if (rest.rfind(ops[k], 0) == 0) op = k;
    if (op < 0) SIGNORINI_USER_ERROR(key << ": condition '" << c << "' needs one of >=, <=, >, <");
    cond.op = op;
    rest = trim(rest.substr(std::string(ops[op]).size()));
    char* end = nullptr;
    cond.value = std::strtod(rest.c_str(), &end);
    if (rest.empty() || *end != '\0' || !std::isfinite(cond.value))
      SIGNORINI_USER_ERROR(key << ": condition '" << c << "' needs a number after " << ops[op]);
    seg.conditions.push_back(cond);
  }
  segments_.push_back(seg);
}

int BoundarySegments::index(const std::string& name, const std::string& key) const {
  std::vector<std::string> names;
  for (size_t i = 0; i < segments_.size(); ++i) {
    if (segments_[i].name == name) return static_cast<int>(i);
    names.push_back(segments_[i].name);
  }
  const std::string guess = core::closestName(name, names);
  SIGNORINI_USER_ERROR(key << ": no boundary segment named '" << name << "' in Mesh/Boundary Segments"
                           << (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
}

unsigned BoundarySegments::match(const CoarseMesh& coarse, int tree, int face, double mx, double my) const {
  unsigned mask = 0;
  const auto& sets = coarse.faceSets(tree, face);
  for (size_t i = 0; i < segments_.size(); ++i) {
    const auto& s = segments_[i];
    if (std::find(sets.begin(), sets.end(), s.set) == sets.end()) continue;
    bool ok = true;
    for (const auto& c : s.conditions) {
      const double v = c.coord == 0 ? mx : my;
      switch (c.op) {
        case 0: ok = ok && v >= c.value; break;
        case 1: ok = ok && v <= c.value; break;
        case 2: ok = ok && v > c.value; break;
        default: ok = ok && v < c.value; break;
      }
    }
    if (ok) mask |= 1u << i;
  }
  return mask;
}

}  // namespace signorini::mesh
