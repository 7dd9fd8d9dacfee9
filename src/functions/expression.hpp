#pragma once
// A formula of position and time given as text in a scene (initial velocity and pressure fields,
// prescribed wall motion), compiled once by muparser and evaluated per particle.
// Variables: x, y, z (m; z = 0 in 2D) and t (s; 0 for initial fields); constants pi and e;
// muparser's functions (sin, cos, tan, exp, log, sqrt, abs, min, max, sign, ...), operators
// and `cond ? a : b`.
#include <memory>
#include <stdexcept>
#include <string>

namespace ryushi {

class ExpressionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Expression {
 public:
  // Throws ExpressionError with muparser's message (which names the position in the text).
  explicit Expression(const std::string& source);
  // Not thread-safe: copies share one compiled parser and its variables (scene set-up is serial).
  double operator()(double x, double y, double z, double t = 0) const;
  const std::string& source() const { return source_; }

 private:
  struct Compiled;
  std::string source_;
  std::shared_ptr<Compiled> compiled_;
};

}  // namespace ryushi
