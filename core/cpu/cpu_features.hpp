// What the CPU this process runs on offers beyond the x86-64 baseline the project is compiled
// for. Kernels also compiled for more (CRC-32 by PCLMULQDQ in core/bytes, the covariance step
// for AVX2 in filter/process_model.cpp) pick their variant by these at run time. Each is asked
// of the CPU once (GCC's __builtin_cpu_supports) and false on other architectures.
#pragma once

namespace navfuse::cpu {

bool has_pclmul();
bool has_avx2();

}  // namespace navfuse::cpu
