// Deck validation (DESIGN section 4): unknown keys with the closest valid name, types, ranges,
// NaN, choices, pass-through and named-string sublists, defaults, --set overrides and
// --print-parameters, all on small hand-made valid lists.
#include <gtest/gtest.h>

#include <Teuchos_XMLParameterListHelpers.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "signorini/core/Error.hpp"
#include "signorini/core/ParameterTools.hpp"

using namespace signorini::core;

namespace {

/// A small valid list shaped like a real deck: typed entries with ranges, a choice, a free
/// string, a named-strings sublist and a pass-through sublist.
ParameterList makeValid() {
  ParameterList v("valid");
  auto& ti = v.sublist("Time Integration", false, "Newmark time stepping");
  addDouble(ti, "Time Step", 0.0025, "k [time], constant", 1e-300, kInf);
  addDouble(ti, "Alpha", 0.5, "Newmark alpha", 0.0, 2.0);
  addInt(ti, "Steps", 10, "number of steps", 1, 1000);
  auto& mesh = v.sublist("Mesh", false, "Coarse mesh");
  addChoice(mesh, "Type", "rectangle", "Coarse mesh kind", {"rectangle", "exodus"});
  addInt(mesh, "Cells X", 1, "Rectangle: number of coarse cells in x", 1, 100000);
  addBool(mesh, "Verbose", false, "Print mesh statistics");
  addString(mesh, "File", "", "Exodus II file");
  addNamedStrings(mesh, "Boundary Segments", "Named boundary segments");
  addPassThrough(v, "Belos", "Passed unchanged to Belos");
  return v;
}

/// The message of the UserError thrown by \p f; fails the test if \p f does not throw one.
std::string userErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (UserError& e) {
    return e.what();
  } catch (std::exception& e) {
    ADD_FAILURE() << "expected signorini::core::UserError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected signorini::core::UserError, nothing was thrown";
  return "";
}

std::string validateError(ParameterList deck, const std::string& context = "deck.xml") {
  const auto valid = makeValid();
  return userErrorOf([&] { validateDeck(deck, valid, context); });
}

std::string overrideError(const std::string& spec) {
  ParameterList deck;
  const auto valid = makeValid();
  return userErrorOf([&] { applyOverride(deck, spec, valid); });
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

#define EXPECT_CONTAINS(s, part) EXPECT_PRED2(contains, s, part)
#define EXPECT_NOT_CONTAINS(s, part) EXPECT_FALSE(contains(s, part)) << "in: " << (s)

// ------------------------------------------------------------------------------------------
// validateDeck

TEST(ValidateDeck, ValidDeckPassesAndKeepsValues) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Time Step", 0.01);
  deck.sublist("Mesh").set("Type", std::string("exodus"));
  deck.sublist("Mesh").set("Cells X", 4);
  deck.sublist("Mesh").set("Verbose", true);
  const auto valid = makeValid();
  EXPECT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
  EXPECT_DOUBLE_EQ(deck.sublist("Time Integration").get<double>("Time Step"), 0.01);
  EXPECT_EQ(deck.sublist("Mesh").get<std::string>("Type"), "exodus");
  EXPECT_EQ(deck.sublist("Mesh").get<int>("Cells X"), 4);
  EXPECT_TRUE(deck.sublist("Mesh").get<bool>("Verbose"));
}

TEST(ValidateDeck, UnknownKeyNamesKeySublistAndClosestName) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Time Stepp", 0.01);
  const auto msg = validateError(deck, "inputs/deck.xml");
  EXPECT_CONTAINS(msg, "inputs/deck.xml");
  EXPECT_CONTAINS(msg, "'Time Stepp'");
  EXPECT_CONTAINS(msg, "sublist 'Time Integration'");
  EXPECT_CONTAINS(msg, "did you mean 'Time Step'");
}

