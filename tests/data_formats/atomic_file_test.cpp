// Outputs are written through a temporary file renamed into place: what that
// rename would do to a link, a special file or a long name is decided before
// any work, and temporary files of killed runs do not pile up.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "data_formats/atomic_file.h"
#include "data_formats/error.h"

namespace skybake {
namespace {

namespace fs = std::filesystem;

std::string contentsOf(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void expectBadInput(const std::function<void()>& run, const std::string& fragment) {
  try {
    run();
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("skybake_atomic_file_test_" + std::to_string(::getpid()));
    fs::create_directories(dir / "elsewhere");
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

// A symbolic link is written through: its target gets the new contents and
// the link stays a link (the rename used to replace the link itself).
TEST_F(AtomicFileTest, SymbolicLinksAreWrittenThrough) {
  const fs::path target = dir / "elsewhere" / "real.csv";
  std::ofstream(target) << "old";
  const fs::path link = dir / "link.csv";
  fs::create_symlink(target, link);
  requireWritableOutput(link);
  writeFileContentsAtomically(link, "new");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  EXPECT_EQ(contentsOf(target), "new");
  fs::create_symlink(dir / "missing.csv", dir / "dangling.csv");
  expectBadInput([&] { requireWritableOutput(dir / "dangling.csv"); }, "symbolic link to a missing file");
}

// A special file (a named pipe here; /dev/null and /dev/full as root) is
// refused before anything is written, and stays what it was.
TEST_F(AtomicFileTest, SpecialFilesAreRefusedAndStayAsTheyWere) {
  const fs::path pipe = dir / "pipe.csv";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  expectBadInput([&] { requireWritableOutput(pipe); }, "pipe.csv: is a named pipe, not a regular file");
  expectBadInput([&] { writeFileContentsAtomically(pipe, "x"); }, "is a named pipe");
  EXPECT_EQ(fs::status(pipe).type(), fs::file_type::fifo);
  expectBadInput([&] { requireWritableOutput("/dev/null"); }, "/dev/null: is a character device");
  EXPECT_EQ(fs::status("/dev/null").type(), fs::file_type::character);
}

// A name whose temporary name would be too long is refused before the work
// (it used to fail only after a whole bake).
TEST_F(AtomicFileTest, NamesTooLongForTheTemporaryFileAreRefusedFirst) {
  const fs::path long_name = dir / (std::string(250, 'n') + ".exr");
  expectBadInput([&] { requireWritableOutput(long_name); }, "the file name is too long");
  EXPECT_NO_THROW(requireWritableOutput(dir / (std::string(200, 'n') + ".exr")));
}

// A run killed while writing leaves its temporary file; the next write of
// the same output removes it, but not one of a run still alive.
TEST_F(AtomicFileTest, TemporaryFilesOfKilledRunsAreRemovedByTheNextWrite) {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);  // a process id no process has now
  const fs::path stale = dir / (".out.tmp-" + std::to_string(child) + ".csv");
  const fs::path alive = dir / (".out.tmp-" + std::to_string(::getppid()) + ".csv");
  const fs::path other = dir / (".other.tmp-" + std::to_string(child) + ".csv");
  for (const fs::path& p : {stale, alive, other}) std::ofstream(p) << "partial";
  writeFileContentsAtomically(dir / "out.csv", "done");
  EXPECT_EQ(contentsOf(dir / "out.csv"), "done");
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(alive));  // its writer may still rename it
  EXPECT_TRUE(fs::exists(other));  // another output's
}

}  // namespace
}  // namespace skybake
