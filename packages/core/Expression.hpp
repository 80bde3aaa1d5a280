#pragma once
/// \file Expression.hpp
/// A scalar function of (x, y, t) given as a muParser expression in a deck.
#include <memory>
#include <string>
#include <vector>

namespace signorini::core {

/// Parsed expression f(x, y, t). Constants pi and e are predefined; muParser syntax
/// (sin, cos, exp, sqrt, abs, min, max, the ternary "c ? a : b", ...).
/// Evaluation is on the host; kernels receive sampled values in Kokkos views.
class Expression {
 public:
  /// Parses \p text; \p where names the deck key for error messages ("Problem/Obstacle").
  /// Throws core::UserError if the text does not parse, uses a variable other than x, y, t,
  /// or evaluates to NaN/inf at (0,0,0). \p variables is what a parse error names as allowed
  /// (a key that takes no t checks isTimeIndependent() itself).
  Expression(const std::string& text, const std::string& where, const std::string& variables = "x, y, t");
  /// Parses other's text again (each Expression owns its parser).
  Expression(const Expression& other);
  /// Parses other's text again (each Expression owns its parser).
  Expression& operator=(const Expression& other);
  ~Expression();

  /// f(x, y, t). Not thread-safe: the parser's variables are set for each call.
  double operator()(double x, double y, double t) const;
  /// f(x, y, t); the first value that is not a finite number is described in \p bad ("<where>:
  /// evaluates to nan at (x, y), t = ..."), for core::throwFirstUserError() after the sampling.
  double sample(double x, double y, double t, std::string& bad) const;
  /// The deck key the expression came from ("Problem/Body Force (component 2)").
  const std::string& where() const { return where_; }
  /// True if the expression uses none of x, y, t (evaluated once).
  bool isConstant() const { return constant_; }
  /// True if the expression does not use t.
  bool isTimeIndependent() const { return timeIndependent_; }
  /// True if the expression does not use y.
  bool isIndependentOfY() const { return yIndependent_; }
  /// The expression as the deck gives it.
  const std::string& text() const { return text_; }

 private:
  struct Impl;
  std::string text_, where_;
  std::unique_ptr<Impl> impl_;
  bool constant_ = false, timeIndependent_ = false, yIndependent_ = false;
  double constantValue_ = 0.0;
};

/// The components of a vector field given as comma-separated expressions ("0, -9.81*t"); commas
/// inside parentheses belong to function calls (max(x, y)). A scalar field is a list of one.
class ExpressionList {
 public:
  /// Parses exactly \p components expressions; the single text "0" stands for all components zero.
  /// Throws core::UserError naming \p where for a wrong number of components or a bad expression.
  ExpressionList(const std::string& text, const std::string& where, int components = 1);

  /// Number of components.
  int size() const { return static_cast<int>(items_.size()); }
  /// Component \p c (throws std::out_of_range outside [0, size())).
  const Expression& operator[](int c) const { return items_.at(static_cast<size_t>(c)); }
  /// The single component of a scalar field (asserts size() == 1).
  const Expression& scalar() const;
  /// scalar(): a scalar field used as an Expression.
  operator const Expression&() const { return scalar(); }
  /// scalar()(x, y, t).
  double operator()(double x, double y, double t) const { return scalar()(x, y, t); }
  /// True if every component is constant (Expression::isConstant()).
  bool isConstant() const;
  /// The whole text as the deck gives it.
  const std::string& text() const { return text_; }

 private:
  std::string text_;
  std::vector<Expression> items_;
};

}  // namespace signorini::core
