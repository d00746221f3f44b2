// The document's surface as the editor shows it, for exports "as displayed": the GPU tessellates
// it with the document's own levels, partitioning, adaptive mode, culling and camera in a view of
// the given size, and the triangles come back through transform feedback
// (render::Renderer::captureSurface), welded.
#pragma once

#include <array>
#include <memory>
#include <string>

#include "core/io/gltf_export.hpp"
#include "core/model/document.hpp"
#include "render/scene/renderer.hpp"

namespace pw::app {

struct DisplayedMeshRequest {
    std::array<int, 2> viewport{1280, 720};  // pixels: screen-space adaptive levels and the camera's aspect
    std::string device;                      // substring of the Vulkan device's name; empty = best available
    bool validation = false;
    std::shared_ptr<const HeightMap> map;  // the document's height map (displacement), or none
};

// The request a file exported as displayed asks for again: its stored viewport (when it has one)
// on the best device.
DisplayedMeshRequest displayedMeshRequest(const ExportOptions& stored);

// InputError (exit 2) when no device can capture (no Vulkan device, no transform feedback).
render::CapturedSurface captureDisplayedMesh(const Document& doc, const DisplayedMeshRequest& request, std::string* deviceName = nullptr);

// One line for the command line: "as displayed at 1280x720 on DEVICE: N triangles from the
// tessellator (M collapsed at poles left out), K patches culled".
std::string describeCapture(const render::CapturedSurface& c, const DisplayedMeshRequest& request, const std::string& deviceName);

}  // namespace pw::app
