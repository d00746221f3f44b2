// The Patchwork document: a pool of control points, bicubic patches and spline nets that index it,
// joins between patch edges, and the tessellation, display and camera settings (DESIGN §1).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/math_types.hpp"
#include "core/model/basis.hpp"

namespace pw {
inline namespace model {

// Edges of a 4x4 window, numbered like the quad domain's outer levels (DESIGN §3):
// U0 = column j=0 (u=0), V0 = row i=0 (v=0), U1 = column j=3 (u=1), V1 = row i=3 (v=1).
// A join's side may also be an edge of a Bézier triangle (issue 40): T0, T1 and T2 are its edges 0,
// 1 and 2 ("e0", "e1", "e2"; see TrianglePatch), and the join's patch index is then a triangle's.
enum class Edge : uint8_t { U0 = 0, V0 = 1, U1 = 2, V1 = 3, T0 = 4, T1 = 5, T2 = 6 };
std::string_view edgeName(Edge e);  // "u0", "v0", "u1", "v1", "e0", "e1", "e2"
// A patch edge: "u0", "v0", "u1" or "v1" (triangle edges are refused; parseJoinEdge takes them).
std::optional<Edge> parseEdge(std::string_view name);
// A patch or triangle edge.
std::optional<Edge> parseJoinEdge(std::string_view name);
inline bool isTriangleEdge(Edge e) { return e >= Edge::T0; }
// 0, 1 or 2 for T0, T1, T2 (the triangle's own edge numbering).
inline int triangleEdgeNumber(Edge e) { return static_cast<int>(e) - static_cast<int>(Edge::T0); }
inline Edge triangleEdge(int number) { return static_cast<Edge>(static_cast<int>(Edge::T0) + number); }

// Net slot (0..15) of the k-th point along edge e (k in increasing parameter), and of the point
// `depth` rows inward from it (depth 0 = on the edge, 1 = the tangent row).
int edgeSlot(Edge e, int k, int depth = 0);

// True when an edge with these four pool indices runs against its canonical direction (its indices
// read backwards are lexicographically smaller); every patch sharing the edge walks it canonically
// (watertight seams, DESIGN §2). The rule of core/gpu/patch_math.h, which the shaders use too.
bool edgeReversed(const std::array<uint32_t, 4>& pool);
inline std::array<uint32_t, 4> reversedEdgePool(const std::array<uint32_t, 4>& p) { return {p[3], p[2], p[1], p[0]}; }

enum class Continuity : uint8_t { C0, C1, G1, C2, G2 };
std::string_view continuityName(Continuity c);  // "C0", "C1", "G1", "C2", "G2"
std::optional<Continuity> parseContinuity(std::string_view name);
// Joins that hold the cross-boundary tangent (C1, G1, C2, G2) and those that also hold curvature.
inline bool holdsTangent(Continuity c) { return c != Continuity::C0; }
inline bool holdsCurvature(Continuity c) { return c == Continuity::C2 || c == Continuity::G2; }

// Displacement along the normal by a height map (DESIGN §11): height = scale * map(uv) + bias, the
// map read as 0..1 (8- or 16-bit PNG). UVs are the window's parameters (a net's windows tile the map
// in net order, so neighbours sample the same texels along their shared edge) or a planar projection
// along the up axis over a rectangle (the model's bounds when none is set), which depends on the
// position alone and so agrees across every seam.
enum class DisplacementMapping : uint8_t { Patch, Planar };
std::string_view displacementMappingName(DisplacementMapping m);  // "patch", "planar"
std::optional<DisplacementMapping> parseDisplacementMapping(std::string_view name);

struct DisplacementOverride {
    float scale = 0.0f;
    float bias = 0.0f;
    bool operator==(const DisplacementOverride&) const = default;
};

struct DisplacementSettings {
    std::string map;  // PNG path as written in the document (relative: to the document's folder); "" = none
    float scale = 0.0f;
    float bias = 0.0f;
    DisplacementMapping mapping = DisplacementMapping::Planar;
    // Planar: the rectangle (x0, y0, width, height) of the ground plane (x-y for Z-up documents,
    // x-z for Y-up) the map covers; none = the model's bounding box.
    std::optional<std::array<double, 4>> rect;
    bool active() const { return !map.empty(); }
    bool operator==(const DisplacementSettings&) const = default;
};

// A trim loop (issue 64): a closed chain of cubic Bézier p-curves in the (u, v) domain of a patch
// (its [0, 1]²) or of a net (all its windows as one [0, 1]²: window (r, c) of W x H covers
// [c/W, (c+1)/W] x [r/H, (r+1)/H]). 3n + 1 points, the last equal to the first. A counter-clockwise
// loop is an outer boundary (what is inside is kept); a clockwise loop is a hole. A surface with
// holes only keeps its whole domain less the holes (core/trim/trim_loops.hpp). Loops live in
// parameter space, so transforms of the surface leave them as they are.
using UV = std::array<double, 2>;
struct TrimLoop {
    std::vector<UV> uv;
    // Live (core/edit/live_trims.hpp): the loop is the document curve `curve` on the surface (closest
    // point, or along `direction` when it is not zero), made again whenever the curve or the surface
    // changes, until `bake` detaches it (-1). `hole`: the inside is removed (`trim … remove`).
    int32_t curve = -1;
    std::array<double, 3> direction{0, 0, 0};
    bool hole = false;
    std::string error;  // "" while live; else why the curve no longer fits (the last good loop stays)
    bool operator==(const TrimLoop&) const = default;
};

// A bicubic patch: 16 indices into the pool, row-major (i = v row, j = u column).
struct Patch {
    std::array<uint32_t, 16> idx{};
    Basis basis = Basis::Bezier;
    double tension = 0.5;  // Catmull-Rom τ
    std::string name;
    // Per-patch tessellation override: four outer and two inner levels.
    std::optional<std::array<float, 6>> tessOverride;
    bool hidden = false;                               // H: not drawn, not picked (saved with the document)
    std::optional<DisplacementOverride> displacement;  // own scale and bias (else the document's)
    std::vector<TrimLoop> trims;                       // none: the whole domain (issue 64)
    bool operator==(const Patch&) const = default;
};

// A cubic Bézier triangle: 10 indices into the pool, b_ijk with i+j+k = 3 weighting
// 3!/(i!j!k!) u^i v^j w^k, (u, v, w) barycentric, w = 1 - u - v. Canonical order:
//   slot: 0    1    2    3    4    5    6    7    8    9
//   b:    300  210  201  120  111  102  030  021  012  003
// Corners: slot 0 at u = 1, slot 6 at v = 1, slot 9 at w = 1. Edges are numbered like the Vulkan
// triangle domain's outer levels: edge 0 is u = 0 (slots 6,7,8,9), edge 1 is v = 0 (9,5,2,0),
// edge 2 is w = 0 (0,1,3,6); see triEdgeSlot in bezier_triangle.hpp. Each edge is a cubic Bézier
// curve of its 4 pool points, so triangles (and quads) that share those points meet watertight.
struct TrianglePatch {
    std::array<uint32_t, 10> idx{};
    std::string name;
    // Per-patch tessellation override: three outer levels (edges 0, 1, 2) and one inner.
    std::optional<std::array<float, 4>> tessOverride;
    bool hidden = false;
    std::optional<DisplacementOverride> displacement;
    bool operator==(const TrianglePatch&) const = default;
};

// A curve: a chain of cubic Bézier segments (composite Bézier, issue 39) through 3n + 1 pool
// points, segment s taking points 3s .. 3s + 3, rational where its points have weights (exact
// circles and arcs). Closed when the last index is the first (the chain's end point is its start).
// Each segment is drawn through the GPU's isoline tessellator (DESIGN §3) with
// TessSettings::isolineLevels[1] segments; exported as a glTF line strip.
// A surface a command names: a patch "3" or a net "n2".
struct SurfaceRef {
    bool net = false;
    uint32_t index = 0;
    bool operator==(const SurfaceRef&) const = default;
};
// A curve made from other items and kept live (issue 64): the intersection of two surfaces (its
// `branch`-th curve), or another curve projected onto a surface (closest point, or along
// `direction` when it is not zero). Remade with the same number of segments whenever its inputs
// change, until `bake` detaches it.
enum class CurveLinkKind : uint8_t { Intersect, Project };
struct CurveLink {
    CurveLinkKind kind = CurveLinkKind::Intersect;
    SurfaceRef a, b;      // intersect: both surfaces; project: the surface in a
    int32_t source = -1;  // project: the curve projected
    std::array<double, 3> direction{0, 0, 0};
    uint32_t branch = 0;
    std::string error;  // "" while live; else why the inputs no longer give the curve
    bool operator==(const CurveLink&) const = default;
};

struct BezierCurve {
    std::vector<uint32_t> idx;  // 3n + 1 pool indices, n >= 1
    std::string name;
    bool hidden = false;
    std::optional<CurveLink> link;  // a live curve (intersection, projection)
    bool operator==(const BezierCurve&) const = default;
};
inline size_t curveSegmentCount(const BezierCurve& c) { return c.idx.size() >= 4 ? (c.idx.size() - 1) / 3 : 0; }
inline std::array<uint32_t, 4> curveSegment(const BezierCurve& c, size_t s) {
    return {c.idx[3 * s], c.idx[3 * s + 1], c.idx[3 * s + 2], c.idx[3 * s + 3]};
}
inline bool curveClosed(const BezierCurve& c) { return c.idx.size() > 4 && c.idx.front() == c.idx.back(); }
// True for a valid chain length (3n + 1 with n >= 1).
inline bool validCurveLength(size_t n) { return n >= 4 && (n - 1) % 3 == 0; }

// A larger control net (rows x cols) under one basis; every 4x4 window is a patch. Bézier windows
// step by 3, spline windows by 1. A closed direction wraps around (tubes and rings).
struct Surface {
    uint32_t rows = 4, cols = 4;
    std::vector<uint32_t> idx;  // rows*cols pool indices, row-major
    Basis basis = Basis::BSpline;
    double tension = 0.5;
    bool closedU = false;  // columns wrap
    bool closedV = false;  // rows wrap
    // Bézier nets only: keep C1 across the window seams (the solver holds each seam point midway
    // between its neighbours); otherwise the windows meet C0.
    bool keepC1 = false;
    std::string name;
    bool hidden = false;
    std::optional<DisplacementOverride> displacement;  // for every window of the net
    std::vector<TrimLoop> trims;                       // in the whole net's [0, 1]² (issue 64)
    bool operator==(const Surface&) const = default;
};

// Edge `edgeA` of patch A meets edge `edgeB` of patch B. They share the four pool entries; point k
// along A's edge is point k (or 3-k when `reversed`) along B's edge. For C1/G1/C2/G2:
//   B1k - B0k = alpha * (A0k - A1k)   (0 = boundary row, 1 = tangent row; alpha = 1 for C1, C2)
// and for C2/G2 also (2 = the third row; beta2 = 0 for C2), the β-constraint of Barsky's G2:
//   B2k - 2 B1k + B0k = alpha² (A2k - 2 A1k + A0k) + (beta2 / 2) (A0k - A1k)
// which, with alpha and beta2 fixed when the join is made, is linear in the points and gives
// equal tangent planes and equal normal curvature in every direction across the seam.
// At a corner where 3, 5 or 6 patches meet, no such rows can hold G1 (core/ops/corner_ops): there
// a G1 join also leans along the seam, B's cross derivative = α·A's + β(t)·the edge's tangent, with
//   β(t) = shear[0] (1−t)² + 2 shear[1] t(1−t) + shear[2] t²   (t = 0 at A's edge point 0)
// and the rows are the five Bernstein coefficients of that degree-4 identity (core/solve/
// sheared_joins.hpp); still linear in the points. Such a join may also let α run linearly from
// `alpha` at A's point 0 to `alphaEnd` at point 3 (each end then matches the seam that continues
// it). Both zero for every other join.
// A side whose edge is a triangle's (Edge::T0..T2) indexes Document::triangles; such a join is C0
// or G1, its rows the same identity with the triangle's quadratic cross derivative in place of the
// cubic one (core/solve/triangle_seams.hpp).
struct Join {
    uint32_t patchA = 0;
    Edge edgeA = Edge::U0;
    uint32_t patchB = 0;
    Edge edgeB = Edge::U0;
    bool reversed = false;
    Continuity continuity = Continuity::C0;
    double alpha = 1.0;             // β1
    double beta2 = 0.0;             // β2 (G2 only)
    std::array<double, 3> shear{};  // β(t) in Bernstein form (G1 only; non-zero at 3-, 5- and 6-patch corners)
    double alphaEnd = 0.0;          // α at A's point 3 when it differs from `alpha` there (G1 only; 0: constant α)
    // G1 only, a fill's side whose two ends ask different ratios (core/ops/fill_hole): the rows let
    // the identity's middle coefficient go, which no bicubic fill can meet (DESIGN §14), and the
    // seam is held to kFittedJoinDegrees by its measured angle instead. A split restricts such a
    // join to a part [t0, t1] of the edge it was made on (A's parameter): the let-go term is then
    // that part of the first's, and the rows hold the identity's coefficients along it.
    bool fitted = false;
    std::array<double, 2> fittedSpan{0.0, 1.0};
    bool operator==(const Join&) const = default;
};
// The largest normal angle a fitted join may reach (the Class-A figure for bicubic surfaces).
inline constexpr double kFittedJoinDegrees = 0.1;
// True when a side of the join is a Bézier triangle's edge (C0 or G1 only; core/solve/triangle_seams.hpp).
inline bool joinHasTriangle(const Join& j) { return isTriangleEdge(j.edgeA) || isTriangleEdge(j.edgeB); }
// Joins between patch edges only: what the quad-only operations (corners, splits, mirror) act on.
inline bool quadJoin(const Join& j) { return !joinHasTriangle(j); }

// A surface built from curves (issue 39) that stays live: its patches are re-made from its inputs
// whenever they change (core/construct/constructions.hpp), until `bake` detaches them.
inline constexpr uint32_t kMaxSweepPieces = 16;
enum class ConstructionKind : uint8_t { Revolve, Extrude, Loft, EdgeSurface, Sweep1, Sweep2, Network, Blend };
// "revolve", "extrude", "loft", "edge-surface", "sweep1", "sweep2", "network", "blend"
std::string_view constructionKindName(ConstructionKind k);
std::optional<ConstructionKind> parseConstructionKind(std::string_view name);

// An input curve: a curve of the document, or the boundary of a patch ("c3", "2:u0").
struct CurveInput {
    int32_t curve = -1;  // >= 0: doc.curves[curve]; else the edge below
    uint32_t patch = 0;
    Edge edge = Edge::U0;
    bool operator==(const CurveInput&) const = default;
};

struct Construction {
    ConstructionKind kind = ConstructionKind::Revolve;
    std::vector<CurveInput> inputs;
    std::array<double, 3> origin{0, 0, 0};  // revolve: a point of the axis
    std::array<double, 3> vector{0, 0, 1};  // revolve: the axis; extrude: the offset
    double degrees = 360.0;                 // revolve
    bool closed = false;                    // loft: back to the first section
    // loft: continuity at the first and last section against the patch whose edge it is (C0 = G0,
    // or G1: the surface leaves the edge along the patch's tangent, scaled by endAlpha); blend: G1
    // or G2 at both edges, endAlpha chosen when it is made.
    std::array<Continuity, 2> ends{Continuity::C0, Continuity::C0};
    std::array<double, 2> endAlpha{1.0, 1.0};
    // network: the first `split` inputs run along u, the rest along v; sweep1: the pieces each rail
    // segment is split into (1 .. kMaxSweepPieces; 0 = 1) so the sweep stays within its tolerance.
    uint32_t split = 0;
    // The made control net: rows x cols pool indices (row-major, Bézier, 3n + 1 each way; a closed
    // direction repeats its first row or column), and the patches that are its 4x4 windows.
    uint32_t rows = 0, cols = 0;
    std::vector<uint32_t> grid;
    std::vector<uint32_t> patches;
    std::string error;  // "" while live; else why the inputs no longer fit (the last good surface stays)
    bool operator==(const Construction&) const = default;
};

enum class Spacing : uint8_t { Equal, FractionalOdd, FractionalEven, Pow2 };
std::string_view spacingName(Spacing s);  // "equal", "fractional_odd", "fractional_even", "pow2"
std::optional<Spacing> parseSpacing(std::string_view name);

enum class AdaptiveMode : uint8_t { None, Distance, ScreenSpace, Orientation };
std::string_view adaptiveName(AdaptiveMode m);  // "none", "distance", "screen", "orientation"
std::optional<AdaptiveMode> parseAdaptive(std::string_view name);

// Distance mode's curve: linear (maxLevel at the near distance, 0 at the far one: the first notes'
// 64 saturate((d1 - d) / (d1 - d0))) or pow2 (2^lerp(near exponent, far exponent, s): the terrain
// notes' 2^lerp(20, 4, s)); core/gpu/patch_math.h distanceLevel.
enum class DistanceCurve : uint8_t { Linear, Pow2 };
std::string_view distanceCurveName(DistanceCurve c);  // "linear", "pow2"
std::optional<DistanceCurve> parseDistanceCurve(std::string_view name);
// Where distance mode measures the distance: each edge from its own chord midpoint (crack-free: both
// patches on an edge agree), every level from the patch centre (the first notes: one level per
// patch, so neighbours at different distances disagree on their shared edge and the surface cracks),
// or edges from their midpoints and the inner levels from the centre (the terrain notes).
enum class DistanceFrom : uint8_t { Edges, Centre, EdgesInnerCentre };
std::string_view distanceFromName(DistanceFrom f);  // "edges", "centre", "edges-inner-centre"
std::optional<DistanceFrom> parseDistanceFrom(std::string_view name);

struct TessSettings {
    std::array<float, 4> outer{16, 16, 16, 16};
    std::array<float, 2> inner{16, 16};
    bool linked = true;  // UI: one slider drives all six
    Spacing spacing = Spacing::Equal;
    AdaptiveMode adaptive = AdaptiveMode::None;
    float distanceNear = 2.0f;  // d0: full level at or below this distance
    float distanceFar = 30.0f;  // d1: level 1 at or beyond this distance
    DistanceCurve distanceCurve = DistanceCurve::Linear;
    std::array<float, 2> distanceExponents{20.0f, 4.0f};  // pow2: the exponents at d0 and d1
    DistanceFrom distanceFrom = DistanceFrom::Edges;
    float targetPixels = 8.0f;  // screen-space mode: pixels per segment
    float maxLevel = 64.0f;
    bool cullBackfaces = false;
    bool cullOffscreen = true;
    // Distance mode: cull a patch whose control points' centre is at or beyond distanceFar, where
    // the lecture notes' formula gives level 0 (otherwise such patches keep level 1).
    bool cullFar = false;
    // Adaptive modes with a height map: edges whose map has more detail than their level shows are
    // raised (displacement-adaptive). Off keeps the levels the formula gives, so a figure shows the
    // distance or screen rule alone (the notes' terrain: the height map only moves the vertices).
    bool heightDetail = true;
    // The isoline domain's two levels, for curves and the isocurve overlay: lines (outer 0, always
    // rounded to an integer) and segments per line (outer 1, under `spacing`). Curves draw one line;
    // the isocurve overlay draws `lines` isoparametric curves per direction of every window, the
    // first and last on its boundary (2 = the boundary curves).
    std::array<float, 2> isolineLevels{2.0f, 16.0f};
    bool operator==(const TessSettings&) const = default;
};

enum class ShadingMode : uint8_t { Lit, Normal, PatchId, UvChecker, Zebra, GaussCurvature, MeanCurvature, Level };
std::string_view shadingName(ShadingMode m);  // "lit", "normal", "patch", "uv", "zebra", "gauss", "mean", "level"
std::optional<ShadingMode> parseShading(std::string_view name);
// "upper-left" (true: D3D, Vulkan's default) or "lower-left" (false: GL), the domain view's origin.
std::optional<bool> parseDomainOrigin(std::string_view name);
std::string_view domainOriginName(bool upperLeft);

struct DisplaySettings {
    ShadingMode shading = ShadingMode::Lit;
    bool showGrid = true;  // control-net lines and points
    bool showWireframe = false;
    bool showNormals = false;
    bool showBoundaries = false;  // patch boundaries and joins coloured by continuity
    bool showIsocurves = false;   // isoparametric curves of every window, through the isoline tessellator
    // Curvature combs (issue 21), drawn by the GPU through the isoline tessellator: teeth along every
    // Bézier curve and, with the isocurve overlay, every isocurve (2 lines = the boundary curves),
    // each tooth −κN long times combToothLength (outward from the centre of curvature),
    // combDensity teeth per curve, joined by their envelope. The selected join also gets its
    // curvature graph: combs on the isocurves that cross it, on both sides.
    bool showCombs = false;
    float combScale = 1.0f;
    int combDensity = 16;  // 2..21 (three segments a tooth within the isoline tessellator's 64)
    float normalLength = 0.1f;
    std::array<float, 3> lightDir{0.4f, 0.5f, 0.75f};
    std::array<float, 3> background{0.16f, 0.17f, 0.19f};
    // The domain view's picture: D3D's and Vulkan's default upper-left origin (v = 0 on top, edges
    // tagged with their SV_TessFactor / gl_TessLevelOuter index) instead of GL's lower-left.
    bool domainUpperLeft = false;
    bool operator==(const DisplaySettings&) const = default;
};

// A comb tooth's length per unit of curvature: combScale × 0.02 × model size² (a circle of radius r
// gets teeth of 0.16 r at scale 1).
inline double combToothLength(const DisplaySettings& d, double modelSize) { return d.combScale * 0.02 * modelSize * modelSize; }

struct Camera {
    std::array<double, 3> target{0, 0, 0};
    double distance = 10.0;
    double yawDeg = 30.0;
    double pitchDeg = 25.0;
    double fovYDeg = 40.0;
    bool orthographic = false;
    bool zUp = true;  // the teapot is +z up
    bool operator==(const Camera&) const = default;
};

// Tolerances the continuity readout checks joins against (Rhino's EdgeContinuity's three): the gap
// between the two sides in model units, the angle between their normals in degrees (largest along
// the seam) and the curvature deviation across the seam in percent (core/solve/continuity_report.hpp).
struct ContinuityTolerances {
    double position = 0.001;
    double angleDeg = 1.0;
    double curvaturePct = 5.0;
    bool operator==(const ContinuityTolerances&) const = default;
};

// The length unit of a document's coordinates (issue 42): written into every file format that
// carries one (STEP's length unit, glTF's metres, an OBJ comment) and taken from a STEP file on import.
enum class LengthUnit : uint8_t { Millimetre, Centimetre, Metre, Inch };
std::string_view lengthUnitName(LengthUnit u);  // "mm", "cm", "m", "in"
std::optional<LengthUnit> parseLengthUnit(std::string_view name);
double metresPer(LengthUnit u);  // 0.001, 0.01, 1, 0.0254

struct Document {
    static constexpr int kFormatVersion = 1;

    std::string name;
    std::vector<Vec3> points;
    std::vector<Patch> patches;
    std::vector<Surface> surfaces;
    std::vector<Join> joins;
    TessSettings tess;
    DisplaySettings display;
    Camera camera;
    // Cubic Bézier triangles, drawn after the quads (last, so that aggregate initialisations of
    // documents without triangles keep working).
    std::vector<TrianglePatch> triangles;
    std::vector<BezierCurve> curves;  // cubic Bézier curves (isoline domain)
    DisplacementSettings displacement;
    ContinuityTolerances tolerances;
    // Rational patches (issue 21): the weight of each pool point, for every item that uses it
    // (homogeneous evaluation, core/gpu/rational_math.h). Points past the end weigh 1, and the vector
    // is kept without trailing 1s (setPointWeight, trimWeights), so a polynomial document has none
    // and two documents with the same weights compare equal.
    std::vector<double> weights;
    std::vector<Construction> constructions;  // live surfaces from curves (issue 39)
    LengthUnit unit = LengthUnit::Metre;

    bool operator==(const Document&) const = default;
};

// The points with, for every on-curve point of a visible curve among them (a segment end), its
// tangent handles on either side: moving an anchor moves its handles with it (Blender, Illustrator),
// so the curve keeps its tangent there. Sorted, without repeats.
std::vector<uint32_t> withCurveHandles(const Document& doc, std::vector<uint32_t> points);

// Weights must be positive and finite; this bound keeps the homogeneous sums well inside a float.
inline constexpr double kMaxWeight = 1e6;
inline double pointWeight(const Document& doc, uint32_t i) { return i < doc.weights.size() ? doc.weights[i] : 1.0; }
// Sets the weight of pool point i (throws EditError outside (0, kMaxWeight]).
void setPointWeight(Document& doc, uint32_t i, double w);
void trimWeights(std::vector<double>& weights);  // drops trailing 1s
inline bool isRational(const Document& doc) { return !doc.weights.empty(); }
// Bézier triangles evaluate without weights: the first triangle slot whose point has a weight other
// than 1, as {triangle, point}, if any (such documents are refused; core/eval/rational_eval.hpp).
std::optional<std::array<uint32_t, 2>> weightedTrianglePoint(const Document& doc);
// Rewrites the weights after a pool renumbering: new point remap[i] takes old point i's weight
// (remap[i] == UINT32_MAX: dropped); newSize points in all.
void remapWeights(Document& doc, const std::vector<uint32_t>& remap, size_t newSize);

// One 4x4 window to evaluate or draw: a patch, or a window of a surface's net.
struct PatchInstance {
    std::array<uint32_t, 16> idx{};
    Basis basis = Basis::Bezier;
    double tension = 0.5;
    int32_t patch = -1;    // index into Document::patches, or -1
    int32_t surface = -1;  // index into Document::surfaces, or -1
    uint32_t windowRow = 0, windowCol = 0;
};

// Every patch followed by every window of every surface, in a stable order.
std::vector<PatchInstance> expandPatches(const Document& doc);
// True when the window's patch or net is hidden (H).
bool windowHidden(const Document& doc, const PatchInstance& w);

// Window step along a net: 3 for Bézier (windows share their boundary rows), 1 for splines.
inline uint32_t netStep(Basis b) { return b == Basis::Bezier ? 3u : 1u; }
// Number of 4x4 windows along one direction of n net rows or columns: open directions stop 3
// before the end, closed ones wrap around (window k starts at k * step).
inline uint64_t netWindowCount(uint32_t n, bool closed, uint32_t step) {
    if (closed) return (uint64_t(n) + step - 1) / step;
    return n >= 4 ? (n - 4) / step + 1 : 0;
}

// Calls f(index) for every pool index of every patch, net, triangle, curve and construction grid (uint32_t& for a
// mutable document, so f may renumber; const uint32_t& otherwise).
template <class Doc, class F>
void forEachPointIndex(Doc& doc, F&& f) {
    for (auto& p : doc.patches)
        for (auto& i : p.idx) f(i);
    for (auto& s : doc.surfaces)
        for (auto& i : s.idx) f(i);
    for (auto& t : doc.triangles)
        for (auto& i : t.idx) f(i);
    for (auto& c : doc.curves)
        for (auto& i : c.idx) f(i);
    for (auto& k : doc.constructions)
        for (auto& i : k.grid) f(i);
}

// Control points of one window.
Net16 gatherNet(const Document& doc, const std::array<uint32_t, 16>& idx);
// Their weights, or none when all sixteen are 1 (a polynomial window).
std::optional<Weights16> gatherWeights(const Document& doc, const std::array<uint32_t, 16>& idx);

struct Bounds {
    Vec3 min{0.0}, max{0.0};
    bool empty = true;
    double diagonal() const { return empty ? 0.0 : glm::length(max - min); }
    void add(const Vec3& p) {
        min = empty ? p : glm::min(min, p);
        max = empty ? p : glm::max(max, p);
        empty = false;
    }
};
Bounds computeBounds(const std::vector<Vec3>& points);

// The model's size for relative tolerances: the bounding-box diagonal, at least 1e-12.
double modelSize(const Document& doc);

}  // namespace model
}  // namespace pw
