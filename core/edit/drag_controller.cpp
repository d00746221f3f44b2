// Transforms with the joins held: the mouse projected onto the drag plane or axis, turned into an
// angle or a factor about the pivot, typed values and snapping; and held point edits
// (core/edit/drag_controller.hpp).
#include "core/edit/drag_controller.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "core/base/limits.hpp"
#include "core/base/point_upload.hpp"
#include "core/construct/constructions.hpp"
#include "core/edit/live_constructions.hpp"
#include "core/edit/live_trims.hpp"
#include "core/model/camera_math.hpp"
#include "core/ops/fitted_sides.hpp"
#include "core/select/picking.hpp"
#include "core/trim/trim_edits.hpp"

namespace pw {
inline namespace edit {

namespace {

Vec3 axisVector(int axis) {
    Vec3 a(0.0);
    a[axis] = 1.0;
    return a;
}

// The fastest an axis drag may go, in multiples of a drag in the view plane: an axis that points
// nearly along the view would otherwise turn a few pixels into a jump to the horizon.
constexpr double kMaxAxisRate = 4.0;

double wrapAngle(double a) {
    while (a > M_PI) a -= 2.0 * M_PI;
    while (a <= -M_PI) a += 2.0 * M_PI;
    return a;
}

const char* kindName(TransformKind k) { return k == TransformKind::Move ? "Move" : k == TransformKind::Rotate ? "Rotate" : "Scale"; }

// Where `p` shows in the view's pixels (nullopt behind the eye).
std::optional<glm::dvec2> pixelOf(const DragView& view, const Vec3& p) {
    return projectToPixel(viewMatrices(view.camera, double(view.width) / std::max(view.height, 1)), p, view.width, view.height);
}

}  // namespace

bool DragController::begin(const Document& doc, const Selection& sel, const DragView& view, double x, double y, bool grab) {
    return begin(doc, TransformStart{sel.points, selectionCentroid(doc, Selection{.points = sel.points}), TransformKind::Move, grab}, view,
                 x, y);
}

bool DragController::begin(const Document& doc, const TransformStart& start, const DragView& view, double x, double y) {
    *this = DragController{};
    if (start.points.empty()) return false;
    if (std::string why = constructedPointsRefusal(doc, start.points); !why.empty()) {
        refusal_ = std::move(why);
        return false;
    }
    snapTarget_ = start.snap;
    kind_ = start.kind;
    grab_ = start.grab;
    start_ = doc.points;
    uploaded_ = doc.points;
    moved_ = start.points;
    symmetry_ = start.symmetry;
    soft_ = start.soft;
    setUp(doc);
    anchor_ = start.pivot;
    Vec3 r, u, f;
    cameraAxes(view.camera, r, u, f);
    planeNormal_ = f;
    startX_ = x;
    startY_ = y;
    const Ray ray = rayThroughPixel(view.camera, x, y, view.width, view.height);
    startHit_ = intersectPlane(ray, anchor_, f).value_or(anchor_);
    const auto c = pixelOf(view, anchor_);
    prevMouseAngle_ = c ? std::atan2(y - c->y, x - c->x) : 0.0;
    return true;
}

void DragController::setAxis(int axis, bool plane) {
    axis_ = axis < 0 || axis > 2 ? -1 : axis;
    plane_ = axis_ >= 0 && plane;
    slide_.reset();
}

bool DragController::toggleSlide(const Document& doc, SlideAxis axis) {
    if (!active() || kind_ != TransformKind::Move) return false;
    if (slide_ == axis) {
        slide_.reset();
        return true;
    }
    Document at = doc;
    at.points = start_;  // the directions of the shape as it was
    std::vector<Vec3> dirs(start_.size(), Vec3(0.0));
    Vec3 sum(0.0);
    for (uint32_t p : moved_) {
        const std::optional<Vec3> d = slideDirection(at, p, axis);
        if (!d) {
            refusal_ = slideRefusal(p);
            return false;
        }
        dirs[p] = *d;
        sum += *d;
    }
    for (uint32_t p : softPoints_.points) dirs[p] = slideDirection(at, p, axis).value_or(Vec3(0.0));
    // The mouse follows the mean direction; where the directions cancel (a ring), the first one.
    slideMean_ = glm::length(sum) > 1e-9 * double(moved_.size()) ? glm::normalize(sum) : dirs[moved_.front()];
    slideDirs_ = std::move(dirs);
    slide_ = axis;
    axis_ = -1;
    plane_ = false;
    refusal_.clear();
    return true;
}

void DragController::toggleAxis(int axis, bool plane) {
    if (axis_ == axis && plane_ == plane)
        setAxis(-1);
    else
        setAxis(axis, plane);
}

void DragController::typeChar(char c) {
    if ((c >= '0' && c <= '9') || c == '.' || (c == '-' && typed_.empty()))
        typed_ += c;
    else if (c == '-' && typed_ == "-")
        typed_.clear();
}

void DragController::backspace() {
    if (!typed_.empty()) typed_.pop_back();
}

std::optional<double> DragController::typedValue() const {
    if (typed_.empty() || typed_ == "-" || typed_ == "." || typed_ == "-.") return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(typed_.c_str(), &end);
    if (end != typed_.c_str() + typed_.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<Vec3> DragController::moveOffset(const Document& doc, const DragView& view, double x, double y, bool snap) const {
    // The offset a constraint allows of a free offset d.
    const auto constrain = [&](Vec3 d) {
        if (axis_ < 0) return d;
        const Vec3 a = axisVector(axis_);
        return plane_ ? d - a * glm::dot(d, a) : a * glm::dot(d, a);
    };
    if (const auto v = typedValue()) return slide_ ? slideMean_ * *v : axisVector(axis_ < 0 ? 0 : plane_ ? (axis_ + 1) % 3 : axis_) * *v;
    if (snap && snapTarget_ != SnapTarget::Grid && !slide_) {
        const auto target = snapPoint(doc, movedMask_, snapTarget_, view.camera, view.width, view.height, x, y);
        if (target) return constrain(*target - anchor_);
    }
    const Ray ray = rayThroughPixel(view.camera, x, y, view.width, view.height);
    const Ray r0 = rayThroughPixel(view.camera, startX_, startY_, view.width, view.height);
    Vec3 delta(0.0);
    const auto viewPlaneDelta = [&]() -> std::optional<Vec3> {
        const auto hit = intersectPlane(ray, anchor_, planeNormal_);
        if (!hit) return std::nullopt;
        return *hit - startHit_;
    };
    // Along direction a under the mouse, exactly, while it shows on screen; a direction nearly
    // along the view moves at most kMaxAxisRate times as fast as a move in the view plane.
    const auto alongDirection = [&](const Vec3& a) -> std::optional<Vec3> {
        const auto screen = axisOnScreen(view.camera, view.width, view.height, anchor_, a);
        if (!screen) return std::nullopt;
        const glm::dvec2 s = screen->alongPx;
        const double perUnit = screen->acrossPx;
        if (glm::length(s) >= perUnit / kMaxAxisRate) return closestPointOnAxis(ray, anchor_, a) - closestPointOnAxis(r0, anchor_, a);
        Vec3 right, up, fwd;
        cameraAxes(view.camera, right, up, fwd);
        glm::dvec2 dir = glm::length(s) > 1e-9 * perUnit ? s / glm::length(s) : glm::dvec2(0.0, glm::dot(a, fwd) < 0.0 ? -1.0 : 1.0);
        return a * (glm::dot(glm::dvec2(x - startX_, y - startY_), dir) * kMaxAxisRate / std::max(perUnit, 1e-300));
    };
    if (slide_) {
        const auto d = alongDirection(slideMean_);
        if (!d) return std::nullopt;
        double dist = glm::dot(*d, slideMean_);
        if (snap) {
            const double step = niceGridStep(modelSize(doc)) / 5.0;
            dist = step * std::round(dist / step);
        }
        return slideMean_ * dist;
    }
    if (axis_ < 0) {
        const auto d = viewPlaneDelta();
        if (!d) return std::nullopt;
        delta = *d;
    } else if (plane_) {
        const Vec3 n = axisVector(axis_);
        const auto a = intersectPlane(ray, anchor_, n), b = intersectPlane(r0, anchor_, n);
        if (std::abs(glm::dot(n, planeNormal_)) > 0.2 && a && b) {
            delta = *a - *b;
        } else {  // the plane is seen edge-on: the view-plane move, flattened into it
            const auto d = viewPlaneDelta();
            if (!d) return std::nullopt;
            delta = constrain(*d);
        }
    } else {
        const auto d = alongDirection(axisVector(axis_));
        if (!d) return std::nullopt;
        delta = *d;
    }
    if (snap && snapTarget_ == SnapTarget::Grid) {  // the moved centre on the grid
        const Vec3 snapped = snapToGrid(anchor_ + delta, niceGridStep(modelSize(doc)) / 5.0);
        delta = constrain(snapped - anchor_) + (delta - constrain(delta));
    }
    return delta;
}

bool DragController::update(Document& doc, const DragView& view, double x, double y, bool snap) {
    if (!active()) return false;
    doc.points = start_;                           // snapping looks at the document as it was
    std::function<Vec3(uint32_t, const Vec3&)> f;  // where point i at p goes
    if (kind_ == TransformKind::Move) {
        const auto d = moveOffset(doc, view, x, y, snap);
        if (!d) return false;
        lastOffset_ = *d;
        if (slide_) {
            lastSlide_ = glm::dot(*d, slideMean_);
            f = [this](uint32_t i, const Vec3& p) { return p + lastSlide_ * slideDirs_[i]; };
        } else {
            f = [d = *d](uint32_t, const Vec3& p) { return p + d; };
        }
    } else {
        const glm::dvec2 c = pixelOf(view, anchor_).value_or(glm::dvec2(view.width, view.height) * 0.5);
        const auto v = typedValue();
        if (kind_ == TransformKind::Rotate) {
            Vec3 right, up, fwd;
            cameraAxes(view.camera, right, up, fwd);
            const Vec3 axis = axis_ < 0 ? -fwd : axisVector(axis_);
            // The mouse's angle about the pivot, accumulated so that turns past 180° go on.
            const double a = std::atan2(y - c.y, x - c.x);
            accumAngle_ += wrapAngle(a - prevMouseAngle_);
            prevMouseAngle_ = a;
            // Screen angles grow clockwise (y down); a positive turn about an axis towards the
            // viewer shows counter-clockwise.
            double deg = -glm::degrees(accumAngle_) * (glm::dot(axis, -fwd) >= 0.0 ? 1.0 : -1.0);
            if (v)
                deg = *v;
            else if (snap)
                deg = 5.0 * std::round(deg / 5.0);
            lastAngle_ = deg;
            const glm::dmat4 m = glm::rotate(glm::dmat4(1.0), glm::radians(deg), axis);
            f = [m, c0 = anchor_](uint32_t, const Vec3& p) { return c0 + Vec3(m * glm::dvec4(p - c0, 0.0)); };
        } else {
            const double d0 = std::max(std::hypot(startX_ - c.x, startY_ - c.y), 5.0);
            double k = std::hypot(x - c.x, y - c.y) / d0;
            if (v)
                k = *v;
            else if (snap)
                k = 0.1 * std::round(k / 0.1);
            Vec3 s(k);
            if (axis_ >= 0) {
                s = plane_ ? Vec3(k) : Vec3(1.0);
                s[axis_] = plane_ ? 1.0 : k;
            }
            lastScale_ = s;
            f = [s, c0 = anchor_](uint32_t, const Vec3& p) { return c0 + s * (p - c0); };
        }
    }
    for (uint32_t p : moved_) doc.points[p] = f(p, start_[p]);
    // Soft selection: the points around take their share of the transform (not fixed: the solver
    // may still move them to hold a join).
    for (size_t k = 0; k < softPoints_.points.size(); ++k) {
        const uint32_t p = softPoints_.points[k];
        if (!movedMask_[p]) doc.points[p] = glm::mix(start_[p], f(p, start_[p]), softPoints_.weights[k]);
    }
    applySymmetry(doc.points, pairs_, symmetry_);
    if (!doc.constructions.empty()) rerunConstructions(doc);  // the surfaces follow their inputs
    projection_ = solver_->project(doc.points);
    if (hasLiveTrims(doc)) refreshTrims(doc);  // intersections and trims follow the moved surfaces
    fittedOut_ = fittedSeamsPast(doc);
    takeChangedPoints(uploaded_, doc.points, changed_);
    lastMoved_ = 0;
    for (size_t i = 0; i < doc.points.size(); ++i) lastMoved_ += doc.points[i] != start_[i] ? 1 : 0;
    return true;
}

std::string DragController::fittedSeamsPast(const Document& doc) const {
    // Only the fitted seams whose patches this drag moved are measured again; a document whose
    // fitted seams were past 0.1° when the drag began is held to getting no worse instead.
    std::vector<size_t> touched;
    for (size_t j : fittedJoins_) {
        const Join& jn = doc.joins[j];
        const auto moved = [&](uint32_t p) {
            return std::any_of(doc.patches[p].idx.begin(), doc.patches[p].idx.end(),
                               [&](uint32_t i) { return doc.points[i] != start_[i]; });
        };
        if (moved(jn.patchA) || moved(jn.patchB)) touched.push_back(j);
    }
    return touched.empty() ? "" : fittedJoinsWorsened(doc, doc, touched, fittedWorstAtStart_);
}

void DragController::setSoftRadius(const Document& doc, double radius) {
    if (!active() || !soft_.on || !(radius > 0.0) || !std::isfinite(radius)) return;
    soft_.radius = radius;
    Document at = doc;
    at.points = start_;  // distances along the nets as they were at the start
    setUp(at);
    if (slide_)  // the points the new radius takes in slide along their own directions too
        for (uint32_t p : softPoints_.points)
            if (p < slideDirs_.size() && !movedMask_[p]) slideDirs_[p] = slideDirection(at, p, *slide_).value_or(Vec3(0.0));
}

void DragController::setUp(const Document& doc) {
    fittedJoins_.clear();
    for (size_t j = 0; j < doc.joins.size(); ++j)
        if (doc.joins[j].fitted && quadJoin(doc.joins[j])) fittedJoins_.push_back(j);
    fittedWorstAtStart_ = fittedJoins_.empty() ? 0.0 : worstFittedAngle(doc, fittedJoins_);
    TransformSetup t = setUpTransform(doc, moved_, soft_, symmetry_);
    softPoints_ = std::move(t.soft);
    pairs_ = std::move(t.pairs);
    movedMask_.assign(doc.points.size(), false);
    for (uint32_t p : t.driven)
        if (p < movedMask_.size()) movedMask_[p] = true;
    solver_ = std::move(t.solver);
}

TransformSetup setUpTransform(const Document& doc, const std::vector<uint32_t>& moved, const SoftSelection& soft, const Symmetry& sym) {
    TransformSetup t;
    t.soft = softWeights(doc, moved, soft, sym);
    // Under symmetry the soft points' mirror partners follow too; only the moved points' own are held.
    std::vector<uint32_t> mirrored = moved;
    mirrored.insert(mirrored.end(), t.soft.points.begin(), t.soft.points.end());
    t.pairs = symmetryPairs(doc, mirrored, sym);
    t.driven = t.pairs.driven(moved);
    // Live constructions: their surfaces and inputs stay where the constructions put them and
    // their neighbours follow; the joins around the soft points are held too.
    SolverOptions options;
    options.regionPoints = t.soft.points;
    t.solver = std::make_unique<DragSolver>(doc, withConstructionPoints(doc, t.driven), options);
    return t;
}

std::string DragController::status() const {
    static const char* const kAxis[3] = {"X", "Y", "Z"};
    static const char* const kPlane[3] = {"YZ", "ZX", "XY"};
    char where[32] = "";
    if (slide_)
        std::snprintf(where, sizeof where, " along %s", *slide_ == SlideAxis::U ? "U" : *slide_ == SlideAxis::V ? "V" : "the normal");
    else if (axis_ < 0)
        std::snprintf(where, sizeof where, "%s",
                      kind_ == TransformKind::Move     ? " in the view plane"
                      : kind_ == TransformKind::Rotate ? " about the view axis"
                                                       : "");
    else if (plane_)
        std::snprintf(where, sizeof where, " in the %s plane", kPlane[axis_]);
    else
        std::snprintf(where, sizeof where, " %s %s", kind_ == TransformKind::Rotate ? "about" : "along", kAxis[axis_]);
    char buf[200];
    if (slide_)
        std::snprintf(buf, sizeof buf, "%.4g", lastSlide_);
    else if (kind_ == TransformKind::Move)
        std::snprintf(buf, sizeof buf, "%.4g, %.4g, %.4g", lastOffset_.x, lastOffset_.y, lastOffset_.z);
    else if (kind_ == TransformKind::Rotate)
        std::snprintf(buf, sizeof buf, "%.4g°", lastAngle_);
    else
        std::snprintf(buf, sizeof buf, "×%.4g", lastScale_[axis_ < 0 ? 0 : plane_ ? (axis_ + 1) % 3 : axis_]);
    const std::string value = buf;
    std::snprintf(buf, sizeof buf, "%s %zu point%s%s: %s", slide_ ? "Slide" : kindName(kind_), moved_.size(), moved_.size() == 1 ? "" : "s",
                  where, value.c_str());
    std::string out = buf;
    if (!typed_.empty()) out += "  [typed " + typed_ + "]";
    if (soft_.on) {
        std::snprintf(buf, sizeof buf, "  soft %.3g %s (%zu around, wheel: radius)", soft_.radius,
                      std::string(falloffName(soft_.falloff)).c_str(), softPoints_.points.size());
        out += buf;
    }
    // How far the edit reached: the moved points, their soft share and what the joins forced.
    out += "  " + std::to_string(lastMoved_) + (lastMoved_ == 1 ? " point moved" : " points moved");
    if (!projection_.ok()) out += "\n" + conflictMessage(projection_);
    if (!fittedOut_.empty()) out += "\n" + fittedOut_ + ": past the 0.1° a fitted seam keeps (released here, the move is undone)";
    return out;
}

void DragController::finish(EditSession& session) {
    const size_t n = moved_.size();
    const std::string kind = slide_ ? "Slide" : kindName(kind_);
    const bool beyond = !fittedOut_.empty();
    const std::vector<Vec3> start = beyond ? start_ : std::vector<Vec3>{};
    *this = DragController{};
    if (beyond) {  // a fitted seam past its angle: nothing is committed
        session.doc.points = start;
        session.changed(false);
        return;
    }
    if (session.doc.points != session.committed().points)
        session.commit(n == 1 ? kind + " point" : kind + " " + std::to_string(n) + " points");
}

void DragController::cancel(Document& doc) {
    if (!start_.empty()) doc.points = start_;
    *this = DragController{};
}

std::string HeldPointEdit::set(EditSession& session, uint32_t point, const Vec3& position) {
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(position[k]) || std::abs(position[k]) > limits::kMaxCoordinate) {
            char msg[160];
            std::snprintf(msg, sizeof msg, "A point coordinate must be a finite number within ±%g; %g was not applied.",
                          limits::kMaxCoordinate, position[k]);
            return msg;
        }
    if (std::string why = constructedPointsRefusal(session.committed(), {point}); !why.empty()) return why;
    if (!solver_ || point_ != point || generation_ != session.generation() || symmetry_ != session.symmetry) {
        pairs_ = symmetryPairs(session.committed(), {point}, session.symmetry);
        solver_ = std::make_unique<DragSolver>(session.committed(), withConstructionPoints(session.committed(), pairs_.driven({point})));
        point_ = point;
        generation_ = session.generation();
        symmetry_ = session.symmetry;
    }
    std::vector<Vec3> pts = session.committed().points;
    pts[point] = position;
    applySymmetry(pts, pairs_, symmetry_);
    session.doc.points = std::move(pts);
    if (!session.doc.constructions.empty()) rerunConstructions(session.doc);
    projection_ = solver_->project(session.doc.points);
    if (hasLiveTrims(session.doc)) refreshTrims(session.doc);
    return "";
}

void HeldPointEdit::finish(EditSession& session) {
    const bool fittedPast = !fittedJoinsWorsened(session.committed(), session.doc).empty();  // as EditSession::apply holds them
    if (projection_.ok() && !fittedPast) return session.commit("Edit point");
    session.doc = session.committed();
    session.changed(false);
}

}  // namespace edit
}  // namespace pw
