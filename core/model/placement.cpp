#include "core/model/placement.hpp"

#include <algorithm>
#include <vector>

namespace pw {
inline namespace model {

namespace {

bool overlaps(const Bounds& a, const Bounds& b) {
    for (int k = 0; k < 3; ++k)
        if (a.max[k] < b.min[k] || b.max[k] < a.min[k]) return false;
    return true;
}

// Boxes of the items whose points all come before `firstNew` (the older items).
std::vector<Bounds> olderItemBoxes(const Document& doc, size_t firstNew) {
    std::vector<Bounds> boxes;
    auto add = [&](const auto& idx) {
        std::vector<Vec3> pts;
        for (uint32_t i : idx) {
            if (i >= firstNew) return;
            pts.push_back(doc.points[i]);
        }
        boxes.push_back(computeBounds(pts));
    };
    for (const auto& p : doc.patches) add(p.idx);
    for (const auto& s : doc.surfaces) add(s.idx);
    for (const auto& t : doc.triangles) add(t.idx);
    for (const auto& c : doc.curves) add(c.idx);
    return boxes;
}

}  // namespace

Vec3 moveClearOfExisting(Document& doc, size_t firstNewPoint) {
    if (firstNewPoint >= doc.points.size()) return Vec3(0.0);
    const std::vector<Vec3> fresh(doc.points.begin() + std::ptrdiff_t(firstNewPoint), doc.points.end());
    Bounds box = computeBounds(fresh);
    const std::vector<Bounds> older = olderItemBoxes(doc, firstNewPoint);
    const double width = std::max(box.max.x - box.min.x, 1e-9);
    const double gap = std::max(0.1 * width, 1e-6);
    Vec3 move(0.0);
    // Each step clears the rightmost box it overlaps, so this ends within older.size() steps.
    for (size_t step = 0; step <= older.size(); ++step) {
        double clearX = -1e300;
        for (const Bounds& b : older)
            if (!b.empty && overlaps(box, b)) clearX = std::max(clearX, b.max.x + gap);
        if (clearX == -1e300) break;
        const double dx = clearX - box.min.x;
        move.x += dx;
        box.min.x += dx;
        box.max.x += dx;
    }
    if (move.x != 0.0)
        for (size_t i = firstNewPoint; i < doc.points.size(); ++i) doc.points[i] += move;
    return move;
}

}  // namespace model
}  // namespace pw
