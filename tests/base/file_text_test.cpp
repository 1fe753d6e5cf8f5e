// Output files (base/file_text.h): what `--out` may replace, what it writes as a stream, and what
// it refuses. Each test guards a way an output once destroyed something that was not its own.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "base/file_text.h"

namespace tactile {
namespace {

namespace fs = std::filesystem;

class OutputFile : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/tactile-out-XXXXXX";
    ASSERT_NE(::mkdtemp(pattern), nullptr);
    dir_ = pattern;
  }
  void TearDown() override {
    guardInputFiles(false);
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  static std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  static void write(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
  }
  // Files in the folder whose name holds ".tmp-" (temporary files left behind).
  int strayTemporaries() const {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(dir_)) {
      if (entry.path().filename().string().find(".tmp-") != std::string::npos) ++count;
    }
    return count;
  }
  fs::path dir_;
};

TEST_F(OutputFile, ReplacesARegularFileAndKeepsItsMode) {
  const fs::path out = dir_ / "model.json";
  write(out, "old");
  ASSERT_EQ(::chmod(out.c_str(), 0600), 0);
  ASSERT_TRUE(writeFileAtomically(out, "new").ok());
  EXPECT_EQ(read(out), "new");
  struct stat info {};
  ASSERT_EQ(::stat(out.c_str(), &info), 0);
  EXPECT_TRUE(S_ISREG(info.st_mode));
  EXPECT_EQ(info.st_mode & 07777, 0600u) << "a private file became readable by others";
  EXPECT_EQ(strayTemporaries(), 0);
}

// Before the tests that read inputs: a new file may reuse the inode of one they read.
TEST_F(OutputFile, APieceByPieceWriteAppearsOnlyOnCommit) {
  const fs::path out = dir_ / "run.mcap";
  write(out, "old");
  {
    AtomicFileWriter file;
    {
      const Status opened = file.open(out);
      ASSERT_TRUE(opened.ok()) << opened.errorText();
    }
    ASSERT_TRUE(file.write("first ").ok());
    ASSERT_TRUE(file.write("second").ok());
    EXPECT_EQ(read(out), "old") << "the file changed before the commit";
    EXPECT_EQ(strayTemporaries(), 1);
    ASSERT_TRUE(file.commit().ok());
  }
  EXPECT_EQ(read(out), "first second");
  EXPECT_EQ(strayTemporaries(), 0);
}

TEST_F(OutputFile, AnAbandonedPieceByPieceWriteLeavesTheOldFile) {
  const fs::path out = dir_ / "run.mcap";
  write(out, "old");
  {
    AtomicFileWriter file;
    {
      const Status opened = file.open(out);
      ASSERT_TRUE(opened.ok()) << opened.errorText();
    }
    ASSERT_TRUE(file.write("half a file").ok());
    file.abandon();
    EXPECT_FALSE(file.commit().ok()) << "a commit after abandon() succeeded";
  }
  {
    AtomicFileWriter dropped;  // destroyed without a commit: a cancelled export
    ASSERT_TRUE(dropped.open(dir_ / "new.mcap").ok());
    ASSERT_TRUE(dropped.write("part").ok());
  }
  EXPECT_EQ(read(out), "old");
  EXPECT_FALSE(fs::exists(dir_ / "new.mcap"));
  EXPECT_EQ(strayTemporaries(), 0);
}

TEST_F(OutputFile, AFifoIsWrittenAsAStreamAndStaysAFifo) {
  const fs::path fifo = dir_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = read(fifo); });
  const Status written = writeFileAtomically(fifo, "through the pipe\n");
  reader.join();
  EXPECT_TRUE(written.ok()) << written.errorText();
  EXPECT_EQ(received, "through the pipe\n");
  struct stat info {};
  ASSERT_EQ(::lstat(fifo.c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode)) << "the FIFO was replaced by a regular file";
  EXPECT_EQ(strayTemporaries(), 0);
}

// `--out /dev/null` as root once replaced the system's /dev/null with a regular file. A link to it
// in a private folder is the same target without risking the machine's own node.
TEST_F(OutputFile, ALinkToACharacterDeviceIsWrittenIntoNotReplaced) {
  const fs::path link = dir_ / "null";
  fs::create_symlink("/dev/null", link);
  ASSERT_TRUE(writeFileAtomically(link, "discarded").ok());
  EXPECT_TRUE(fs::is_symlink(link)) << "the link was replaced";
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_TRUE(checkWritable(link).ok());
  EXPECT_EQ(strayTemporaries(), 0);
}

