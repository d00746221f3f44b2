#include "core/base/file_io.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <random>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace pw {
inline namespace base {

namespace {
std::string fileKind(mode_t m);

// Opens `path` for reading as a regular file on a real file system, without blocking (a FIFO would
// wait for a writer) and checked on the opened descriptor (no swap between a check and the open):
// a device, FIFO, socket or directory, or a file of /proc or /sys (whose sizes say 0 or 4096 and
// whose reads never end, as /dev/zero's), is refused naming what it is.
int openRegular(const std::filesystem::path& path, struct stat& st) {
    const std::string name = path.string();
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        if (errno == ENOENT) throw InputError(name, "no such file");
        if (errno == EISDIR) throw InputError(name, "is a directory, not a file");
        throw InputError(name, std::string("cannot open: ") + std::strerror(errno));
    }
    struct statfs fs {};
    if (::fstat(fd, &st) != 0) {
        ::close(fd);
        throw InputError(name, std::string("cannot read: ") + std::strerror(errno));
    }
    if (!S_ISREG(st.st_mode)) {
        ::close(fd);
        throw InputError(name, S_ISDIR(st.st_mode) ? "is a directory, not a file"
                                                   : "is " + fileKind(st.st_mode) + "; Patchwork reads only regular files");
    }
    if (::fstatfs(fd, &fs) == 0 && (fs.f_type == 0x9fa0 /* proc */ || fs.f_type == 0x62656572 /* sysfs */)) {
        ::close(fd);
        throw InputError(name, "is a file of the kernel's /proc or /sys, not a document; Patchwork reads only regular files");
    }
    return fd;
}

// Reads up to `limit` bytes of an opened file.
std::string readUpTo(int fd, size_t limit, const std::string& name) {
    std::string data(limit, '\0');
    size_t done = 0;
    while (done < limit) {
        const ssize_t n = ::read(fd, data.data() + done, limit - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            ::close(fd);
            throw InputError(name, std::string("cannot read: ") + std::strerror(errno));
        }
        if (n == 0) break;
        done += size_t(n);
    }
    data.resize(done);
    return data;
}
}  // namespace

std::string readFileLimited(const std::filesystem::path& path, size_t maxBytes) {
    const std::string name = path.string();
    struct stat st {};
    const int fd = openRegular(path, st);
    const auto size = static_cast<unsigned long long>(st.st_size);
    if (size > maxBytes) {
        ::close(fd);
        throw InputError(name, "file is " + std::to_string(size) + " bytes; the limit is " + std::to_string(maxBytes));
    }
    std::string data = readUpTo(fd, size_t(size), name);
    ::close(fd);
    if (data.size() != size) throw InputError(name, "cannot read the whole file");
    return data;
}

FileStamp fileStamp(const std::filesystem::path& path) {
    struct stat st {};
    FileStamp f;
    if (::stat(path.c_str(), &st) != 0) return f;
    f.exists = true;
    f.mtimeNs = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
    f.size = static_cast<long long>(st.st_size);
    f.inode = static_cast<unsigned long long>(st.st_ino);
    f.device = static_cast<unsigned long long>(st.st_dev);
    return f;
}

std::string readFileHead(const std::filesystem::path& path, size_t bytes) {
    struct stat st {};
    const int fd = openRegular(path, st);
    std::string data = readUpTo(fd, bytes, path.string());
    ::close(fd);
    return data;
}

namespace {

std::string fileKind(mode_t m) {
    if (S_ISCHR(m)) return "a character device";
    if (S_ISBLK(m)) return "a block device";
    if (S_ISFIFO(m)) return "a FIFO";
    if (S_ISSOCK(m)) return "a socket";
    if (S_ISDIR(m)) return "a directory";
    return "not a regular file";
}

// A staged file is named ".<target>.tmp-<writer's pid>-<n>" beside its target. One whose writer is
// no longer running (killed in the middle of a save) is removed by the next write into that folder
// (issue 71): only regular files of ours with that exact form, whose pid no process has.
std::string tempName(const std::filesystem::path& target, unsigned n) {
    return "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(n);
}

void removeDeadWritersTemps(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::directory_iterator it(dir, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        const size_t at = name.rfind(".tmp-");
        if (name.empty() || name[0] != '.' || at == std::string::npos || at == 0) continue;
        const std::string tail = name.substr(at + 5);  // "<pid>-<n>"
        const size_t dash = tail.find('-');
        const auto digits = [](const std::string& d) {
            return !d.empty() && d.size() < 11 && std::all_of(d.begin(), d.end(), [](char c) { return c >= '0' && c <= '9'; });
        };
        if (dash == std::string::npos || !digits(tail.substr(0, dash)) || !digits(tail.substr(dash + 1))) continue;
        const long pid = std::stol(tail.substr(0, dash));
        if (pid <= 0 || pid > 0x7fffffffL || (::kill(pid_t(pid), 0) == 0 || errno != ESRCH)) continue;  // running (or not ours to ask)
        struct stat st {};
        if (::lstat(it->path().c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::getuid()) continue;
        std::error_code rm;
        std::filesystem::remove(it->path(), rm);
    }
}

bool writeAll(int fd, std::string_view data) {
    size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        done += static_cast<size_t>(n);
    }
    return true;
}

void syncDirectory(const std::filesystem::path& dir) {
    const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
}

}  // namespace

