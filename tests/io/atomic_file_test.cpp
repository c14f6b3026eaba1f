#include "tessera/io/atomic_file.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "io_test_util.hpp"

namespace tessera {
namespace {

using io_test::files_in;
using io_test::read_bytes;
using io_test::TempDir;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(WriteFileAtomic, WritesTheBytesAndLeavesNoTemporary) {
  TempDir dir;
  const std::string bytes("a\0b\nc", 5);
  ASSERT_TRUE(write_file_atomic(dir / "out.bin", bytes));
  EXPECT_EQ(read_bytes(dir / "out.bin"), bytes);
  EXPECT_THAT(files_in(dir.path()), ElementsAre("out.bin"));
}

TEST(WriteFileAtomic, ReplacesAnExistingFile) {
  TempDir dir;
  io_test::write_bytes(dir / "out.txt", "old contents that are longer");
  ASSERT_TRUE(write_file_atomic(dir / "out.txt", "new"));
  EXPECT_EQ(read_bytes(dir / "out.txt"), "new");
  EXPECT_THAT(files_in(dir.path()), ElementsAre("out.txt"));
}

TEST(WriteFileAtomic, WritesAnEmptyFile) {
  TempDir dir;
  ASSERT_TRUE(write_file_atomic(dir / "empty", ""));
  EXPECT_TRUE(std::filesystem::exists(dir / "empty"));
  EXPECT_EQ(std::filesystem::file_size(dir / "empty"), 0u);
}

TEST(WriteFileAtomic, MissingFolderIsARuntimeErrorNamingThePath) {
  TempDir dir;
  const Status s = write_file_atomic(dir / "no" / "such" / "out.txt", "x");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().kind, ErrorKind::kRuntime);
  EXPECT_THAT(s.error().message, HasSubstr("out.txt"));
  EXPECT_THAT(s.error().message, HasSubstr("cannot write"));
  EXPECT_TRUE(files_in(dir.path()).empty());
}

TEST(WriteFileAtomic, FailedRenameRemovesTheTemporaryAndKeepsTheTarget) {
  TempDir dir;
  // A non-empty directory where the file should go: rename(2) fails after the temp is written.
  std::filesystem::create_directories(dir / "target" / "inside");
  const Status s = write_file_atomic(dir / "target", "x");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().kind, ErrorKind::kRuntime);
  EXPECT_THAT(s.error().message, HasSubstr("target"));
  EXPECT_THAT(files_in(dir.path()), ElementsAre("target"));
  EXPECT_TRUE(std::filesystem::is_directory(dir / "target" / "inside"));
}

// The id of a process that has exited (and been reaped), as a killed writer leaves it.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST(WriteFileAtomic, RemovesTheTemporariesOfKilledWritersAndKeepsThoseOfLiveOnes) {
  TempDir dir;
  const std::string stale = ".map.png.tmp-" + std::to_string(dead_pid());
  const std::string live = ".map.png.tmp-" + std::to_string(::getppid());
  io_test::write_bytes(dir / stale, "half a picture");
  io_test::write_bytes(dir / live, "another process is writing");
  const std::string other = ".other.png.tmp-" + std::to_string(dead_pid());
  io_test::write_bytes(dir / other, "another output's: left to its own next write");
  ASSERT_TRUE(write_file_atomic(dir / "map.png", "picture"));
  EXPECT_THAT(files_in(dir.path()), ElementsAre(live, other, "map.png"));
}

TEST(WriteFilesAtomic, WritesEveryFileOfTheGroup) {
  TempDir dir;
  const PendingFile files[] = {{dir / "a.pgm", "A"}, {dir / "a.yaml", "B"}};
  ASSERT_TRUE(write_files_atomic(files));
  EXPECT_EQ(read_bytes(dir / "a.pgm"), "A");
  EXPECT_EQ(read_bytes(dir / "a.yaml"), "B");
  EXPECT_THAT(files_in(dir.path()), ElementsAre("a.pgm", "a.yaml"));
}

TEST(WriteFilesAtomic, OneFailingFileLeavesNoneOfTheGroupBehind) {
  TempDir dir;
  const PendingFile files[] = {{dir / "a.pgm", "A"}, {dir / "missing" / "a.yaml", "B"}};
  const Status s = write_files_atomic(files);
  ASSERT_FALSE(s);
  EXPECT_THAT(s.error().message, HasSubstr("a.yaml"));
  EXPECT_TRUE(files_in(dir.path()).empty());
}

TEST(EnsureDirectory, CreatesMissingParentsAndAcceptsAnExistingFolder) {
  TempDir dir;
  ASSERT_TRUE(ensure_directory(dir / "a" / "b" / "c"));
  EXPECT_TRUE(std::filesystem::is_directory(dir / "a" / "b" / "c"));
  EXPECT_TRUE(ensure_directory(dir / "a" / "b" / "c"));
}

TEST(EnsureDirectory, AFileInTheWayIsARuntimeError) {
  TempDir dir;
  io_test::write_bytes(dir / "file", "x");
  const Status s = ensure_directory(dir / "file");
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().kind, ErrorKind::kRuntime);
  EXPECT_THAT(s.error().message, HasSubstr("file"));
  EXPECT_THAT(s.error().message, HasSubstr("a file is in the way"));
}

TEST(AtomicFileWriter, PiecesAppearOnlyOnCommit) {
  TempDir dir;
  const auto path = dir / "run.mcap";
  io_test::write_bytes(path, "old");
  Result<AtomicFileWriter> writer = AtomicFileWriter::open(path);
  ASSERT_TRUE(writer.ok()) << writer.error().message;
  ASSERT_TRUE(writer->append("new "));
  ASSERT_TRUE(writer->append("bytes"));
  EXPECT_EQ(writer->size(), 9U);
  EXPECT_EQ(read_bytes(path), "old");  // until committed
  AtomicFileWriter moved = std::move(*writer);
  ASSERT_TRUE(moved.commit());
  EXPECT_EQ(read_bytes(path), "new bytes");
  EXPECT_THAT(files_in(dir.path()), ElementsAre("run.mcap"));
  EXPECT_FALSE(moved.commit());  // once
}

TEST(AtomicFileWriter, DroppedWithoutCommitLeavesTheOldFileAndNoTemporary) {
  TempDir dir;
  const auto path = dir / "run.mcap";
  io_test::write_bytes(path, "old");
  {
    Result<AtomicFileWriter> writer = AtomicFileWriter::open(path);
    ASSERT_TRUE(writer.ok());
    ASSERT_TRUE(writer->append("half a recording"));
  }
  EXPECT_EQ(read_bytes(path), "old");
  EXPECT_THAT(files_in(dir.path()), ElementsAre("run.mcap"));
}

}  // namespace
}  // namespace tessera
