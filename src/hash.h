// Content hashes: XXH3 128-bit (Debian's libxxhash), as 32 lowercase hex digits.
// Not cryptographic: collisions are astronomically unlikely for honest data,
// which is all a cache key or a pair fingerprint has to resist.
#pragma once

#include <string>
#include <string_view>

namespace pd {

/// Incremental hasher: feed bytes, then take the digest once.
class Hasher {
 public:
  Hasher();
  ~Hasher();
  Hasher(const Hasher&) = delete;
  Hasher& operator=(const Hasher&) = delete;
  /// Adds bytes; fields added one after another are separated by their length,
  /// so ("ab", "c") and ("a", "bc") hash differently.
  Hasher& add(std::string_view bytes);
  Hasher& add(double x);  ///< the exact bits
  std::string hex() const;

 private:
  void* state_;
};

/// The hash of one byte string.
std::string content_hash(std::string_view bytes);

}  // namespace pd
