// carom_machine_probes: Google Benchmark's main for the machine's memory probes.
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