TEST_F(OutputFile, ACharacterDeviceNodeStaysADevice) {
  if (::geteuid() != 0) GTEST_SKIP() << "making a device node needs root";
  const fs::path node = dir_ / "devnull";
  ASSERT_EQ(::mknod(node.c_str(), S_IFCHR | 0666, makedev(1, 3)), 0);
  ASSERT_TRUE(writeFileAtomically(node, "discarded").ok());
  EXPECT_TRUE(fs::is_character_file(node)) << "the device node became a regular file";
}

// The temporary file's name was predictable (FILE.tmp-PID-N) and opened without O_EXCL, so a link
// planted there was written through: the victim overwritten, the output a link to it.
TEST_F(OutputFile, ALinkPlantedAtATemporaryNameIsNeverWrittenThrough) {
  const fs::path out = dir_ / "out.csv";
  const fs::path victim = dir_ / "victim";
  write(victim, "precious");
  for (int i = 0; i < 2000; ++i) {
    fs::create_symlink(
        victim, out.string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(i));
  }
  ASSERT_TRUE(writeFileAtomically(out, "output").ok());
  EXPECT_EQ(read(victim), "precious");
  EXPECT_FALSE(fs::is_symlink(out));
  EXPECT_EQ(read(out), "output");
}

TEST_F(OutputFile, AnOrdinaryLinkIsReplacedNotFollowed) {
  const fs::path target = dir_ / "elsewhere";
  const fs::path link = dir_ / "out.json";
  write(target, "keep");
  fs::create_symlink(target, link);
  ASSERT_TRUE(writeFileAtomically(link, "new").ok());
  EXPECT_EQ(read(target), "keep");
  EXPECT_FALSE(fs::is_symlink(link));
  EXPECT_EQ(read(link), "new");
}

TEST_F(OutputFile, AFolderOrAnEmptyPathIsRefusedInWords) {
  const Status folder = writeFileAtomically(dir_, "x");
  ASSERT_FALSE(folder.ok());
  EXPECT_NE(folder.errorText().find("is a folder"), std::string::npos) << folder.errorText();
  EXPECT_EQ(folder.errorText().find("Success"), std::string::npos) << folder.errorText();
  const Status empty = writeFileAtomically("", "x");
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(empty.errorText().find("empty"), std::string::npos) << empty.errorText();
  EXPECT_FALSE(checkWritable(dir_).ok());
  EXPECT_TRUE(fs::is_directory(dir_));
}

TEST_F(OutputFile, AnOutputThatIsAnInputIsRefused) {
  const fs::path in = dir_ / "in.csv";
  write(in, "input");
  const fs::path alias = dir_ / "alias.csv";
  fs::create_hard_link(in, alias);
  const Status same = checkNotAnInput(alias, {dir_ / "other.csv", in});
  ASSERT_FALSE(same.ok());
  EXPECT_NE(same.errorText().find("is also an input"), std::string::npos) << same.errorText();
  EXPECT_TRUE(checkNotAnInput(dir_ / "new.csv", {in}).ok());

  guardInputFiles(true);
  ASSERT_TRUE(readFileText(in).ok());
  EXPECT_FALSE(checkWritable(alias).ok());
  EXPECT_FALSE(writeFileAtomically(in, "output").ok());
  EXPECT_EQ(read(in), "input");
  EXPECT_TRUE(writeFileAtomically(dir_ / "new.csv", "output").ok());
}

// Under a file-size limit the write fails (EFBIG once SIGXFSZ is ignored, as the command line
// does): the old file stays and no temporary file is left.
TEST_F(OutputFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  const fs::path out = dir_ / "big.csv";
  write(out, "old");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    struct rlimit limit {
      1000, 1000
    };
    ::setrlimit(RLIMIT_FSIZE, &limit);
    const Status written = writeFileAtomically(out, std::string(100000, 'x'));
    ::_exit(written.ok() ? 3 : 0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the write under the limit reported success";
  EXPECT_EQ(read(out), "old");
  EXPECT_EQ(strayTemporaries(), 0);
}

}  // namespace
}  // namespace tactile
