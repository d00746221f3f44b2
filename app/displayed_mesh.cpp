#include "app/displayed_mesh.hpp"

#include "render/targets/offscreen_target.hpp"
#include "render/vk/device.hpp"

namespace pw::app {

DisplayedMeshRequest displayedMeshRequest(const ExportOptions& stored) {
    DisplayedMeshRequest request;
    if (stored.viewport[0] > 0 && stored.viewport[1] > 0) request.viewport = stored.viewport;
    return request;
}

render::CapturedSurface captureDisplayedMesh(const Document& doc, const DisplayedMeshRequest& request, std::string* deviceName) {
    render::DeviceOptions dopt;
    dopt.name = request.device;
    dopt.validation = request.validation;
    render::Device dev(dopt);
    if (deviceName) *deviceName = dev.name();
    // Single-sampled: nothing is rasterised, the target only gives the view its size.
    render::OffscreenTarget target(dev, uint32_t(request.viewport[0]), uint32_t(request.viewport[1]), /*msaa=*/false);
    render::Renderer renderer(dev, target);
    renderer.setDocument(doc, request.map);
    return renderer.captureSurface(render::optionsFromDocument(doc));
}

std::string describeCapture(const render::CapturedSurface& c, const DisplayedMeshRequest& request, const std::string& deviceName) {
    std::string s = "as displayed at " + std::to_string(request.viewport[0]) + "x" + std::to_string(request.viewport[1]) + " on " +
                    deviceName + ": " + std::to_string(c.gpuTriangles) + " triangles from the tessellator";
    if (c.degenerate) s += " (" + std::to_string(c.degenerate) + " collapsed at poles left out)";
    if (c.patchesCulled) s += ", " + std::to_string(c.patchesCulled) + " patches culled as on screen";
    if (request.map) s += ", displaced by " + request.map->source;
    return s;
}

}  // namespace pw::app
