// Text escaped for XML and HTML (markup_escape.cpp).
#include <gtest/gtest.h>

#include "report/markup_escape.h"

using namespace pd;

TEST(MarkupEscape, EntitiesAndControlCharacters) {
  EXPECT_EQ(markup_escape(""), "");
  EXPECT_EQ(markup_escape("plain text"), "plain text");
  EXPECT_EQ(markup_escape("a<b>&\"c\"'d'"), "a&lt;b&gt;&amp;&quot;c&quot;&apos;d&apos;");
  EXPECT_EQ(markup_escape("&amp;"), "&amp;amp;");  // escaped again: no double decoding
  // XML 1.0 cannot carry control characters other than tab, LF and CR.
  EXPECT_EQ(markup_escape(std::string("a\x01"
                                      "b\x1f"
                                      "c\td\ne\rf",
                                      11)),
            "a?b?c\td\ne\rf");
  EXPECT_EQ(markup_escape(std::string("x\0y", 3)), "x?y");
  // UTF-8 passes through byte for byte.
  EXPECT_EQ(markup_escape("Ø 10 mm – µm"), "Ø 10 mm – µm");
  EXPECT_EQ(markup_escape("</script>"), "&lt;/script&gt;");
}
