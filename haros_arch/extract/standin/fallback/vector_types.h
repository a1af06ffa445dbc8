// haros_arch stand-in: vector_types.h, whose names the CUDA runtime stand-in declares
#include "cuda_runtime.h"
