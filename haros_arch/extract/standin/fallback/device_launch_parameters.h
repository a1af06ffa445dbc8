// haros_arch stand-in: device_launch_parameters.h, whose names the CUDA runtime stand-in declares
#include "cuda_runtime.h"
