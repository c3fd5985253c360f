#pragma once
// Length-prefixed records in a byte string: arrays of plain values and texts, for what one
// process of a run sends another (the same build on both ends, so native byte order and
// sizes). The reader refuses a record that ends early with a runtime_error naming what was
// read, and says whether anything is left over.
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace magfem {

inline void append_record(std::string& out, const void* data, std::uint64_t bytes) {
  out.append(reinterpret_cast<const char*>(&bytes), sizeof bytes);
  out.append(static_cast<const char*>(data), bytes);
}

template <class T> void append_record(std::string& out, const std::vector<T>& values) {
  static_assert(std::is_trivially_copyable_v<T>);
  append_record(out, values.data(), values.size() * sizeof(T));
}

inline void append_record(std::string& out, std::string_view text) {
  append_record(out, text.data(), text.size());
}

class ByteRecordReader {
public:
  // `what`: named in the errors ("a mesh piece's bytes").
  ByteRecordReader(std::string_view bytes, std::string what) : in_(bytes), what_(std::move(what)) {}

  template <class T> std::vector<T> array() {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::string_view raw = record();
    if (raw.size() % sizeof(T) != 0)
      throw std::runtime_error(what_ + " hold an array of a wrong size");
    std::vector<T> values(raw.size() / sizeof(T));
    if (!raw.empty())
      std::memcpy(values.data(), raw.data(), raw.size());
    return values;
  }
  std::string text() { return std::string(record()); }
  bool done() const { return in_.empty(); }

private:
  std::string_view record() {
    std::uint64_t n = 0;
    if (in_.size() < sizeof n)
      throw std::runtime_error(what_ + " end early");
    std::memcpy(&n, in_.data(), sizeof n);
    in_.remove_prefix(sizeof n);
    if (in_.size() < n)
      throw std::runtime_error(what_ + " end early");
    const std::string_view raw = in_.substr(0, n);
    in_.remove_prefix(n);
    return raw;
  }

  std::string_view in_;
  std::string what_;
};

} // namespace magfem
