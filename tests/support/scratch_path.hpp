// Scratch files and folders of the tests, under ::testing::TempDir(). Each lives in a folder of
// its own, unique per process and call, emptied before use (an earlier process with the same pid
// may have left it behind) and removed with everything in it: also what the code under test put
// beside the path (a NAME.part temporary file, a parent folder it made). A ScratchDir goes at
// the end of its scope, a failed assertion included; the folder of a ScratchPath when the
// process exits. Set TEHL_KEEP_TEST_FILES to keep them, e.g. to look at what a failing test
// wrote.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace tehl::testing {

// A fresh, empty folder TempDir()/<prefix>_<pid>_<n>, removed with its contents by the
// destructor.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& prefix)
      : path_((std::filesystem::path(::testing::TempDir()) /
               (prefix + "_" + std::to_string(getpid()) + "_" + std::to_string(Count()++)))
                  .string()) {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    std::filesystem::create_directories(path_);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  ~ScratchDir() {
    if (std::getenv("TEHL_KEEP_TEST_FILES")) return;
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }

  const std::string& path() const { return path_; }
  // A file or folder `name` ("out", "sub/table.csv") in the folder; not made.
  std::string Path(const std::string& name) const { return path_ + "/" + name; }

 private:
  static std::atomic<int>& Count() {
    static std::atomic<int> count{0};
    return count;
  }

  std::string path_;
};

// A fresh scratch path `name` (file or folder, not made) in a ScratchDir of its own that lasts
// until the process exits: for paths a helper returns, which outlive any scope of its own.
inline std::string ScratchPath(const std::string& prefix, const std::string& name) {
  static std::mutex mutex;
  static std::vector<std::unique_ptr<ScratchDir>> dirs;
  const std::lock_guard<std::mutex> lock(mutex);
  dirs.push_back(std::make_unique<ScratchDir>(prefix));
  return dirs.back()->Path(name);
}

}  // namespace tehl::testing
