// Binary glTF (GLB) containers checked before assimp reads them: Debian's
// assimp 5.2.5 allocates whatever a chunk header declares (a 748-byte file
// declaring a 4 GB JSON chunk costs seconds and gigabytes before it fails).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace pd {

/// True when `bytes` begin like a binary glTF ("glTF").
bool looks_like_glb(std::string_view bytes);

/// Why a GLB container cannot be what its headers say, or "" when they fit:
/// the header's total length beyond the file, a version other than 1 or 2, a
/// chunk (or version 1's content) reaching past the total length, a first
/// chunk that is not JSON. `at(offset, n)` returns up to n bytes of the file
/// from offset (fewer at its end); `size` is the file's size. Pure given `at`.
std::string glb_problem(const std::function<std::string(uint64_t, size_t)>& at, uint64_t size);

}  // namespace pd
