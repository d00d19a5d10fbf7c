#include "hash.h"

#include <xxhash.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

namespace pd {

Hasher::Hasher() : state_(XXH3_createState()) {
  if (!state_) throw std::bad_alloc();
  XXH3_128bits_reset(static_cast<XXH3_state_t*>(state_));
}

Hasher::~Hasher() {
  XXH3_freeState(static_cast<XXH3_state_t*>(state_));
}

Hasher& Hasher::add(std::string_view bytes) {
  const std::uint64_t n = bytes.size();
  auto* s = static_cast<XXH3_state_t*>(state_);
  XXH3_128bits_update(s, &n, sizeof n);
  XXH3_128bits_update(s, bytes.data(), bytes.size());
  return *this;
}

Hasher& Hasher::add(double x) {
  char b[sizeof x];
  std::memcpy(b, &x, sizeof x);
  return add(std::string_view(b, sizeof b));
}

std::string Hasher::hex() const {
  const XXH128_hash_t h = XXH3_128bits_digest(static_cast<XXH3_state_t*>(state_));
  char out[33];
  std::snprintf(out, sizeof out, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return out;
}

std::string content_hash(std::string_view bytes) {
  const XXH128_hash_t h = XXH3_128bits(bytes.data(), bytes.size());
  char out[33];
  std::snprintf(out, sizeof out, "%016llx%016llx", static_cast<unsigned long long>(h.high64),
                static_cast<unsigned long long>(h.low64));
  return out;
}

}  // namespace pd
