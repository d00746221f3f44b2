// The editor's live continuity readout (issue 21): the continuity report of every join, kept up to
// date as the document changes. While a drag is under way only the joins next to the dragged
// points are measured again (at most kLiveJoins of them, each frame), so the readout follows the
// mouse without measuring a whole 32×32 grid per event; when the drag ends everything is measured.
#pragma once

#include <cstdint>
#include <vector>

#include "core/model/document.hpp"
#include "core/solve/continuity_report.hpp"

namespace pw {
inline namespace solve {

class ContinuityWatch {
public:
    static constexpr size_t kLiveJoins = 128;
    static constexpr int kSamples = 16;

    // `version` changes whenever the document does; `interacting` during a drag, whose moved
    // points are `moving` (measured again on every call then: a drag changes no version).
    void update(const Document& doc, uint64_t version, bool interacting, const std::vector<uint32_t>& moving);

    const std::vector<JoinContinuity>& report() const { return report_; }  // one entry per join, by join index
    uint8_t failures(size_t join) const { return join < failures_.size() ? failures_[join] : 0; }
    size_t outOfTolerance() const;
    // The joins measured by the last update (all of them, or the ones next to the drag).
    const std::vector<size_t>& lastMeasured() const { return measured_; }

private:
    uint64_t version_ = ~0ull;
    ContinuityTolerances tolerances_;
    std::vector<JoinContinuity> report_;
    std::vector<uint8_t> failures_;
    std::vector<size_t> measured_;
};

// Joins whose patches hold any of `points` (pool indices), in join order.
std::vector<size_t> joinsTouching(const Document& doc, const std::vector<uint32_t>& points);

}  // namespace solve
}  // namespace pw
