// Lets one header be compiled as C++ and included by the GLSL shaders (glslc -I <repo root>), so a
// formula or an interface struct has one home for the CPU and the GPU. Such headers keep to the
// common subset of both languages: float literals with an f suffix, no references, no enums (named
// constants instead), no arrays as parameters, and the macros below where the languages differ.
// In C++ their declarations live in namespace pw::gpu with glm's types and functions.
#ifndef PW_GLSL_CPP_H
#define PW_GLSL_CPP_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#define PW_BEGIN_NAMESPACE \
    namespace pw::gpu {    \
    using uint = std::uint32_t;
#define PW_END_NAMESPACE }
#define PW_FN inline               // a function defined in a header
#define PW_CONST inline constexpr  // a named constant
#define PW_OUT(T) T&               // an out parameter
#define PW_PRECISE                 // GLSL's `precise` (no contraction); no-op in C++, whose uses
                                   // (batching bounds, tests) tolerate float-rounding differences
#define PW_INIT(x) \
    { x }  // a C++ default member value (GLSL blocks have none)
// A uniform or storage block: a plain struct in C++, the block with its layout in GLSL.
#define PW_BLOCK(glslHead, cppName) struct cppName
#define PW_END_BLOCK(instance) ;
// Functions over a real type: templates in C++ (float for the GPU's rules, double for the CPU's
// evaluation), float in GLSL.
#define PW_REAL_FN             \
    template <typename PwReal> \
    inline
#define PW_REAL PwReal
#define PW_REAL_VEC2 glm::vec<2, PwReal>
#define PW_REAL_VEC3 glm::vec<3, PwReal>
#define PW_REAL_VEC4 glm::vec<4, PwReal>

namespace pw::gpu {
using glm::ceil;
using glm::clamp;
using glm::distance;
using glm::dot;
using glm::exp2;
using glm::length;
using glm::log2;
using glm::mat4;
using glm::max;
using glm::min;
using glm::mix;
using glm::normalize;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;
}  // namespace pw::gpu

#else  // GLSL

#define PW_BEGIN_NAMESPACE
#define PW_END_NAMESPACE
#define PW_FN
#define PW_CONST const
#define PW_OUT(T) out T
#define PW_PRECISE precise
#define PW_INIT(x)
#define PW_BLOCK(glslHead, cppName) glslHead
#define PW_END_BLOCK(instance) instance;
#define PW_REAL_FN
#define PW_REAL float
#define PW_REAL_VEC2 vec2
#define PW_REAL_VEC3 vec3
#define PW_REAL_VEC4 vec4

#endif
#endif  // PW_GLSL_CPP_H
