#include "ui/panels/panel_rows.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/model/settings.hpp"
#include "ui/platform/imgui_tip.hpp"
#include "ui/platform/widgets.hpp"

namespace pw::ui {
inline namespace panels {

namespace {

std::vector<std::string> setWords(const Setting& s, const std::vector<double>& values) {
    std::vector<std::string> words = {"set", std::string(s.key)};
    for (std::string& w : formatSettingValues(s, values)) words.push_back(std::move(w));
    return words;
}

// A number row's widget over `buf`, labelled `label`; true when it changed.
bool numberWidget(const Setting& s, const std::string& label, float* buf) {
    const std::string format(s.format);
    const bool narrower = s.sliderMin != 0.0 || s.sliderMax != 0.0;
    const float lo = float(narrower ? s.sliderMin : s.min), hi = float(narrower ? s.sliderMax : s.max);
    // The slider clamps typed values (Ctrl+click) itself where its range is the accepted one.
    const ImGuiSliderFlags clamp = narrower ? ImGuiSliderFlags_None : ImGuiSliderFlags_AlwaysClamp;
    switch (s.widget) {
        case SettingWidget::Colour:
            return widget::ColorEdit3(label.c_str(), buf);
        case SettingWidget::Drag: {
            const float speed = std::max(0.001f, 0.01f * std::max(std::abs(buf[0]), 1.0f));
            return widget::DragScalarN(label.c_str(), ImGuiDataType_Float, buf, s.count, speed, &lo, &hi, format.c_str(), clamp);
        }
        case SettingWidget::LogSlider:
            return widget::SliderScalarN(label.c_str(), ImGuiDataType_Float, buf, s.count, &lo, &hi, format.c_str(),
                                         clamp | ImGuiSliderFlags_Logarithmic);
        case SettingWidget::Slider:
            break;
    }
    if (s.integer && s.count == 1) {
        int i = int(buf[0]);
        const int ilo = int(lo), ihi = int(hi);
        if (!widget::SliderScalar(label.c_str(), ImGuiDataType_S32, &i, &ilo, &ihi, "%d", clamp)) return false;
        buf[0] = float(i);
        return true;
    }
    return widget::SliderScalarN(label.c_str(), ImGuiDataType_Float, buf, s.count, &lo, &hi, format.c_str(), clamp);
}

}  // namespace

bool settingRow(PanelContext& ctx, std::string_view key) {
    const Setting& s = setting(key);
    const std::vector<double> current = s.get(ctx.session().doc);
    const std::string label = std::string(s.label) + "##" + std::string(key);  // traced under its key
    bool changed = false;
    std::vector<double> next = current;
    switch (s.kind) {
        case SettingKind::Switch: {
            bool on = current[0] != 0.0;
            changed = widget::Checkbox(label.c_str(), &on);
            next[0] = on ? 1.0 : 0.0;
            break;
        }
        case SettingKind::Choice: {
            int i = int(current[0]);
            std::vector<const char*> items;
            for (std::string_view c : s.choiceLabels) items.push_back(c.data());
            changed = widget::Combo(label.c_str(), &i, items.data(), int(items.size()));
            next[0] = double(i);
            break;
        }
        case SettingKind::Number: {
            float buf[4] = {};
            for (size_t i = 0; i < current.size() && i < 4; ++i) buf[i] = float(current[i]);
            changed = numberWidget(s, label, buf);
            for (size_t i = 0; i < next.size() && i < 4; ++i) next[i] = std::clamp(double(buf[i]), s.min, s.max);
            if (s.integer)
                for (double& v : next) v = std::round(v);
            break;
        }
    }
    tip(std::string(s.tooltip).c_str());
    const bool slider = s.kind == SettingKind::Number;
    if (changed) {
        if (slider && ImGui::IsItemActive())
            ctx.previewCommand(setWords(s, next));
        else
            ctx.runCommand(setWords(s, next));
    } else if (slider && ImGui::IsItemDeactivatedAfterEdit()) {
        ctx.runCommand(setWords(s, current));  // one undo step for what the preview did
    }
    return changed;
}

}  // namespace panels
}  // namespace pw::ui
