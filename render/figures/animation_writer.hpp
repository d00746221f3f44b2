// Animations for slides: RGBA frames encoded as GIF (palette made from the frames, loops forever),
// MP4 (H.264, yuv420p, plays in PowerPoint, Keynote and browsers) or WebM (VP9) by Debian's
// `ffmpeg` program (PATCHWORK_FFMPEG names another), fed through a pipe. The file is made in a
// private temporary folder and handed back as bytes, so the caller writes it atomically (an
// OutputBatch): a failed encode leaves nothing behind and whatever was at the path untouched.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pw::render {
inline namespace figures {

enum class AnimationFormat { Gif, Mp4, Webm };

// GIF, MP4 or WebM by the name's extension (any case); nothing for other names.
std::optional<AnimationFormat> animationFormatFor(const std::filesystem::path& path);

class AnimationEncoder {
public:
    // Starts ffmpeg for `width` x `height` frames at `fps`; `output` names the file in messages.
    // Throws OutputError naming `output` when ffmpeg cannot be started.
    AnimationEncoder(const std::filesystem::path& output, AnimationFormat format, uint32_t width, uint32_t height, double fps);
    ~AnimationEncoder();  // an unfinished encode is stopped and its files removed
    AnimationEncoder(const AnimationEncoder&) = delete;
    AnimationEncoder& operator=(const AnimationEncoder&) = delete;

    // One frame, width x height RGBA8, top row first.
    void addFrame(const std::vector<uint8_t>& rgba);
    // Ends the stream and returns the encoded file; throws OutputError with ffmpeg's message.
    std::string finish();

private:
    void stop();
    std::filesystem::path encodedFile() const;  // ffmpeg's output in the temporary folder
    std::filesystem::path output_, dir_;
    uint32_t width_, height_;
    int pipe_ = -1;
    pid_t child_ = -1;
};

}  // namespace figures
}  // namespace pw::render
