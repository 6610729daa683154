// Writing a file whole or not at all. AtomicFile writes into a temporary file beside the target
// and renames it over the target on commit(); until then the old file (if any) is untouched, and
// if commit() is never reached the temporary is removed. Opening one before a long render makes
// an unwritable output path fail at once, not after the work.
//
// A target that exists and is neither a regular file nor a directory (a device such as
// /dev/stdout or /dev/null, a named pipe) cannot be replaced by a rename, and must not be: it
// is opened and written directly, and commit() only closes it. So is a regular file that is
// already this process's standard output (or input or error): `-o /dev/stdout > out.png`. A
// symbolic link is kept: the file it names is the one replaced.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace quaternia {

class AtomicFile {
  public:
    // Creates "<path>.tmp-XXXXXX" in the target's directory (or opens a device or pipe target
    // itself). Throws UserError(path, "cannot write '<path>': <reason>") when it cannot (no
    // such directory, no permission, ...).
    explicit AtomicFile(std::string path);
    // Removes the temporary unless committed. Never throws.
    ~AtomicFile();

    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    // The moved-from file is left empty: writing to or committing it throws std::logic_error.
    AtomicFile(AtomicFile&& other) noexcept;
    AtomicFile& operator=(AtomicFile&& other) noexcept;

    // Appends to the temporary. Throws UserError on a write error (disk full, ...).
    void write(const void* data, std::size_t size);
    void write(const std::vector<uint8_t>& bytes) { write(bytes.data(), bytes.size()); }

    // Closes the temporary and renames it over the target. With `durable` (the default) the
    // data is fsynced first and the directory after, so a crash leaves the old file or the
    // new one, never a truncated one. Throws UserError on failure (the temporary is then
    // removed by the destructor); a second commit() throws std::logic_error.
    void commit(bool durable = true);

    const std::string& path() const { return path_; }
    // The temporary's name; empty once committed or moved from, and for a device or pipe.
    const std::string& temporaryPath() const { return temporaryPath_; }
    // Whether the target is a device or pipe written in place (it cannot be read back).
    bool isDirect() const { return direct_; }
    // Where the bytes go until commit(): the temporary, or the device or pipe itself (for a
    // program given the path to write, such as ffmpeg).
    const std::string& writePath() const { return direct_ ? path_ : temporaryPath_; }

  private:
    void discard() noexcept;
    [[noreturn]] void fail(int error) const;

    std::string path_;
    std::string renamePath_;  // path_, or the file a symbolic link path_ names
    std::string temporaryPath_;
    int fd_ = -1;
    bool direct_ = false;  // a device or pipe, written in place
};

// Writes `bytes` to `path` through an AtomicFile. Throws UserError as AtomicFile does.
void writeFileAtomically(const std::string& path, const std::vector<uint8_t>& bytes);

}  // namespace quaternia
