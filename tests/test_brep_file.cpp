// brep/brep_file.h and the scene's B-rep meshes (scene/mesh_loader.h) on STEP
// and .brep files made with Open CASCADE's primitives (tests/brep_cases.h).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <map>

#include "brep/brep_file.h"
#include "brep_cases.h"
#include "geometry/mesh_intersect.h"
#include "scene/mesh_loader.h"
#include "scratch_dir.h"

namespace {

using pd::Mesh;
using pd::Vec3;
using pd_test::BrepCasePart;
using pd_test::BrepSolid;
using Kind = BrepSolid::Kind;

// A pin, a plate with a hole, an O-ring, a two-solid part, a surface model and
// a tilted box, placed as an assembly places its instances.
std::vector<BrepCasePart> mixed_parts() {
  return {
      {"pin", {Kind::kCylinder, {4.0, 30.0}}, Vec3(10, 10, -10)},
      {"plate", {Kind::kPlateWithHole, {20.0, 20.0, 5.0, 4.0}}, Vec3(0, 0, 0)},
      {"o-ring", {Kind::kTorus, {12.0, 1.5}}, Vec3(40, 0, 0), Vec3::UnitX(), 0.5},
      {"clip", {Kind::kTwoBoxes, {3.0, 2.0, 1.0}}, Vec3(-20, 0, 0)},
      {"cover", {Kind::kBoxShell, {5.0, 5.0, 5.0}}, Vec3(0, -30, 0)},
      {"tilted", {Kind::kTilted, {6.0, 4.0, 2.0}}, Vec3(1e4, 2e4, -3e4)},
  };
}

std::string assembly_file(const std::string& name, const std::string& unit = "mm") {
  const std::string path = pd_test::process_dir() + name;
  pd_test::write_step_assembly(path, mixed_parts(), unit);
  return path;
}

long odd_edges(const Mesh& m) {
  std::map<std::pair<int, int>, int> count;
  for (long k = 0; k < m.triangles.cols(); ++k)
    for (int c = 0; c < 3; ++c) {
      const int a = m.triangles(c, k), b = m.triangles((c + 1) % 3, k);
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  long odd = 0;
  for (const auto& [e, n] : count) odd += n % 2;
  return odd;
}

TEST(BrepFile, AnAssemblyIsOneMeshPerLeafNamedByItsInstance) {
  const pd::NodeMeshes m = pd::load_brep_meshes(assembly_file("mixed.step"), 0.05, true);
  ASSERT_EQ(m.meshes.size(), 6u);
  EXPECT_EQ(m.nodes,
            (std::vector<std::string>{"pin", "plate", "o-ring", "clip", "cover", "tilted"}));
  ASSERT_EQ(m.leaf_errors.size(), 6u);
  for (size_t k = 0; k < 6; ++k) {
    if (m.nodes[k] == "cover") {  // a surface model: the part's error names it
      EXPECT_NE(m.leaf_errors[k].find("\"assembly/cover\" holds no solid"), std::string::npos)
          << m.leaf_errors[k];
      continue;
    }
    EXPECT_EQ(m.leaf_errors[k], "") << m.nodes[k];
    EXPECT_GT(m.meshes[k].triangles.cols(), 0) << m.nodes[k];
    EXPECT_EQ(odd_edges(m.meshes[k]), 0) << m.nodes[k] << ": the solid's mesh is closed";
    EXPECT_EQ(m.tessellations[k].basis, pd::SagBasis::kBound) << m.nodes[k];
    EXPECT_EQ(m.tessellations[k].deflection, 0.05);
  }
  // Placed by the assembly, in double precision far from the origin.
  const auto box = [](const Mesh& x) {
    return std::pair<Vec3, Vec3>(x.vertices.rowwise().minCoeff(), x.vertices.rowwise().maxCoeff());
  };
  // (a cylinder's mesh lies within the sag inside it)
  EXPECT_LT((box(m.meshes[0]).first - Vec3(6, 6, -10)).cwiseAbs().maxCoeff(), 0.05);
  EXPECT_LT((box(m.meshes[0]).second - Vec3(14, 14, 20)).cwiseAbs().maxCoeff(), 0.05);
  EXPECT_EQ(box(m.meshes[0]).first.z(), -10.0);
  EXPECT_TRUE(box(m.meshes[3]).second.isApprox(Vec3(-14, 2, 1), 1e-12));  // both solids
  EXPECT_GT(box(m.meshes[5]).first.x(), 1e4 - 7);
  EXPECT_LT(box(m.meshes[5]).second.z(), -3e4 + 7);
  // Flat faces carry no sag; curved ones at most about the deflection.
  EXPECT_EQ(m.tessellations[3].sag, 0.0);
  EXPECT_EQ(m.tessellations[5].sag, 0.0);
  EXPECT_GT(m.tessellations[0].sag, 0.0);
  EXPECT_LT(m.tessellations[0].sag, 0.1);
}

// Where the report says a sag is a bound, dense samples of every face lie
// within it of the mesh (the mesh's own faces, every triangle).
TEST(BrepFile, EveryFaceLiesWithinTheSagBoundOfTheMesh) {
  const std::string path = pd_test::process_dir() + "sag.step";
  std::vector<BrepCasePart> parts = mixed_parts();
  parts.push_back({"ball", {Kind::kSphere, {7.0}}, Vec3(0, 50, 0)});
  parts.push_back({"shaft", {Kind::kShaftWithGroove, {5.0, 20.0, 1.0, 8.0}}, Vec3(0, 80, 0)});
  // A chamfered hex head's or nut's edges: a cone cut by flat sides (hyperbolas).
  parts.push_back({"chamfer", {Kind::kChamferedSquare, {5.0, 4.0}}, Vec3(0, 160, 0)});
  parts.push_back({"wave", {Kind::kWavySlab, {6.0, 3.0}}, Vec3(0, 120, 0)});
  pd_test::write_step_assembly(path, parts);
  for (double deflection : {0.2, 0.01}) {
    const pd::NodeMeshes m = pd::load_brep_meshes(path, deflection, true);
    EXPECT_EQ(m.tessellations[m.tessellations.size() - 2].basis, pd::SagBasis::kBound);
    // A non-rational B-spline face and its extrusion sides carry bounds too.
    EXPECT_EQ(m.tessellations.back().basis, pd::SagBasis::kBound);
    EXPECT_GT(m.tessellations.back().sag, 0.0);
    const std::vector<pd::Points> samples = pd_test::leaf_face_samples(path, 24);
    ASSERT_EQ(samples.size(), m.meshes.size());
    for (size_t k = 0; k < m.meshes.size(); ++k) {
      if (!m.leaf_errors[k].empty()) continue;
      const pd::PreparedMesh mesh(m.meshes[k]);
      double worst = 0.0;
      for (long s = 0; s < samples[k].cols(); ++s)
        worst = std::max(worst, mesh.unsigned_distance(samples[k].col(s), nullptr, nullptr));
      EXPECT_LE(worst, m.tessellations[k].sag + 1e-9)
          << m.nodes[k] << " at deflection " << deflection;
      // And the bound is of the error's size, not a loose cap; on the
      // free-form part only at the coarse deflection. A triangle's bound also
      // counts how unevenly the parameter runs along the surface (here along
      // the straight boundary of the B-spline face, meshed as one segment,
      // and the flat side extruded from it), which moves no point off the
      // triangle: at the fine deflection that is what the bound reads.
      const bool wave = m.nodes[k] == "wave";
      if (worst > 0 && (!wave || deflection > 0.1)) {
        EXPECT_LE(m.tessellations[k].sag, (wave ? 15.0 : 3.0) * worst) << m.nodes[k];
      }
    }
  }
}

TEST(BrepFile, AFileInInchesIsReadInMillimetres) {
  const std::string path = pd_test::process_dir() + "inch.step";
  pd_test::write_step_assembly(path,
                               {{"block", {Kind::kBox, {25.4, 50.8, 12.7}}, Vec3(254, 0, 0)},
                                {"peg", {Kind::kCylinder, {2.54, 25.4}}}},
                               "in");
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_NE(text.find("INCH"), std::string::npos) << "the writer wrote inches";
  const pd::NodeMeshes m = pd::load_brep_meshes(path, 0.1, true);
  ASSERT_EQ(m.meshes.size(), 2u);
  const Vec3 lo = m.meshes[0].vertices.rowwise().minCoeff();
  const Vec3 hi = m.meshes[0].vertices.rowwise().maxCoeff();
  EXPECT_TRUE(lo.isApprox(Vec3(254, 0, 0), 1e-9)) << lo.transpose();
  EXPECT_TRUE(hi.isApprox(Vec3(279.4, 50.8, 12.7), 1e-9)) << hi.transpose();
}

// Products meshed side by side (threads, and each product's faces on Open
// CASCADE's pool) come out as meshed one by one, to the bit.
TEST(BrepFile, ProductsMeshedSideBySideComeOutTheSame) {
  const std::string path = assembly_file("side-by-side.step");
  const pd::BrepFile one = pd::read_brep_file(path, 0.02, 1);
  const pd::BrepFile three = pd::read_brep_file(path, 0.02, 3);
  ASSERT_EQ(one.leaves.size(), 6u);
  ASSERT_EQ(three.leaves.size(), one.leaves.size());
  EXPECT_EQ(three.warnings, one.warnings);
  for (size_t k = 0; k < one.leaves.size(); ++k) {
    const pd::BrepLeaf &a = one.leaves[k], &b = three.leaves[k];
    EXPECT_EQ(a.mesh.vertices, b.mesh.vertices) << k;
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles) << k;
    EXPECT_EQ(a.triangle_sags, b.triangle_sags) << k;
    EXPECT_EQ(a.tessellation.sag, b.tessellation.sag) << k;
    EXPECT_EQ(a.error, b.error) << k;
  }
}

TEST(BrepFile, APartFileIsOneLeafAndABrepFileHasNoUnit) {
  const std::string step = pd_test::process_dir() + "part.stp";
  pd_test::write_step_part(step, {"washer", {Kind::kTorus, {6.0, 1.0}}, Vec3(1, 2, 3)});
  const pd::BrepFile f = pd::read_brep_file(step, 0.05);
  ASSERT_EQ(f.leaves.size(), 1u);
  EXPECT_EQ(f.unit, "mm");
  EXPECT_EQ(f.nodes[0].name, "washer");
  const std::string brep = pd_test::process_dir() + "part.brep";
  pd_test::write_brep_part(brep, {"clip", {Kind::kTwoBoxes, {3.0, 2.0, 1.0}}});
  const pd::BrepFile b = pd::read_brep_file(brep, 0.05);
  ASSERT_EQ(b.leaves.size(), 1u);
  EXPECT_EQ(b.unit, "");
  EXPECT_EQ(b.leaves[0].solids, 2);
  // Read whole, the file is one mesh of every leaf.
  const pd::NodeMeshes whole = pd::load_brep_meshes(brep, 0.05, false);
  ASSERT_EQ(whole.meshes.size(), 1u);
  EXPECT_EQ(whole.meshes[0].triangles.cols(), b.leaves[0].mesh.triangles.cols());
}

// Open CASCADE prints on standard output, where pdcheck writes its report:
// reading a damaged file leaves it untouched, and the error names the file.
TEST(BrepFile, ADamagedFileIsAnErrorNamingItAndPrintsNothing) {
  const std::string path = pd_test::process_dir() + "damaged.step";
  std::ofstream(path) << "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('x'),'2;1');\nENDSEC;\n"
                         "DATA;\n#1=PRODUCT('a','a','',(#2));\n#3=NONSENSE(#99,#1);\nENDSEC;\n"
                         "END-ISO-10303-21;\n";
  std::fflush(stdout);
  const std::string out = pd_test::process_dir() + "stdout.txt";
  const int saved = dup(1);
  std::FILE* f = std::fopen(out.c_str(), "w");
  dup2(fileno(f), 1);
  std::string error;
  try {
    pd::load_brep_meshes(path, 0.1, true);
  } catch (const pd::MeshError& e) {
    error = e.what();
  }
  std::fflush(stdout);
  dup2(saved, 1);
  close(saved);
  std::fclose(f);
  EXPECT_NE(error.find(path), std::string::npos) << error;
  std::ifstream printed(out);
  EXPECT_EQ(
      std::string((std::istreambuf_iterator<char>(printed)), std::istreambuf_iterator<char>()), "");
}

}  // namespace
