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

void collect(const aiScene* scene, const aiNode* node, const Mat4& parent, std::vector<Mesh>& out) {
  const Mat4 world = parent * to_eigen(node->mTransformation);
  for (unsigned k = 0; k < node->mNumMeshes; ++k) {
    const aiMesh* mesh = scene->mMeshes[node->mMeshes[k]];
    Mesh m;
    m.vertices.resize(3, mesh->mNumVertices);
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& x = mesh->mVertices[v];
      m.vertices.col(v) =
          world.topLeftCorner<3, 3>() * Vec3(x.x, x.y, x.z) + world.topRightCorner<3, 1>();
    }
    long tris = 0;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices >= 3) tris += mesh->mFaces[f].mNumIndices - 2;
    m.triangles.resize(3, tris);
    tris = 0;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      for (unsigned i = 2; i < face.mNumIndices; ++i) {
        const unsigned idx[3] = {face.mIndices[0], face.mIndices[i - 1], face.mIndices[i]};
        for (int c = 0; c < 3; ++c) {
          if (idx[c] >= mesh->mNumVertices) throw MeshError("face index out of range");
          m.triangles(c, tris) = static_cast<int>(idx[c]);
        }
        ++tris;
      }
    }
    if (m.vertices.cols() > 0) out.push_back(std::move(m));
  }
  for (unsigned c = 0; c < node->mNumChildren; ++c) collect(scene, node->mChildren[c], world, out);
}

}  // namespace

std::vector<Mesh> load_meshes(const std::string& path, bool split_instances) {
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
  std::vector<Mesh> pieces;
  try {
    collect(scene, scene->mRootNode, Mat4::Identity(), pieces);
  } catch (const MeshError& e) {
    throw MeshError("mesh file " + path + ": " + e.what());
  }
  if (pieces.empty()) throw MeshError("mesh file " + path + " has no vertices");
  if (split_instances) return pieces;
  Eigen::Index n = 0, t = 0;
  for (const auto& p : pieces) {
    n += p.vertices.cols();
    t += p.triangles.cols();
  }
  Mesh all;
  all.vertices.resize(3, n);
  all.triangles.resize(3, t);
  n = t = 0;
  for (const auto& p : pieces) {
    all.vertices.middleCols(n, p.vertices.cols()) = p.vertices;
    all.triangles.middleCols(t, p.triangles.cols()) = p.triangles.array() + int(n);
    n += p.vertices.cols();
    t += p.triangles.cols();
  }
  return {std::move(all)};
}

std::vector<Points> load_mesh_vertices(const std::string& path, bool split_instances) {
  std::vector<Points> out;
  for (Mesh& m : load_meshes(path, split_instances)) out.push_back(std::move(m.vertices));
  return out;
}

}  // namespace pd
