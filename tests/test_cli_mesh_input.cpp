// The pdcheck binary on bad mesh input: a loader that hangs or crashes, damaged
// PLY files, paths that are not files. Each costs only its part.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "memory_limit.h"
#include "run_capture.h"

using nlohmann::json;

namespace {

const std::string kBox = std::string(PDCHECK_SOURCE_DIR) + "/testdata/formats/box_binary.stl";

struct TimedRun {
  int code = -1;
  std::string out, err;
  double seconds = 0;
};

/// Runs pdcheck without a cache (unless `args` name one): every file is read,
/// never settled from an earlier run's entries.
TimedRun timed_pdcheck(const std::string& args, const std::string& env = "") {
  const std::string err_file =
      testing::TempDir() + "pdcheck_mesh_err_" + std::to_string(getpid()) + ".txt";
  const std::string cache = args.find("--cache") == std::string::npos ? " --no-cache" : "";
  const std::string cmd =
      env + " " + pd_test::pdcheck_binary_for(env) + " " + args + cache + " </dev/null";
  TimedRun r;
  const auto t0 = std::chrono::steady_clock::now();
  pd_test::Captured c = pd_test::run_capture(cmd, err_file);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.code = WIFEXITED(c.status) ? WEXITSTATUS(c.status) : -1;
  r.out = std::move(c.out);
  r.err = std::move(c.err);
  return r;
}

/// A directory with a scene of three parts: "a" and "b" (the box, overlapping)
/// and "c" from `c_name`, placed far away; `c_bytes` empty = a copy of the box.
std::string scene_with(const std::string& c_name, const std::string& c_bytes = "") {
  const std::string d = testing::TempDir() + "pdcheck_mesh_" + std::to_string(getpid()) + "_" +
                        testing::UnitTest::GetInstance()->current_test_info()->name() + "/";
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  std::filesystem::copy_file(kBox, d + "box.stl");
  if (c_bytes.empty())
    std::filesystem::copy_file(kBox, d + c_name);
  else
    std::ofstream(d + c_name, std::ios::binary) << c_bytes;
  std::ofstream(d + "scene.json")
      << R"({"tolerance": 0.01, "parts": [
    {"id": "a", "mesh": "box.stl"},
    {"id": "b", "mesh": "box.stl", "transform": [1,0,0,1.5, 0,1,0,0, 0,0,1,0, 0,0,0,1]},
    {"id": "c", "mesh": ")" +
             c_name + R"(", "transform": [1,0,0,0.5, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]})";
  return d + "scene.json";
}

/// Part c failed with a message holding `says`; a and b were still checked.
void expect_only_c_lost(const TimedRun& r, const std::string& says) {
  EXPECT_EQ(r.code, 3) << r.err;
  const json rep = json::parse(r.out);
  ASSERT_EQ(rep["parts"].size(), 3u);
  EXPECT_FALSE(rep["parts"][0].contains("error"));
  EXPECT_FALSE(rep["parts"][1].contains("error"));
  ASSERT_TRUE(rep["parts"][2].contains("error")) << rep["parts"][2];
  EXPECT_NE(rep["parts"][2]["error"].get<std::string>().find(says), std::string::npos)
      << rep["parts"][2]["error"];
  EXPECT_NE(r.err.find("part \"c\""), std::string::npos) << r.err;
  ASSERT_EQ(rep["pairs"].size(), 1u);
  EXPECT_EQ(rep["pairs"][0]["status"], "interference");
}

}  // namespace

TEST(MeshIsolation, AHangingLoaderIsStoppedAtTheLimit) {
  const TimedRun r = timed_pdcheck(scene_with("hang_me.stl") + " --quiet --load-timeout 1",
                                   "PDCHECK_TEST_HANG_MESH=hang_me.stl");
  expect_only_c_lost(r, "load limit of 1 s");
  EXPECT_LT(r.seconds, 30.0);  // bounded, not forever (the limit is 1 s)
}

