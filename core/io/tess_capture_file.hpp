// Tessellation captures as files (docs/FILE_FORMAT.md, "Tessellation captures"): the patterns one
// device's tessellator made (core/tess/tess_pattern.hpp) with the device that made them, so that a
// lecturer can draw another GPU's choices beside the one in front of them. `patchwork capture`
// writes them; `render --compare-device FILE` reads them; data/captures holds lavapipe's and an
// NVIDIA H200's for the notes' presets.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/tess/tess_pattern.hpp"

namespace pw {
inline namespace io {

struct TessCaptureFile {
    std::string device;  // VkPhysicalDeviceProperties::deviceName
    std::string driver;  // driver name and version as the device reports them
    std::string vulkan;  // the device's Vulkan API version, "1.3.255"
    std::vector<TessPattern> patterns;

    // The pattern of this set, or nullptr.
    const TessPattern* find(DomainKind kind, Spacing spacing, const DomainLevels& levels) const;
};

// The file's text (JSON; each point's coordinates as the shortest decimals that read back to the
// same float).
std::string writeTessCaptureFile(const TessCaptureFile& f);
// Reads a capture file's text; InputError naming `source` and the field on anything malformed
// (unknown domain, levels outside [0, 64], indices past the points, points outside the domain).
TessCaptureFile readTessCaptureFile(const std::string& text, const std::string& source);
TessCaptureFile loadTessCaptureFile(const std::filesystem::path& path);

}  // namespace io
}  // namespace pw
