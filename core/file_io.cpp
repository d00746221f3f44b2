#include "core/file_io.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>

#include "core/errors.hpp"
#include "core/limits.hpp"

namespace pw {

std::string readFileLimited(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw InputError(name, "no such file");
    if (std::filesystem::is_directory(path, ec)) throw InputError(name, "is a directory, not a file");
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(name, "cannot read: " + ec.message());
    if (size > limits::kMaxFileBytes)
        throw InputError(name, "file is " + std::to_string(size) + " bytes; the limit is " +
                                   std::to_string(limits::kMaxFileBytes));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(name, std::string("cannot open: ") + std::strerror(errno));
    std::string data(static_cast<size_t>(size), '\0');
    in.read(data.data(), static_cast<std::streamsize>(size));
    if (static_cast<size_t>(in.gcount()) != size) throw InputError(name, "cannot read the whole file");
    return data;
}

void writeFileAtomic(const std::filesystem::path& path, std::string_view data) {
    const std::string name = path.string();
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) throw OutputError(name, "directory " + dir.string() + " does not exist");
    if (std::filesystem::is_directory(path, ec)) throw OutputError(name, "is a directory");

    std::random_device rd;
    const std::filesystem::path tmp = dir / ("." + path.filename().string() + ".tmp" + std::to_string(rd() % 1000000));
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) throw OutputError(name, std::strerror(errno));
    auto fail = [&](const std::string& why) {
        ::close(fd);
        std::filesystem::remove(tmp, ec);
        throw OutputError(name, why);
    };
    size_t done = 0;
    while (done < data.size()) {
        const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(std::strerror(errno));
        }
        done += static_cast<size_t>(n);
    }
    if (::fsync(fd) != 0) fail(std::strerror(errno));
    if (::close(fd) != 0) {
        std::filesystem::remove(tmp, ec);
        throw OutputError(name, std::strerror(errno));
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::filesystem::remove(tmp, ec);
        throw OutputError(name, why);
    }
    // Make the rename itself durable.
    const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
}

std::string lowerExtension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

}  // namespace pw
