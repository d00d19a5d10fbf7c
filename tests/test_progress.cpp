// Progress lines in a log (not a terminal): sparse, counted right under threads.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "batch/progress.h"

using namespace pd;

namespace {

std::string contents(std::FILE* f) {
  std::string s(static_cast<size_t>(std::ftell(f)), '\0');
  std::rewind(f);
  s.resize(std::fread(s.data(), 1, s.size(), f));
  return s;
}

std::string run(bool quiet, std::chrono::milliseconds wait) {
  std::FILE* f = std::tmpfile();
  {
    Progress p(1000, quiet, "parts", f);
    std::this_thread::sleep_for(wait);
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
      threads.emplace_back([&] {
        for (int k = 0; k < 125; ++k) p.tick(2);
      });
    for (auto& t : threads) t.join();
    p.finish();
  }
  const std::string s = contents(f);
  std::fclose(f);
  return s;
}

}  // namespace

TEST(Progress, PlainLinesAfterTheFirstSecond) {
  const std::string log = run(false, std::chrono::milliseconds(1100));
  EXPECT_NE(log.find("pdcheck: 1000/1000 parts (100%)"), std::string::npos) << log;
  size_t lines = 0;
  for (char c : log) lines += c == '\n';
  EXPECT_GE(lines, 1u);
  EXPECT_LE(lines, 10u) << log;  // at most one per 10 %
}

TEST(Progress, ShortStagesAndQuietRunsSayNothing) {
  EXPECT_EQ(run(false, std::chrono::milliseconds(0)), "");
  EXPECT_EQ(run(true, std::chrono::milliseconds(1100)), "");
}