TEST(ValidateDeck, UnknownKeyInNestedSublistNamesFullSublistPath) {
  ParameterList deck;
  deck.sublist("Mesh").set("Cels X", 4);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Cels X'");
  EXPECT_CONTAINS(msg, "sublist 'Mesh'");
  EXPECT_CONTAINS(msg, "did you mean 'Cells X'");
}

TEST(ValidateDeck, UnknownTopLevelSublistSuggestsClosest) {
  ParameterList deck;
  deck.sublist("Mesch").set("Cells X", 4);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "unknown sublist 'Mesch'");  // a sublist is not called a parameter
  EXPECT_CONTAINS(msg, "top level");
  EXPECT_CONTAINS(msg, "did you mean 'Mesh'");
}

// A key given outside its sublist is found in the sublist that has it (as --set does).
TEST(ValidateDeck, KeyOutsideItsSublistNamesTheSublist) {
  ParameterList deck;
  deck.set("Time Step", 0.01);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "unknown parameter 'Time Step' in the top level");
  EXPECT_CONTAINS(msg, "did you mean 'Time Integration/Time Step'");
}

TEST(ValidateDeck, UnknownKeyIsCaseInsensitiveWhenSuggesting) {
  ParameterList deck;
  deck.sublist("Time Integration").set("time step", 0.01);
  EXPECT_CONTAINS(validateError(deck), "did you mean 'Time Step'");
}

TEST(ValidateDeck, UnknownKeyFarFromEveryNameHasNoSuggestion) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Preconditioner Overlap Level", 2);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Preconditioner Overlap Level'");
  EXPECT_NOT_CONTAINS(msg, "did you mean");
}

TEST(ValidateDeck, ContextPrefixesTheMessage) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Alpha", 7.0);
  const auto msg = validateError(deck, "my/deck.xml");
  EXPECT_EQ(msg.rfind("my/deck.xml", 0), 0u) << msg;
}

TEST(ValidateDeck, WrongTypeNamesKeyAndBothTypes) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Time Step", std::string("0.01"));
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Time Integration/Time Step'");
  EXPECT_CONTAINS(msg, "string");
  EXPECT_CONTAINS(msg, "double");
}

TEST(ValidateDeck, DoubleIsNotAcceptedForAnInt) {
  ParameterList deck;
  deck.sublist("Mesh").set("Cells X", 4.0);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Mesh/Cells X'");
  EXPECT_CONTAINS(msg, "int");
}

TEST(ValidateDeck, StringIsNotAcceptedForABool) {
  ParameterList deck;
  deck.sublist("Mesh").set("Verbose", std::string("yes"));
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Mesh/Verbose'");
  EXPECT_CONTAINS(msg, "bool");
}

TEST(ValidateDeck, ParameterGivenWhereSublistExpected) {
  ParameterList deck;
  deck.set("Mesh", 3);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Mesh'");
  EXPECT_CONTAINS(msg, "sublist");
}

TEST(ValidateDeck, SublistGivenWhereParameterExpected) {
  ParameterList deck;
  deck.sublist("Mesh").sublist("Cells X").set("n", 3);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Mesh/Cells X'");
  EXPECT_CONTAINS(msg, "parameter");
}

TEST(ValidateDeck, DoubleOutOfRangeNamesKeyValueAndRange) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Alpha", 3.0);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Time Integration/Alpha'");
  EXPECT_CONTAINS(msg, "3");
  EXPECT_CONTAINS(msg, "[0, 2]");
}

TEST(ValidateDeck, NonPositiveValueRejectedForPositiveDouble) {
  for (double k : {0.0, -0.0025}) {
    ParameterList deck;
    deck.sublist("Time Integration").set("Time Step", k);
    const auto msg = validateError(deck);
    EXPECT_CONTAINS(msg, "'Time Integration/Time Step'");
    EXPECT_CONTAINS(msg, "not allowed");
  }
}

