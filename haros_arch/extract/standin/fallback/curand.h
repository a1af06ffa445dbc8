// haros_arch stand-in: cuRAND's host API (curand.h), declarations only; no ROS call.
// Read only when the workspace has no such header.
#ifndef HAROS_CURAND_H
#define HAROS_CURAND_H

#include "cuda_runtime.h"

typedef enum curandStatus { CURAND_STATUS_SUCCESS = 0 } curandStatus_t;
typedef enum curandRngType {
  CURAND_RNG_PSEUDO_DEFAULT = 100, CURAND_RNG_PSEUDO_XORWOW = 101,
  CURAND_RNG_PSEUDO_MRG32K3A = 121, CURAND_RNG_PSEUDO_MTGP32 = 141,
  CURAND_RNG_PSEUDO_PHILOX4_32_10 = 161, CURAND_RNG_QUASI_DEFAULT = 200
} curandRngType_t;
struct curandGenerator_st;
typedef curandGenerator_st* curandGenerator_t;

curandStatus_t curandCreateGenerator(curandGenerator_t* generator, curandRngType_t type);
curandStatus_t curandDestroyGenerator(curandGenerator_t generator);
curandStatus_t curandSetPseudoRandomGeneratorSeed(curandGenerator_t generator,
                                                  unsigned long long seed);
curandStatus_t curandSetStream(curandGenerator_t generator, cudaStream_t stream);
curandStatus_t curandGenerateNormal(curandGenerator_t generator, float* outputPtr,
                                    size_t n, float mean, float stddev);
curandStatus_t curandGenerateNormalDouble(curandGenerator_t generator, double* outputPtr,
                                          size_t n, double mean, double stddev);
curandStatus_t curandGenerateUniform(curandGenerator_t generator, float* outputPtr,
                                     size_t num);

#endif
