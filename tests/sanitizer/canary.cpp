// The sanitizer tree's own check that its sanitizers are live at the optimisation it is built
// with: each mode commits one error they must report. CTest passes the test only on the report's
// text, so a tree whose instrumentation was dropped or optimised away fails it.
// Usage: canary heap | shift | overflow
#include <climits>
#include <cstdio>
#include <cstring>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  // The values come from the command line so the compiler cannot fold the errors away.
  volatile int one = argc - 1;
  if (std::strcmp(argv[1], "heap") == 0) {
    std::vector<int> v(4, 0);
    const int read = v.data()[4 * one];  // one past the end: heap-buffer-overflow
    std::printf("read %d\n", read);
  } else if (std::strcmp(argv[1], "overflow") == 0) {
    const int big = INT_MAX;
    const int sum = big + one;  // signed integer overflow
    std::printf("sum %d\n", sum);
  } else if (std::strcmp(argv[1], "shift") == 0) {
    const int shifted = one << (32 * one);  // shift exponent too large for int
    std::printf("shifted %d\n", shifted);
  } else {
    return 2;
  }
  return 0;
}
