// haros_arch stand-in: cuda_runtime_api.h, whose names the CUDA runtime stand-in declares
#include "cuda_runtime.h"
