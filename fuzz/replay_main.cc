// A main() for fuzz targets built without libFuzzer (any compiler): runs the target's
// LLVMFuzzerTestOneInput once on every file given, or on every file in every directory given,
// so ordinary ctest replays the seed corpora and a regression on a known input fails without
// clang. A target signals a violated invariant by aborting; this driver names the input first.
//   constraint_fuzz_replay fuzz/corpus/constraint
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

// The files named by `arg` (itself, or the regular files of a directory, sorted). False when
// `arg` is neither.
bool collect(const std::filesystem::path& arg, std::vector<std::filesystem::path>* files,
             std::string* err) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(arg, ec)) {
    files->push_back(arg);
    return true;
  }
  if (!std::filesystem::is_directory(arg, ec)) {
    *err = arg.string() + ": not a file or a directory";
    return false;
  }
  std::vector<std::filesystem::path> found;
  for (const auto& entry : std::filesystem::directory_iterator(arg, ec))
    if (entry.is_regular_file()) found.push_back(entry.path());
  if (ec) {
    *err = arg.string() + ": " + ec.message();
    return false;
  }
  std::sort(found.begin(), found.end());
  files->insert(files->end(), found.begin(), found.end());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s FILE|DIR...\n", argv[0]);
    return 2;
  }
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    std::string err;
    if (!collect(argv[i], &files, &err)) {
      std::fprintf(stderr, "%s\n", err.c_str());
      return 2;
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "no input files: an empty corpus replays nothing\n");
    return 2;
  }
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!in.good() && !in.eof()) {
      std::fprintf(stderr, "%s: cannot read\n", file.c_str());
      return 2;
    }
    std::fprintf(stderr, "replaying %s (%zu bytes)\n", file.c_str(), bytes.size());
    std::fflush(stderr);
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%zu inputs replayed\n", files.size());
  return 0;
}
