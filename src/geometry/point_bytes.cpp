#include "geometry/point_bytes.h"

#include <cstring>

namespace pd {

std::string point_sets_bytes(const std::vector<Points>& sets) {
  std::string out;
  for (const Points& p : sets) {
    const long n = p.cols();
    out.append(reinterpret_cast<const char*>(&n), sizeof n);
    out.append(reinterpret_cast<const char*>(p.data()), sizeof(double) * 3 * n);
  }
  return out;
}

std::optional<std::vector<Points>> point_sets_from_bytes(const std::string& e, size_t off,
                                                         long count) {
  if (count < 0) return std::nullopt;
  std::vector<Points> sets;
  for (long k = 0; k < count; ++k) {
    long n = 0;
    if (off + sizeof n > e.size()) return std::nullopt;
    std::memcpy(&n, e.data() + off, sizeof n);
    off += sizeof n;
    if (n < 0 || static_cast<size_t>(n) > (e.size() - off) / (3 * sizeof(double)))
      return std::nullopt;
    Points p(3, n);
    if (n > 0) std::memcpy(p.data(), e.data() + off, sizeof(double) * 3 * n);
    off += sizeof(double) * 3 * n;
    sets.push_back(std::move(p));
  }
  if (off != e.size()) return std::nullopt;
  return sets;
}

}  // namespace pd
