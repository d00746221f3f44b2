// Camera maths shared by the renderer and the editor: view and projection matrices from pw::Camera
// (Vulkan clip space: y down, depth 0..1), named views, framing a bounding box, projecting points.
// Pure GLM, no Vulkan.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "core/model/document.hpp"

namespace pw {
inline namespace model {

struct ViewMatrices {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    glm::mat4 viewProj{1.0f};
    glm::vec3 eye{0.0f};
    glm::vec3 forward{0.0f, 0.0f, -1.0f};
};

// The eye position of an orbit camera: yaw around the up axis, pitch above the horizon. With yaw = 0
// and pitch = 0 the camera looks from the front (−y for z-up, +z for y-up) at the target.
glm::dvec3 cameraEye(const Camera& cam);

// View and projection for a viewport of `aspect` = width / height. Near and far planes follow the
// distance (near = distance / 1000, far = distance * 100) unless given.
ViewMatrices viewMatrices(const Camera& cam, double aspect, double nearPlane = 0.0, double farPlane = 0.0);

// Named views: front, back, left, right, top, bottom, iso. Sets yaw and pitch only.
std::optional<Camera> applyNamedView(Camera cam, std::string_view name);

// The orbit camera whose eye is at `eye` looking at `target` (yaw, pitch and distance set; the up
// axis, field of view and projection kept); nullopt when the two coincide.
std::optional<Camera> lookFrom(Camera cam, const glm::dvec3& eye, const glm::dvec3& target);

// Moves target and distance so that the box fills the view (margin > 1 leaves room around it).
Camera frameBounds(Camera cam, const Bounds& box, double aspect, double margin = 1.15);

// Aims the camera (same direction) at the middle of `points` as seen from it and moves it so that
// they just fit the view, `margin` (>= 1) times their extent: tighter than frameBounds' bounding
// sphere, for slides.
Camera frameTightly(Camera cam, const std::vector<glm::dvec3>& points, double aspect, double margin = 1.04);

// World point -> pixel coordinates (x right, y down, origin top-left) of a width x height image;
// nullopt when the point is behind the camera.
std::optional<glm::dvec2> projectToPixel(const ViewMatrices& vm, const glm::dvec3& p, int width, int height);

}  // namespace model
}  // namespace pw
