#include "io/file_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "model/errors.hpp"

namespace sphjet {

namespace fs = std::filesystem;

namespace {

// Owns one POSIX file descriptor.
class Fd {
public:
    explicit Fd(int fd = -1) : fd_(fd) {}
    Fd(const Fd&) = delete;
    Fd& operator=(const Fd&) = delete;
    ~Fd() {
        if (fd_ >= 0) ::close(fd_);
    }
    [[nodiscard]] int get() const { return fd_; }
    // Closes now and returns close()'s errno (0 on success): close can report a write error.
    int close() {
        if (fd_ < 0) return 0;
        const int rc = ::close(std::exchange(fd_, -1));
        return rc == 0 ? 0 : errno;
    }

private:
    int fd_;
};

fs::path parent_of(const fs::path& p) {
    return p.has_parent_path() ? p.parent_path() : fs::path(".");
}

// Writes all of bytes at the current position (O_APPEND: the end); returns 0 or errno.
int write_all(int fd, std::string_view bytes) {
    const char* p = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (n == 0) return EIO;  // no progress and no errno: treat as an I/O error
        p += n;
        left -= static_cast<std::size_t>(n);
    }
    return 0;
}

// fsync of a directory, so that a rename in it survives a machine crash. Some file systems
// cannot fsync a directory (EINVAL, EBADF); the rename is still atomic there. Returns errno.
int sync_directory(const fs::path& dir) {
    Fd fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (fd.get() < 0) return errno == EACCES ? 0 : errno;  // cannot open: nothing to sync
    if (::fsync(fd.get()) != 0 && errno != EINVAL && errno != EBADF) return errno;
    return fd.close();
}

bool out_of_space(int err) { return err == ENOSPC || err == EDQUOT; }

}  // namespace

std::string human_bytes(std::uintmax_t n) {
    const double v = static_cast<double>(n);
    if (n < 1000) return fmt::format("{} B", n);
    if (v < 1e6) return fmt::format("{:.3g} kB", v / 1e3);
    if (v < 1e9) return fmt::format("{:.3g} MB", v / 1e6);
    return fmt::format("{:.3g} GB", v / 1e9);
}

void throw_write_error(const fs::path& path, std::string_view what, int err, std::uintmax_t bytes,
                       std::string_view detail) {
    std::string problem = fmt::format("cannot write {}", what);
    if (err != 0) problem += fmt::format(": {}", std::strerror(err));
    if (!detail.empty()) problem += fmt::format(" ({})", detail);
    std::string expected, found;
    if (out_of_space(err)) {
        expected = fmt::format("room for {} on the file system", human_bytes(bytes));
        struct statvfs vfs {};
        if (::statvfs(parent_of(path).c_str(), &vfs) == 0) {
            found = fmt::format("{} free", human_bytes(static_cast<std::uintmax_t>(vfs.f_bavail) *
                                                       vfs.f_frsize));
        } else {
            found = "less";
        }
    }
    throw WriteError(path.string(), err, problem, expected, found);
}

void write_file_atomically(const fs::path& path, std::string_view bytes, std::string_view what,
                           std::string_view tmp_suffix) {
    fs::path tmp = path;
    tmp += std::string(tmp_suffix);
    Fd fd(::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666));
    // Any failure below: remove the temporary file (closed first, so that its space is free
    // when the message counts it), keep `path` as it was, say why.
    const auto fail = [&](int err, std::string_view detail = {}) {
        fd.close();
        ::unlink(tmp.c_str());
        throw_write_error(path, what, err, bytes.size(), detail);
    };
    if (fd.get() < 0) {
        const int err = errno;
        if (err == ENOENT || err == ENOTDIR) {  // nothing was created: nothing to remove
            throw_write_error(path, what, err, bytes.size(), "the directory is missing");
        }
        fail(err, "cannot create " + tmp.filename().string());
    }
    if (const int err = write_all(fd.get(), bytes); err != 0) fail(err);
    // fsync: the data is on the disk before the rename makes it the file, and a write error
    // that the file system reports only at writeback (NFS, some quotas) surfaces here.
    if (::fsync(fd.get()) != 0 && errno != EINVAL) fail(errno);
    if (const int err = fd.close(); err != 0) fail(err);
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        fail(errno, "cannot rename " + tmp.filename().string() + " into place");
    }
    if (const int err = sync_directory(parent_of(path)); err != 0) {
        // The new file is in place and complete; only its durability is in doubt.
        throw_write_error(path, what, err, bytes.size(), "fsync of the directory failed");
    }
}

