#include "casefile/case_parameters.hpp"

#include <charconv>
#include <cmath>
#include <functional>
#include <optional>
#include <string_view>

#include "casefile/parameter_expression.hpp"
#include "casefile/reader_helpers.hpp"
#include "core/constants.hpp"

namespace magfem {
namespace {

const std::string section = "parameters";

// Shortest text that reads back as the same double.
std::string number_text(double v) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

// A `${...}` found in a scalar: [begin, end) spans the whole `${...}`.
struct Placeholder {
  std::size_t begin = 0, end = 0;
  std::string expression;
};

std::vector<Placeholder> placeholders(const YamlNode& node, const std::string& text) {
  std::vector<Placeholder> out;
  for (std::size_t at = text.find("${"); at != std::string::npos; at = text.find("${", at)) {
    const std::size_t close = text.find('}', at);
    if (close == std::string::npos)
      node.fail("'${' without a closing '}' in '" + text + "'");
    out.push_back({at, close + 1, text.substr(at + 2, close - at - 2)});
    at = close + 1;
  }
  return out;
}

class Resolver {
public:
  Resolver(const YamlNode& root, const ParameterOverrides& overrides, double length_unit)
      : length_unit_(length_unit) {
    if (const auto p = root.find(section)) {
      if (!p->is_map())
        p->fail("expected a map of name: value or name: {value, unit}");
      for (const auto& name : p->keys())
        declare(p->at(name), name);
    }
    for (const auto& [name, value] : overrides) {
      const auto it = index_.find(name);
      if (it == index_.end())
        throw InputError("<command line>", 0, "--param",
                         "'" + name + "' is not a parameter of " + root.file() + " (" +
                             declared_names() + ")");
      Entry& e = entries_[it->second];
      e.expression.reset();
      e.value = convert(value, e.parameter.unit);
      e.state = State::done;
    }
  }

  std::vector<CaseParameter> resolve_all() {
    std::vector<CaseParameter> out;
    for (auto& e : entries_) {
      value_of(e.parameter.name);
      e.parameter.value = e.value;
      out.push_back(e.parameter);
    }
    return out;
  }

  // Evaluates one `${...}` met at `where` (a node outside the parameters section).
  double evaluate(const YamlNode& where, const std::string& expression) {
    try {
      return evaluate_expression(expression,
                                 [&](const std::string& name) { return value_of(name); });
    } catch (const ExpressionError& e) {
      where.fail(e.what());
    }
  }

private:
  enum class State { pending, visiting, done };
  struct Entry {
    CaseParameter parameter;
    std::optional<YamlNode> node; // where its value is written
    std::optional<std::string> expression;
    double value = 0;
    State state = State::pending;
  };

  void declare(const YamlNode& node, const std::string& name) {
    Entry e;
    e.parameter.name = name;
    e.parameter.line = node.line();
    // No YamlNode assignment here: yaml-cpp's Node::operator= rebinds the node in the tree.
    if (node.is_map()) {
      node.allow_keys({"value", "unit", "description"});
      e.parameter.unit = node.get_string("unit", "");
    }
    const YamlNode value = node.is_map() ? node.at("value") : node;
    if (!value.is_scalar())
      value.fail("expected a number or ${expression}");
    e.node = value;
    const std::string text = value.as_string();
    const auto found = placeholders(value, text);
    if (found.size() == 1 && found[0].begin == 0 && found[0].end == text.size())
      e.expression = found[0].expression;
    else
      e.value = convert(value.as_double(), e.parameter.unit);
    if (!e.expression)
      e.state = State::done;
    index_[name] = entries_.size();
    entries_.push_back(std::move(e));
  }

  // Literal values with a length or angle unit into the case's units.
  double convert(double v, const std::string& unit) const {
    if (unit == "m")
      return v / length_unit_;
    if (unit == "cm")
      return v * 1e-2 / length_unit_;
    if (unit == "mm")
      return v * 1e-3 / length_unit_;
    if (unit == "um")
      return v * 1e-6 / length_unit_;
    if (unit == "rad")
      return v * rad_to_deg;
    return v;
  }

