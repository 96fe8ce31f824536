// libFuzzer harness over the user-input parsers (see fuzz_one_input.hpp for the input format).
// Not part of the CMake build: it needs clang's libFuzzer. Build and run from the repository
// root, after building springblock_core with the same compiler and sanitizers:
//
//   cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DSPRINGBLOCK_SANITIZE=ON \
//         -DSPRINGBLOCK_BUILD_REPRODUCE=OFF -DSPRINGBLOCK_BUILD_BENCH=OFF
//   cmake --build build-fuzz --target springblock_core -j2
//   clang++ -std=c++20 -g -O1 -fsanitize=fuzzer,address,undefined -Isrc \
//       tests/fuzz/fuzz_parsers.cpp build-fuzz/src/libspringblock_core.a \
//       -lgsl -lgslcblas -lfmt -fopenmp -o build-fuzz/fuzz_parsers
//   build-fuzz/fuzz_parsers -max_total_time=60 -max_len=256 tests/fuzz/corpus
//
// Any exception other than sb::InputError, any sanitizer report or a timeout is a finding.
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "fuzz_one_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)sbfuzz::parse_one(data, size);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "non-InputError exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}
