#include "scene/mesh_loader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>

#include "scene/glb_check.h"
#include "scene/node_names.h"
#include "scene/ply_check.h"
#include "zip_archive.h"

namespace pd {

namespace {

Mat4 to_eigen(const aiMatrix4x4& m) {
  Mat4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(i, j) = m[i][j];
  return r;
}

Mesh placed_mesh(const aiMesh* mesh, const Mat4& world) {
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
  return m;
}

/// The node's meshes and its descendants', placed by their accumulated node
/// transforms; `paths`, when given, gets each mesh's node path (node_names.h).
void collect(const aiScene* scene, const aiNode* node, const Mat4& parent, const std::string& path,
             std::vector<Mesh>& out, std::vector<std::string>* paths) {
  const Mat4 world = parent * to_eigen(node->mTransformation);
  for (unsigned k = 0; k < node->mNumMeshes; ++k) {
    Mesh m = placed_mesh(scene->mMeshes[node->mMeshes[k]], world);
    if (m.vertices.cols() == 0) continue;
    out.push_back(std::move(m));
    if (paths) paths->push_back(path);
  }
  std::vector<std::string> names;
  if (paths)
    for (unsigned c = 0; c < node->mNumChildren; ++c)
      names.emplace_back(node->mChildren[c]->mName.C_Str());
  const std::vector<std::string> segments = sibling_segments(names);
  for (unsigned c = 0; c < node->mNumChildren; ++c)
    collect(scene, node->mChildren[c], world,
            !paths         ? path
            : path.empty() ? segments[c]
                           : path + "/" + segments[c],
            out, paths);
}

/// Every mesh instance with its node path, from the root's children down. The
/// root's own meshes (a file of one node: STL, PLY) are named by the root as
/// if it were the first of its children.
void collect_by_node(const aiScene* scene, std::vector<Mesh>& out,
                     std::vector<std::string>& paths) {
  const aiNode* root = scene->mRootNode;
  const Mat4 world = to_eigen(root->mTransformation);
  std::vector<std::string> names;
  if (root->mNumMeshes > 0) names.emplace_back(root->mName.C_Str());
  for (unsigned c = 0; c < root->mNumChildren; ++c)
    names.emplace_back(root->mChildren[c]->mName.C_Str());
  const std::vector<std::string> segments = sibling_segments(names);
  size_t at = 0;
  if (root->mNumMeshes > 0) {
    const std::string& own = segments[at++];
    for (unsigned k = 0; k < root->mNumMeshes; ++k) {
      Mesh m = placed_mesh(scene->mMeshes[root->mMeshes[k]], world);
      if (m.vertices.cols() == 0) continue;
      out.push_back(std::move(m));
      paths.push_back(own);
    }
  }
  for (unsigned c = 0; c < root->mNumChildren; ++c)
    collect(scene, root->mChildren[c], world, segments[at++], out, &paths);
}

/// The meshes of an imported scene, split per instance or joined into one.
std::vector<Mesh> meshes_of(const aiScene* scene, bool split_instances) {
  std::vector<Mesh> pieces;
  collect(scene, scene->mRootNode, Mat4::Identity(), {}, pieces, nullptr);
  if (pieces.empty()) throw MeshError("has no vertices");
  if (split_instances) return pieces;
  return {join_meshes(pieces)};
}

NodeMeshes node_meshes_of(const aiScene* scene) {
  NodeMeshes out;
  collect_by_node(scene, out.meshes, out.nodes);
  if (out.meshes.empty()) throw MeshError("has no vertices");
  return out;
}

/// What a read returns: the meshes split or joined, or split by node.
struct Want {
  bool split_instances = false;
  bool by_node = false;
  NodeMeshes of(const aiScene* scene) const {
    if (by_node) return node_meshes_of(scene);
    NodeMeshes out;
    out.meshes = meshes_of(scene, split_instances);
    return out;
  }
};

}  // namespace

Mesh join_meshes(const std::vector<Mesh>& pieces) {
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
  return all;
}

namespace {

const aiScene* checked(const aiScene* scene, const Assimp::Importer& importer) {
  if (!scene || !scene->mRootNode) {
    const std::string why = importer.GetErrorString();
    throw MeshError(why.empty() ? "unknown format" : why);
  }
  return scene;
}

/// The vertices assimp returned, in its mesh order (a PLY has one mesh).
Eigen::Matrix<float, 3, Eigen::Dynamic> raw_vertices(const aiScene* scene) {
  Eigen::Index n = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) n += scene->mMeshes[m]->mNumVertices;
  Eigen::Matrix<float, 3, Eigen::Dynamic> out(3, n);
  n = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
    for (unsigned v = 0; v < scene->mMeshes[m]->mNumVertices; ++v, ++n) {
      const aiVector3D& x = scene->mMeshes[m]->mVertices[v];
      out.col(n) << x.x, x.y, x.z;
    }
  return out;
}

NodeMeshes read_ply(std::string_view bytes, const Want& want, std::vector<std::string>* warnings) {
  const PlyFile ply = check_ply(bytes);
  if (warnings) warnings->insert(warnings->end(), ply.warnings.begin(), ply.warnings.end());
  Assimp::Importer importer;
  const aiScene* scene =
      checked(importer.ReadFileFromMemory(ply.for_assimp.data(), ply.for_assimp.size(), 0, "ply"),
              importer);
  check_ply_read(ply, raw_vertices(scene));
  return want.of(scene);
}

/// Why `path` cannot be read as a mesh file, or empty when it is a regular file.
std::string path_problem(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const int err = errno;
    struct stat link {};
    if (err == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
      return "it is a dangling symbolic link";
    if (err == ENOENT) return "no such file";
    if (err == ELOOP) return "it is a symbolic link loop (too many levels of symbolic links)";
    return std::strerror(err);
  }
  if (S_ISREG(st.st_mode)) return {};
  if (S_ISDIR(st.st_mode)) return "it is a directory, not a mesh file";
  if (S_ISFIFO(st.st_mode)) return "it is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "it is a device, not a regular file";
  if (S_ISSOCK(st.st_mode)) return "it is a socket, not a regular file";
  return "it is not a regular file";
}

/// The whole file, or its first `limit` bytes (from `offset`).
std::string read_bytes(const std::string& path, size_t limit = std::string::npos,
                       uint64_t offset = 0) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw MeshError(std::strerror(errno));
  if (offset > 0 && ::lseek(fd, off_t(offset), SEEK_SET) < 0) {
    const int err = errno;
    ::close(fd);
    throw MeshError(std::strerror(err));
  }
  std::string out;
  char buf[1 << 16];
  while (out.size() < limit) {
    const ssize_t r = ::read(fd, buf, std::min(sizeof buf, limit - out.size()));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) {
      const int err = errno;
      ::close(fd);
      throw MeshError(std::strerror(err));
    }
    if (r == 0) break;
    out.append(buf, size_t(r));
  }
  ::close(fd);
  return out;
}

