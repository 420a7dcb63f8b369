// Text files written atomically: the file under its final name is complete, and a write or a
// rename that fails is a filesystem_error naming the path that leaves no temporary file behind.
#include "io/atomic_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/scratch_path.hpp"

namespace tehl::internal {
namespace {
namespace fs = std::filesystem;

std::string Contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(WriteTextAtomically, ReplacesTheFileAndLeavesNoTemporaryFile) {
  const testing::ScratchDir dir("tehl_atomic");
  const std::string path = dir.Path("sub/table.csv");
  WriteTextAtomically(path, "old\n");
  WriteTextAtomically(path, "new\n");
  EXPECT_EQ(Contents(path), "new\n");
  EXPECT_FALSE(fs::exists(path + ".part"));
}

// A folder under the final name: the text is written, the rename fails.
TEST(WriteTextAtomically, AFailedRenameIsAFilesystemErrorAndLeavesNoTemporaryFile) {
  const testing::ScratchDir dir("tehl_atomic");
  const std::string path = dir.Path("index.csv");
  fs::create_directories(path + "/inside");
  try {
    WriteTextAtomically(path, "scene,status\n");
    FAIL() << "written over a folder";
  } catch (const fs::filesystem_error& e) {
    EXPECT_EQ(e.path1().string(), path);
    EXPECT_TRUE(e.code()) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(path + "/inside"));
  EXPECT_FALSE(fs::exists(path + ".part"));
}

// A folder in the way of the temporary file: not written, and the folder is not ours to remove.
TEST(WriteTextAtomically, AFailedWriteIsAFilesystemErrorAndKeepsAFolderInTheWay) {
  const testing::ScratchDir dir("tehl_atomic");
  const std::string path = dir.Path("blocked.csv");
  fs::create_directories(path + ".part");
  try {
    WriteTextAtomically(path, "scene,status\n");
    FAIL() << "written";
  } catch (const fs::filesystem_error& e) {
    EXPECT_EQ(e.path1().string(), path + ".part");
    EXPECT_TRUE(e.code()) << e.what();
  }
  EXPECT_TRUE(fs::is_directory(path + ".part"));
  EXPECT_FALSE(fs::exists(path));
}

// A device is written in place, never replaced by a regular file (`--csv /dev/stdout`), and a
// device that refuses the text (/dev/full: no space left) is a filesystem_error naming it.
TEST(WriteTextAtomically, ADeviceIsWrittenInPlace) {
  ASSERT_TRUE(fs::is_character_file("/dev/null"));
  WriteTextAtomically("/dev/null", "x,y\n1,2\n");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_FALSE(fs::exists("/dev/null.part"));
  if (!fs::is_character_file("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  try {
    WriteTextAtomically("/dev/full", std::string(1 << 16, 'x'));
    FAIL() << "a full device took the text";
  } catch (const fs::filesystem_error& e) {
    EXPECT_EQ(e.path1().string(), "/dev/full");
    EXPECT_EQ(e.code(), std::errc::no_space_on_device) << e.code().message();
  }
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

}  // namespace
}  // namespace tehl::internal
