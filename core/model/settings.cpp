#include "core/model/settings.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"

namespace pw {
inline namespace model {

namespace {

using Values = std::vector<double>;

template <size_t N>
Values fromArray(const std::array<float, N>& a) {
    return Values(a.begin(), a.end());
}
template <size_t N>
void toArray(std::array<float, N>& a, const Values& v) {
    for (size_t i = 0; i < N; ++i) a[i] = float(v[i]);
}

// A number row bound to a float (or float array) member reached through `field`.
template <class F>
Setting numberRow(std::string_view key, std::string_view label, std::string_view tooltip, std::string_view unit, double lo, double hi,
                  SettingWidget widget, std::string_view format, F field) {
    Setting s{.key = key,
              .label = label,
              .tooltip = tooltip,
              .unit = unit,
              .kind = SettingKind::Number,
              .min = lo,
              .max = hi,
              .widget = widget,
              .format = format};
    using T = std::remove_reference_t<decltype(field(std::declval<Document&>()))>;
    if constexpr (std::is_same_v<T, float>) {
        s.count = 1;
        s.get = [field](const Document& d) { return Values{double(field(const_cast<Document&>(d)))}; };
        s.set = [field](Document& d, const Values& v) { field(d) = float(v[0]); };
    } else {
        s.count = int(std::tuple_size_v<T>);
        s.get = [field](const Document& d) { return fromArray(field(const_cast<Document&>(d))); };
        s.set = [field](Document& d, const Values& v) { toArray(field(d), v); };
    }
    return s;
}

Setting switchRow(std::string_view key, std::string_view label, std::string_view tooltip, bool& (*field)(Document&)) {
    return {.key = key,
            .label = label,
            .tooltip = tooltip,
            .kind = SettingKind::Switch,
            .min = 0,
            .max = 1,
            .integer = true,
            .get = [field](const Document& d) { return Values{field(const_cast<Document&>(d)) ? 1.0 : 0.0}; },
            .set = [field](Document& d, const Values& v) { field(d) = v[0] != 0.0; }};
}

template <class E>
Setting choiceRow(std::string_view key, std::string_view label, std::string_view tooltip, std::vector<std::string_view> names,
                  std::vector<std::string_view> labels, E& (*field)(Document&)) {
    const double last = double(names.size() - 1);
    return {.key = key,
            .label = label,
            .tooltip = tooltip,
            .kind = SettingKind::Choice,
            .min = 0,
            .max = last,
            .integer = true,
            .choices = std::move(names),
            .choiceLabels = std::move(labels),
            .get = [field](const Document& d) { return Values{double(int(field(const_cast<Document&>(d))))}; },
            .set = [field](Document& d, const Values& v) { field(d) = E(int(v[0])); }};
}

constexpr double kLo = limits::kMinTessLevel, kHi = limits::kMaxTessLevel;

std::vector<Setting> makeSettings() {
    std::vector<Setting> t;
    // Tessellation (the Tessellation panel, `tess` in files).
    t.push_back(switchRow("tess.linked", "Link levels", "One slider drives all four outer and both inner levels",
                          [](Document& d) -> bool& { return d.tess.linked; }));
    Setting level = numberRow("tess.level", "Level", "Outer and inner tessellation level (1-64)", "", kLo, kHi, SettingWidget::Slider,
                              "%.1f", [](Document& d) -> float& { return d.tess.outer[0]; });
    level.set = [](Document& d, const Values& v) {
        d.tess.outer.fill(float(v[0]));
        d.tess.inner.fill(float(v[0]));
        d.tess.linked = true;
    };
    t.push_back(std::move(level));
    t.push_back(numberRow("tess.outer", "Outer", "Outer levels: edge u=0, v=0, u=1, v=1", "", kLo, kHi, SettingWidget::Slider, "%.1f",
                          [](Document& d) -> std::array<float, 4>& { return d.tess.outer; }));
    t.push_back(numberRow("tess.inner", "Inner", "Inner levels along u and v", "", kLo, kHi, SettingWidget::Slider, "%.1f",
                          [](Document& d) -> std::array<float, 2>& { return d.tess.inner; }));
    Setting spacing = choiceRow<Spacing>(
        "tess.spacing", "Partitioning",
        "Spacing of the tessellator: equal (also called integer), fractional odd/even (smooth level changes), pow2 (rounded up)",
        {"equal", "fractional_odd", "fractional_even", "pow2"}, {"equal", "fractional odd", "fractional even", "pow2"},
        [](Document& d) -> Spacing& { return d.tess.spacing; });
    spacing.choiceAliases = {{"integer", int(Spacing::Equal)}};
    t.push_back(std::move(spacing));
    t.push_back(choiceRow<AdaptiveMode>("tess.adaptive", "Adaptive",
                                        "Per-edge levels from the distance to the eye, the projected edge length, or the silhouette",
                                        {"none", "distance", "screen", "orientation"}, {"none", "distance", "screen space", "orientation"},
                                        [](Document& d) -> AdaptiveMode& { return d.tess.adaptive; }));
    t.push_back(numberRow("tess.distanceNear", "Near", "Full level at or below this distance", "model units", 0.0, 1e9, SettingWidget::Drag,
                          "%.3g", [](Document& d) -> float& { return d.tess.distanceNear; }));
    t.push_back(numberRow("tess.distanceFar", "Far", "Level 1 at or beyond this distance", "model units", 0.0, 1e9, SettingWidget::Drag,
                          "%.3g", [](Document& d) -> float& { return d.tess.distanceFar; }));
    t.push_back(choiceRow<DistanceCurve>(
        "tess.distanceCurve", "Curve",
        "Distance mode's curve: linear, max level at Near and 0 at Far (the first notes' 64 saturate((d1 - "
        "d) / (d1 - d0))); pow2, 2^lerp(exponent at Near, exponent at Far, s) (the terrain notes)",
        {"linear", "pow2"}, {"linear", "pow2 (2^lerp)"}, [](Document& d) -> DistanceCurve& { return d.tess.distanceCurve; }));
    t.push_back(numberRow("tess.distanceExponents", "Exponents",
                          "pow2 curve: the level is 2^x at Near and 2^y at Far (the terrain notes: 20, 4)", "",
                          limits::kMinDistanceExponent, limits::kMaxDistanceExponent, SettingWidget::Drag, "%.2f",
                          [](Document& d) -> std::array<float, 2>& { return d.tess.distanceExponents; }));
    t.push_back(choiceRow<DistanceFrom>(
        "tess.distanceFrom", "Measured from",
        "Where distance is measured: each edge from its midpoint (crack-free), everything from the patch centre (the first notes; "
        "neighbours disagree and cracks open), or edges from midpoints and inner from the centre (the terrain notes)",
        {"edges", "centre", "edges-inner-centre"}, {"edge midpoints", "patch centre", "edges, inner from centre"},
        [](Document& d) -> DistanceFrom& { return d.tess.distanceFrom; }));
    Setting pixels =
        numberRow("tess.targetPixels", "Pixels/segment", "Target length of one segment on screen (about 8 px is the lecture advice)", "px",
                  0.0, 1e9, SettingWidget::Slider, "%.1f", [](Document& d) -> float& { return d.tess.targetPixels; });
    pixels.sliderMin = 1.0;
    pixels.sliderMax = 64.0;
    t.push_back(std::move(pixels));
    t.push_back(numberRow("tess.maxLevel", "Max level", "Upper clamp of every level", "", kLo, kHi, SettingWidget::Slider, "%.0f",
                          [](Document& d) -> float& { return d.tess.maxLevel; }));
    t.push_back(numberRow("tess.isoline", "Isolines",
                          "Isoline domain: lines (always rounded up to an integer) and segments per line (under the partitioning). "
                          "Curves draw one line; the isocurve overlay draws this many per direction, the first and last on the boundary",
                          "", kLo, kHi, SettingWidget::Slider, "%.2f",
                          [](Document& d) -> std::array<float, 2>& { return d.tess.isolineLevels; }));
    t.push_back(switchRow("tess.cullBackfaces", "Cull back faces", "Skip patches whose control net faces away from the eye",
                          [](Document& d) -> bool& { return d.tess.cullBackfaces; }));
    t.push_back(switchRow("tess.cullOffscreen", "Cull off-screen", "Skip patches outside the view frustum",
                          [](Document& d) -> bool& { return d.tess.cullOffscreen; }));
    t.push_back(
        switchRow("tess.cullFar", "Cull beyond far",
                  "Distance mode: cull patches centred at or beyond the far distance (the notes' level 0) instead of keeping level 1",
                  [](Document& d) -> bool& { return d.tess.cullFar; }));
    t.push_back(switchRow("tess.heightDetail", "Height map raises levels",
                          "Adaptive modes with a height map: raise an edge's level where the map has more detail than it shows, the "
                          "map band-limited to what the view shows (its mip level per pixel); off keeps the distance or screen "
                          "formula's levels (the full map only moves the vertices)",
                          [](Document& d) -> bool& { return d.tess.heightDetail; }));
    // Display (the Display panel, `display` in files).
    t.push_back(choiceRow<ShadingMode>(
        "display.shading", "Shading", "How the surface is coloured", {"lit", "normal", "patch", "uv", "zebra", "gauss", "mean", "level"},
        {"lit", "normal", "patch id", "uv checker", "zebra", "gaussian curvature", "mean curvature", "tessellation level"},
        [](Document& d) -> ShadingMode& { return d.display.shading; }));
    t.push_back(switchRow("display.showGrid", "Control net", "Show the control points and net lines",
                          [](Document& d) -> bool& { return d.display.showGrid; }));
    t.push_back(switchRow("display.showWireframe", "Wireframe", "Show the tessellated triangles",
                          [](Document& d) -> bool& { return d.display.showWireframe; }));
    t.push_back(
        switchRow("display.showNormals", "Normals", "Show surface normals", [](Document& d) -> bool& { return d.display.showNormals; }));
    t.push_back(switchRow("display.showBoundaries", "Boundaries",
                          "Patch boundaries coloured by continuity (grey open, red C0, green C1, blue G1, yellow C2, violet G2); joins out "
                          "of tolerance thick in orange",
                          [](Document& d) -> bool& { return d.display.showBoundaries; }));
    t.push_back(switchRow("display.showIsocurves", "Isocurves",
                          "Isoparametric curves of every patch through the isoline tessellator (levels in Tessellation)",
                          [](Document& d) -> bool& { return d.display.showIsocurves; }));
    t.push_back(switchRow("display.showCombs", "Combs",
                          "Curvature combs (GPU, isoline tessellator) on every curve and on the isocurves (2 isocurve lines: the boundary "
                          "curves); with a joined edge of the selected patch highlighted, the curvature graph across that join",
                          [](Document& d) -> bool& { return d.display.showCombs; }));
    Setting combScale = numberRow("display.combScale", "Comb scale",
                                  "Tooth length: 1 = 0.02 x model size² x curvature; negative points the teeth towards the centre of "
                                  "curvature",
                                  "", -1e6, 1e6, SettingWidget::Slider, "%.3g", [](Document& d) -> float& { return d.display.combScale; });
    combScale.sliderMin = -10.0;
    combScale.sliderMax = 10.0;
    t.push_back(std::move(combScale));
    Setting teeth{.key = "display.combDensity",
                  .label = "Comb teeth",
                  .tooltip = "Teeth per curve or isocurve",
                  .kind = SettingKind::Number,
                  .min = 2,
                  .max = 21,
                  .integer = true,
                  .format = "%.0f",
                  .get = [](const Document& d) { return Values{double(d.display.combDensity)}; },
                  .set = [](Document& d, const Values& v) { d.display.combDensity = int(v[0]); }};
    t.push_back(std::move(teeth));
    Setting normalLength = numberRow("display.normalLength", "Normal length", "Length of the drawn normals", "model units", 0.0, 1e9,
                                     SettingWidget::LogSlider, "%.3f", [](Document& d) -> float& { return d.display.normalLength; });
    normalLength.sliderMin = 0.001;
    normalLength.sliderMax = 1.0;
    t.push_back(std::move(normalLength));
    Setting light = numberRow("display.lightDir", "Light", "Direction towards the light", "", -1e9, 1e9, SettingWidget::Slider, "%.2f",
                              [](Document& d) -> std::array<float, 3>& { return d.display.lightDir; });
    light.sliderMin = -1.0;
    light.sliderMax = 1.0;
    t.push_back(std::move(light));
    t.push_back(numberRow("display.background", "Background", "Viewport clear colour", "", -1e9, 1e9, SettingWidget::Colour, "%.2f",
                          [](Document& d) -> std::array<float, 3>& { return d.display.background; }));
    // Displacement (the Displacement panel, `displacement` in files; DESIGN §11).
    t.push_back(numberRow("displacement.scale", "Scale", "Height of the map's white above its black (model units)", "model units", -1e9,
                          1e9, SettingWidget::Drag, "%.4g", [](Document& d) -> float& { return d.displacement.scale; }));
    t.push_back(numberRow("displacement.bias", "Bias", "Height of the map's black (model units)", "model units", -1e9, 1e9,
                          SettingWidget::Drag, "%.4g", [](Document& d) -> float& { return d.displacement.bias; }));
    t.push_back(choiceRow<DisplacementMapping>(
        "displacement.mapping", "Mapping",
        "Planar: the map lies over the ground plane (the model's bounds), crack-free across every seam.\n"
        "Patch parameters: each patch gets the whole map; a net's patches tile it",
        {"patch", "planar"}, {"patch parameters", "planar"}, [](Document& d) -> DisplacementMapping& { return d.displacement.mapping; }));
    // The document's length unit (File ▸ Unit, shown after the title in the menu bar; `unit` in
    // files; issue 42): what the numbers mean in STEP, glTF (metres) and OBJ. Changing it relabels
    // the numbers, it does not scale them.
    t.push_back(choiceRow<LengthUnit>("unit", "Unit", "The length unit of the document's coordinates, written into STEP, glTF and OBJ",
                                      {"mm", "cm", "m", "in"}, {"millimetres", "centimetres", "metres", "inches"},
                                      [](Document& d) -> LengthUnit& { return d.unit; }));
    return t;
}

std::string number(double v) {
    std::ostringstream o;
    o.precision(9);
    o << v;
    return o.str();
}

}  // namespace

std::span<const Setting> settings() {
    static const std::vector<Setting> rows = makeSettings();
    return rows;
}

const Setting* findSetting(std::string_view key) {
    for (const Setting& s : settings())
        if (s.key == key) return &s;
    return nullptr;
}

const Setting& setting(std::string_view key) {
    const Setting* s = findSetting(key);
    if (!s) throw std::logic_error("no setting named " + std::string(key));
    return *s;
}

std::optional<std::string> settingProblem(const Setting& s, const std::vector<double>& values) {
    if (values.size() != size_t(s.count))
        return "expected " + std::to_string(s.count) + (s.count == 1 ? " value" : " values") + ", got " + std::to_string(values.size());
    for (double v : values) {
        if (!std::isfinite(v)) return "value " + number(v) + " is not a finite number";
        if (v < s.min || v > s.max) return "value " + number(v) + " is outside [" + number(s.min) + ", " + number(s.max) + "]";
        if (s.integer && v != std::floor(v)) return "value " + number(v) + " is not a whole number";
    }
    return std::nullopt;
}

std::vector<std::string> formatSettingValues(const Setting& s, const std::vector<double>& values) {
    std::vector<std::string> out;
    for (double v : values) {
        if (s.kind == SettingKind::Switch)
            out.emplace_back(v != 0.0 ? "on" : "off");
        else if (s.kind == SettingKind::Choice && v >= 0 && size_t(v) < s.choices.size())
            out.emplace_back(s.choices[size_t(v)]);
        else
            out.push_back(number(v));
    }
    return out;
}

std::vector<double> parseSettingValues(const Setting& s, const std::vector<std::string>& words) {
    std::vector<double> out;
    for (const std::string& w : words) {
        if (s.kind == SettingKind::Switch) {
            if (w != "on" && w != "off") throw EditError(std::string(s.key) + ": expected on or off, got '" + w + "'");
            out.push_back(w == "on" ? 1.0 : 0.0);
        } else if (s.kind == SettingKind::Choice) {
            size_t i = 0;
            while (i < s.choices.size() && s.choices[i] != w) ++i;
            for (const auto& [alias, choice] : s.choiceAliases)
                if (i == s.choices.size() && alias == w) i = size_t(choice);
            if (i == s.choices.size()) {
                std::string names;
                for (std::string_view c : s.choices) names += (names.empty() ? "" : ", ") + std::string(c);
                throw EditError(std::string(s.key) + ": expected one of " + names + ", got '" + w + "'");
            }
            out.push_back(double(i));
        } else {
            size_t used = 0;
            double v = 0;
            try {
                v = std::stod(w, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != w.size() || w.empty()) throw EditError(std::string(s.key) + ": expected a number, got '" + w + "'");
            out.push_back(v);
        }
    }
    if (auto p = settingProblem(s, out)) throw EditError(std::string(s.key) + ": " + *p);
    return out;
}

}  // namespace model
}  // namespace pw