/// Whether the PLY check, not assimp, gets the file first. By content ("ply"
/// and a line end) and by extension: assimp 5.2.5's PLY reader, chosen by the
/// extension, crashes or spins on files that start "ply" without the line end
/// (tests/fuzz/regressions/ply/), which check_ply refuses.
bool goes_to_ply_check(std::string_view head, std::string_view extension) {
  std::string ext(extension);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  return looks_like_ply(head) || ext == "ply";
}

std::string lower_extension(std::string_view extension) {
  std::string ext(extension);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  return ext;
}

/// A 3MF file (a zip of XML parts), read by libzip and repacked as a plain zip
/// before assimp reads it: assimp 5.2.5's unzip finds no model in archives
/// whose entries carry Zip64 size fields, as lib3mf (OpenSCAD's 3MF export)
/// writes them even for small files, and then reads an empty scene.
NodeMeshes read_3mf(const std::string& bytes, const Want& want) {
  std::string plain;
  try {
    plain = zip_archive(zip_entries(bytes));
  } catch (const ZipError& e) {
    throw MeshError(std::string("the 3MF container (a zip archive) could not be opened: ") +
                    e.what());
  }
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFileFromMemory(plain.data(), plain.size(), 0, "3mf");
  if (!scene || !scene->mRootNode) {
    const std::string why = importer.GetErrorString();
    throw MeshError("the 3MF container opened, but " +
                    (why.empty() ? std::string("no 3D model in it could be read") : why));
  }
  return want.of(scene);
}

