// scene/glb_check.h: binary glTF headers against the file, before assimp
// allocates what they declare.
#include <gtest/gtest.h>

#include <cstring>

#include "scene/glb_check.h"
#include "scene/mesh_loader.h"
#include "scratch_dir.h"

namespace {

void put32(std::string& b, uint32_t v) {
  for (int i = 0; i < 4; ++i) b.push_back(char((v >> (8 * i)) & 0xff));
}

// A GLB of one triangle: header, JSON chunk, BIN chunk (lengths as declared).
std::string glb(uint32_t json_declared = 0, uint32_t total_extra = 0) {
  std::string json =
      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
      R"("min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
      R"("buffers":[{"byteLength":36}]})";
  while (json.size() % 4) json.push_back(' ');
  std::string bin;
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  bin.append(reinterpret_cast<const char*>(v), sizeof v);
  std::string out = "glTF";
  put32(out, 2);
  put32(out, uint32_t(12 + 8 + json.size() + 8 + bin.size()) + total_extra);
  put32(out, json_declared ? json_declared : uint32_t(json.size()));
  put32(out, 0x4E4F534A);
  out += json;
  put32(out, uint32_t(bin.size()));
  put32(out, 0x004E4942);
  out += bin;
  return out;
}

std::string problem(const std::string& bytes) {
  return pd::glb_problem(
      [&](uint64_t at, size_t n) { return bytes.substr(std::min<size_t>(at, bytes.size()), n); },
      bytes.size());
}

TEST(GlbCheck, AWellFormedFileHasNoProblemAndLoads) {
  const std::string b = glb();
  EXPECT_TRUE(pd::looks_like_glb(b));
  EXPECT_EQ(problem(b), "");
  EXPECT_EQ(pd::read_meshes(b, "glb", false).size(), 1u);
}

TEST(GlbCheck, HeadersDeclaringMoreThanTheFileAreNamed) {
  EXPECT_NE(problem(glb(0xf6000290u)).find("chunk 0 declares 4127195792 bytes"), std::string::npos);
  EXPECT_NE(problem(glb(0, 100)).find("header declares"), std::string::npos);
  std::string v3 = glb();
  v3[4] = 3;
  EXPECT_NE(problem(v3).find("version 3"), std::string::npos);
  std::string bin_first = glb();
  std::memcpy(&bin_first[16], "BIN", 4);
  EXPECT_NE(problem(bin_first).find("not JSON"), std::string::npos);
  EXPECT_NE(problem("glTF\x02").find("cut short"), std::string::npos);
}

// The fuzzer's find: assimp allocated the declared 4 GB (9 s) before failing
// with "No suitable reader". Now an error naming the file and the chunk.
TEST(GlbCheck, AFileDeclaringGigabytesFailsAtOnceNamingIt) {
  const std::string path = pd_test::process_dir() + "huge-chunk.glb";
  pd_test::write_bytes(path, glb(0xf6000290u));
  try {
    pd::load_meshes(path, false);
    FAIL() << "loaded";
  } catch (const pd::MeshError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("declares 4127195792 bytes"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(pd::read_meshes(glb(0xf6000290u), "glb", false), pd::MeshError);
}

}  // namespace