TEST(ValidateDeck, IntOutOfRangeNamesKeyAndRange) {
  for (int n : {0, 100001}) {
    ParameterList deck;
    deck.sublist("Mesh").set("Cells X", n);
    const auto msg = validateError(deck);
    EXPECT_CONTAINS(msg, "'Mesh/Cells X'");
    EXPECT_CONTAINS(msg, std::to_string(n));
    EXPECT_CONTAINS(msg, "[1, 100000]");
  }
}

TEST(ValidateDeck, NaNRejected) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Time Step", std::numeric_limits<double>::quiet_NaN());
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Time Integration/Time Step'");
  EXPECT_CONTAINS(msg, "finite");
}

TEST(ValidateDeck, InfinityRejectedEvenWhenTheRangeIsUnbounded) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Time Step", kInf);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Time Integration/Time Step'");
  EXPECT_CONTAINS(msg, "finite");
}

TEST(ValidateDeck, IntAcceptedForADoubleAndStoredAsDouble) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Time Step", 1);
  const auto valid = makeValid();
  ASSERT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
  const auto& ti = deck.sublist("Time Integration");
  ASSERT_TRUE(ti.isType<double>("Time Step"));
  EXPECT_EQ(ti.get<double>("Time Step"), 1.0);
}

TEST(ValidateDeck, IntOutOfRangeForADoubleStillRejected) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Alpha", 5);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Time Integration/Alpha'");
  EXPECT_CONTAINS(msg, "[0, 2]");
}

TEST(ValidateDeck, DisallowedChoiceListsTheChoices) {
  ParameterList deck;
  deck.sublist("Mesh").set("Type", std::string("exodos"));
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Mesh/Type'");
  EXPECT_CONTAINS(msg, "exodos");
  EXPECT_CONTAINS(msg, "\"rectangle\"");
  EXPECT_CONTAINS(msg, "\"exodus\"");
}

TEST(ValidateDeck, PassThroughSublistKeysAreNotChecked) {
  ParameterList deck;
  auto& belos = deck.sublist("Belos");
  belos.set("Maximum Iterations", 500);
  belos.set("Convergence Tolerance", 1e-10);
  belos.set("Anything Goes", std::string("really"));
  belos.sublist("Nested").set("Deep", true);
  const auto valid = makeValid();
  ASSERT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
  EXPECT_EQ(deck.sublist("Belos").get<int>("Maximum Iterations"), 500);
  EXPECT_EQ(deck.sublist("Belos").get<std::string>("Anything Goes"), "really");
  EXPECT_TRUE(deck.sublist("Belos").sublist("Nested").get<bool>("Deep"));
}

TEST(ValidateDeck, NamedStringsAcceptAnyNameWithAStringValue) {
  ParameterList deck;
  auto& segs = deck.sublist("Mesh").sublist("Boundary Segments");
  segs.set("clamped", std::string("left"));
  segs.set("my contact zone", std::string("bottom, x >= 0.15"));
  const auto valid = makeValid();
  ASSERT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
  EXPECT_EQ(deck.sublist("Mesh").sublist("Boundary Segments").get<std::string>("my contact zone"),
            "bottom, x >= 0.15");
}

TEST(ValidateDeck, NamedStringsValuesMustBeStrings) {
  ParameterList deck;
  deck.sublist("Mesh").sublist("Boundary Segments").set("contact", 3);
  const auto msg = validateError(deck);
  EXPECT_CONTAINS(msg, "'Mesh/Boundary Segments/contact'");
  EXPECT_CONTAINS(msg, "string");
}