TEST(MeshIsolation, ACrashingLoaderCostsOnlyItsPart) {
  const TimedRun r = timed_pdcheck(scene_with("crash_me.stl") + " --quiet -j 2",
                                   "PDCHECK_TEST_CRASH_MESH=crash_me.stl");
  expect_only_c_lost(r, "loader process failed");
  EXPECT_NE(r.err.find("crash_me.stl"), std::string::npos) << r.err;
}

TEST(MeshIsolation, PlyCutInItsHeaderIsAPartError) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\n"
      "property float y\nproperty float z\nelement face 12\n"
      "property list uchar int vertex_indices\nend_header\n";
  // Without end_header, and cut inside the header (an interrupted download):
  // assimp 5.2.5 loops forever on both.
  for (const std::string& bytes :
       {header.substr(0, header.find("end_header")) + std::string(40, '\x01'),
        header.substr(0, 50)}) {
    const TimedRun r = timed_pdcheck(scene_with("cut.ply", bytes) + " --quiet --load-timeout 20");
    expect_only_c_lost(r, "end_header");
    EXPECT_NE(r.err.find("cut.ply"), std::string::npos) << r.err;
    EXPECT_LT(r.seconds, 20.0);
  }
}

TEST(MeshIsolation, PlyHeaderLineWithoutCommentLoadsWithAWarning) {
  // As in assimp's own Wuson.ply: a Blender 2.47 header line without `comment`.
  const std::string ply =
      "ply\nformat ascii 1.0\nCreated by Blender3D 247 - www.blender.org, source file: \n"
      "element vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar uint vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n3 0 1 2\n";
  const TimedRun r = timed_pdcheck(scene_with("wuson.ply", ply));
  EXPECT_EQ(r.code, 1) << r.err;  // a and b interfere; c loads
  const json rep = json::parse(r.out);
  ASSERT_FALSE(rep["parts"][2].contains("error")) << rep["parts"][2];
  EXPECT_EQ(rep["parts"][2]["vertices"], 8);
  // The loader's warning, then the mesh's (one triangle: an open mesh).
  ASSERT_EQ(rep["parts"][2]["warnings"].size(), 2u) << rep["parts"][2];
  EXPECT_EQ(
      rep["parts"][2]["warnings"][1].get<std::string>().rfind("open mesh: 3 boundary edges", 0), 0u)
      << rep["parts"][2];
  EXPECT_NE(rep["parts"][2]["warnings"][0].get<std::string>().find(
                "PLY header line 3: unknown line \"Created by Blender3D"),
            std::string::npos)
      << rep["parts"][2]["warnings"];
  EXPECT_NE(r.err.find("part \"c\": mesh file"), std::string::npos) << r.err;
}

TEST(MeshIsolation, LoadTimeoutMustBeANumberOfSeconds) {
  for (const char* bad : {"-1", "nan", "inf", "1e300"}) {
    const TimedRun r = timed_pdcheck(scene_with("c.stl") + " --quiet --load-timeout " + bad);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--load-timeout"), std::string::npos) << r.err;
  }
}

TEST(MeshPathsCli, APathThatIsNotAFileSaysWhatItIsAndItsPairsAreUnchecked) {
  const std::string scene = scene_with("c.stl");
  const std::string c = std::filesystem::path(scene).parent_path() / "c.stl";
  const std::pair<std::function<void()>, const char*> cases[] = {
      {[&] { std::filesystem::create_directory(c); }, "is a directory"},
      {[&] { ASSERT_EQ(::mkfifo(c.c_str(), 0600), 0); }, "is a FIFO"},
      {[&] { std::filesystem::create_symlink(c, c); }, "symbolic link loop"},
  };
  for (const auto& [make, says] : cases) {
    std::filesystem::remove_all(c);
    make();
    const TimedRun r = timed_pdcheck(scene + " --quiet");
    expect_only_c_lost(r, says);
    const json s = json::parse(r.out)["summary"];
    EXPECT_EQ(s["pairs"], 3);
    EXPECT_EQ(s["unchecked"], 2) << s;  // a:c and b:c, not culled by the broad phase
    EXPECT_EQ(s["culled"], 0) << s;
    EXPECT_EQ(s["exit_code"], 3);
  }
}

