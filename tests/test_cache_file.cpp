// Checked cache entries (cache_file.h), shared by the decomposition,
// refinement and convexity caches: an entry reads back exactly; a damaged,
// truncated or foreign file is a miss, never a crash; concurrent writers of
// one key never leave a torn entry or a temporary file behind. Each cache's own
// entries: test_decomposition_cache.cpp, test_convexity_cache.cpp, test_refine_cache.cpp.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "cache_file.h"
#include "scratch_dir.h"

using namespace pd;
namespace fs = std::filesystem;

namespace {

constexpr CacheKind kKind{"pdcheck-test-1", ".pdt"};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void spit(const fs::path& p, const std::string& s) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << s;
}

}  // namespace

TEST(CacheFile, EntryReadsBackExactly) {
  const fs::path dir = pd_test::absent_dir("cache_file", "roundtrip");
  std::string body = "line\n";
  for (int k = 0; k < 256; ++k) body += static_cast<char>(k);  // binary, NULs, newlines
  ASSERT_EQ(write_cache_entry(dir.string(), kKind, "k1", body), "");
  EXPECT_EQ(read_cache_entry(dir.string(), kKind, "k1"), body);
  ASSERT_EQ(write_cache_entry(dir.string(), kKind, "k2", ""), "");
  EXPECT_EQ(read_cache_entry(dir.string(), kKind, "k2"), std::string());
  EXPECT_FALSE(read_cache_entry(dir.string(), kKind, "k3"));  // absent
  EXPECT_FALSE(read_cache_entry("", kKind, "k1"));            // no cache
  EXPECT_EQ(write_cache_entry("", kKind, "k1", body), "");    // no cache: nothing, no error
  fs::remove_all(dir);
}

TEST(CacheFile, DamagedOrForeignEntriesAreMisses) {
  const fs::path dir = pd_test::absent_dir("cache_file", "damage");
  const std::string body(1000, 'x');
  ASSERT_EQ(write_cache_entry(dir.string(), kKind, "k", body), "");
  const fs::path file = dir / "k.pdt";
  const std::string whole = slurp(file);
  ASSERT_TRUE(read_cache_entry(dir.string(), kKind, "k"));

  // Truncated anywhere: in the body, in the header, empty.
  for (size_t keep : {whole.size() - 1, whole.size() - 500, size_t(40), size_t(3), size_t(0)}) {
    spit(file, whole.substr(0, keep));
    EXPECT_FALSE(read_cache_entry(dir.string(), kKind, "k")) << "kept " << keep;
  }
  // One byte of the body changed; bytes appended.
  std::string edited = whole;
  edited[edited.size() - 10] = 'y';
  spit(file, edited);
  EXPECT_FALSE(read_cache_entry(dir.string(), kKind, "k"));
  spit(file, whole + "z");
  EXPECT_FALSE(read_cache_entry(dir.string(), kKind, "k"));
  // Another key's entry under this name; another kind's format.
  spit(file, whole);
  fs::copy_file(file, dir / "other.pdt");
  EXPECT_FALSE(read_cache_entry(dir.string(), kKind, "other"));
  EXPECT_FALSE(read_cache_entry(dir.string(), CacheKind{"pdcheck-test-2", ".pdt"}, "k"));
  // Garbage, and a directory where the entry should be.
  spit(file, std::string("\0\0\0\n\n\n\xff", 7));
  EXPECT_FALSE(read_cache_entry(dir.string(), kKind, "k"));
  fs::create_directories(dir / "d.pdt");
  EXPECT_FALSE(read_cache_entry(dir.string(), kKind, "d"));
  // A FIFO where the entry should be: a miss, not a read that waits for a writer.
  ASSERT_EQ(mkfifo((dir / "f.pdt").c_str(), 0600), 0);
  EXPECT_FALSE(read_cache_entry(dir.string(), kKind, "f"));
  fs::remove_all(dir);
}

TEST(CacheFile, AnUnwritableCacheIsReportedNotThrown) {
  const fs::path dir = pd_test::absent_dir("cache_file", "unwritable");
  fs::create_directories(dir.parent_path());
  spit(dir, "a file where the cache directory should be");
  const std::string why = write_cache_entry(dir.string(), kKind, "k", "body");
  EXPECT_NE(why, "");
  EXPECT_NE(why.find(dir.string()), std::string::npos) << why;
  EXPECT_FALSE(read_cache_entry(dir.string(), kKind, "k"));
  fs::remove(dir);
}

// Four processes rewrite one key with bodies of their own while this one
// reads it: every read is a miss or one writer's body, whole.
TEST(CacheFile, ConcurrentWritersNeverTearAnEntry) {
  const fs::path dir = pd_test::absent_dir("cache_file", "concurrent");
  constexpr int kWriters = 4, kWrites = 40;
  std::set<std::string> bodies;
  for (int w = 0; w < kWriters; ++w) bodies.insert(std::string(200000 + 1000 * w, char('a' + w)));
  std::vector<pid_t> pids;
  for (const std::string& body : bodies) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      int failures = 0;
      for (int k = 0; k < kWrites; ++k)
        failures += write_cache_entry(dir.string(), kKind, "shared", body) != "";
      _exit(failures == 0 ? 0 : 1);
    }
    pids.push_back(pid);
  }
  int reads = 0, torn = 0, done = 0;
  while (done < kWriters) {
    const auto got = read_cache_entry(dir.string(), kKind, "shared");
    ++reads;
    if (got && !bodies.count(*got)) ++torn;
    int status = 0;
    while (waitpid(-1, &status, WNOHANG) > 0) {
      ++done;
      EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
  }
  EXPECT_EQ(torn, 0) << "of " << reads << " reads";
  const auto last = read_cache_entry(dir.string(), kKind, "shared");
  ASSERT_TRUE(last);
  EXPECT_TRUE(bodies.count(*last));
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(e.path().filename(), "shared.pdt") << "left behind";
  }
  EXPECT_EQ(files, 1);
  fs::remove_all(dir);
}
