// Content hashes (hash.cpp): XXH3-128 as 32 lowercase hex digits, fields
// separated by their lengths, doubles by their exact bits.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>

#include "hash.h"

using namespace pd;

TEST(Hash, ThirtyTwoLowercaseHexDigitsOfTheBytes) {
  const std::regex hex("[0-9a-f]{32}");
  std::set<std::string> seen;
  for (const std::string& bytes :
       {std::string(), std::string("a"), std::string("b"), std::string("ab"),
        std::string(1 << 16, 'x'), std::string("a\0b", 3), std::string("a\0c", 3)}) {
    const std::string h = content_hash(bytes);
    EXPECT_TRUE(std::regex_match(h, hex)) << h;
    EXPECT_EQ(h, content_hash(bytes));
    EXPECT_TRUE(seen.insert(h).second) << "a collision on " << bytes.size() << " bytes";
  }
  // XXH3-128 of nothing (the published test vector): the algorithm, not just a hash.
  EXPECT_EQ(content_hash(""), "99aa06d3014798d86001c324468d497f");
}

TEST(Hash, FieldsAreSeparatedByTheirLengths) {
  auto fields = [](std::initializer_list<std::string_view> parts) {
    Hasher h;
    for (std::string_view p : parts) h.add(p);
    return h.hex();
  };
  EXPECT_NE(fields({"ab", "c"}), fields({"a", "bc"}));
  EXPECT_NE(fields({"abc"}), fields({"ab", "c"}));
  EXPECT_NE(fields({"", "a"}), fields({"a", ""}));
  EXPECT_EQ(fields({"ab", "c"}), fields({"ab", "c"}));
  EXPECT_NE(fields({"abc"}), content_hash("abc"));  // a field is more than its bytes
}

TEST(Hash, DoublesByTheirBits) {
  auto of = [](double x) {
    Hasher h;
    h.add(x);
    return h.hex();
  };
  EXPECT_NE(of(0.0), of(-0.0));
  EXPECT_NE(of(1.0), of(std::nextafter(1.0, 2.0)));
  EXPECT_EQ(of(0.1 + 0.2), of(0.30000000000000004));
  EXPECT_EQ(of(NAN), of(NAN));
}
