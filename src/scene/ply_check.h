// PLY files checked before assimp reads them, and rewritten where Debian's
// assimp 5.2.5 misreads valid files (see ply_check.cpp for the two behaviours).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "geometry/types.h"

namespace pd {

/// A PLY file as checked: what to hand assimp, and the vertices the file holds.
struct PlyFile {
  std::string for_assimp;  ///< the file's bytes, or an equivalent file assimp reads right
  bool rewritten = false;  ///< for_assimp differs from the file
  bool ascii = false;
  Points vertices;  ///< x, y, z of every `vertex` instance, as the file holds them
  std::vector<std::string> warnings;  ///< header lines skipped, as assimp skips them
};

/// True when `bytes` begin like a PLY file ("ply" and a line end).
bool looks_like_ply(std::string_view bytes);

/// Parses the header and walks every element's data. Throws MeshError naming
/// the header line or the element instance for: no `end_header` (a file cut
/// inside its header), an unknown format or property type, binary or ASCII
/// data cut short, a value that is not a number, a negative list length, a
/// header line holding control characters. A header line of text that is no
/// PLY keyword is skipped as assimp skips it, with a warning.
PlyFile check_ply(std::string_view bytes);

/// Throws MeshError("the mesh loader misread the file (PLY): …") when the
/// vertices assimp returned (file order, one mesh) disagree with the file's,
/// and MeshError when a finite coordinate of the file is beyond the single
/// precision assimp stores. `read` has 3 rows, one column per vertex.
void check_ply_read(const PlyFile& file, const Eigen::Matrix<float, 3, Eigen::Dynamic>& read);

}  // namespace pd
