#include "brep/brep_backend.h"

#include <dlfcn.h>

#include <atomic>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <system_error>

namespace pd {

namespace {

struct State {
  std::mutex mutex;  ///< held while loading
  /// Set once loaded: read without the lock, so that a process forked while
  /// another thread held it still finds the backend its parent loaded.
  std::atomic<const BrepBackend*> backend{nullptr};
  bool tried = false;
  std::string error;  ///< why the module could not be loaded
};

State& state() {
  static State s;
  return s;
}

std::string executable_dir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.parent_path().string();
}

// Beside the executable first (where the build puts it), then wherever the
// dynamic linker looks (LD_LIBRARY_PATH, the system's directories). Never
// unloaded: its code runs until the process ends.
void load(State& s) {
  if (s.backend.load() || s.tried) return;
  s.tried = true;
  const std::string dir = executable_dir();
  std::string first_error;
  for (const std::string& path :
       {dir.empty() ? std::string() : dir + "/" + kBrepModuleName, std::string(kBrepModuleName)}) {
    if (path.empty()) continue;
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    const char* why = handle ? nullptr : ::dlerror();
    if (handle) {
      using Entry = const BrepBackend* (*)();
      if (const auto entry = reinterpret_cast<Entry>(::dlsym(handle, kBrepBackendEntry))) {
        s.backend = entry();
        return;
      }
      why = "it has no entry point (another program's module?)";
    }
    // dlerror() names the file it tried.
    if (first_error.empty()) first_error = why ? why : path + ": cannot be loaded";
  }
  s.error = std::string("STEP and .brep files need pdcheck's Open CASCADE module, ") +
            kBrepModuleName + ", which the build puts beside the pdcheck binary; it could not be " +
            "loaded (" + first_error + ")";
}

}  // namespace

const BrepBackend& brep_backend() {
  State& s = state();
  if (const BrepBackend* b = s.backend.load()) return *b;
  std::lock_guard<std::mutex> lock(s.mutex);
  load(s);
  if (const BrepBackend* b = s.backend.load()) return *b;
  throw std::runtime_error(s.error);
}

bool preload_brep_backend() {
  State& s = state();
  if (s.backend.load()) return true;
  std::lock_guard<std::mutex> lock(s.mutex);
  load(s);
  return s.backend.load() != nullptr;
}

void use_brep_backend(const BrepBackend& backend) {
  state().backend = &backend;
}

BrepFile read_brep_file(const std::string& path, double deflection, int threads) {
  const BrepBackend* backend = nullptr;
  try {
    backend = &brep_backend();
  } catch (const std::runtime_error& e) {
    throw std::runtime_error("B-rep file " + path + ": " + e.what());
  }
  return backend->read_file(path, deflection, threads);
}

ExactMeasure measure_exact_pair(const ExactPart& a, const ExactPart& b, const ExactRequest& r) {
  return brep_backend().measure_pair(a, b, r);
}

}  // namespace pd
