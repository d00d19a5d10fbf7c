// A main for fuzz targets built without libFuzzer (any compiler): runs the
// target once on each file named on the command line, as libFuzzer does when
// given files, so the same regression replay works in every build.
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (!arg.empty() && arg[0] == '-') continue;  // libFuzzer flags: nothing to do here
    std::ifstream in(arg, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "replay: cannot read %s\n", arg.c_str());
      return 2;
    }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "Running: %s\n", arg.c_str());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::fprintf(stderr, "replay: %d inputs, no failure\n", argc - 1);
  return 0;
}
