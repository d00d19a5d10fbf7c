// Inline vertex lists kept as a summary (VertexSummary, scene/scene.h): a shard
// reads again only the lists of the parts it loads.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <vector>

#include "hash.h"
#include "scene/scene.h"
#include "scene/vertex_scan.h"

namespace pd {

Points place_points(const Points& p, const PartSpec& spec) {
  // Units first (the mesh's own unit to the scene's), then the part transform.
  const Points scaled = p * spec.to_scene_units;
  return (spec.transform.topLeftCorner<3, 3>() * scaled).colwise() +
         Vec3(spec.transform.topRightCorner<3, 1>());
}

std::string vertex_digest(const Points& p) {
  return content_hash(std::string_view(reinterpret_cast<const char*>(p.data()),
                                       sizeof(double) * static_cast<size_t>(p.size())));
}

namespace {

/// Closes the file however the read ends.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

bool read_at(int fd, std::string& out, size_t offset, size_t length) {
  out.resize(length);
  size_t got = 0;
  while (got < length) {
    const ssize_t n = pread(fd, out.data() + got, length - got, static_cast<off_t>(offset + got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    got += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace

void read_inline_vertices(SceneSpec& s) {
  Fd file{-1};
  std::string text;
  std::vector<double> xyz;
  for (PartSpec& p : s.parts) {
    if (!p.vertex_summary) continue;
    if (file.fd < 0) file.fd = open(s.path.c_str(), O_RDONLY | O_CLOEXEC);
    if (file.fd < 0) throw SceneError(s.path + ": cannot open the scene file again");
    const VertexSummary& sum = *p.vertex_summary;
    const bool same = read_at(file.fd, text, sum.offset, sum.length) &&
                      scan_vertex_array(text, xyz) && long(xyz.size()) == 3 * sum.count;
    Points v;
    if (same) v = Eigen::Map<const Points>(xyz.data(), 3, static_cast<Eigen::Index>(sum.count));
    if (!same || vertex_digest(v) != std::string_view(sum.digest.data(), sum.digest.size()))
      throw SceneError(p.where +
                       ": vertices: the scene file changed while pdcheck read it (run again)");
    p.vertices = std::move(v);
    p.vertex_summary.reset();
  }
}

}  // namespace pd
