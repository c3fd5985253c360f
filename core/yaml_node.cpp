#include "core/yaml_node.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/did_you_mean.hpp"

namespace magfem {

YamlNode::YamlNode(YAML::Node node, std::shared_ptr<const std::string> file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {}

namespace {
YamlNode load_from_stream(std::istream& in, const std::string& name) {
  auto file = std::make_shared<const std::string>(name);
  try {
    YAML::Node root = YAML::Load(in);
    if (!root.IsDefined() || root.IsNull())
      throw InputError(name, 1, "", "the file is empty");
    return YamlNode(root, file, "");
  } catch (const YAML::ParserException& e) {
    throw InputError(name, e.mark.line + 1, "", "malformed YAML: " + e.msg);
  }
}
} // namespace

YamlNode YamlNode::load_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "", "cannot open the file");
  return load_from_stream(in, path);
}

YamlNode YamlNode::load_string(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  return load_from_stream(in, name);
}

int YamlNode::line() const {
  const auto mark = node_.Mark();
  return mark.line >= 0 ? mark.line + 1 : 0;
}

InputError YamlNode::error(const std::string& message) const {
  return InputError(*file_, line(), path_, message);
}

void YamlNode::fail(const std::string& message) const { throw error(message); }

std::string YamlNode::child_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

bool YamlNode::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

YamlNode YamlNode::at(const std::string& key) const {
  if (!node_.IsMap()) fail("expected a map with field '" + key + "'");
  if (!has(key)) throw InputError(*file_, line(), child_path(key), "missing required field");
  return YamlNode(node_[key], file_, child_path(key));
}

std::optional<YamlNode> YamlNode::find(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return YamlNode(node_[key], file_, child_path(key));
}

std::size_t YamlNode::size() const { return node_.size(); }

YamlNode YamlNode::operator[](std::size_t i) const {
  return YamlNode(node_[i], file_, path_ + "[" + std::to_string(i) + "]");
}

std::vector<YamlNode> YamlNode::items() const {
  if (!node_.IsSequence()) fail("expected a list");
  std::vector<YamlNode> out;
  for (std::size_t i = 0; i < node_.size(); ++i) out.push_back((*this)[i]);
  return out;
}

std::vector<std::string> YamlNode::keys() const {
  if (!node_.IsMap()) fail("expected a map");
  std::vector<std::string> out;
  for (const auto& kv : node_) out.push_back(key_text(kv.first));
  return out;
}

void YamlNode::allow_keys(std::initializer_list<const char*> allowed) const {
  allow_keys(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void YamlNode::allow_keys(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap()) fail("expected a map");
  for (const auto& kv : node_) {
    const auto key = key_text(kv.first);
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
      const int key_line = kv.first.Mark().line + 1;
      throw InputError(*file_, key_line, child_path(key),
                       "unknown field" + did_you_mean(key, allowed) + " (allowed here: " + list +
                           ")");
    }
  }
}

std::string YamlNode::key_text(const YAML::Node& key) const {
  if (!key.IsScalar())
    throw InputError(*file_, key.Mark().line + 1, path_, "a key must be plain text");
  return key.Scalar();
}

std::string YamlNode::as_string() const {
  if (!node_.IsScalar()) fail("expected a text value");
  return node_.Scalar();
}

std::optional<double> parse_number(const std::string& text) {
  try {
    std::size_t used = 0;
    const double value = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(value))
      return std::nullopt;
    return value;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

double YamlNode::as_double() const {
  if (!node_.IsScalar())
    fail("expected a number");
  const std::string text = node_.Scalar();
  const auto value = parse_number(text);
  if (!value)
    fail("expected a number, got '" + text + "'");
  return *value;
}

double YamlNode::as_positive() const {
  const double v = as_double();
  if (!(v > 0.0)) fail("must be positive, got " + node_.Scalar());
  return v;
}

double YamlNode::as_non_negative() const {
  const double v = as_double();
  if (v < 0.0) fail("must not be negative, got " + node_.Scalar());
  return v;
}

int YamlNode::as_int() const {
  const double v = as_double();
  if (v != std::floor(v) || std::abs(v) > 2e9) fail("expected an integer, got " + node_.Scalar());
  return static_cast<int>(v);
}

bool YamlNode::as_bool() const {
  if (!node_.IsScalar()) fail("expected true or false");
  const std::string t = node_.Scalar();
  if (t == "true" || t == "yes" || t == "on") return true;
  if (t == "false" || t == "no" || t == "off") return false;
  fail("expected true or false, got '" + t + "'");
}

std::vector<double> YamlNode::as_doubles() const {
  std::vector<double> out;
  for (const auto& item : items()) out.push_back(item.as_double());
  return out;
}

std::vector<double> YamlNode::as_doubles(std::size_t count) const {
  if (!node_.IsSequence() || node_.size() != count)
    fail("expected a list of " + std::to_string(count) + " numbers");
  return as_doubles();
}

double YamlNode::get_double(const std::string& key, double fallback) const {
  auto n = find(key);
  return n ? n->as_double() : fallback;
}

double YamlNode::get_positive(const std::string& key, double fallback) const {
  auto n = find(key);
  return n ? n->as_positive() : fallback;
}

int YamlNode::get_int(const std::string& key, int fallback) const {
  auto n = find(key);
  return n ? n->as_int() : fallback;
}

bool YamlNode::get_bool(const std::string& key, bool fallback) const {
  auto n = find(key);
  return n ? n->as_bool() : fallback;
}

std::string YamlNode::get_string(const std::string& key, const std::string& fallback) const {
  auto n = find(key);
  return n ? n->as_string() : fallback;
}

} // namespace magfem
