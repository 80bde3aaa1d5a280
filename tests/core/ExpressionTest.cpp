// Expression: muParser expressions of (x, y, t) from a deck, checked against hand values;
// dependency flags; errors are UserErrors naming the deck key; copies are independent.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "signorini/core/Error.hpp"
#include "signorini/core/Expression.hpp"

using signorini::core::Expression;
using signorini::core::UserError;

namespace {

/// The message of the UserError thrown when parsing \p text as key \p where ("" if none).
std::string parseError(const std::string& text, const std::string& where) {
  try {
    Expression e(text, where);
  } catch (UserError& e) {
    return e.what();
  } catch (std::exception& e) {
    ADD_FAILURE() << "'" << text << "': expected signorini::core::UserError, got: " << e.what();
    return "";
  } catch (...) {
    ADD_FAILURE() << "'" << text << "': expected signorini::core::UserError, got a non-std exception";
    return "";
  }
  ADD_FAILURE() << "'" << text << "': expected signorini::core::UserError, nothing was thrown";
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(Expression, ConstantsAndArithmetic) {
  EXPECT_DOUBLE_EQ(Expression("1 + 2*3", "k")(0, 0, 0), 7.0);
  EXPECT_DOUBLE_EQ(Expression("pi", "k")(0.3, 0.7, 1.1), M_PI);
  EXPECT_DOUBLE_EQ(Expression("e", "k")(0, 0, 0), M_E);
  EXPECT_DOUBLE_EQ(Expression("2^10", "k")(0, 0, 0), 1024.0);
  EXPECT_DOUBLE_EQ(Expression("-0.5", "k")(1, 2, 3), -0.5);
}

TEST(Expression, TrigonometryAgainstHandValues) {
  const Expression s("sin(pi*x/2)", "Problem/Initial Velocity");
  EXPECT_NEAR(s(0.0, 0, 0), 0.0, 1e-15);
  EXPECT_NEAR(s(1.0, 0, 0), 1.0, 1e-15);
  EXPECT_NEAR(s(1.0 / 3.0, 0, 0), 0.5, 1e-15);  // sin(pi/6)
  EXPECT_NEAR(s(-1.0, 0, 0), -1.0, 1e-15);
  const Expression c("cos(pi*y)", "k");
  EXPECT_NEAR(c(0, 0.0, 0), 1.0, 1e-15);
  EXPECT_NEAR(c(0, 1.0, 0), -1.0, 1e-15);
  EXPECT_NEAR(c(0, 0.5, 0), 0.0, 1e-15);
  EXPECT_NEAR(c(0, 1.0 / 3.0, 0), 0.5, 1e-15);  // cos(pi/3)
  const Expression obstacle("sin(pi*y) - 1.05", "Problem/Obstacle");
  EXPECT_NEAR(obstacle(1.0, 0.5, 0.0), -0.05, 1e-15);
  EXPECT_NEAR(obstacle(1.0, 0.0, 0.0), -1.05, 1e-15);
}

TEST(Expression, AllThreeVariables) {
  const Expression f("x + 10*y + 100*t", "k");
  EXPECT_DOUBLE_EQ(f(1, 2, 3), 321.0);
  EXPECT_DOUBLE_EQ(f(-1, 0.5, 0.25), 29.0);
  const Expression g("exp(-t) * sqrt(x*x + y*y)", "k");
  EXPECT_NEAR(g(3, 4, 0), 5.0, 1e-14);
  EXPECT_NEAR(g(3, 4, 1), 5.0 * std::exp(-1.0), 1e-14);
}

TEST(Expression, Ternary) {
  const Expression f("x > 0.5 ? 1 : -1", "k");
  EXPECT_DOUBLE_EQ(f(0.75, 0, 0), 1.0);
  EXPECT_DOUBLE_EQ(f(0.25, 0, 0), -1.0);
  EXPECT_DOUBLE_EQ(f(0.5, 0, 0), -1.0);
  const Expression g("t < 0.1 ? sin(pi*x) : (y >= 0 ? 2 : 3)", "k");
  EXPECT_NEAR(g(0.5, -1, 0.0), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(g(0.5, 1, 0.2), 2.0);
  EXPECT_DOUBLE_EQ(g(0.5, -1, 0.2), 3.0);
}

TEST(Expression, MinMaxAbs) {
  EXPECT_DOUBLE_EQ(Expression("min(x, y)", "k")(2, -3, 0), -3.0);
  EXPECT_DOUBLE_EQ(Expression("max(x, y)", "k")(2, -3, 0), 2.0);
  EXPECT_DOUBLE_EQ(Expression("abs(x - 1)", "k")(-2, 0, 0), 3.0);
}

TEST(Expression, RepeatedEvaluationUsesTheNewArguments) {
  const Expression f("x*y - t", "k");
  for (int i = 0; i < 5; ++i) EXPECT_DOUBLE_EQ(f(i, 2.0, 1.0), 2.0 * i - 1.0);
}

TEST(Expression, DependencyFlags) {
  const Expression constant("sin(pi/2) + 1", "k");
  EXPECT_TRUE(constant.isConstant());
  EXPECT_TRUE(constant.isTimeIndependent());
  EXPECT_TRUE(constant.isIndependentOfY());
  EXPECT_DOUBLE_EQ(constant(5, 6, 7), 2.0);

  const Expression xOnly("-sin(pi*x/2)", "k");
  EXPECT_FALSE(xOnly.isConstant());
  EXPECT_TRUE(xOnly.isTimeIndependent());
  EXPECT_TRUE(xOnly.isIndependentOfY());

  const Expression xy("x*y", "k");
  EXPECT_FALSE(xy.isConstant());
  EXPECT_TRUE(xy.isTimeIndependent());
  EXPECT_FALSE(xy.isIndependentOfY());

  const Expression tOnly("cos(t)", "k");
  EXPECT_FALSE(tOnly.isConstant());
  EXPECT_FALSE(tOnly.isTimeIndependent());
  EXPECT_TRUE(tOnly.isIndependentOfY());

  const Expression yt("y*t", "k");
  EXPECT_FALSE(yt.isConstant());
  EXPECT_FALSE(yt.isTimeIndependent());
  EXPECT_FALSE(yt.isIndependentOfY());
}

TEST(Expression, TextIsKept) {
  EXPECT_EQ(Expression("sin(pi*y) - 1.05", "k").text(), "sin(pi*y) - 1.05");
}

TEST(Expression, UnknownVariableThrowsUserErrorNamingTheKey) {
  const auto msg = parseError("z+1", "Problem/Obstacle");
  EXPECT_TRUE(contains(msg, "Problem/Obstacle")) << msg;
  EXPECT_TRUE(contains(msg, "z+1")) << msg;
}

TEST(Expression, UnknownFunctionThrowsUserErrorNamingTheKey) {
  const auto msg = parseError("sinus(x)", "Problem/Body Force");
  EXPECT_TRUE(contains(msg, "Problem/Body Force")) << msg;
}

TEST(Expression, SyntaxErrorThrowsUserErrorNamingTheKey) {
  for (const std::string text : {"sin(x", "x +", "x y", "(1 + 2))", "x > 0 ? 1"}) {
    const auto msg = parseError(text, "Problem/Initial Displacement");
    EXPECT_TRUE(contains(msg, "Problem/Initial Displacement")) << text << ": " << msg;
    EXPECT_TRUE(contains(msg, text)) << text << ": " << msg;
  }
}

// muParser's "=" assigns ("x=1 ? 0 : -1" sets x and evaluates to 0): refused, naming the key and "==".
TEST(Expression, AssignmentThrowsUserErrorNamingTheKey) {
  for (const std::string text : {"x=1 ? 0 : -1", "(x=0.3)*0 + x", "t = 1", "x === 1", "x+=1", "=x"}) {
    const auto msg = parseError(text, "Problem/Initial Velocity");
    EXPECT_TRUE(contains(msg, "Problem/Initial Velocity")) << text << ": " << msg;
    EXPECT_TRUE(contains(msg, "'=='")) << text << ": " << msg;
  }
}

TEST(Expression, ComparisonsAreNotAssignments) {
  EXPECT_EQ(Expression("x==1 ? 0 : -1", "k")(1, 0, 0), 0.0);
  EXPECT_EQ(Expression("x==1 ? 0 : -1", "k")(0.5, 0, 0), -1.0);
  EXPECT_EQ(Expression("(x<=1) + (x>=1) + (x!=1)", "k")(1, 0, 0), 2.0);
  EXPECT_EQ(Expression("x <= 0.5 ? x : y >= 2", "k")(1, 3, 0), 1.0);
  EXPECT_EQ(Expression("x != y", "k")(1, 1, 0), 0.0);
}

TEST(Expression, EmptyExpressionThrows) {
  for (const std::string text : {"", "   ", " \t\n"}) {
    const auto msg = parseError(text, "Problem/Neumann Data");
    EXPECT_TRUE(contains(msg, "Problem/Neumann Data")) << msg;
    EXPECT_TRUE(contains(msg, "empty")) << msg;
  }
}

TEST(Expression, NonFiniteConstantThrows) {
  for (const std::string text : {"1/0", "sqrt(-1)", "log(0)"}) {
    const auto msg = parseError(text, "Problem/Obstacle");
    EXPECT_TRUE(contains(msg, "Problem/Obstacle")) << text << ": " << msg;
  }
}

TEST(Expression, CopyEvaluatesIndependentlyOfTheOriginal) {
  auto original = std::make_unique<Expression>("x + 2*y + 3*t", "Problem/Body Force");
  const Expression copy(*original);
  EXPECT_EQ(copy.text(), original->text());
  EXPECT_DOUBLE_EQ(copy(1, 1, 1), 6.0);
  // Evaluating the original must not change what the copy sees, and the copy must outlive it.
  EXPECT_DOUBLE_EQ((*original)(10, 0, 0), 10.0);
  EXPECT_DOUBLE_EQ(copy(0, 1, 0), 2.0);
  original.reset();
  EXPECT_DOUBLE_EQ(copy(0, 0, 1), 3.0);
  EXPECT_FALSE(copy.isConstant());
  EXPECT_FALSE(copy.isTimeIndependent());
  EXPECT_FALSE(copy.isIndependentOfY());
}

TEST(Expression, CopyAssignmentReplacesExpressionAndFlags) {
  Expression a("5", "k");
  EXPECT_TRUE(a.isConstant());
  {
    const Expression b("sin(pi*x) * t", "k2");
    a = b;
  }
  EXPECT_EQ(a.text(), "sin(pi*x) * t");
  EXPECT_FALSE(a.isConstant());
  EXPECT_FALSE(a.isTimeIndependent());
  EXPECT_TRUE(a.isIndependentOfY());
  EXPECT_NEAR(a(0.5, 0, 2), 2.0, 1e-15);
  // Assigning a constant back to a variable expression.
  a = Expression("7", "k3");
  EXPECT_TRUE(a.isConstant());
  EXPECT_DOUBLE_EQ(a(1, 2, 3), 7.0);
  // Self-assignment is harmless.
  const Expression& self = a;
  a = self;
  EXPECT_DOUBLE_EQ(a(1, 2, 3), 7.0);
}

TEST(Expression, CopyInitialisationEvaluatesLikeTheOriginal) {
  const Expression original("y > 0 ? x : -x", "Output/Probes");
  Expression copy = original;
  EXPECT_DOUBLE_EQ(copy(2, 1, 0), 2.0);
  EXPECT_DOUBLE_EQ(copy(2, -1, 0), -2.0);
}

}  // namespace
