#include "quaternia/util/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "quaternia/util/error.h"

namespace quaternia {

namespace {

// The process's umask without changing it (umask() can only be read by setting it, which
// would race with other threads creating files): Linux reports it in /proc/self/status.
mode_t currentUmask() {
    mode_t mask = 022;
    if (FILE* status = std::fopen("/proc/self/status", "re")) {
        char line[256];
        while (std::fgets(line, sizeof line, status)) {
            unsigned value;
            if (std::sscanf(line, "Umask: %o", &value) == 1) {
                mask = mode_t(value);
                break;
            }
        }
        std::fclose(status);
    }
    return mask;
}

// mkstemp creates the temporary readable by its owner only; the result should get the mode a
// plainly created file would (0666 less the umask), or keep the mode of the file it replaces.
mode_t targetMode(const struct stat* existing) {
    if (existing) return existing->st_mode & 07777;
    return 0666 & ~currentUmask();
}

std::string directoryOf(const std::string& path) {
    size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

// Makes the rename itself durable. Best effort: some file systems refuse fsync on directories.
void syncDirectory(const std::string& directory) {
    int fd = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

// A regular file that is this process's standard input, output or error: the shell opened it
// (`-o /dev/stdout > out.png`), and a rename would leave the shell's descriptor on the old file
// (and, through /dev/stdout, replace the system's link with a file).
bool isStandardStream(const struct stat& file) {
    for (int fd = 0; fd <= 2; ++fd) {
        struct stat stream;
        if (::fstat(fd, &stream) == 0 && stream.st_dev == file.st_dev &&
            stream.st_ino == file.st_ino)
            return true;
    }
    return false;
}

// A symbolic link stays one: the temporary goes beside the file it names, and replaces that. A
// dangling link is replaced itself.
std::string linkTarget(const std::string& path) {
    struct stat link;
    if (::lstat(path.c_str(), &link) != 0 || !S_ISLNK(link.st_mode)) return path;
    std::unique_ptr<char, decltype(&std::free)> target(::realpath(path.c_str(), nullptr),
                                                       &std::free);
    return target ? std::string(target.get()) : path;
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
    if (path_.empty()) throw UserError(path_, "cannot write '': the path is empty");
    struct stat existing;
    const bool exists = ::stat(path_.c_str(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode)) fail(EISDIR);
    if (exists && (!S_ISREG(existing.st_mode) || isStandardStream(existing))) {
        fd_ = ::open(path_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
        if (fd_ < 0) fail(errno);
        direct_ = true;
        return;
    }
    renamePath_ = linkTarget(path_);

    std::string name = renamePath_ + ".tmp-XXXXXX";
    fd_ = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd_ < 0) fail(errno);
    temporaryPath_ = std::move(name);
    ::fchmod(fd_, targetMode(exists && S_ISREG(existing.st_mode) ? &existing : nullptr));
}

AtomicFile::~AtomicFile() {
    discard();
}

AtomicFile::AtomicFile(AtomicFile&& other) noexcept
    : path_(std::move(other.path_)),
      renamePath_(std::move(other.renamePath_)),
      temporaryPath_(std::exchange(other.temporaryPath_, {})),
      fd_(std::exchange(other.fd_, -1)),
      direct_(other.direct_) {}

AtomicFile& AtomicFile::operator=(AtomicFile&& other) noexcept {
    if (this != &other) {
        discard();
        path_ = std::move(other.path_);
        renamePath_ = std::move(other.renamePath_);
        temporaryPath_ = std::exchange(other.temporaryPath_, {});
        fd_ = std::exchange(other.fd_, -1);
        direct_ = other.direct_;
    }
    return *this;
}

void AtomicFile::discard() noexcept {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!temporaryPath_.empty()) ::unlink(temporaryPath_.c_str());
    temporaryPath_.clear();
}

void AtomicFile::fail(int error) const {
    throw UserError(path_,
                    "cannot write '" + path_ + "': " + std::generic_category().message(error));
}

void AtomicFile::write(const void* data, size_t size) {
    if (fd_ < 0) throw std::logic_error("AtomicFile::write after commit or move");
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
        ssize_t written = ::write(fd_, bytes, size);
        if (written < 0) {
            if (errno == EINTR) continue;
            fail(errno);
        }
        bytes += written;
        size -= size_t(written);
    }
}

void AtomicFile::commit(bool durable) {
    if (fd_ < 0) throw std::logic_error("AtomicFile::commit after commit or move");
    // Devices and pipes cannot be synced (EINVAL); what they were given is theirs.
    if (durable && ::fsync(fd_) != 0 && errno != EINVAL) fail(errno);
    // Linux closes the descriptor even when close() fails, so it is never retried; EINTR is
    // not a failure of the data.
    int closed = ::close(fd_);
    fd_ = -1;
    if (closed != 0 && errno != EINTR) fail(errno);
    if (direct_) return;
    if (::rename(temporaryPath_.c_str(), renamePath_.c_str()) != 0) fail(errno);
    temporaryPath_.clear();
    if (durable) syncDirectory(directoryOf(renamePath_));
}

void writeFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes) {
    AtomicFile file(path);
    file.write(bytes);
    file.commit();
}

}  // namespace quaternia
