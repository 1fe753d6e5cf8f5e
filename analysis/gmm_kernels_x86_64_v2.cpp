// The kernels of gmm_kernels_impl.h for one instruction-set level (its -march is set in
// analysis/CMakeLists.txt).
#define TACTILE_KERNEL_NS kernels_x86_64_v2
#include "analysis/gmm_kernels_impl.h"
