// carom internal: CAROM_VECTOR_CLONES, for a vectorised kernel in a portable build.
// A portable build still runs the widest vectors the machine has: the compiler emits the function
// once per instruction set listed and the loader picks the best the CPU supports (an ELF ifunc).
// The answers do not depend on the pick: with FMA contraction off (cmake/CaromOptions.cmake)
// each lane does the same correctly rounded operations at every width. A -march=native build
// needs no clones. Nor does a ThreadSanitizer build: the sanitizer instruments the ifunc's
// resolver, which the loader runs before the sanitizer's runtime is up, and it crashes.
#pragma once

#if defined(__x86_64__) && defined(__ELF__) && !defined(__AVX2__) && !defined(CAROM_NO_CLONES) && \
    !defined(__SANITIZE_THREAD__)
#define CAROM_VECTOR_CLONES __attribute__((target_clones("default", "avx2", "avx512f")))
#else
#define CAROM_VECTOR_CLONES
#endif
