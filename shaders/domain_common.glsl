// Declarations of the domain view's shaders: its push constants `dp` (core/gpu/domain_interface.h,
// which C++ compiles too) and the patch math of core/gpu/patch_math.h.
#include "core/gpu/domain_interface.h"