TEST(ValidateDeck, DefaultsFilledIn) {
  ParameterList deck;
  deck.sublist("Mesh").set("Cells X", 8);
  const auto valid = makeValid();
  ASSERT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
  // Missing entries of a given sublist get their defaults; the given one is kept.
  EXPECT_EQ(deck.sublist("Mesh").get<int>("Cells X"), 8);
  EXPECT_EQ(deck.sublist("Mesh").get<std::string>("Type"), "rectangle");
  EXPECT_FALSE(deck.sublist("Mesh").get<bool>("Verbose"));
  EXPECT_EQ(deck.sublist("Mesh").get<std::string>("File"), "");
  EXPECT_TRUE(deck.sublist("Mesh").isSublist("Boundary Segments"));
  // A missing sublist is filled in with all its defaults.
  ASSERT_TRUE(deck.isSublist("Time Integration"));
  EXPECT_DOUBLE_EQ(deck.sublist("Time Integration").get<double>("Time Step"), 0.0025);
  EXPECT_DOUBLE_EQ(deck.sublist("Time Integration").get<double>("Alpha"), 0.5);
  EXPECT_EQ(deck.sublist("Time Integration").get<int>("Steps"), 10);
  EXPECT_TRUE(deck.isSublist("Belos"));
}

TEST(ValidateDeck, EmptyDeckIsValidAndGetsEveryDefault) {
  ParameterList deck;
  const auto valid = makeValid();
  ASSERT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
  EXPECT_DOUBLE_EQ(deck.sublist("Time Integration").get<double>("Time Step"), 0.0025);
  EXPECT_EQ(deck.sublist("Mesh").get<std::string>("Type"), "rectangle");
}

// ------------------------------------------------------------------------------------------
// applyOverride (--set)

TEST(ApplyOverride, TypedConversionFollowsTheValidList) {
  ParameterList deck;
  const auto valid = makeValid();
  applyOverride(deck, "Time Integration/Time Step=0.01", valid);
  applyOverride(deck, "Mesh/Cells X=8", valid);
  applyOverride(deck, "Mesh/Verbose=true", valid);
  applyOverride(deck, "Mesh/Type=exodus", valid);
  applyOverride(deck, "Mesh/File=meshes/a=b.exo", valid);  // the first '=' separates
  const auto& ti = deck.sublist("Time Integration");
  const auto& mesh = deck.sublist("Mesh");
  ASSERT_TRUE(ti.isType<double>("Time Step"));
  EXPECT_DOUBLE_EQ(ti.get<double>("Time Step"), 0.01);
  ASSERT_TRUE(mesh.isType<int>("Cells X"));
  EXPECT_EQ(mesh.get<int>("Cells X"), 8);
  ASSERT_TRUE(mesh.isType<bool>("Verbose"));
  EXPECT_TRUE(mesh.get<bool>("Verbose"));
  ASSERT_TRUE(mesh.isType<std::string>("Type"));
  EXPECT_EQ(mesh.get<std::string>("Type"), "exodus");
  EXPECT_EQ(mesh.get<std::string>("File"), "meshes/a=b.exo");
  EXPECT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
}

TEST(ApplyOverride, IntegerTextGivesADoubleForADoubleKey) {
  ParameterList deck;
  const auto valid = makeValid();
  applyOverride(deck, "Time Integration/Alpha=1", valid);
  ASSERT_TRUE(deck.sublist("Time Integration").isType<double>("Alpha"));
  EXPECT_EQ(deck.sublist("Time Integration").get<double>("Alpha"), 1.0);
}

TEST(ApplyOverride, BoolAcceptsTrueFalseOneZero) {
  const auto valid = makeValid();
  for (const auto& [text, value] : std::vector<std::pair<std::string, bool>>{
           {"true", true}, {"false", false}, {"1", true}, {"0", false}}) {
    ParameterList deck;
    applyOverride(deck, "Mesh/Verbose=" + text, valid);
    ASSERT_TRUE(deck.sublist("Mesh").isType<bool>("Verbose")) << text;
    EXPECT_EQ(deck.sublist("Mesh").get<bool>("Verbose"), value) << text;
  }
}

TEST(ApplyOverride, ReplacesTheDeckValue) {
  ParameterList deck;
  deck.sublist("Time Integration").set("Time Step", 0.5);
  const auto valid = makeValid();
  applyOverride(deck, "Time Integration/Time Step=0.125", valid);
  EXPECT_DOUBLE_EQ(deck.sublist("Time Integration").get<double>("Time Step"), 0.125);
}

