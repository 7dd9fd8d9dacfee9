#include "functions/expression.hpp"

#include <muParser.h>

#include <numbers>

namespace ryushi {

struct Expression::Compiled {
  mu::Parser parser;
  double x = 0, y = 0, z = 0, t = 0;  // the parser reads the variables through these addresses
};

Expression::Expression(const std::string& source) : source_(source), compiled_(std::make_shared<Compiled>()) {
  auto& c = *compiled_;
  try {
    c.parser.DefineVar("x", &c.x);
    c.parser.DefineVar("y", &c.y);
    c.parser.DefineVar("z", &c.z);
    c.parser.DefineVar("t", &c.t);
    c.parser.DefineConst("pi", std::numbers::pi);
    c.parser.DefineConst("e", std::numbers::e);
    c.parser.SetExpr(source);
    c.parser.Eval();  // muparser compiles on the first evaluation: a syntax error shows here
  } catch (const mu::Parser::exception_type& e) {
    throw ExpressionError(e.GetMsg());
  }
}

double Expression::operator()(double x, double y, double z, double t) const {
  auto& c = *compiled_;
  c.x = x, c.y = y, c.z = z, c.t = t;
  try {
    return c.parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw ExpressionError(e.GetMsg());
  }
}

}  // namespace ryushi
