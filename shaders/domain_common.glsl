// Declarations of the domain view's shaders: its push constants `dp` (render/domain_interface.h,
// which C++ compiles too) and the patch math of core/patch_math.h.
#include "render/domain_interface.h"