TEST(ApplyOverride, OverriddenValueIsStillRangeChecked) {
  ParameterList deck;
  const auto valid = makeValid();
  applyOverride(deck, "Time Integration/Alpha=3", valid);
  const auto msg = userErrorOf([&] { validateDeck(deck, valid, "deck.xml"); });
  EXPECT_CONTAINS(msg, "'Time Integration/Alpha'");
  EXPECT_CONTAINS(msg, "[0, 2]");
}

TEST(ApplyOverride, NamesWhatIsWrongWithAnInteger) {
  EXPECT_CONTAINS(overrideError("Mesh/Cells X=4.5"), "'4.5' is not a valid int");
  EXPECT_CONTAINS(overrideError("Mesh/Cells X=eight"), "'eight' is not a valid int");
  for (const std::string big : {"2147483648", "-2147483649", "99999999999999999999"})
    EXPECT_CONTAINS(overrideError("Mesh/Cells X=" + big), "'" + big + "' is out of the range of an int");
  ParameterList deck;
  applyOverride(deck, "Mesh/Cells X=2147483647", makeValid());
  EXPECT_EQ(deck.sublist("Mesh").get<int>("Cells X"), 2147483647);
}

TEST(ApplyOverride, NumbersMayHaveBlanksAroundThemAsInADeck) {
  ParameterList deck;
  const auto valid = makeValid();
  applyOverride(deck, "Mesh/Cells X= 8 ", valid);
  applyOverride(deck, "Time Integration/Time Step=\t0.01 ", valid);
  EXPECT_EQ(deck.sublist("Mesh").get<int>("Cells X"), 8);
  EXPECT_EQ(deck.sublist("Time Integration").get<double>("Time Step"), 0.01);
  EXPECT_CONTAINS(overrideError("Mesh/Cells X= "), "is not a valid int");
  EXPECT_CONTAINS(overrideError("Time Integration/Time Step=0.01 0.02"), "is not a valid double");
}

TEST(ApplyOverride, UnknownKeySuggestsClosest) {
  const auto msg = overrideError("Time Integration/Time Stp=0.01");
  EXPECT_CONTAINS(msg, "Time Integration/Time Stp=0.01");  // the --set spec
  EXPECT_CONTAINS(msg, "'Time Stp'");
  EXPECT_CONTAINS(msg, "'Time Integration'");
  EXPECT_CONTAINS(msg, "did you mean 'Time Step'");
}

TEST(ApplyOverride, UnknownSublistSuggestsClosest) {
  const auto msg = overrideError("Time Integraton/Time Step=0.01");
  EXPECT_CONTAINS(msg, "'Time Integraton'");
  EXPECT_CONTAINS(msg, "did you mean 'Time Integration'");
}

TEST(ApplyOverride, SublistNameUsedAsAKeyIsRejected) {
  const auto msg = overrideError("Mesh=3");
  EXPECT_CONTAINS(msg, "Mesh=3");
  EXPECT_CONTAINS(msg, "'Mesh'");
}

TEST(ApplyOverride, BadValueForADoubleRejected) {
  for (const std::string value : {"fast", "", "0.01s", "1,5"}) {
    const auto msg = overrideError("Time Integration/Time Step=" + value);
    EXPECT_CONTAINS(msg, "'" + value + "'");
    EXPECT_CONTAINS(msg, "double");
  }
}

TEST(ApplyOverride, NaNForADoubleIsRejectedBeforeTheRun) {
  // Either --set itself or the validation that follows must refuse NaN.
  ParameterList deck;
  const auto valid = makeValid();
  const auto msg = userErrorOf([&] {
    applyOverride(deck, "Time Integration/Time Step=nan", valid);
    validateDeck(deck, valid, "deck.xml");
  });
  EXPECT_CONTAINS(msg, "Time Step");
  // A not-a-number in the deck is named as "nan", without the sign glibc may print.
  for (const double value : {std::nan(""), -std::nan("")}) {
    ParameterList bad;
    bad.sublist("Time Integration").set("Time Step", value);
    const auto message = userErrorOf([&] { validateDeck(bad, valid, "deck.xml"); });
    EXPECT_CONTAINS(message, "'Time Integration/Time Step' is nan; a finite number is required");
  }
}

