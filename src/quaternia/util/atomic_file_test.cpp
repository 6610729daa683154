#include "quaternia/util/atomic_file.h"

#include <fcntl.h>
#include <grp.h>
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "quaternia/util/error.h"

namespace quaternia {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test, removed at the end.
class AtomicFileTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = ::testing::TempDir() + "quaternia_atomic_XXXXXX";
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string path(const std::string& name) const { return dir_ + "/" + name; }
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    static std::string contents(const std::string& file) {
        std::ifstream in(file, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

    std::string dir_;
};

TEST_F(AtomicFileTest, CommitProducesExactContent) {
    const std::string target = path("out.bin");
    {
        AtomicFile file(target);
        EXPECT_EQ(file.path(), target);
        EXPECT_EQ(file.temporaryPath().rfind(target + ".tmp-", 0), 0u) << file.temporaryPath();
        const std::string first = "hello, ";
        file.write(first.data(), first.size());
        file.write(std::vector<uint8_t>{'w', 0, 'r', 255, 'd'});
        EXPECT_FALSE(fs::exists(target)) << "nothing at the target before commit";
        file.commit();
        EXPECT_TRUE(file.temporaryPath().empty());
    }
    EXPECT_EQ(contents(target), std::string("hello, w\0r\xff"
                                            "d",
                                            12));
    EXPECT_EQ(listing(), std::vector<std::string>{"out.bin"});
}

TEST_F(AtomicFileTest, DestroyingWithoutCommitLeavesNothing) {
    {
        AtomicFile file(path("out.bin"));
        file.write("partial", 7);
        EXPECT_EQ(listing().size(), 1u) << "the temporary exists while writing";
    }
    EXPECT_TRUE(listing().empty());
}

TEST_F(AtomicFileTest, ExceptionDuringWorkLeavesNothing) {
    try {
        AtomicFile file(path("out.bin"));
        file.write("partial", 7);
        throw std::runtime_error("render failed");
    } catch (const std::runtime_error&) {
    }
    EXPECT_TRUE(listing().empty());
}

TEST_F(AtomicFileTest, MissingDirectoryThrowsUserErrorNamingThePath) {
    const std::string target = path("missing/out.png");
    try {
        AtomicFile file(target);
        FAIL() << "opened a file in a missing directory";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), target);
        EXPECT_EQ(std::string(e.what()),
                  "cannot write '" + target + "': No such file or directory");
    }
    EXPECT_THROW(writeFileAtomically(target, {1, 2, 3}), UserError);
    EXPECT_TRUE(listing().empty());
}

// Runs `check` in a child process without root's power to write anywhere (as user and group
// nobody when the tests run as root, as CI's do; as the caller otherwise) and returns its exit
// code.
int exitCodeWithoutRoot(const std::function<int()>& check) {
    const pid_t child = ::fork();
    if (child == 0) {
        if (::geteuid() == 0 &&
            (::setgroups(0, nullptr) != 0 || ::setgid(65534) != 0 || ::setuid(65534) != 0))
            ::_exit(90);
        ::_exit(check());
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 100 + WTERMSIG(status);
}

TEST_F(AtomicFileTest, UnwritableDirectoryThrowsUserError) {
    ASSERT_EQ(::chmod(dir_.c_str(), 0755), 0);  // nobody may look in, not write
    const std::string locked = path("locked");
    ASSERT_EQ(::mkdir(locked.c_str(), 0555), 0);
    const std::string target = locked + "/out.png";
    // 0: the right error; 1: opened; 2: another message.
    const int code = exitCodeWithoutRoot([&] {
        try {
            AtomicFile file(target);
            return 1;
        } catch (const UserError& e) {
            return e.key() == target && std::string(e.what()) ==
                                            "cannot write '" + target + "': Permission denied"
                       ? 0
                       : 2;
        }
    });
    EXPECT_EQ(code, 0) << "0: refused as it should be, 1: opened, 2: another message, 90: "
                          "could not drop root";
    EXPECT_TRUE(fs::is_empty(locked));
    ::chmod(locked.c_str(), 0700);
}

TEST_F(AtomicFileTest, DeviceTargetIsWrittenInPlaceNeverReplaced) {
    // /dev/null takes the bytes and stays the device; /dev/full refuses them with the reason.
    {
        AtomicFile sink("/dev/null");
        EXPECT_TRUE(sink.isDirect());
        EXPECT_EQ(sink.writePath(), "/dev/null");
        sink.write("bytes", 5);
        sink.commit();
    }
    struct stat device;
    ASSERT_EQ(::stat("/dev/null", &device), 0);
    EXPECT_TRUE(S_ISCHR(device.st_mode));
    try {
        AtomicFile full("/dev/full");
        full.write("bytes", 5);
        full.commit();
        FAIL() << "wrote to /dev/full";
    } catch (const UserError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write '/dev/full': No space left on device");
    }
    ASSERT_EQ(::stat("/dev/full", &device), 0);
    EXPECT_TRUE(S_ISCHR(device.st_mode));
}

TEST_F(AtomicFileTest, NamedPipeTargetIsWrittenThrough) {
    const std::string fifo = path("pipe");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string received;
    std::thread reader([&] {
        std::ifstream in(fifo, std::ios::binary);
        received.assign(std::istreambuf_iterator<char>(in), {});
    });
    {
        AtomicFile file(fifo);
        file.write("through the pipe", 16);
        file.commit();
    }
    reader.join();
    EXPECT_EQ(received, "through the pipe");
    struct stat status;
    ASSERT_EQ(::stat(fifo.c_str(), &status), 0);
    EXPECT_TRUE(S_ISFIFO(status.st_mode));
    EXPECT_EQ(listing(), std::vector<std::string>{"pipe"});
}

TEST_F(AtomicFileTest, StandardStreamFileIsWrittenInPlace) {
    // `-o /dev/stdout > out.png`, here through standard input so that the test's own output
    // stays where it is: the file the shell opened is written, /dev/stdin stays a link.
    const std::string target = path("stream.png");
    const int saved = ::dup(0);
    ASSERT_GE(saved, 0);
    const int fd = ::open(target.c_str(), O_RDWR | O_CREAT | O_TRUNC, 0644);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::dup2(fd, 0), 0);
    ::close(fd);
    bool direct = false;
    try {
        AtomicFile file("/dev/stdin");
        direct = file.isDirect();
        file.write("in place", 8);
        file.commit();
    } catch (...) {
        ::dup2(saved, 0);
        throw;
    }
    ::dup2(saved, 0);
    ::close(saved);
    EXPECT_TRUE(direct);
    EXPECT_EQ(contents(target), "in place");
    EXPECT_TRUE(fs::is_symlink("/dev/stdin"));
    EXPECT_EQ(listing(), std::vector<std::string>{"stream.png"});
}

