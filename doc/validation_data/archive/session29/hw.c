// Two kernels for the machine's 1 -> 2 process scaling: a compute-bound
// dependent FMA chain (no memory traffic) and a STREAM-like triad over
// 3 x 128 MB arrays. Prints seconds per kernel.
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(void) { struct timespec t; clock_gettime(CLOCK_MONOTONIC, &t); return t.tv_sec + 1e-9 * t.tv_nsec; }
int main(void) {
  double t0 = now(), x = 1.0, y = 0.999999, z = 1e-9;
  for (long i = 0; i < 800000000L; ++i) { x = x * y + z; }
  double t1 = now();
  const long n = 16L * 1024 * 1024; // 128 MB per array
  double *a = malloc(n * 8), *b = malloc(n * 8), *c = malloc(n * 8);
  for (long i = 0; i < n; ++i) { a[i] = 0; b[i] = 1; c[i] = 2; }
  double t2 = now();
  for (int r = 0; r < 20; ++r)
    for (long i = 0; i < n; ++i) a[i] = b[i] + 3.0 * c[i];
  double t3 = now();
  printf("compute %.3f s  triad %.3f s (%.1f GB/s)  [%g %g]\n", t1 - t0, t3 - t2,
         20.0 * 3 * n * 8 / (t3 - t2) / 1e9, x, a[n / 2]);
  return 0;
}