TEST(ApplyOverride, BadValueForAnIntRejected) {
  for (const std::string value : {"4.5", "four", ""}) {
    const auto msg = overrideError("Mesh/Cells X=" + value);
    EXPECT_CONTAINS(msg, "'" + value + "'");
    EXPECT_CONTAINS(msg, "int");
  }
}

TEST(ApplyOverride, IntThatOverflowsIsRejectedNotWrapped) {
  // 2^32 + 4 would wrap to 4 (a valid Cells X) if the long were narrowed silently.
  ParameterList deck;
  const auto valid = makeValid();
  const auto msg = userErrorOf([&] {
    applyOverride(deck, "Mesh/Cells X=4294967300", valid);
    validateDeck(deck, valid, "deck.xml");
  });
  EXPECT_CONTAINS(msg, "Cells X");
}

TEST(ApplyOverride, BadValueForABoolRejected) {
  const auto msg = overrideError("Mesh/Verbose=maybe");
  EXPECT_CONTAINS(msg, "'maybe'");
  EXPECT_CONTAINS(msg, "bool");
}

// The words Teuchos' XML reader takes for a bool in a deck (true/false, yes/no, 1/0, any case),
// with blanks around them as for numbers; nothing else.
TEST(ReadBool, TheDecksWordsInAnyCaseWithBlanks) {
  bool b = false;
  for (const std::string word : {"true", "TRUE", " True ", "yes", "YES\t", "1"}) {
    b = false;
    EXPECT_TRUE(readBool(word, b) && b) << "'" << word << "'";
  }
  for (const std::string word : {"false", "False", "\tno", "NO", "0 "}) {
    b = true;
    EXPECT_TRUE(readBool(word, b) && !b) << "'" << word << "'";
  }
  for (const std::string word : {"", " ", "maybe", "t", "y", "2", "true false", "on", "off", "10"}) {
    EXPECT_FALSE(readBool(word, b)) << "'" << word << "'";
  }
}

TEST(ApplyOverride, MissingEqualsOrKeyRejected) {
  // An empty name anywhere in the path (the driver refuses the same forms with a usage error).
  for (const std::string spec : {"Time Integration/Time Step", "=0.01", "Mesh/=3", "/Mesh/Cells X=3",
                                 "Problem//Obstacle=1", "Mesh/Cells X/=3"}) {
    EXPECT_FALSE(isOverrideSpec(spec)) << spec;
    const auto msg = overrideError(spec);
    EXPECT_CONTAINS(msg, spec);
    EXPECT_CONTAINS(msg, "Sublist/key=value");
  }
}

TEST(ApplyOverride, WellFormedSpecsAreOverrides) {
  for (const std::string spec : {"Mesh/Cells X=3", "Mesh/File=a=b.exo", "Output/Basename=", "Top=1"})
    EXPECT_TRUE(isOverrideSpec(spec)) << spec;
}

