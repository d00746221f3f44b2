// Shared declarations of the Patchwork shaders: the interface blocks frame, counters and draw and
// the patch math, each written once for C++ and GLSL (core/gpu/gpu_interface.h, core/gpu/patch_math.h).
#include "core/gpu/gpu_interface.h"

// binding 1: per-patch tessellation overrides, indexed by patchBase + gl_PrimitiveID.
layout(set = 0, binding = 1, std430) readonly buffer Patches { PatchData patches[]; };

// A window's displacement scale and bias: its own (disp.z > 0.5), else the document's.
vec2 displacementScaleBias(PatchData pd) { return pd.disp.z > 0.5 ? pd.disp.xy : frame.displace.xy; }

// The shorter of a triangle's two parametric segment spans on screen (pixels), ignoring a collapsed
// direction (a pole) where the other still tells the density.
float segmentSpan(float a, float b) { return a < 1e-3 ? b : b < 1e-3 ? a : min(a, b); }
