// The harnesses as regression tests in the ordinary build (issue 13: each fixed finding
// becomes a regression test): a main that feeds every file of the given folders to the
// harness's LLVMFuzzerTestOneInput, as libFuzzer replays a corpus. The harness checks the
// contract (fuzz_check.hpp) and aborts on a finding, so the test fails naming the call and
// the decoded input. ctest runs one per harness over fuzz/corpus/<harness>/, whose crash_*
// seeds are the reproducers of the fixed findings (fuzz/make_corpus.py, CRASH_SEEDS); in
// `make test-sanitize` they run under ASan + UBSan too.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> inputs;
  for (int i = 1; i < argc; ++i) {
    for (const auto& entry : std::filesystem::directory_iterator(argv[i])) {
      if (entry.is_regular_file()) inputs.push_back(entry.path());
    }
  }
  std::sort(inputs.begin(), inputs.end());
  if (inputs.empty()) {
    std::fprintf(stderr, "replay: no inputs in the folders given\n");
    return 2;
  }
  int crashSeeds = 0;
  for (const auto& path : inputs) {
    std::ifstream file(path, std::ios::binary);
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "replay: %s\n", path.filename().c_str());
    LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
    crashSeeds += path.filename().string().rfind("crash_", 0) == 0;
  }
  std::printf("replay: %zu inputs kept the contract (%d of them reproducers of fixed findings)\n", inputs.size(),
              crashSeeds);
  return 0;
}
