#pragma once
// One table-driven parser for every command's options. A command declares its options once
// (name, value placeholder, handler); the same table parses the command line, names the
// options for `magfem help` and the bash completion (tests check both against it), and turns
// a misspelt option into "unknown option ... (did you mean --x?)" instead of a silent default.
#include <functional>
#include <string>
#include <vector>

#include "core/input_error.hpp"

namespace magfem {

struct OptionInfo {
  std::string name;  // "--mesh-scale"
  std::string value; // placeholder ("S"); empty for a flag
};

// The option of `known` nearest to `typed` by edit distance, or "" when none is close enough
// to be a likely typo.
std::string nearest_option(const std::string& typed, const std::vector<OptionInfo>& known);

// InputError for the command line (no file, no line), naming the option.
[[noreturn]] void throw_option_error(const std::string& option, const std::string& message);

template <class Options> class OptionTable {
public:
  // handler(options, option_name, value); a flag's value is "".
  using Handler = std::function<void(Options&, const std::string&, const std::string&)>;

  explicit OptionTable(std::string command) : command_(std::move(command)) {}

  OptionTable& value(std::string name, std::string placeholder, Handler handler) {
    entries_.push_back({{std::move(name), std::move(placeholder)}, std::move(handler)});
    return *this;
  }
  OptionTable& flag(std::string name, Handler handler) {
    return value(std::move(name), "", handler);
  }

  // Applies every option to `options` in order; returns the positional arguments.
  std::vector<std::string> parse(const std::vector<std::string>& args, Options& options) const {
    std::vector<std::string> positional;
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& arg = args[i];
      if (arg.rfind("--", 0) != 0) {
        positional.push_back(arg);
        continue;
      }
      const Entry& entry = find(arg);
      std::string value;
      if (!entry.info.value.empty()) {
        if (i + 1 >= args.size())
          throw_option_error(arg, "missing value (" + entry.info.value + ")");
        value = args[++i];
      }
      entry.handler(options, arg, value);
    }
    return positional;
  }

  std::vector<OptionInfo> options() const {
    std::vector<OptionInfo> out;
    for (const auto& e : entries_)
      out.push_back(e.info);
    return out;
  }
  const std::string& command() const { return command_; }

private:
  struct Entry {
    OptionInfo info;
    Handler handler;
  };

  const Entry& find(const std::string& arg) const {
    for (const auto& e : entries_)
      if (e.info.name == arg)
        return e;
    const std::string guess = nearest_option(arg, options());
    throw_option_error(arg, "unknown option for " + command_ +
                                (guess.empty() ? std::string() : " (did you mean " + guess + "?)"));
  }

  std::string command_;
  std::vector<Entry> entries_;
};

} // namespace magfem