AppendFile::AppendFile(fs::path path, std::string what, bool keep, std::string_view header)
    : path_(std::move(path)), what_(std::move(what)) {
    const int flags = O_RDWR | O_CREAT | O_APPEND | O_CLOEXEC | (keep ? 0 : O_TRUNC);
    fd_ = ::open(path_.c_str(), flags, 0666);
    if (fd_ < 0) throw_write_error(path_, what_, errno, 0, "cannot open it for writing");
    struct stat sb {};
    if (::fstat(fd_, &sb) != 0) {
        const int err = errno;
        ::close(std::exchange(fd_, -1));
        throw_write_error(path_, what_, err, 0, "cannot stat it");
    }
    size_ = static_cast<std::uintmax_t>(sb.st_size);
    if (keep && size_ > 0) {
        // Cut off a last row without its newline: scan back to the last '\n'.
        char buf[4096];
        std::uintmax_t end = size_;
        std::uintmax_t keep_bytes = 0;
        bool found = false;
        while (end > 0 && !found) {
            const std::uintmax_t start = end > sizeof buf ? end - sizeof buf : 0;
            const auto len = static_cast<std::size_t>(end - start);
            const ssize_t n = ::pread(fd_, buf, len, static_cast<off_t>(start));
            if (n != static_cast<ssize_t>(len)) break;  // unreadable: keep the file as it is
            for (std::size_t i = len; i-- > 0;) {
                if (buf[i] == '\n') {
                    keep_bytes = start + i + 1;
                    found = true;
                    break;
                }
            }
            end = start;
            if (!found && end == 0) found = true;  // no newline at all: nothing whole to keep
        }
        if (found && keep_bytes < size_ && ::ftruncate(fd_, static_cast<off_t>(keep_bytes)) == 0) {
            size_ = keep_bytes;
        }
    }
    if (size_ == 0 && !header.empty()) {
        try {
            append(header);
        } catch (...) {
            ::close(std::exchange(fd_, -1));
            throw;
        }
    }
}

AppendFile::~AppendFile() {
    if (fd_ >= 0) ::close(fd_);
}

AppendFile::AppendFile(AppendFile&& o) noexcept
    : path_(std::move(o.path_)),
      what_(std::move(o.what_)),
      fd_(std::exchange(o.fd_, -1)),
      size_(o.size_) {}

AppendFile& AppendFile::operator=(AppendFile&& o) noexcept {
    if (this != &o) {
        if (fd_ >= 0) ::close(fd_);
        path_ = std::move(o.path_);
        what_ = std::move(o.what_);
        fd_ = std::exchange(o.fd_, -1);
        size_ = o.size_;
    }
    return *this;
}

void AppendFile::append(std::string_view text) {
    if (fd_ < 0) throw_write_error(path_, what_, EBADF, text.size(), "the file is not open");
    const int err = write_all(fd_, text);
    if (err == 0) {
        size_ += text.size();
        return;
    }
    // Part of the text may be in the file: cut it back to the last whole row. Shrinking a
    // file needs no space, so this works on a full disk.
    std::string detail;
    if (::ftruncate(fd_, static_cast<off_t>(size_)) != 0) {
        detail = fmt::format("and it could not be cut back to {} bytes: {}", size_,
                             std::strerror(errno));
    }
    throw_write_error(path_, what_, err, text.size(), detail);
}

std::vector<std::string> remove_temporaries(const fs::path& dir) noexcept {
    std::vector<std::string> removed;
    try {
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(dir, ec)) {
            const std::string name = e.path().filename().string();
            const bool tmp = name.ends_with(".tmp") || name.ends_with(".tmp-sphjet");
            if (!tmp || !e.is_regular_file(ec)) continue;
            if (fs::remove(e.path(), ec)) removed.push_back(name);
        }
    } catch (...) {
        // Out of memory or an unreadable directory: nothing more can be done here.
    }
    return removed;
}

}  // namespace sphjet
