// The tensor-product sums of a 4x4 window and their first and second partial derivatives, for any
// point type: Vec3 for polynomial windows (core/eval/patch_eval.cpp), homogeneous 4-vectors for
// rational ones (core/eval/rational_eval.cpp). Rows first (along u), then across them (along v).
#pragma once

#include <array>
#include <cstddef>

#include "core/model/basis.hpp"

namespace pw {
inline namespace eval {

template <class V>
struct TensorSums {
    V p{0.0}, du{0.0}, dv{0.0}, duu{0.0}, duv{0.0}, dvv{0.0};
};

template <class V>
TensorSums<V> tensorSums(const std::array<V, 16>& net, const BasisWeights& wu, const BasisWeights& wv) {
    TensorSums<V> s;
    for (int i = 0; i < 4; ++i) {
        V row{0.0}, rowDu{0.0}, rowDuu{0.0};
        for (int k = 0; k < 4; ++k) {
            const V& q = net[size_t(i * 4 + k)];
            row += wu.w[k] * q;
            rowDu += wu.dw[k] * q;
            rowDuu += wu.ddw[k] * q;
        }
        s.p += wv.w[i] * row;
        s.du += wv.w[i] * rowDu;
        s.dv += wv.dw[i] * row;
        s.duu += wv.w[i] * rowDuu;
        s.duv += wv.dw[i] * rowDu;
        s.dvv += wv.ddw[i] * row;
    }
    return s;
}

}  // namespace eval
}  // namespace pw
