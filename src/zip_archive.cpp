#include "zip_archive.h"

#include <sys/stat.h>
#include <zip.h>

#include <cstdio>
#include <ctime>
#include <memory>

namespace pd {

namespace {

/// 1980-01-01 00:00 in the machine's time zone: libzip turns a time_t into the
/// zip's DOS date and time through localtime(), so a time made by mktime() from
/// the same local fields comes back as exactly those fields in any zone.
time_t fixed_zip_time() {
  std::tm t{};
  t.tm_year = 80;
  t.tm_mon = 0;
  t.tm_mday = 1;
  t.tm_isdst = -1;
  return std::mktime(&t);
}

struct SourceFree {
  void operator()(zip_source_t* s) const { zip_source_free(s); }
};

std::string libzip_message(zip_error_t* e) {
  return zip_error_strerror(e);
}

/// Reads back the whole buffer source libzip wrote the archive into.
std::string source_bytes(zip_source_t* src) {
  if (zip_source_open(src) < 0)
    throw ZipError("zip: cannot read the archive back: " + libzip_message(zip_source_error(src)));
  std::string out;
  char buf[65536];
  zip_int64_t n;
  while ((n = zip_source_read(src, buf, sizeof buf)) > 0) out.append(buf, static_cast<size_t>(n));
  const bool failed = n < 0;
  zip_source_close(src);
  if (failed)
    throw ZipError("zip: cannot read the archive back: " + libzip_message(zip_source_error(src)));
  return out;
}

}  // namespace

std::string zip_archive(const std::vector<ZipEntry>& entries) {
  zip_error_t error;
  zip_error_init(&error);
  std::unique_ptr<zip_source_t, SourceFree> src(zip_source_buffer_create(nullptr, 0, 0, &error));
  if (!src) throw ZipError("zip: " + libzip_message(&error));
  zip_source_keep(src.get());  // zip_close would free it: the bytes are read after it
  zip_t* za = zip_open_from_source(src.get(), ZIP_TRUNCATE, &error);
  if (!za) {
    const std::string m = libzip_message(&error);
    zip_error_fini(&error);
    throw ZipError("zip: " + m);
  }
  const time_t when = fixed_zip_time();
  auto fail = [&](const ZipEntry& e) {
    const std::string m = zip_strerror(za);
    zip_discard(za);
    throw ZipError("zip: entry " + e.name + ": " + m);
  };
  for (const ZipEntry& e : entries) {
    const bool dir = !e.name.empty() && e.name.back() == '/';
    zip_int64_t idx;
    if (dir) {
      idx = zip_dir_add(za, e.name.c_str(), ZIP_FL_ENC_UTF_8);
    } else {
      // The data stays in `entries` until zip_close has written it.
      zip_source_t* s = zip_source_buffer(za, e.data.data(), e.data.size(), 0);
      if (!s) fail(e);
      idx = zip_file_add(za, e.name.c_str(), s, ZIP_FL_ENC_UTF_8);
      if (idx < 0) zip_source_free(s);
    }
    if (idx < 0) fail(e);
    const auto index = static_cast<zip_uint64_t>(idx);
    const zip_uint32_t mode = dir ? (S_IFDIR | 0755) : (S_IFREG | 0644);
    if ((!dir && zip_set_file_compression(za, index, ZIP_CM_DEFLATE, 0) < 0) ||
        zip_file_set_mtime(za, index, when, 0) < 0 ||
        zip_file_set_external_attributes(za, index, 0, ZIP_OPSYS_UNIX, mode << 16) < 0)
      fail(e);
  }
  if (zip_close(za) < 0) {
    const std::string m = zip_strerror(za);
    zip_discard(za);
    throw ZipError("zip: " + m);
  }
  return source_bytes(src.get());
}

std::vector<ZipEntry> zip_entries(const std::string& bytes) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* src = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  if (!src) throw ZipError("zip: " + libzip_message(&error));
  zip_t* za = zip_open_from_source(src, ZIP_RDONLY | ZIP_CHECKCONS, &error);
  if (!za) {
    zip_source_free(src);
    const std::string m = libzip_message(&error);
    zip_error_fini(&error);
    throw ZipError(m);
  }
  std::unique_ptr<zip_t, void (*)(zip_t*)> archive(za, [](zip_t* z) { zip_discard(z); });
  std::vector<ZipEntry> out;
  const zip_int64_t n = zip_get_num_entries(za, 0);
  for (zip_int64_t k = 0; k < n; ++k) {
    const auto index = static_cast<zip_uint64_t>(k);
    const char* name = zip_get_name(za, index, ZIP_FL_ENC_RAW);
    ZipEntry e{name ? name : "", ""};
    zip_file_t* f = zip_fopen_index(za, index, 0);
    if (!f) throw ZipError("entry " + e.name + ": " + zip_strerror(za));
    char buf[65536];
    zip_int64_t got;
    while ((got = zip_fread(f, buf, sizeof buf)) > 0) e.data.append(buf, static_cast<size_t>(got));
    const std::string why = got < 0 ? zip_file_strerror(f) : "";
    zip_fclose(f);
    if (got < 0) throw ZipError("entry " + e.name + ": " + why);
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace pd
