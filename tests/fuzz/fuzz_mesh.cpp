// Fuzz target: one mesh format (PDCHECK_FUZZ_FORMAT, the file extension)
// through the reading path of a mesh part, in process: the input is written to
// a file and read with load_meshes, exactly what a loader process runs (the
// PLY check, then assimp from the path: assimp's in-memory reader takes other
// branches, e.g. for OBJ face indices), then each mesh reduced to its hull's
// vertices and hulled again placed, as build_parts does.
// A hang or crash inside assimp costs a real run only its part (the loader
// process); here it is a finding to record (tests/fuzz/README.md).
//
// Oracles beyond "no crash, no exception but MeshError from reading": triangle
// indices in range; a hull either fails with an exception or has finite
// vertices.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "geometry/hull.h"
#include "scene/mesh_loader.h"

#ifndef PDCHECK_FUZZ_FORMAT
#error "PDCHECK_FUZZ_FORMAT names the mesh format (stl, obj, ply, gltf)"
#endif

namespace {

void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "fuzz_mesh_%s: oracle failed: %s\n", PDCHECK_FUZZ_FORMAT, what);
    std::abort();
  }
}

/// The input file, in a directory of its own per fuzzing process under TMPDIR
/// (removed at exit), named for the format: a glTF's relative buffer names
/// resolve there, as beside a real mesh.
std::string input_path(const std::string& extension) {
  static const std::string dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string d = std::string(tmp && *tmp ? tmp : "/tmp") + "/pdcheck-fuzz-XXXXXX";
    check(mkdtemp(d.data()) != nullptr, "mkdtemp");
    return d;
  }();
  static const bool cleanup = [] {
    return std::atexit([] {
             std::error_code ignored;
             std::filesystem::remove_all(dir, ignored);
           }) == 0;
  }();
  (void)cleanup;
  return dir + "/input." + extension;
}

void write_file(const std::string& path, std::string_view bytes) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  check(f != nullptr, "open the input file");
  check(std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size(), "write the input file");
  check(std::fclose(f) == 0, "close the input file");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::string format = PDCHECK_FUZZ_FORMAT;
  if (format == "gltf" && bytes.substr(0, 4) == "glTF") format = "glb";  // binary glTF
  std::vector<pd::Mesh> meshes;
  try {
    const std::string path = input_path(format);
    write_file(path, bytes);
    meshes = pd::load_meshes(path, /*split_instances=*/true);
  } catch (const pd::MeshError&) {
    return 0;
  }
  for (const pd::Mesh& m : meshes) {
    check(m.triangles.size() == 0 ||
              (m.triangles.minCoeff() >= 0 && m.triangles.maxCoeff() < m.vertices.cols()),
          "triangle indices in range");
    try {
      const pd::Points reduced = pd::convex_hull(m.vertices).vertices;
      Eigen::Matrix3d turn;
      turn << 0, -2, 0, 2, 0, 0, 0, 0, 2;  // placed: turned, scaled, moved
      const pd::Hull placed = pd::convex_hull((turn * reduced).colwise() + pd::Vec3(1, 2, 3));
      check(placed.vertices.allFinite(), "finite hull vertices");
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception&) {
      // Non-finite or unusable points: build_parts makes it the part's error.
    }
  }
  return 0;
}
