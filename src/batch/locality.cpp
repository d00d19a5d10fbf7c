#include "batch/locality.h"

#include <algorithm>

namespace pd {

std::vector<std::uint64_t> locality_codes(const std::vector<Part>& parts) {
  Aabb all;
  bool any = false;
  for (const Part& p : parts)
    if (!p.error) {
      all = any ? all.merged(p.box) : p.box;
      any = true;
    }
  std::vector<std::uint64_t> codes(parts.size(), 0);
  if (!any) return codes;
  const Vec3 span = (all.hi - all.lo).cwiseMax(1e-300);
  for (size_t p = 0; p < parts.size(); ++p) {
    if (parts[p].error) continue;
    const Vec3 c = 0.5 * (parts[p].box.lo + parts[p].box.hi);
    std::uint32_t q[3];
    for (int d = 0; d < 3; ++d)
      q[d] = std::uint32_t(std::clamp((c(d) - all.lo(d)) / span(d), 0.0, 1.0) * 2097151.0);
    std::uint64_t code = 0;
    for (int bit = 20; bit >= 0; --bit)
      for (int d = 0; d < 3; ++d) code = (code << 1) | ((q[d] >> bit) & 1u);
    codes[p] = code;
  }
  return codes;
}

}  // namespace pd
