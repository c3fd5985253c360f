#include "casefile/parameter_expression.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace magfem {
namespace {

// Recursive descent: expr = term {(+|-) term}, term = factor {(*|/) factor},
// factor = (+|-) factor | number | name | "(" expr ")".
class Parser {
public:
  Parser(const std::string& text, const NameLookup& lookup) : text_(text), lookup_(lookup) {}

  double parse() {
    const double v = expression();
    skip_space();
    if (pos_ != text_.size())
      fail("unexpected '" + text_.substr(pos_, 1) + "'");
    return v;
  }

private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ExpressionError(ExpressionError::Kind::syntax, what + " at character " +
                                                             std::to_string(pos_ + 1) + " of '" +
                                                             text_ + "'");
  }
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_])))
      ++pos_;
  }
  bool accept(char c) {
    skip_space();
    if (pos_ < text_.size() && text_[pos_] == c)
      return ++pos_, true;
    return false;
  }
  double expression() {
    double v = term();
    for (;;) {
      if (accept('+'))
        v += term();
      else if (accept('-'))
        v -= term();
      else
        return v;
    }
  }
  double term() {
    double v = factor();
    for (;;) {
      if (accept('*'))
        v *= factor();
      else if (accept('/'))
        v /= factor();
      else
        return v;
    }
  }
  double factor() {
    // Each nesting level (a parenthesis, a sign) is a few stack frames: a bound keeps a
    // hostile `${((((...` an error instead of a stack overflow.
    if (++depth_ > max_depth)
      fail("nested deeper than " + std::to_string(max_depth) + " levels");
    const double v = nested_factor();
    --depth_;
    return v;
  }
  double nested_factor() {
    if (accept('-'))
      return -factor();
    if (accept('+'))
      return factor();
    if (accept('(')) {
      const double v = expression();
      if (!accept(')'))
        fail("missing ')'");
      return v;
    }
    skip_space();
    if (pos_ >= text_.size())
      fail("expected a number or a name");
    const char c = text_[pos_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const char* begin = text_.c_str() + pos_;
      char* end = nullptr;
      const double v = std::strtod(begin, &end);
      if (end == begin)
        fail("bad number");
      pos_ += static_cast<std::size_t>(end - begin);
      return v;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = pos_;
      while (pos_ < text_.size() &&
             (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
        ++pos_;
      return lookup_(text_.substr(start, pos_ - start));
    }
    fail("expected a number or a name, got '" + std::string(1, c) + "'");
  }

  static constexpr int max_depth = 200;
  const std::string& text_;
  const NameLookup& lookup_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

} // namespace

double evaluate_expression(const std::string& text, const NameLookup& lookup) {
  const double v = Parser(text, lookup).parse();
  if (!std::isfinite(v))
    throw ExpressionError(ExpressionError::Kind::not_finite,
                          "'" + text + "' does not evaluate to a finite number");
  return v;
}

} // namespace magfem
