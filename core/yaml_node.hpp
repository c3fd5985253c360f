#pragma once
// A YAML node that remembers its file and its dotted path, so that every accessor can
// report a bad value with file, line and field (see InputError). All user-facing parsing
// goes through this class; nothing reads yaml-cpp nodes directly.
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "core/input_error.hpp"

namespace magfem {

// The number rule of YamlNode::as_double (the whole text, finite); nullopt otherwise. Shared
// with table files (bh_file) so that a table read from a file equals the same table written
// inline, bit for bit.
std::optional<double> parse_number(const std::string& text);

class YamlNode {
public:
  YamlNode(YAML::Node node, std::shared_ptr<const std::string> file, std::string path);

  // Loads a file; malformed YAML becomes an InputError with the parser's line.
  static YamlNode load_file(const std::string& path);
  // Parses text (tests, embedded data); `name` plays the role of the file name.
  static YamlNode load_string(const std::string& text, const std::string& name);

  [[noreturn]] void fail(const std::string& message) const;
  InputError error(const std::string& message) const;

  const std::string& path() const { return path_; }
  const std::string& file() const { return *file_; }
  int line() const; // 1-based; 0 if unknown

  bool is_map() const { return node_.IsMap(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }
  bool has(const std::string& key) const;

  // Required child; fails "missing required field" at this node's line.
  YamlNode at(const std::string& key) const;
  std::optional<YamlNode> find(const std::string& key) const;
  // Sequence access.
  std::size_t size() const;
  YamlNode operator[](std::size_t i) const;
  std::vector<YamlNode> items() const; // sequence elements in order
  std::vector<std::string> keys() const;  // map keys in file order

  // Fails on the first key not in `allowed`, naming it and its line.
  void allow_keys(std::initializer_list<const char*> allowed) const;
  void allow_keys(const std::vector<std::string>& allowed) const;

  std::string as_string() const;
  double as_double() const;
  double as_positive() const;     // > 0
  double as_non_negative() const; // >= 0
  int as_int() const;
  bool as_bool() const;
  std::vector<double> as_doubles() const;                 // a sequence of numbers
  std::vector<double> as_doubles(std::size_t count) const; // exactly `count` numbers

  // Convenience for optional scalars with defaults.
  double get_double(const std::string& key, double fallback) const;
  double get_positive(const std::string& key, double fallback) const;
  int get_int(const std::string& key, int fallback) const;
  bool get_bool(const std::string& key, bool fallback) const;
  std::string get_string(const std::string& key, const std::string& fallback) const;

  const YAML::Node& raw() const { return node_; }
  // The text of a key of this map; a key that is not plain text (YAML allows `? [a, b]`) is
  // an InputError at the key's line.
  std::string key_text(const YAML::Node& key) const;

private:
  std::string child_path(const std::string& key) const;
  YAML::Node node_;
  std::shared_ptr<const std::string> file_;
  std::string path_;
};

} // namespace magfem
