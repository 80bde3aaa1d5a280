#pragma once
/// \file Expression.hpp
/// A scalar function of (x, y, t) given as a muParser expression in a deck.
#include <memory>
#include <string>

namespace signorini::core {

/// Parsed expression f(x, y, t). Constants pi and e are predefined; muParser syntax
/// (sin, cos, exp, sqrt, abs, min, max, the ternary "c ? a : b", ...).
/// Evaluation is on the host; kernels receive sampled values in Kokkos views.
class Expression {
 public:
  /// Parses \p text; \p where names the deck key for error messages ("Problem/Obstacle").
  /// Throws core::UserError if the text does not parse, uses a variable other than x, y, t,
  /// or evaluates to NaN/inf at (0,0,0).
  Expression(const std::string& text, const std::string& where);
  Expression(const Expression& other);
  Expression& operator=(const Expression& other);
  ~Expression();

  double operator()(double x, double y, double t) const;
  /// True if the expression uses none of x, y, t (evaluated once).
  bool isConstant() const { return constant_; }
  /// True if the expression does not use t.
  bool isTimeIndependent() const { return timeIndependent_; }
  /// True if the expression does not use y.
  bool isIndependentOfY() const { return yIndependent_; }
  const std::string& text() const { return text_; }

 private:
  struct Impl;
  std::string text_, where_;
  std::unique_ptr<Impl> impl_;
  bool constant_ = false, timeIndependent_ = false, yIndependent_ = false;
  double constantValue_ = 0.0;
};

}  // namespace signorini::core
