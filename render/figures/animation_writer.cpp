#include "render/figures/animation_writer.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/base/errors.hpp"
#include "core/base/file_io.hpp"

extern char** environ;

namespace pw::render {
inline namespace figures {

std::optional<AnimationFormat> animationFormatFor(const std::filesystem::path& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".gif") return AnimationFormat::Gif;
    if (ext == ".mp4") return AnimationFormat::Mp4;
    if (ext == ".webm") return AnimationFormat::Webm;
    return std::nullopt;
}

namespace {

// The encoder's options per format (after the raw RGBA input).
std::vector<std::string> encodeArgs(AnimationFormat f) {
    switch (f) {
        case AnimationFormat::Gif:  // one palette for the whole sweep, made from its frames
            return {"-filter_complex", "[0:v]split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=sierra2_4a", "-loop",
                    "0"};
        case AnimationFormat::Mp4:  // yuv420p needs even sizes: an odd last column or row is left out
            return {"-vf",       "crop=trunc(iw/2)*2:trunc(ih/2)*2:0:0",
                    "-c:v",      "libx264",
                    "-pix_fmt",  "yuv420p",
                    "-crf",      "18",
                    "-preset",   "medium",
                    "-movflags", "+faststart"};
        case AnimationFormat::Webm:
            return {"-vf",       "crop=trunc(iw/2)*2:trunc(ih/2)*2:0:0",
                    "-c:v",      "libvpx-vp9",
                    "-pix_fmt",  "yuv420p",
                    "-crf",      "30",
                    "-b:v",      "0",
                    "-deadline", "good",
                    "-cpu-used", "4",
                    "-row-mt",   "1"};
    }
    return {};
}

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string tailOf(const std::string& text, size_t lines) {
    size_t at = text.size();
    while (at > 0 && (text[at - 1] == '\n' || text[at - 1] == ' ')) --at;
    const size_t end = at;
    for (size_t n = 0; at > 0; --at)
        if (text[at - 1] == '\n' && ++n == lines) break;
    return text.substr(at, end - at);
}

}  // namespace

AnimationEncoder::AnimationEncoder(const std::filesystem::path& output, AnimationFormat format, uint32_t width, uint32_t height, double fps)
    : output_(output), width_(width), height_(height) {
    // A broken pipe (ffmpeg stopped early) is reported by write() and finish(), not a signal.
    std::signal(SIGPIPE, SIG_IGN);
    std::string tmpl = (std::filesystem::temp_directory_path() / "patchwork-animation-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) throw OutputError(output.string(), std::string("cannot make a temporary folder: ") + std::strerror(errno));
    dir_ = tmpl;
    const char* program = std::getenv("PATCHWORK_FFMPEG");
    const std::string ffmpeg = program && *program ? program : "ffmpeg";
    char rate[32];
    std::snprintf(rate, sizeof rate, "%.6g", fps);
    std::vector<std::string> args = {ffmpeg,
                                     "-hide_banner",
                                     "-nostdin",
                                     "-loglevel",
                                     "error",
                                     "-f",
                                     "rawvideo",
                                     "-pix_fmt",
                                     "rgba",
                                     "-video_size",
                                     std::to_string(width) + "x" + std::to_string(height),
                                     "-framerate",
                                     rate,
                                     "-i",
                                     "pipe:0"};
    for (std::string& a : encodeArgs(format)) args.push_back(std::move(a));
    args.push_back("-y");
    args.push_back(encodedFile().string());

    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
        std::filesystem::remove_all(dir_);
        throw OutputError(output.string(), std::string("cannot make a pipe: ") + std::strerror(errno));
    }
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, fds[0], 0);
    const std::string log = (dir_ / "ffmpeg.log").string();
    posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    const int rc = posix_spawnp(&child_, ffmpeg.c_str(), &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    close(fds[0]);
    pipe_ = fds[1];
    if (rc != 0) {
        child_ = -1;
        stop();
        throw OutputError(output.string(), "'" + ffmpeg + "' could not be started (" + std::strerror(rc) +
                                               "); GIF, MP4 and WebM animations are encoded by ffmpeg (Debian: apt install ffmpeg)");
    }
}

AnimationEncoder::~AnimationEncoder() { stop(); }

std::filesystem::path AnimationEncoder::encodedFile() const { return dir_ / ("out" + lowerExtension(output_)); }

void AnimationEncoder::stop() {
    if (pipe_ >= 0) close(pipe_);
    pipe_ = -1;
    if (child_ > 0) {
        kill(child_, SIGTERM);
        int status = 0;
        waitpid(child_, &status, 0);
    }
    child_ = -1;
    std::error_code ec;
    if (!dir_.empty()) std::filesystem::remove_all(dir_, ec);
    dir_.clear();
}

void AnimationEncoder::addFrame(const std::vector<uint8_t>& rgba) {
    if (rgba.size() != size_t(width_) * height_ * 4) throw std::logic_error("AnimationEncoder: frame size differs from the animation's");
    const uint8_t* p = rgba.data();
    size_t left = rgba.size();
    while (left > 0) {
        const ssize_t n = write(pipe_, p, left);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string log = slurp(dir_ / "ffmpeg.log");
            stop();
            throw OutputError(output_.string(), "ffmpeg stopped reading frames" + (log.empty() ? std::string() : ": " + tailOf(log, 3)));
        }
        p += n;
        left -= size_t(n);
    }
}

std::string AnimationEncoder::finish() {
    close(pipe_);
    pipe_ = -1;
    int status = 0;
    while (waitpid(child_, &status, 0) < 0 && errno == EINTR) {
    }
    child_ = -1;
    const std::string log = slurp(dir_ / "ffmpeg.log");
    const std::string bytes = slurp(encodedFile());
    stop();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || bytes.empty())
        throw OutputError(output_.string(),
                          "ffmpeg could not encode the animation" + (log.empty() ? std::string() : ": " + tailOf(log, 3)));
    return bytes;
}

}  // namespace figures
}  // namespace pw::render
