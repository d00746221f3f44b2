// Partial upload of dragged points: only changed pool entries are found and written as float3.
#include <gtest/gtest.h>

#include "core/base/point_upload.hpp"

using namespace pw;

TEST(EditorUpload, ChangedPointsAreFoundAndWritten) {
    std::vector<Vec3> uploaded = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
    std::vector<Vec3> now = uploaded;
    now[1] = {1.5, 1, 1};
    now[3] = {3, 3, -3};
    std::vector<uint32_t> changed;
    takeChangedPoints(uploaded, now, changed);
    EXPECT_EQ(changed, (std::vector<uint32_t>{1, 3}));
    EXPECT_EQ(uploaded, now);  // remembered as uploaded
    std::vector<float> gpu(16, -7.0f);
    writePoolPositions(now, changed, gpu.data());
    EXPECT_EQ(gpu[4], 1.5f);
    EXPECT_EQ(gpu[5], 1.0f);
    EXPECT_EQ(gpu[14], -3.0f);
    EXPECT_EQ(gpu[7], -7.0f);  // the weight stays
    EXPECT_EQ(gpu[15], -7.0f);
    EXPECT_EQ(gpu[0], -7.0f);  // untouched
    takeChangedPoints(uploaded, now, changed);
    EXPECT_TRUE(changed.empty());
}
