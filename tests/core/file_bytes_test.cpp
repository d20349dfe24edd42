// The one capped file reader and writer (core/file_bytes.h): a file's bytes come back whole, anything but a regular
// file or a file over the cap is refused with the reason in words, and a write replaces the file whole.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/file_bytes.h"
#include "support/test_support.h"

namespace meshedit {
namespace {

TEST(FileBytes, ReadsAWholeFileAndWritesItBack) {
  const auto dir = testing::scratch_dir();
  const std::string bytes("a\0b\nc", 5);
  EXPECT_EQ(write_file_bytes(dir / "f.bin", bytes), "");
  const FileBytes read = read_file_bytes(dir / "f.bin");
  EXPECT_TRUE(read.ok()) << read.error;
  EXPECT_EQ(read.bytes, bytes);
  EXPECT_FALSE(std::filesystem::exists(dir / "f.bin.meshedit-tmp"));
}

TEST(FileBytes, RefusesWhatIsNotARegularFileWithTheReason) {
  const auto dir = testing::scratch_dir();
  EXPECT_EQ(read_file_bytes(dir / "absent").error, "cannot open: No such file or directory");
  EXPECT_EQ(read_file_bytes(dir).error, "cannot open: Is a directory");
  EXPECT_EQ(read_file_bytes("/dev/zero").error, "cannot open: not a regular file");
  EXPECT_EQ(write_file_bytes(dir / "no" / "such" / "folder.txt", "x").rfind("cannot write: ", 0), 0u);
}

TEST(FileBytes, RefusesAFileOverTheCap) {
  const auto dir = testing::scratch_dir();
  std::ofstream(dir / "big.txt") << std::string(100, 'x');
  EXPECT_TRUE(read_file_bytes(dir / "big.txt", 100).ok());
  const FileBytes over = read_file_bytes(dir / "big.txt", 99);
  EXPECT_FALSE(over.ok());
  EXPECT_EQ(over.error, "file is 100 bytes; MeshEdit reads files up to 99 bytes");
  EXPECT_TRUE(over.bytes.empty());
}

}  // namespace
}  // namespace meshedit
