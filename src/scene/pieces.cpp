// The "pieces" vocabulary: one table for the scene parser, the CLI and the report.
#include <array>
#include <utility>

#include "scene/scene.h"

namespace pd {

namespace {

constexpr std::array<std::pair<Pieces, const char*>, 4> kPieces = {
    {{Pieces::kAuto, "auto"},
     {Pieces::kHull, "hull"},
     {Pieces::kMeshes, "meshes"},
     {Pieces::kDecompose, "decompose"}}};

}  // namespace

std::optional<Pieces> parse_pieces(const std::string& name) {
  for (const auto& [p, n] : kPieces)
    if (name == n) return p;
  return std::nullopt;
}

const char* pieces_name(Pieces p) {
  for (const auto& [q, n] : kPieces)
    if (p == q) return n;
  return "?";
}

void override_pieces(SceneSpec& s, Pieces p) {
  for (PartSpec& part : s.parts)
    if (part.mesh) part.pieces = p;
}

}  // namespace pd