TEST_F(AtomicFileTest, SymbolicLinkStaysALinkAndItsTargetIsReplaced) {
    fs::create_directory(path("renders"));
    const std::string target = path("renders/real.png");
    std::ofstream(target) << "old";
    fs::create_symlink("renders/real.png", path("latest.png"));
    {
        AtomicFile file(path("latest.png"));
        EXPECT_EQ(file.temporaryPath().rfind(fs::canonical(target).string() + ".tmp-", 0), 0u)
            << file.temporaryPath();
        file.write("new", 3);
        file.commit();
    }
    EXPECT_TRUE(fs::is_symlink(path("latest.png")));
    EXPECT_EQ(contents(target), "new");
    EXPECT_EQ(listing(), (std::vector<std::string>{"latest.png", "renders"}));
    // A dangling link is replaced by the file.
    fs::create_symlink("renders/missing.png", path("dangling.png"));
    writeFileAtomically(path("dangling.png"), {'x'});
    EXPECT_FALSE(fs::is_symlink(path("dangling.png")));
    EXPECT_EQ(contents(path("dangling.png")), "x");
}

TEST_F(AtomicFileTest, DirectoryAsTargetFailsAtOnce) {
    const std::string target = path("subdir");
    fs::create_directory(target);
    try {
        AtomicFile file(target);
        FAIL() << "opened a directory as a file";
    } catch (const UserError& e) {
        EXPECT_EQ(e.key(), target);
        EXPECT_EQ(std::string(e.what()), "cannot write '" + target + "': Is a directory");
    }
    EXPECT_THROW(AtomicFile(""), UserError);
}

TEST_F(AtomicFileTest, OverwriteKeepsOldContentUntilCommit) {
    const std::string target = path("image.png");
    writeFileAtomically(target, {'o', 'l', 'd'});
    ::chmod(target.c_str(), 0640);
    {
        AtomicFile file(target);
        file.write("new content", 11);
        EXPECT_EQ(contents(target), "old") << "old content while writing";
        file.commit();
    }
    EXPECT_EQ(contents(target), "new content");
    EXPECT_EQ(listing(), std::vector<std::string>{"image.png"});
    struct stat info;
    ASSERT_EQ(::stat(target.c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777, 0640u) << "the replaced file's mode is kept";

    {
        AtomicFile abandoned(target);
        abandoned.write("never", 5);
    }
    EXPECT_EQ(contents(target), "new content") << "an abandoned overwrite changes nothing";
    EXPECT_EQ(listing(), std::vector<std::string>{"image.png"});
}

TEST_F(AtomicFileTest, NewFileGetsTheUmaskMode) {
    const mode_t mask = ::umask(027);
    writeFileAtomically(path("a"), {1});
    ::umask(mask);
    struct stat info;
    ASSERT_EQ(::stat(path("a").c_str(), &info), 0);
    EXPECT_EQ(info.st_mode & 0777, 0640u);
}

TEST_F(AtomicFileTest, MovesKeepOneOwnerOfTheTemporary) {
    const std::string target = path("moved.bin");
    std::optional<AtomicFile> holder;
    {
        AtomicFile file(target);
        file.write("abc", 3);
        holder.emplace(std::move(file));
        EXPECT_TRUE(file.temporaryPath().empty());
        EXPECT_THROW(file.write("x", 1), std::logic_error);
    }
    EXPECT_EQ(listing().size(), 1u) << "the moved-from destructor removed nothing";
    AtomicFile other(path("other.bin"));
    other = std::move(*holder);  // discards other's temporary
    EXPECT_EQ(listing().size(), 1u);
    other.write("def", 3);
    other.commit();
    EXPECT_THROW(other.commit(), std::logic_error);
    EXPECT_EQ(contents(target), "abcdef");
    EXPECT_EQ(listing(), std::vector<std::string>{"moved.bin"});
}

TEST_F(AtomicFileTest, NonDurableCommitAndEmptyFile) {
    AtomicFile file(path("empty"));
    file.commit(false);
    EXPECT_EQ(contents(path("empty")), "");
    EXPECT_EQ(listing(), std::vector<std::string>{"empty"});
}

}  // namespace
}  // namespace quaternia
