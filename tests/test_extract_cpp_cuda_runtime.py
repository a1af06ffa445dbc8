"""The CUDA runtime (``cuda_runtime.h``, ``curand.h``) a ``.cu`` node includes, when the
workspace has no such header: AutoRally's MPPI controller (survey Z47) allocates its cost
maps with ``cudaMalloc`` / ``cudaMemcpy`` in the constructor that reads its parameters,
takes ``float2`` / ``make_float2`` control bounds in ``main`` and marks functions
``__host__ __device__``. The header stood in empty: ``float2`` and the qualifiers were
declared permissively, but ``cudaMalloc``, ``make_float2`` and the enumerators
(``cudaMemcpyHostToDevice``) stayed errors beside the ROS calls, and its three nodes were
partial. A kernel launch (``k<<<grid, block>>>(...)``) is no C++ and stays an error."""

from __future__ import annotations

from conftest import package_xml

from haros_arch.extract.cpp import extract_cpp
from haros_arch.workspace import scan

NODE = """#include <ros/ros.h>
#include <std_msgs/Float32.h>
#include <cuda_runtime.h>
#include <curand.h>

__global__ void scale(float* values, float factor) {
  int i = blockDim.x * blockIdx.x + threadIdx.x;
  values[i] *= factor;
  __syncthreads();
}

class Costs {
 public:
  explicit Costs(ros::NodeHandle nh) {
    float width = nh.param<float>("track_width", 1.0f);
    float* host = new float[16];
    cudaMalloc((void**)&device_, 16 * sizeof(float));
    cudaMemcpy(device_, host, 16 * sizeof(float), cudaMemcpyHostToDevice);
    cudaTextureDesc tex;
    tex.addressMode[0] = cudaAddressModeClamp;
    tex.filterMode = cudaFilterModePoint;
    cudaChannelFormatDesc channel = cudaCreateChannelDesc(32, 0, 0, 0,
                                                          cudaChannelFormatKindFloat);
    curandGenerator_t gen;
    curandCreateGenerator(&gen, CURAND_RNG_PSEUDO_DEFAULT);
    pub_ = nh.advertise<std_msgs::Float32>("cost", 1);
  }
  __host__ __device__ float at(int i) const { return device_[i]; }
  float* device_;
  ros::Publisher pub_;
};

int main(int argc, char** argv) {
  ros::init(argc, argv, "mppi");
  ros::NodeHandle nh("~");
  float2 bounds[2] = {make_float2(-.99, .99), make_float2(-.99, .65)};
  Costs costs(nh);
  if (cudaDeviceSynchronize() != cudaSuccess) {
    ROS_ERROR("%s", cudaGetErrorString(cudaGetLastError()));
  }
  double hz = nh.param<double>("hz", 50.0);
  ros::spin();
}
"""


def test_a_cuda_node_reads_its_parameters_beside_the_runtime_calls(tmp_path) -> None:
    (tmp_path / "package.xml").write_text(package_xml("mppi"))
    source = tmp_path / "mppi.cu"
    source.write_text(NODE)
    result = extract_cpp([str(source)], scan([str(tmp_path)]), cache_dir=None,
                         distro="noetic")
    assert [(d.location.line, d.message) for d in result.diagnostics
            if d.code in ("CPP_PARSE_ERROR", "CPP_ERROR_NEAR_CALL",
                          "CPP_INCLUDE_MISSING")] == []
    assert sorted((c.kind, c.name) for c in result.calls) == [
        ("publish", "~cost"), ("read", "~hz"), ("read", "~track_width")]
