// Text made safe for one log line (printable.cpp). Through the binary (ids
// that would forge log lines): test_run_control.cpp.
#include <gtest/gtest.h>

#include "printable.h"

TEST(Printable, ControlCharactersAreEscaped) {
  EXPECT_EQ(pd::printable("a\nb\x1b[2K\r\t\x7f\x01 \xc2\x9b \xc3\xbc\\"),
            "a\\nb\\e[2K\\r\\t\\x7f\\x01 \\u009b \xc3\xbc\\");
}
