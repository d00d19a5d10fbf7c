// Fuzz target: one mesh format (PDCHECK_FUZZ_FORMAT, the file extension)
// through the loading path of a part: the file is read, each mesh reduced to
// its hull, placed and hulled again (build_parts, as a scene part with
// "pieces": "meshes").
//
// Oracle beyond "no crash": a part either has an error or convex pieces whose
// vertices and box are finite.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "scene/parts.h"

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

// The input is written to a file of the format's extension in a directory of
// its own (an OBJ's mtllib or a glTF's buffer uri then finds nothing else).
const std::string& mesh_path() {
  // Never destroyed: the exit handler that removes the file still needs it.
  static const std::string* path = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string dir = std::string(tmp && *tmp ? tmp : "/tmp") + "/pdcheck-fuzz-XXXXXX";
    check(mkdtemp(dir.data()) != nullptr, "a temporary directory");
    auto* file = new std::string(dir + "/input." PDCHECK_FUZZ_FORMAT);
    std::atexit([] {
      std::remove(mesh_path().c_str());
      rmdir(mesh_path().substr(0, mesh_path().rfind('/')).c_str());
    });
    return file;
  }();
  return *path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(mesh_path(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    check(static_cast<bool>(out), "the input written");
  }
  pd::SceneSpec scene;
  pd::PartSpec spec;
  spec.id = "fuzz";
  spec.where = "fuzz";
  spec.mesh = mesh_path();
  spec.pieces = pd::Pieces::kMeshes;
  scene.parts.push_back(spec);
  const auto parts = pd::build_parts(scene);
  check(parts.size() == 1, "one part");
  const pd::Part& p = parts[0];
  if (p.error) return 0;
  check(!p.pieces.empty(), "a part without error has pieces");
  for (const auto& h : p.pieces) check(h.vertices.allFinite(), "finite hull vertices");
  check(p.box.lo.allFinite() && p.box.hi.allFinite(), "a finite box");
  return 0;
}