// Throws MeshError when a binary glTF's headers declare more than the file
// holds (glb_check.h), before assimp allocates what they declare.
void check_glb(const std::function<std::string(uint64_t, size_t)>& at, uint64_t size) {
  const std::string problem = glb_problem(at, size);
  if (!problem.empty()) throw MeshError(problem);
}

NodeMeshes read_with(std::string_view bytes, const std::string& extension, const Want& want,
                     std::vector<std::string>* warnings) {
  if (goes_to_ply_check(bytes, extension)) return read_ply(bytes, want, warnings);
  if (looks_like_glb(bytes))
    check_glb(
        [&](uint64_t at, size_t n) {
          return std::string(bytes.substr(std::min<uint64_t>(at, bytes.size()), n));
        },
        bytes.size());
  if (lower_extension(extension) == "3mf") return read_3mf(std::string(bytes), want);
  Assimp::Importer importer;
  // Only positions are needed; no post-processing that could move vertices.
  const aiScene* scene = checked(
      importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, extension.c_str()), importer);
  return want.of(scene);
}

NodeMeshes load_with(const std::string& path, const Want& want,
                     std::vector<std::string>* warnings) {
  const std::string problem = path_problem(path);
  if (!problem.empty()) throw MeshError("cannot read mesh file " + path + ": " + problem);
  try {
    // A PLY is read from memory, checked and maybe rewritten; other formats
    // from the path, so a glTF finds its external buffers.
    const std::string head = read_bytes(path, 4);
    const std::string extension = std::filesystem::path(path).extension().string();
    if (goes_to_ply_check(head, extension)) {
      std::vector<std::string> found;
      NodeMeshes meshes = read_ply(read_bytes(path), want, &found);
      if (warnings)
        for (const std::string& w : found) warnings->push_back("mesh file " + path + ": " + w);
      return meshes;
    }
    if (lower_extension(extension) == "3mf") return read_3mf(read_bytes(path), want);
    if (looks_like_glb(head)) {
      std::error_code ec;
      const uintmax_t size = std::filesystem::file_size(path, ec);
      if (ec) throw MeshError(ec.message());
      check_glb([&](uint64_t at, size_t n) { return read_bytes(path, n, at); }, size);
    }
    Assimp::Importer importer;
    // Only positions are needed; no post-processing that could move vertices.
    return want.of(checked(importer.ReadFile(path, 0), importer));
  } catch (const MeshError& e) {
    throw MeshError("cannot load mesh file " + path + ": " + e.what());
  }
}

}  // namespace

std::vector<Mesh> read_meshes(std::string_view bytes, const std::string& extension,
                              bool split_instances, std::vector<std::string>* warnings) {
  return read_with(bytes, extension, Want{split_instances, false}, warnings).meshes;
}

NodeMeshes read_node_meshes(std::string_view bytes, const std::string& extension,
                            std::vector<std::string>* warnings) {
  return read_with(bytes, extension, Want{true, true}, warnings);
}

std::vector<Mesh> load_meshes(const std::string& path, bool split_instances,
                              std::vector<std::string>* warnings) {
  return load_with(path, Want{split_instances, false}, warnings).meshes;
}

NodeMeshes load_node_meshes(const std::string& path, std::vector<std::string>* warnings) {
  return load_with(path, Want{true, true}, warnings);
}

std::vector<Points> load_mesh_vertices(const std::string& path, bool split_instances) {
  std::vector<Points> out;
  for (Mesh& m : load_meshes(path, split_instances)) out.push_back(std::move(m.vertices));
  return out;
}

}  // namespace pd