OutputTarget checkOutputPath(const std::filesystem::path& path) {
    const std::string name = path.string();
    OutputTarget t;
    t.requested = path;
    t.path = path;
    // Through symlinks to what they name (a link stays a link; a dangling one is refused).
    struct stat st {};
    if (::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
        std::error_code ec;
        t.path = std::filesystem::canonical(path, ec);
        if (ec) throw OutputError(name, "is a symbolic link to a file that does not exist (" + ec.message() + ")");
    }
    const std::filesystem::path dir = t.path.has_parent_path() ? t.path.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) throw OutputError(name, "directory " + dir.string() + " does not exist");
    if (::stat(t.path.c_str(), &st) == 0) {
        if (!S_ISREG(st.st_mode)) throw OutputError(name, "is " + fileKind(st.st_mode) + "; Patchwork writes only regular files");
        if ((st.st_mode & 0222) == 0) throw OutputError(name, "is read-only; make it writable or choose another name");
        t.exists = true;
        t.mode = st.st_mode & 07777;
        t.uid = st.st_uid;
        t.gid = st.st_gid;
    }
    if (::access(dir.c_str(), W_OK | X_OK) != 0) throw OutputError(name, "cannot write in " + dir.string() + ": " + std::strerror(errno));
    return t;
}

OutputBatch::~OutputBatch() {
    std::error_code ec;
    for (const Staged& s : staged_) std::filesystem::remove(s.temp, ec);
}

void OutputBatch::stage(const std::filesystem::path& path, std::string_view data) { stage(path, std::vector<std::string_view>{data}); }

void OutputBatch::stage(const std::filesystem::path& path, const std::vector<std::string_view>& pieces) {
    const OutputTarget t = checkOutputPath(path);
    const std::string name = path.string();
    const std::filesystem::path dir = t.path.has_parent_path() ? t.path.parent_path() : std::filesystem::path(".");
    removeDeadWritersTemps(dir);
    std::random_device rd;
    const std::filesystem::path tmp = dir / tempName(t.path, unsigned(rd() % 1000000));
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, t.exists ? 0600 : 0666);
    if (fd < 0) throw OutputError(name, std::strerror(errno));
    std::error_code ec;
    auto fail = [&](const std::string& why) {
        ::close(fd);
        std::filesystem::remove(tmp, ec);
        throw OutputError(name, why);
    };
    for (std::string_view data : pieces)
        if (!writeAll(fd, data)) fail(errno ? std::strerror(errno) : "short write");
    if (t.exists) {
        // Keep the old file's permissions and, where allowed, its owner.
        if (::fchown(fd, t.uid, t.gid) != 0) { /* not ours to give away: keep ours */
        }
        if (::fchmod(fd, t.mode) != 0) fail(std::string("cannot keep the permissions: ") + std::strerror(errno));
    }
    if (::fsync(fd) != 0) fail(std::strerror(errno));
    if (::close(fd) != 0) {
        std::filesystem::remove(tmp, ec);
        throw OutputError(name, std::strerror(errno));
    }
    staged_.push_back({t, tmp});
}

void OutputBatch::commit() {
    for (const Staged& s : staged_) {
        // A file with other hard links is replaced like any other: the other names keep the old
        // file. Rewriting it in place would keep them on it, but a kill in the middle left every
        // name empty (issue 73).
        if (::rename(s.temp.c_str(), s.target.path.c_str()) != 0) throw OutputError(s.target.requested.string(), std::strerror(errno));
        syncDirectory(s.target.path.has_parent_path() ? s.target.path.parent_path() : std::filesystem::path("."));
    }
    staged_.clear();
}

void writeFileAtomic(const std::filesystem::path& path, std::string_view data,
                     const std::function<void(const std::filesystem::path& staged)>& readBack) {
    writeFileAtomic(path, std::vector<std::string_view>{data}, readBack);
}

void writeFileAtomic(const std::filesystem::path& path, const std::vector<std::string_view>& pieces,
                     const std::function<void(const std::filesystem::path& staged)>& readBack, const std::function<void()>& written) {
    OutputBatch batch;
    batch.stage(path, pieces);
    if (written) written();
    if (readBack) {
        try {
            readBack(batch.lastStaged());
        } catch (const InputError& e) {
            throw OutputError(path.string(), "written, but it does not read back (" + e.reason() +
                                                 (e.line() > 0 ? " at line " + std::to_string(e.line()) : "") +
                                                 (e.field().empty() ? "" : " in " + e.field()) + "); nothing was replaced");
        }
    }
    batch.commit();
}

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace base
}  // namespace pw
