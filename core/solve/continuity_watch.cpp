// The live continuity readout: full reports when the document settles, the dragged neighbourhood
// while it moves.
#include "core/solve/continuity_watch.hpp"

#include <algorithm>

namespace pw {
inline namespace solve {

std::vector<size_t> joinsTouching(const Document& doc, const std::vector<uint32_t>& points) {
    std::vector<char> hit(doc.points.size(), 0);
    for (uint32_t p : points)
        if (p < hit.size()) hit[p] = 1;
    auto touches = [&](uint32_t patch) {
        if (patch >= doc.patches.size()) return false;
        for (uint32_t i : doc.patches[patch].idx)
            if (i < hit.size() && hit[i]) return true;
        return false;
    };
    std::vector<size_t> out;
    for (size_t j = 0; j < doc.joins.size(); ++j)
        if (touches(doc.joins[j].patchA) || touches(doc.joins[j].patchB)) out.push_back(j);
    return out;
}

void ContinuityWatch::update(const Document& doc, uint64_t version, bool interacting, const std::vector<uint32_t>& moving) {
    const bool sameJoins = report_.size() == doc.joins.size();
    // A drag moves points without a new version: while interacting, measure every frame.
    if (!interacting && version == version_ && sameJoins && tolerances_ == doc.tolerances) return;
    measured_.clear();
    if (interacting && sameJoins) {
        // Orbiting or panning moves no point: nothing to measure (an empty subset would mean every
        // join to continuityReport, 32 % of an orbit's frame at 4 096 patches).
        if (moving.empty()) return;
        measured_ = joinsTouching(doc, moving);
        if (measured_.size() > kLiveJoins) measured_.resize(kLiveJoins);
        if (!measured_.empty())
            for (const JoinContinuity& c : continuityReport(doc, kSamples, measured_)) report_[c.join] = c;
    } else {
        report_ = continuityReport(doc, kSamples);
        measured_.resize(report_.size());
        for (size_t j = 0; j < measured_.size(); ++j) measured_[j] = j;
    }
    failures_.assign(report_.size(), 0);
    for (const JoinContinuity& c : report_) failures_[c.join] = toleranceFailures(c, doc.joins[c.join].continuity, doc.tolerances);
    version_ = version;
    tolerances_ = doc.tolerances;
}

size_t ContinuityWatch::outOfTolerance() const {
    return size_t(std::count_if(failures_.begin(), failures_.end(), [](uint8_t f) { return f != 0; }));
}

}  // namespace solve
}  // namespace pw
