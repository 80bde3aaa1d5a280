#include "Expression.hpp"

#include <cmath>
#include <muParser.h>

#include "Error.hpp"

namespace signorini::core {

struct Expression::Impl {
  mu::Parser parser;
  mutable double x = 0, y = 0, t = 0;
  void bind() {
    parser.DefineVar("x", &x);
    parser.DefineVar("y", &y);
    parser.DefineVar("t", &t);
  }
};

Expression::Expression(const std::string& text, const std::string& where)
    : text_(text), where_(where), impl_(std::make_unique<Impl>()) {
  if (text.find_first_not_of(" \t\n") == std::string::npos)
    SIGNORINI_USER_ERROR(where << ": empty expression");
  try {
    impl_->bind();
    impl_->parser.DefineConst("pi", M_PI);
    impl_->parser.DefineConst("e", M_E);
    impl_->parser.SetExpr(text);
    const auto used = impl_->parser.GetUsedVar();  // also checks for unknown names
    timeIndependent_ = used.count("t") == 0;
    yIndependent_ = used.count("y") == 0;
    constant_ = used.empty();
    const double v = impl_->parser.Eval();
    if (constant_) constantValue_ = v;
    if (!std::isfinite(v) && constant_)
      SIGNORINI_USER_ERROR(where << ": expression '" << text << "' evaluates to " << v);
  } catch (mu::Parser::exception_type& e) {
    SIGNORINI_USER_ERROR(where << ": cannot parse expression '" << text << "': " << e.GetMsg()
                               << " (allowed variables: x, y, t)");
  }
}

Expression::Expression(const Expression& o) : Expression(o.text_, o.where_) {}

Expression& Expression::operator=(const Expression& o) {
  if (this != &o) {
    Expression tmp(o);
    std::swap(text_, tmp.text_);
    std::swap(where_, tmp.where_);
    std::swap(impl_, tmp.impl_);
    constant_ = tmp.constant_;
    timeIndependent_ = tmp.timeIndependent_;
    yIndependent_ = tmp.yIndependent_;
    constantValue_ = tmp.constantValue_;
  }
  return *this;
}

Expression::~Expression() = default;

double Expression::operator()(double x, double y, double t) const {
  if (constant_) return constantValue_;
  impl_->x = x;
  impl_->y = y;
  impl_->t = t;
  return impl_->parser.Eval();
}

}  // namespace signorini::core
