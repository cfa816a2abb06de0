/* External C program using corlab's DEM library (find_package(corlab) or pkg-config corlab).
 * Sample run (after `cmake --install build --prefix $HOME/.local --component dem`):
 *   cmake -S examples/dem_c -B /tmp/dem_c -DCMAKE_PREFIX_PATH=$HOME/.local && cmake --build /tmp/dem_c
 *   /tmp/dem_c/dem_c_example
 * or: cc main.c $(pkg-config --cflags --libs corlab) -o dem_c_example
 * Prints e(v) and chi(v) of alumina on aluminium (Thornton 1997), then integrates one impact
 * with corlab_dem_force (semi-implicit Euler) and prints the rebound e against the target. */
/* SPDX-License-Identifier: BSD-3-Clause */
#include <corlab/corlab_dem.h>
#include <math.h>
#include <stdio.h>

int main(void) {
  char err[256];
  const double radius = 0.005; /* [m] */
  corlab_dem_pair* pair = corlab_dem_pair_from_materials("alumina_ma2023", "aluminium_ma2023",
                                                         "thornton1997", radius, 0.1, 10.0, err,
                                                         sizeof err);
  if (pair == NULL) {
    fprintf(stderr, "corlab: %s\n", err);
    return 1;
  }
  printf("corlab_dem %s\n", corlab_dem_version());
  const double mass = 4.0 / 3.0 * 3.14159265358979 * radius * radius * radius * 3958.226;
  const double speeds[] = {0.3, 1.0, 3.0};
  int failures = 0;
  for (int i = 0; i < 3; ++i) {
    const double v = speeds[i];
    corlab_dem_state state = {0.0, 0.0};
    double x = 0.0, u = v; /* overlap [m], overlap rate [m/s] */
    const double dt = 1e-9;
    for (long n = 0; n < 10000000 && x >= 0.0; ++n) {
      u -= corlab_dem_force(pair, x, u, &state) / mass * dt;
      x += u * dt;
    }
    const double target = corlab_dem_restitution(pair, v);
    printf("v = %.2f m/s  e_target = %.5f  chi = %.5f  e_integrated = %.5f\n", v, target,
           corlab_dem_chi(pair, v), -u / v);
    if (fabs(-u / v - target) > 2e-3) ++failures;
  }
  /* A pair from an FE results table (v [m/s], e), E* [Pa], R* [m]: e(v) linear between rows. */
  const double table_v[] = {0.5, 1.0, 4.0};
  const double table_e[] = {0.8, 0.7, 0.55};
  corlab_dem_pair* fe = corlab_dem_pair_from_table(table_v, table_e, 3, 1.15e11, 0.004, err,
                                                   sizeof err);
  if (fe == NULL || fabs(corlab_dem_restitution(fe, 2.5) - 0.625) > 1e-3) {
    fprintf(stderr, "corlab: table pair failed: %s\n", fe == NULL ? err : "wrong e");
    ++failures;
  } else {
    printf("table pair: e(2.5 m/s) = %.4f\n", corlab_dem_restitution(fe, 2.5));
  }
  corlab_dem_pair_free(fe);
  /* Bad input: a clear one-line error, no crash. */
  if (corlab_dem_pair_from_materials("alumina_ma2023", "nope", "thornton1997", radius, 0.1, 10.0,
                                     err, sizeof err) == NULL) {
    printf("bad input -> %s\n", err);
  } else {
    ++failures;
  }
  corlab_dem_pair_free(pair);
  return failures == 0 ? 0 : 1;
}
