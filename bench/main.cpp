// carom benchmarks: Google Benchmark's main, plus the build facts that a figure needs beside it
// (they appear in the context of the console and JSON output).
#include <benchmark/benchmark.h>

namespace {

// The widest vectors the compiler may use here, as its predefined macros say; CAROM_NATIVE
// and -march flags in CMAKE_CXX_FLAGS both show up.
#if defined(__AVX512F__)
constexpr const char* kVectors = "AVX-512 (8 doubles)";
#elif defined(__AVX2__)
constexpr const char* kVectors = "AVX2 (4 doubles)";
#elif defined(__SSE2__)
constexpr const char* kVectors = "SSE2 (2 doubles)";
#else
constexpr const char* kVectors = "none known";
#endif

// The batch kernel's loop is compiled once per instruction set (target_clones in
// src/sweep_batch.cpp) in a build below AVX2; the loader runs the widest this CPU supports.
const char* batch_kernel_vectors() {
#if defined(__x86_64__) && defined(__ELF__) && !defined(__AVX2__)
  if (__builtin_cpu_supports("avx512f")) return "AVX-512 clone (8 doubles), picked at load time";
  if (__builtin_cpu_supports("avx2")) return "AVX2 clone (4 doubles), picked at load time";
#endif
  return kVectors;
}

#if CAROM_BENCH_NATIVE
constexpr const char* kNative = "ON (-march=native)";
#else
constexpr const char* kNative = "OFF";
#endif

#if CAROM_BENCH_BOX2D
constexpr const char* kBox2D = "b2TimeOfImpact included";
#else
constexpr const char* kBox2D = "not found at configure time: no Box2D benchmark";
#endif

}  // namespace

int main(int argc, char** argv) {
  benchmark::AddCustomContext("carom_build_type", CAROM_BENCH_BUILD_TYPE);
  benchmark::AddCustomContext("carom_native", kNative);
  benchmark::AddCustomContext("carom_vectors", kVectors);
  benchmark::AddCustomContext("carom_batch_kernel", batch_kernel_vectors());
  benchmark::AddCustomContext("carom_compiler", CAROM_BENCH_COMPILER);
  benchmark::AddCustomContext("box2d", kBox2D);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
