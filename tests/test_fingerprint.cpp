// Pair fingerprints and content hashes: stable, symmetric, injective on id pairs.
#include <gtest/gtest.h>

#include "hash.h"
#include "results/fingerprint.h"
#include "scene/mesh_loader.h"

namespace pd {

TEST(Fingerprint, IndependentOfOrderAndStable) {
  const std::string f = pair_fingerprint("BRKT-112", "BOLT-M6-07");
  EXPECT_EQ(f, pair_fingerprint("BOLT-M6-07", "BRKT-112"));
  EXPECT_EQ(f.size(), 32u);
  EXPECT_EQ(f.find_first_not_of("0123456789abcdef"), std::string::npos);
  // The scheme is a promise to users' baselines: changing it breaks them.
  EXPECT_EQ(pair_fingerprint("a", "b"), "7b621ac81bf0fbdefc34f8b754f99308");
}

TEST(Fingerprint, DistinguishesIdBoundaries) {
  EXPECT_NE(pair_fingerprint("ab", "c"), pair_fingerprint("a", "bc"));
  EXPECT_NE(pair_fingerprint("a", "b"), pair_fingerprint("a", "c"));
  EXPECT_NE(pair_fingerprint("", "ab"), pair_fingerprint("a", "b"));
}

TEST(ContentHash, DiffersOnAnyByte) {
  EXPECT_EQ(content_hash("abc"), content_hash("abc"));
  EXPECT_NE(content_hash("abc"), content_hash("abd"));
  Hasher h1, h2;
  h1.add(1.0).add("x");
  h2.add(1.0).add("x");
  EXPECT_EQ(h1.hex(), h2.hex());
  Hasher h3;
  h3.add(-0.0).add("x");  // the exact bits: -0 is not +0 for a cache key
  Hasher h4;
  h4.add(0.0).add("x");
  EXPECT_NE(h3.hex(), h4.hex());
}

TEST(MeshLoader, TrianglesIndexTheVertices) {
  const std::string dir = std::string(PDCHECK_SOURCE_DIR) + "/testdata/formats/";
  for (const char* f : {"box.obj", "box_ascii.stl", "box_binary.ply"}) {
    const auto meshes = load_meshes(dir + f, false);
    ASSERT_EQ(meshes.size(), 1u) << f;
    const Mesh& m = meshes[0];
    EXPECT_EQ(m.triangles.cols(), 12) << f;  // a box: 6 quads or 12 triangles
    EXPECT_GE(m.triangles.minCoeff(), 0) << f;
    EXPECT_LT(m.triangles.maxCoeff(), m.vertices.cols()) << f;
  }
}

}  // namespace pd