TEST(ApplyOverride, PassThroughSublistInfersType) {
  ParameterList deck;
  const auto valid = makeValid();
  applyOverride(deck, "Belos/Maximum Iterations=100", valid);
  applyOverride(deck, "Belos/Convergence Tolerance=1e-8", valid);
  applyOverride(deck, "Belos/Implicit Residual Scaling=false", valid);
  applyOverride(deck, "Belos/Solver Type=Pseudoblock GMRES", valid);
  applyOverride(deck, "Belos/Nested/Deep=0.5", valid);
  const auto& belos = deck.sublist("Belos");
  ASSERT_TRUE(belos.isType<int>("Maximum Iterations"));
  EXPECT_EQ(belos.get<int>("Maximum Iterations"), 100);
  ASSERT_TRUE(belos.isType<double>("Convergence Tolerance"));
  EXPECT_DOUBLE_EQ(belos.get<double>("Convergence Tolerance"), 1e-8);
  ASSERT_TRUE(belos.isType<bool>("Implicit Residual Scaling"));
  EXPECT_FALSE(belos.get<bool>("Implicit Residual Scaling"));
  ASSERT_TRUE(belos.isType<std::string>("Solver Type"));
  EXPECT_EQ(belos.get<std::string>("Solver Type"), "Pseudoblock GMRES");
  ASSERT_TRUE(belos.isSublist("Nested"));
  ASSERT_TRUE(belos.sublist("Nested").isType<double>("Deep"));
  EXPECT_DOUBLE_EQ(belos.sublist("Nested").get<double>("Deep"), 0.5);
  EXPECT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
}

TEST(ApplyOverride, NamedStringsSublistGetsAString) {
  ParameterList deck;
  const auto valid = makeValid();
  applyOverride(deck, "Mesh/Boundary Segments/contact=right, y >= 0.5", valid);
  ASSERT_TRUE(deck.sublist("Mesh").sublist("Boundary Segments").isType<std::string>("contact"));
  EXPECT_EQ(deck.sublist("Mesh").sublist("Boundary Segments").get<std::string>("contact"), "right, y >= 0.5");
  EXPECT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
}

TEST(ApplyOverride, NamedStringsSublistKeepsNumericLookingTextAsAString) {
  // Named-strings values are strings by definition (addNamedStrings), e.g. an Exodus side set
  // named "1" or "2"; --set must not turn them into an int the validation then rejects.
  ParameterList deck;
  const auto valid = makeValid();
  applyOverride(deck, "Mesh/Boundary Segments/contact=2", valid);
  const auto& segs = deck.sublist("Mesh").sublist("Boundary Segments");
  EXPECT_TRUE(segs.isType<std::string>("contact"));
  EXPECT_NO_THROW(validateDeck(deck, valid, "deck.xml"));
}

// ------------------------------------------------------------------------------------------
// printParameters (--print-parameters)

/// Checks that every entry of \p valid (recursively, except inside pass-through and
/// named-strings sublists) appears in \p text with its path, type and doc string.
void expectEveryEntryPrinted(const std::string& text, const ParameterList& valid, const std::string& path) {
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string name = valid.name(it);
    const std::string full = path.empty() ? name : path + "/" + name;
    const auto& e = valid.entry(it);
    if (e.isList()) {
      EXPECT_CONTAINS(text, full + "/  (sublist)");
      const auto& doc = e.docString();
      if (doc.find("[pass-through]") == std::string::npos && doc.find("[named strings]") == std::string::npos)
        expectEveryEntryPrinted(text, valid.sublist(name), full);
      continue;
    }
    const auto& a = e.getAny();
    const std::string type = a.type() == typeid(double) ? "double"
                             : a.type() == typeid(int)  ? "int"
                             : a.type() == typeid(bool) ? "bool"
                                                        : "string";
    EXPECT_CONTAINS(text, "\n" + full + " : " + type + " = ");
    EXPECT_CONTAINS(text, e.docString());
  }
}

TEST(PrintParameters, PrintsEveryEntryWithTypeDefaultAndDoc) {
  const auto valid = makeValid();
  std::ostringstream os;
  printParameters(os, valid);
  const std::string text = "\n" + os.str();
  expectEveryEntryPrinted(text, valid, "");
  // Defaults, ranges and choices.
  EXPECT_CONTAINS(text, "\nTime Integration/Time Step : double = 0.0025");
  EXPECT_CONTAINS(text, "\nTime Integration/Alpha : double = 0.5  (in [0, 2])");
  EXPECT_CONTAINS(text, "\nTime Integration/Steps : int = 10  (in [1, 1000])");
  EXPECT_CONTAINS(text, "\nMesh/Cells X : int = 1  (in [1, 100000])");
  EXPECT_CONTAINS(text, "\nMesh/Type : string = \"rectangle\"  (one of \"rectangle\", \"exodus\")");
  EXPECT_CONTAINS(text, "\nMesh/File : string = \"\"");
  EXPECT_CONTAINS(text, "\nMesh/Verbose : bool = ");
  // Doc strings on their own indented line after the entry.
  EXPECT_CONTAINS(text, "\nTime Integration/Time Step : double = 0.0025  (finite, >= 1e-300)\n    k [time], constant\n");
  EXPECT_CONTAINS(text, "Passed unchanged to Belos");
  EXPECT_CONTAINS(text, "Named boundary segments");
}

