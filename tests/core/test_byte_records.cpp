// Length-prefixed records (core/byte_records.hpp), what one process sends another: a round trip
// keeps every value and text, and a damaged string is refused with an error naming what was
// read rather than read as something else. Each check below fails if its guard is removed:
// the size check (a record of 12 bytes read as doubles would silently drop 4 bytes), the
// header and body length checks (reads past the end), done() (trailing bytes unseen).
#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/byte_records.hpp"

namespace magfem {
namespace {

// Calls f and returns the runtime_error's message ("" if none was thrown).
template <class F> std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ByteRecords, RoundTripKeepsArraysAndTextsInOrder) {
  const std::vector<double> points{1.5, -2.25, 1e-300};
  const std::vector<int> tets{7, -1, 2147483647};
  const std::vector<double> none;
  std::string bytes;
  append_record(bytes, points);
  append_record(bytes, "piece 1: no volume");
  append_record(bytes, tets);
  append_record(bytes, none);
  ByteRecordReader in(bytes, "the test's bytes");
  EXPECT_EQ(in.array<double>(), points);
  EXPECT_FALSE(in.done());
  EXPECT_EQ(in.text(), "piece 1: no volume");
  EXPECT_EQ(in.array<int>(), tets);
  EXPECT_TRUE(in.array<double>().empty());
  EXPECT_TRUE(in.done());
}

// Three ints (12 bytes) read as doubles: 12 is not a multiple of 8.
TEST(ByteRecords, AnArrayOfAWrongSizeIsRefusedNamingWhatWasRead) {
  std::string bytes;
  append_record(bytes, std::vector<int>{1, 2, 3});
  ByteRecordReader in(bytes, "a mesh piece's bytes");
  EXPECT_EQ(error_of([&] { in.array<double>(); }),
            "a mesh piece's bytes hold an array of a wrong size");
}

// Cut inside the length header, and inside the record's body.
TEST(ByteRecords, BytesThatEndEarlyAreRefused) {
  std::string bytes;
  append_record(bytes, std::vector<double>{1, 2});
  for (const std::size_t keep :
       {std::size_t{0}, sizeof(std::uint64_t) - 1, sizeof(std::uint64_t) + 8, bytes.size() - 1}) {
    ByteRecordReader in(std::string_view(bytes).substr(0, keep), "the piece");
    EXPECT_EQ(error_of([&] { in.array<double>(); }), "the piece end early") << keep << " bytes";
  }
  ByteRecordReader whole(bytes, "the piece");
  EXPECT_EQ(whole.array<double>(), (std::vector<double>{1, 2}));
  EXPECT_EQ(error_of([&] { whole.text(); }), "the piece end early"); // nothing left to read
}

TEST(ByteRecords, TrailingBytesAreSeenByDone) {
  std::string bytes;
  append_record(bytes, "message");
  bytes += "x";
  ByteRecordReader in(bytes, "the message");
  EXPECT_EQ(in.text(), "message");
  EXPECT_FALSE(in.done());
}

} // namespace
} // namespace magfem
