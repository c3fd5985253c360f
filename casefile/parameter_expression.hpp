#pragma once
// Arithmetic in case-file parameters: `${R_out - 10}`, `${2 * (R_in + gap)}`. Numbers (with
// exponents), parameter names ([A-Za-z_][A-Za-z0-9_]*), + - * /, unary minus and
// parentheses; the usual precedence, left to right. Nothing else (no functions), so an
// expression is readable at a glance and cannot surprise.
#include <functional>
#include <stdexcept>
#include <string>

namespace magfem {

// What an expression error is about, so that the case reader can phrase it.
class ExpressionError : public std::runtime_error {
public:
  enum class Kind { syntax, undefined_name, not_finite };
  ExpressionError(Kind kind, const std::string& message, std::string name = {})
      : std::runtime_error(message), kind_(kind), name_(std::move(name)) {}
  Kind kind() const { return kind_; }
  const std::string& name() const { return name_; } // the undefined name, if any

private:
  Kind kind_;
  std::string name_;
};

// Value of a name; throws (anything) to report it undefined or failing.
using NameLookup = std::function<double(const std::string& name)>;

// Evaluates `text` (the part between "${" and "}"). Throws ExpressionError for syntax errors
// (naming the position), names the lookup reports undefined (it should throw ExpressionError
// with Kind::undefined_name), and results that are not finite (division by zero).
double evaluate_expression(const std::string& text, const NameLookup& lookup);

} // namespace magfem
