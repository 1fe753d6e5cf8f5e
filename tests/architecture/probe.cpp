// Compiled by the architecture tests with one part's include path: includes PROBE_HEADER.
#define TACTILE_STRINGIFY2(x) #x
#define TACTILE_STRINGIFY(x) TACTILE_STRINGIFY2(x)
#include TACTILE_STRINGIFY(PROBE_HEADER)

int main() {
  return 0;
}
