// Scratch files and folders of a test process, under ::testing::TempDir(): unique per process
// and call, emptied before use (an earlier process with the same pid may have left the path
// behind), and removed when the process exits. Set TEHL_KEEP_TEST_FILES to keep them, e.g. to
// look at what a failing test wrote.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

namespace tehl::testing {

class ScratchPaths {
 public:
  ScratchPaths() = default;
  ScratchPaths(const ScratchPaths&) = delete;
  ScratchPaths& operator=(const ScratchPaths&) = delete;
  ~ScratchPaths() {
    if (std::getenv("TEHL_KEEP_TEST_FILES")) return;
    std::error_code ec;
    for (const auto& p : paths_) std::filesystem::remove_all(p, ec);
  }
  // TempDir()/<prefix>_<pid>_<counter>_<name>, not existing on return.
  std::string New(const std::string& prefix, const std::string& name) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::string path = ::testing::TempDir() + "/" + prefix + "_" + std::to_string(getpid()) +
                             "_" + std::to_string(paths_.size()) + "_" + name;
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
    paths_.push_back(path);
    return path;
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> paths_;
};

// A fresh scratch path (file or folder) for this process; see ScratchPaths.
inline std::string ScratchPath(const std::string& prefix, const std::string& name) {
  static ScratchPaths paths;
  return paths.New(prefix, name);
}

}  // namespace tehl::testing
