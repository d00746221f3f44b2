#include "core/model/camera_math.hpp"

#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

namespace pw {
inline namespace model {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Orbit direction (target -> eye) and up vector in a z-up frame.
void orbitFrame(const Camera& cam, glm::dvec3& dir, glm::dvec3& up) {
    const double yaw = cam.yawDeg * kPi / 180.0, pitch = cam.pitchDeg * kPi / 180.0;
    dir = {std::cos(pitch) * std::sin(yaw), -std::cos(pitch) * std::cos(yaw), std::sin(pitch)};
    up = {-std::sin(pitch) * std::sin(yaw), std::sin(pitch) * std::cos(yaw), std::cos(pitch)};
    if (!cam.zUp) {  // y-up world: (x, y, z)_zup -> (x, z, -y)
        dir = {dir.x, dir.z, -dir.y};
        up = {up.x, up.z, -up.y};
    }
}

}  // namespace

glm::dvec3 cameraEye(const Camera& cam) {
    glm::dvec3 dir, up;
    orbitFrame(cam, dir, up);
    const glm::dvec3 target{cam.target[0], cam.target[1], cam.target[2]};
    return target + dir * cam.distance;
}

std::optional<Camera> lookFrom(Camera cam, const glm::dvec3& eye, const glm::dvec3& target) {
    glm::dvec3 d = eye - target;
    const double dist = glm::length(d);
    if (!(dist > 1e-12) || !std::isfinite(dist)) return std::nullopt;
    d /= dist;
    if (!cam.zUp) d = {d.x, -d.z, d.y};  // y-up world -> the z-up frame the angles are in
    cam.target = {target.x, target.y, target.z};
    cam.distance = dist;
    cam.pitchDeg = std::asin(std::clamp(d.z, -1.0, 1.0)) * 180.0 / kPi;
    cam.yawDeg = std::abs(d.z) > 1.0 - 1e-12 ? cam.yawDeg : std::atan2(d.x, -d.y) * 180.0 / kPi;
    return cam;
}

ViewMatrices viewMatrices(const Camera& cam, double aspect, double nearPlane, double farPlane) {
    glm::dvec3 dir, up;
    orbitFrame(cam, dir, up);
    const glm::dvec3 target{cam.target[0], cam.target[1], cam.target[2]};
    const double dist = std::max(cam.distance, 1e-9);
    const glm::dvec3 eye = target + dir * dist;
    if (nearPlane <= 0.0) nearPlane = dist / 1000.0;
    if (farPlane <= nearPlane) farPlane = dist * 100.0;

    ViewMatrices vm;
    const glm::dmat4 view = glm::lookAtRH(eye, target, up);
    glm::dmat4 proj;
    if (cam.orthographic) {
        const double h = dist * std::tan(cam.fovYDeg * kPi / 360.0);
        proj = glm::orthoRH_ZO(-h * aspect, h * aspect, -h, h, 0.0, farPlane);
    } else {
        proj = glm::perspectiveRH_ZO(cam.fovYDeg * kPi / 180.0, aspect, nearPlane, farPlane);
    }
    proj[1][1] *= -1.0;  // Vulkan: y points down in clip space
    vm.view = glm::mat4(view);
    vm.proj = glm::mat4(proj);
    vm.viewProj = glm::mat4(proj * view);
    vm.eye = glm::vec3(eye);
    vm.forward = glm::vec3(glm::normalize(target - eye));
    return vm;
}

std::optional<Camera> applyNamedView(Camera cam, std::string_view name) {
    if (name == "front") {
        cam.yawDeg = 0;
        cam.pitchDeg = 0;
    } else if (name == "back") {
        cam.yawDeg = 180;
        cam.pitchDeg = 0;
    } else if (name == "right") {
        cam.yawDeg = 90;
        cam.pitchDeg = 0;
    } else if (name == "left") {
        cam.yawDeg = -90;
        cam.pitchDeg = 0;
    } else if (name == "top") {
        cam.yawDeg = 0;
        cam.pitchDeg = 90;
    } else if (name == "bottom") {
        cam.yawDeg = 0;
        cam.pitchDeg = -90;
    } else if (name == "iso") {
        cam.yawDeg = 45;
        cam.pitchDeg = 35.264389682754654;
    } else
        return std::nullopt;
    return cam;
}

Camera frameBounds(Camera cam, const Bounds& box, double aspect, double margin) {
    if (box.empty) return cam;
    const glm::dvec3 c = (box.min + box.max) * 0.5;
    cam.target = {c.x, c.y, c.z};
    const double radius = std::max(0.5 * box.diagonal(), 1e-9);
    const double halfFov = cam.fovYDeg * kPi / 360.0;
    const double halfFovX = std::atan(std::tan(halfFov) * std::max(aspect, 1e-6));
    const double s = std::sin(std::min(halfFov, halfFovX));
    cam.distance = radius * margin / std::max(s, 1e-6);
    if (cam.orthographic) cam.distance = radius * margin / std::max(std::tan(std::min(halfFov, halfFovX)), 1e-6);
    return cam;
}

Camera frameTightly(Camera cam, const std::vector<glm::dvec3>& points, double aspect, double margin) {
    if (points.empty()) return cam;
    glm::dvec3 dir, up;
    orbitFrame(cam, dir, up);  // dir: target -> eye
    const glm::dvec3 fwd = -dir, right = glm::normalize(glm::cross(fwd, up));
    const double tanY = std::tan(cam.fovYDeg * kPi / 360.0) / margin, tanX = tanY * std::max(aspect, 1e-6);
    glm::dvec3 centroid(0.0);
    for (const glm::dvec3& p : points) centroid += p / double(points.size());
    if (cam.orthographic) {  // the extent across the view, centred; the distance sets the size
        double aMin = 1e300, aMax = -1e300, bMin = 1e300, bMax = -1e300;
        for (const glm::dvec3& p : points) {
            aMin = std::min(aMin, glm::dot(p - centroid, right)), aMax = std::max(aMax, glm::dot(p - centroid, right));
            bMin = std::min(bMin, glm::dot(p - centroid, up)), bMax = std::max(bMax, glm::dot(p - centroid, up));
        }
        const glm::dvec3 t = centroid + right * (0.5 * (aMin + aMax)) + up * (0.5 * (bMin + bMax));
        cam.target = {t.x, t.y, t.z};
        cam.distance = std::max({0.5 * (bMax - bMin) / tanY, 0.5 * (aMax - aMin) / tanX, 1e-9});
        return cam;
    }
    // Perspective: each side of the frustum touches the point furthest out on that side. With the
    // eye at e (coordinates er, eu, ef along right, up, forward), a point p is inside the right
    // side when p·r − tanX p·f <= er − tanX ef; the tight eye solves the two sides of each axis
    // and takes the axis that needs it further back (the other is then centred).
    double R = -1e300, L = -1e300, U = -1e300, D = -1e300;
    for (const glm::dvec3& p : points) {
        const double pr = glm::dot(p, right), pu = glm::dot(p, up), pf = glm::dot(p, fwd);
        R = std::max(R, pr - tanX * pf), L = std::max(L, -pr - tanX * pf);
        U = std::max(U, pu - tanY * pf), D = std::max(D, -pu - tanY * pf);
    }
    const double er = 0.5 * (R - L), eu = 0.5 * (U - D);
    const double ef = std::min(-(R + L) / (2.0 * tanX), -(U + D) / (2.0 * tanY));
    const glm::dvec3 eye = right * er + up * eu + fwd * ef;
    const double depth = std::max(glm::dot(centroid - eye, fwd), 1e-9);
    const glm::dvec3 t = eye + fwd * depth;
    cam.target = {t.x, t.y, t.z};
    cam.distance = depth;
    return cam;
}

std::optional<glm::dvec2> projectToPixel(const ViewMatrices& vm, const glm::dvec3& p, int width, int height) {
    const glm::dvec4 c = glm::dmat4(vm.viewProj) * glm::dvec4(p, 1.0);
    if (c.w <= 1e-12) return std::nullopt;
    const double x = c.x / c.w, y = c.y / c.w;
    return glm::dvec2((x * 0.5 + 0.5) * width, (y * 0.5 + 0.5) * height);
}

}  // namespace model
}  // namespace pw
