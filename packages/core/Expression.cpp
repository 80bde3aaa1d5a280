#include "signorini/core/Expression.hpp"

#include <cmath>
#include <sstream>
#include <muParser.h>

#include "signorini/core/Error.hpp"
#include "signorini/core/StringTools.hpp"

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

Expression::Expression(const std::string& text, const std::string& where, const std::string& variables)
    : text_(text), where_(where), impl_(std::make_unique<Impl>()) {
  if (text.find_first_not_of(" \t\n") == std::string::npos)
    SIGNORINI_USER_ERROR(where << ": empty expression");
  // muParser's "=" assigns to a variable: "x=1 ? 0 : -1" sets x to 0 and evaluates to 0, which
  // changes the point every later term sees. A lone "=" (not in ==, <=, >=, !=) is refused.
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if ((c == '=' || c == '<' || c == '>' || c == '!') && i + 1 < text.size() && text[i + 1] == '=')
      ++i;  // a comparison
    else if (c == '=')
      SIGNORINI_USER_ERROR(where << ": expression '" << text << "' contains '=', which assigns to a variable "
                                 << "(muParser's assignment operator); write '==' to compare");
  }
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
      SIGNORINI_USER_ERROR(where << ": expression '" << text << "' evaluates to " << nonFiniteText(v)
                                 << " (it depends on none of x, y, t: everywhere)");
  } catch (mu::Parser::exception_type& e) {
    SIGNORINI_USER_ERROR(where << ": cannot parse expression '" << text << "': " << e.GetMsg()
                               << " (allowed variables: " << variables << ")");
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

double Expression::sample(double x, double y, double t, std::string& bad) const {
  const double v = (*this)(x, y, t);
  if (!std::isfinite(v) && bad.empty()) {
    std::ostringstream os;
    os << where_ << ": '" << text_ << "' evaluates to " << nonFiniteText(v) << " at (" << x << ", " << y << "), t = " << t;
    bad = os.str();
  }
  return v;
}

ExpressionList::ExpressionList(const std::string& text, const std::string& where, int components) : text_(text) {
  std::vector<std::string> parts(1);
  int depth = 0;
  for (char c : text) {
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == ',' && depth == 0)
      parts.emplace_back();
    else
      parts.back() += c;
  }
  const auto b = text.find_first_not_of(" \t\n"), e = text.find_last_not_of(" \t\n");
  const std::string trimmed = b == std::string::npos ? std::string() : text.substr(b, e - b + 1);
  if (parts.size() == 1 && components > 1 && trimmed == "0")
    parts.assign(static_cast<size_t>(components), "0");
  if (static_cast<int>(parts.size()) != components)
    SIGNORINI_USER_ERROR(where << ": expected " << components << " comma-separated expression"
                               << (components > 1 ? "s (one per component)" : "") << ", got " << parts.size()
                               << " in '" << text << "'");
  for (size_t c = 0; c < parts.size(); ++c)
    items_.emplace_back(parts[c], components > 1 ? where + " (component " + std::to_string(c + 1) + ")" : where);
}

const Expression& ExpressionList::scalar() const {
  SIGNORINI_ASSERT(items_.size() == 1, "a vector field used as a scalar one");
  return items_.front();
}

bool ExpressionList::isConstant() const {
  for (const auto& e : items_)
    if (!e.isConstant()) return false;
  return true;
}

}  // namespace signorini::core