TEST(PrintParameters, EmptyListPrintsNothing) {
  std::ostringstream os;
  printParameters(os, ParameterList());
  EXPECT_EQ(os.str(), "");
}

// ------------------------------------------------------------------------------------------
// closestName

TEST(ClosestName, FindsTheNearestCandidate) {
  const std::vector<std::string> c = {"Time Step", "Final Time", "Alpha", "Beta"};
  EXPECT_EQ(closestName("Time Stp", c), "Time Step");
  EXPECT_EQ(closestName("Time Stepp", c), "Time Step");
  EXPECT_EQ(closestName("Final Tme", c), "Final Time");
  EXPECT_EQ(closestName("Alfa", c), "Alpha");
  EXPECT_EQ(closestName("Beta", c), "Beta");
}

TEST(ClosestName, IsCaseInsensitive) {
  EXPECT_EQ(closestName("time step", {"Final Time", "Time Step"}), "Time Step");
  EXPECT_EQ(closestName("CELLS X", {"Cells Y", "Cells X"}), "Cells X");
}

TEST(ClosestName, EmptyWhenNothingIsClose) {
  EXPECT_EQ(closestName("Preconditioner Overlap Level", {"Time Step", "Alpha"}), "");
  EXPECT_EQ(closestName("Time Step", {}), "");
}

}  // namespace

// deckAsXml (the deck in the Exodus files' info records)

TEST(DeckAsXml, ReadsBackToTheSameValues) {
  ParameterList deck("my deck");
  deck.sublist("Time Integration").set("Time Step", 0.1);
  deck.sublist("Time Integration").set("Final Time", 1.0 / 3.0);
  deck.sublist("Problem").set("Poisson's Ratio", 0.3);
  deck.sublist("Problem").set("Tiny", 1e-300);
  deck.sublist("Problem").set("Obstacle", std::string("x < 0.5 && y > 0 ? \"a\" & 'b' : 1"));
  deck.sublist("Problem").set("Empty", std::string());
  deck.sublist("Problem").set("Lines", std::string("first line \\\nsecond\r\n"));
  deck.sublist("Mesh").set("Cells X", -7);
  deck.sublist("Mesh").set("Verbose", true);
  deck.sublist("Mesh").sublist("Boundary Segments").set("clamped", std::string("left"));
  const std::string xml = deckAsXml(deck);
  const auto back = Teuchos::getParametersFromXmlString(xml);
  EXPECT_EQ(xml.rfind("<ParameterList name=\"my deck\">\n", 0), 0u) << xml;
  EXPECT_TRUE(Teuchos::haveSameValues(deck, *back)) << xml;
  EXPECT_EQ(back->sublist("Time Integration").get<double>("Final Time"), 1.0 / 3.0);  // every bit
  EXPECT_NE(xml.find("value=\"0.3\""), std::string::npos) << xml;  // as a user writes it, not 0.29999999999999999
  EXPECT_EQ(xml.find("docString"), std::string::npos);
  std::istringstream lines(xml);  // every line ends in '>' (an Exodus info line ending in '\' continues)
  for (std::string line; std::getline(lines, line);) EXPECT_EQ(line.back(), '>') << line;
  EXPECT_EQ(xml.find(" id="), std::string::npos);
}