namespace {
std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}
}  // namespace

// Real files the fuzzer found that crash assimp 5.2.5 when read from memory
// (tests/fuzz/assimp-known/): no fault injection, the loader process is all
// that stands between them and the batch. A binary glTF whose chunk header
// declares 3 GB once hung assimp (allocating it) until the load limit; its
// headers are now checked first (scene/glb_check.h), and it is a prompt error.
TEST(MeshIsolation, FilesThatHangAssimpCostOnlyTheirPart) {
  const std::string regressions = std::string(PDCHECK_SOURCE_DIR) + "/tests/fuzz/regressions/";
  const std::string known = std::string(PDCHECK_SOURCE_DIR) + "/tests/fuzz/assimp-known/";
  const TimedRun hang = timed_pdcheck(
      scene_with("hang.glb", file_bytes(regressions + "gltf/chunk-declares-3gb-hung-assimp.glb")) +
      " --quiet --load-timeout 1");
  expect_only_c_lost(hang, "hang.glb: binary glTF chunk 0 declares 3020226560 bytes");
  const TimedRun obj =
      timed_pdcheck(scene_with("c.obj", file_bytes(known + "obj/segv-in-assimp-from-memory.obj")) +
                    " --quiet --load-timeout 5");
  expect_only_c_lost(obj, "c.obj");
}

namespace {
/// A binary STL of `n` small triangles in a row (50 bytes each).
std::string binary_stl(int n) {
  std::string s(80, '\0');
  const auto put = [&](const void* p, size_t k) { s.append(static_cast<const char*>(p), k); };
  const std::uint32_t count = n;
  put(&count, 4);
  for (int i = 0; i < n; ++i) {
    const float x = float(i % 1000), y = float(i / 1000);
    const float t[12] = {0, 0, 1, x, y, 0, x + 1, y, 0, x, y + 1, 0.5f};
    put(t, sizeof t);
    s.append(2, '\0');
  }
  return s;
}
}  // namespace

// A loader may allocate only its share of memory (--load-memory): a file that
// needs more costs its part, named with the limit, and the batch goes on. A
// real 10 MB STL, no fault injection; assimp needs several times its size.
TEST(MeshIsolation, AFileNeedingMoreThanTheLoadMemoryCostsOnlyItsPart) {
  if (!pd::can_cap_address_space()) GTEST_SKIP() << "no address-space cap under AddressSanitizer";
  const std::string scene = scene_with("big.stl", binary_stl(200000));
  const TimedRun capped = timed_pdcheck(scene + " --quiet --load-memory 16");
  expect_only_c_lost(capped, "memory limit of 16 MB (--load-memory)");
  const TimedRun room = timed_pdcheck(scene + " --quiet --load-memory 2000");
  EXPECT_EQ(room.code, 1) << room.err;
  EXPECT_FALSE(json::parse(room.out)["parts"][2].contains("error"));
}

TEST(MeshIsolation, LoadMemoryMustBeANumberOfMegabytes) {
  for (const char* bad : {"-1", "nan", "inf", "1e300"}) {
    const TimedRun r = timed_pdcheck(scene_with("c.stl") + " --quiet --load-memory " + bad);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--load-memory"), std::string::npos) << r.err;
  }
}

TEST(MemoryLimit, LoadersShareHalfTheMemory) {
  EXPECT_DOUBLE_EQ(pd::memory_share_mb(16000, 4), 2000);
  EXPECT_DOUBLE_EQ(pd::memory_share_mb(16000, 0), 8000);  // at least one loader
  EXPECT_EQ(pd::memory_share_mb(0, 4), 0);                // unknown: no limit
  EXPECT_GT(pd::available_memory_mb(), 0);
}