  double value_of(const std::string& name) {
    const auto it = index_.find(name);
    if (it == index_.end())
      throw ExpressionError(ExpressionError::Kind::undefined_name,
                            "undefined parameter '" + name + "' (" + declared_names() + ")", name);
    Entry& e = entries_[it->second];
    if (e.state == State::done)
      return e.value;
    if (e.state == State::visiting) {
      std::string chain;
      for (const auto& n : stack_)
        chain += n + " -> ";
      e.node->fail("parameters form a cycle: " + chain + name);
    }
    e.state = State::visiting;
    stack_.push_back(name);
    try {
      e.value =
          evaluate_expression(*e.expression, [&](const std::string& n) { return value_of(n); });
    } catch (const ExpressionError& err) {
      e.node->fail(err.what());
    }
    stack_.pop_back();
    e.state = State::done;
    return e.value;
  }

  std::string declared_names() const {
    if (entries_.empty())
      return "the file declares no parameters";
    std::string list = "parameters: ";
    for (std::size_t i = 0; i < entries_.size(); ++i)
      list += (i ? ", " : "") + entries_[i].parameter.name;
    return list;
  }

  double length_unit_;
  std::vector<Entry> entries_;
  std::map<std::string, std::size_t> index_;
  std::vector<std::string> stack_;
};

// Rewrites the scalars under `node` that contain `${`.
void substitute(const YamlNode& node, Resolver& resolver) {
  if (node.is_scalar()) {
    const std::string text = node.as_string();
    if (text.find("${") == std::string::npos)
      return;
    std::string out;
    std::size_t done = 0;
    for (const auto& p : placeholders(node, text)) {
      out += text.substr(done, p.begin - done);
      out += number_text(resolver.evaluate(node, p.expression));
      done = p.end;
    }
    out += text.substr(done);
    YAML::Node handle = node.raw(); // a handle: assigning rewrites the tree, keeping the mark
    handle = out;
  } else if (node.is_sequence()) {
    for (const auto& item : node.items())
      substitute(item, resolver);
  } else if (node.is_map()) {
    for (const auto& key : node.keys())
      if (const auto child = node.find(key); child && !(node.path().empty() && key == section))
        substitute(*child, resolver);
  }
}

// One line of quote_expressions().
std::string quote_line(const std::string& line) {
  std::string out;
  char quote = 0; // the open quote character, if any
  std::size_t i = 0;
  auto last_visible = [&out]() {
    const auto at = out.find_last_not_of(" \t");
    return at == std::string::npos ? '\0' : out[at];
  };
  constexpr std::string_view value_starts("\0:,[{-", 6); // '\0': the start of the line
  constexpr std::string_view value_ends(",]}#");
  while (i < line.size()) {
    const char c = line[i];
    if (quote) {
      if (c == quote)
        quote = 0;
      out += c, ++i;
    } else if (c == '"' || c == '\'') {
      quote = c, out += c, ++i;
    } else if (c == '#' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t')) {
      return out + line.substr(i); // a comment
    } else if (line.compare(i, 2, "${") == 0) {
      const std::size_t close = line.find('}', i);
      const std::size_t after =
          close == std::string::npos ? close : line.find_first_not_of(" \t", close + 1);
      const bool alone =
          close != std::string::npos &&
          value_starts.find(last_visible()) != std::string_view::npos &&
          (after == std::string::npos || value_ends.find(line[after]) != std::string_view::npos);
      if (alone) {
        out += '"' + line.substr(i, close + 1 - i) + '"';
        i = close + 1;
      } else {
        out += c, ++i;
      }
    } else {
      out += c, ++i;
    }
  }
  return out;
}

} // namespace

std::string quote_expressions(const std::string& text) {
  std::string out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = text.find('\n', start);
    out += quote_line(text.substr(start, end == std::string::npos ? end : end - start));
    if (end == std::string::npos)
      return out;
    out += '\n';
    start = end + 1;
  }
}

std::vector<CaseParameter>
apply_parameters(const YamlNode& root, const ParameterOverrides& overrides, double length_unit) {
  Resolver resolver(root, overrides, length_unit);
  auto out = resolver.resolve_all();
  substitute(root, resolver);
  return out;
}

} // namespace magfem
