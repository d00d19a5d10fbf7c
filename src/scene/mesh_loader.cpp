#include "scene/mesh_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <filesystem>

namespace pd {

namespace {

Mat4 to_eigen(const aiMatrix4x4& m) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(i, j) = m[i][j];
  return r;
}

void collect(const aiScene* scene, const aiNode* node, const Mat4& parent,
             std::vector<Points>& out) {
  const Mat4 world = parent * to_eigen(node->mTransformation);
  for (unsigned k = 0; k < node->mNumMeshes; ++k) {
    const aiMesh* mesh = scene->mMeshes[node->mMeshes[k]];
    Points p(3, mesh->mNumVertices);
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& x = mesh->mVertices[v];
      p.col(v) = world.topLeftCorner<3, 3>() * Vec3(x.x, x.y, x.z) + world.topRightCorner<3, 1>();
    }
    if (p.cols() > 0) out.push_back(std::move(p));
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) collect(scene, node->mChildren[c], world, out);
}

}  // namespace

std::vector<Points> load_mesh_vertices(const std::string& path, bool split_instances) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw MeshError("cannot read mesh file " + path + ": no such file");
  Assimp::Importer importer;
  // Only positions are needed; no post-processing that could move vertices.
  const aiScene* scene = importer.ReadFile(path, 0);
  if (!scene || !scene->mRootNode) {
    std::string why = importer.GetErrorString();
    throw MeshError("cannot load mesh file " + path + ": " +
                    (why.empty() ? "unknown format" : why));
  }
  std::vector<Points> pieces;
  collect(scene, scene->mRootNode, Mat4::Identity(), pieces);
  if (pieces.empty()) throw MeshError("mesh file " + path + " has no vertices");
  if (split_instances) return pieces;
  Eigen::Index n = 0;
  for (const auto& p : pieces) n += p.cols();
  Points all(3, n);
  n = 0;
  for (const auto& p : pieces) {
    all.middleCols(n, p.cols()) = p;
    n += p.cols();
  }
  return {all};
}

}  // namespace pd
