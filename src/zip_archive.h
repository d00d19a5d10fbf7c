// Zip archives in memory, with libzip (Debian's libzip-dev): made with the
// same bytes for the same entries (--bcf: BCF is a zip), and read (a 3MF mesh
// file is a zip, repacked for assimp: scene/mesh_loader.cpp).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace pd {

/// A file, or a directory when `name` ends in '/' (its data then empty).
struct ZipEntry {
  std::string name;
  std::string data;
};

/// libzip could not build the archive (out of memory; names the entry), or
/// could not read one (says why: not a zip, truncated, damaged).
struct ZipError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The archive of `entries`, in their order: files deflated, every entry dated
/// 1980-01-01 00:00 (the earliest zip date; no run time is stored, whatever the
/// machine's time zone), files mode 0644 and directories 0755, no extra fields
/// and no archive comment. Equal entries give equal bytes with the same zlib.
/// Throws ZipError.
std::string zip_archive(const std::vector<ZipEntry>& entries);

/// The entries of the zip archive `bytes`, in its order (directories with
/// their '/'), read by libzip: Zip64 fields and any dates are taken as they
/// are. Throws ZipError with libzip's reason when it is no readable zip.
std::vector<ZipEntry> zip_entries(const std::string& bytes);

}  // namespace pd
