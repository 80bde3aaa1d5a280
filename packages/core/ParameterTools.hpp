#pragma once
/// \file ParameterTools.hpp
/// Building and enforcing validated Teuchos::ParameterLists (DESIGN section 4): every entry has
/// a default, a doc string and a validator; unknown keys are errors that suggest the closest name.
#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace signorini::core {

using ParameterList = Teuchos::ParameterList;  ///< decks, sublists and their valid lists

/// +infinity: "no upper bound" for addDouble().
constexpr double kInf = std::numeric_limits<double>::infinity();

/// A double entry valid in [min, max].
void addDouble(ParameterList& valid, const std::string& name, double def, const std::string& doc,
               double min = -kInf, double max = kInf);
/// An int entry valid in [min, max].
void addInt(ParameterList& valid, const std::string& name, int def, const std::string& doc,
            int min = std::numeric_limits<int>::min(), int max = std::numeric_limits<int>::max());
/// A bool entry.
void addBool(ParameterList& valid, const std::string& name, bool def, const std::string& doc);
/// A free string (expressions, file names, lists); its consumer checks the content.
void addString(ParameterList& valid, const std::string& name, const std::string& def,
               const std::string& doc);
/// A string restricted to \p choices.
void addChoice(ParameterList& valid, const std::string& name, const std::string& def,
               const std::string& doc, const std::vector<std::string>& choices);
/// A sublist whose content is passed unchanged to another library (Belos, MueLu) that
/// validates it itself; signorini does not check its keys.
ParameterList& addPassThrough(ParameterList& valid, const std::string& name, const std::string& doc);
/// A sublist whose keys are user-chosen names (e.g. named boundary segments or probes) with
/// string values; signorini checks the values' content itself.
ParameterList& addNamedStrings(ParameterList& valid, const std::string& name, const std::string& doc);

/// Checks \p deck against \p valid and fills in defaults. Throws UserError for an unknown key
/// (naming the key, its sublist and the closest valid name), a wrong type, an out-of-range
/// value, a disallowed string or NaN. \p context prefixes messages (e.g. the deck's file name).
void validateDeck(ParameterList& deck, const ParameterList& valid, const std::string& context);

/// Whether \p spec has the form of an override, "Sublist/.../key=value": an '=' after a path of
/// non-empty names separated by single slashes (the value may be empty or hold '=').
bool isOverrideSpec(const std::string& spec);

/// Applies a command-line override "Sublist/.../key=value" to \p deck, typed after \p valid
/// (inside pass-through sublists the type is inferred: int, double, bool, else string). Throws
/// UserError for a \p spec that is not of that form (isOverrideSpec).
void applyOverride(ParameterList& deck, const std::string& spec, const ParameterList& valid);

/// Prints every valid parameter with its path, type, default and doc string.
void printParameters(std::ostream& os, const ParameterList& valid);

/// How a text reads as a number: in full, blanks around it allowed (as Teuchos reads a deck).
enum class NumberText { valid, notANumber, outOfRange };
/// \p value is set when the text is valid. A double never counts as out of range (1e999 reads as inf).
NumberText readDouble(const std::string& text, double& value);
/// The same for an int (base 10): out of range beyond the limits of int.
NumberText readInt(const std::string& text, int& value);
/// A bool as a deck or --set may write it: true/false, yes/no or 1/0 in any case, blanks around it
/// allowed (Teuchos' XML reader takes the same words in any case, without blanks).
bool readBool(const std::string& text, bool& value);
/// The keys of the validated list \p list that it sets to other than their values in \p defaults,
/// among those \p filter accepts (all when empty), as "<path>/key, <path>/key2" (empty if none).
/// Compared by value: Teuchos' isDefault flag is not set when validation adds a whole sublist.
std::string keysSetOtherThanDefaults(const ParameterList& list, const ParameterList& defaults, const std::string& path,
                                     const std::function<bool(const std::string&)>& filter = {});
/// The shortest text that reads back to \p value (1.0000000001, not 1): for messages that quote a value.
std::string shortestText(double value);

/// \p deck as an XML deck that reads back to the same values (doubles with 17 significant digits),
/// without Teuchos' ids, doc strings and validators: for the records of the output files.
std::string deckAsXml(const ParameterList& deck);

/// The name in \p candidates closest to \p name (edit distance, case-insensitive); empty if none.
std::string closestName(const std::string& name, const std::vector<std::string>& candidates);

}  // namespace signorini::core
