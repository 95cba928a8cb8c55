#include "core/cpu/cpu_features.hpp"

namespace navfuse::cpu {

#if defined(__x86_64__)
// __builtin_cpu_supports takes only a literal feature name, hence one function per feature.
bool has_pclmul() {
  static const bool available = (__builtin_cpu_init(), __builtin_cpu_supports("pclmul") != 0);
  return available;
}
bool has_avx2() {
  static const bool available = (__builtin_cpu_init(), __builtin_cpu_supports("avx2") != 0);
  return available;
}
#else
bool has_pclmul() { return false; }
bool has_avx2() { return false; }
#endif

}  // namespace navfuse::cpu
