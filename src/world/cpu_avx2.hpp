// carom internal: whether this CPU runs AVX2, for the batch kernels that pick their four-wide
// path at run time (pair_batch.cpp, growing_pair_batch.cpp). x86-64 only; elsewhere the kernels
// have no AVX2 path and never include this.
#pragma once

namespace carom::detail {

// Asked once, at load time: before the runtime library's own constructor may have run, hence
// __builtin_cpu_init first. Each kernel reads it only when called, after every initialiser.
inline const bool kCpuHasAvx2 = [] {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") != 0;
}();

}  // namespace carom::detail
