/* corlab_dem.h: stable C API of corlab for DEM and multibody codes (C, C++, Fortran via
 * ISO_C_BINDING). SI units throughout: m, kg, s, N, Pa.
 *
 * A pair holds a restitution curve e(v) tabulated on [v_min, v_max] (linear in v, 1024 points;
 * end values outside), the exact hysteresis damping chi(e) table, and a Hertz stiffness. Its
 * force law is F = K delta^1.5 (1 + chi(e(v_in)) delta_dot / v_in) with v_in the approach speed at
 * first touch, which delivers e(v_in) exactly for every impact (chi (1+e) = ln[(1+chi)/(1-e chi)]).
 *
 *   char err[256];
 *   corlab_dem_pair* p = corlab_dem_pair_from_materials("alumina_ma2023", "aluminium_ma2023",
 *                                                      "thornton1997", 0.005, 0.1, 10.0,
 *                                                      err, sizeof err);
 *   double e = corlab_dem_restitution(p, 1.0);
 *   corlab_dem_state s = {0};            // one per contact, zeroed at first touch
 *   double f = corlab_dem_force(p, 1e-6, 0.9, &s);
 *   corlab_dem_pair_free(p);
 *
 * Functions returning a pointer return NULL on bad input and write a one-line message naming
 * the field, value and constraint into err (if err != NULL). The material database is read from
 * $CORLAB_DATA_DIR/materials.toml, else from <prefix>/share/corlab when the library is
 * installed in <prefix>/lib/<multiarch> (any prefix), else from the source tree it was built from.
 */
/* SPDX-License-Identifier: BSD-3-Clause */
#ifndef CORLAB_DEM_H
#define CORLAB_DEM_H

#ifdef __cplusplus
#include <cstddef>
#else
#include <stddef.h>
#endif

#if defined(_WIN32)
#define CORLAB_DEM_API __declspec(dllexport)
#else
#define CORLAB_DEM_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** Opaque pair of a sphere and a substrate (or a table). */
struct corlab_dem_pair;

/** Per-contact memory; zero-initialise at first touch. */
struct corlab_dem_state {
  double impact_velocity; /**< approach speed at first touch [m/s]; 0 = not yet set */
  double max_overlap;     /**< largest overlap so far [m] */
};

/* C needs the typedefs to use the bare names; in C++ the struct names are already type names. */
#ifndef __cplusplus
typedef struct corlab_dem_pair corlab_dem_pair;
typedef struct corlab_dem_state corlab_dem_state;
#endif

/** Version string of the library, e.g. "0.1.0". */
CORLAB_DEM_API const char* corlab_dem_version(void);

/** A pair from the material database: a sphere of radius [m] on a flat substrate, e(v) from the
 *  registered CoR model `model` (e.g. "thornton1997", "ma2023-exact"), tabulated on
 *  [v_min, v_max] [m/s]. */
CORLAB_DEM_API corlab_dem_pair* corlab_dem_pair_from_materials(const char* sphere,
                                                               const char* substrate,
                                                               const char* model,
                                                               double radius,
                                                               double v_min,
                                                               double v_max,
                                                               char* err,
                                                               size_t err_len);

/** A pair from a table of n >= 2 rows (v [m/s] strictly increasing, e in (0, 1]), e.g. FE
 *  results, with effective modulus E* [Pa] and effective radius R* [m] for the Hertz stiffness. */
CORLAB_DEM_API corlab_dem_pair* corlab_dem_pair_from_table(const double* velocities,
                                                           const double* restitution,
                                                           size_t n,
                                                           double effective_modulus,
                                                           double effective_radius,
                                                           char* err,
                                                           size_t err_len);

/** e at impact speed v [m/s] (table, end values outside its range). */
CORLAB_DEM_API double corlab_dem_restitution(const corlab_dem_pair* pair, double velocity);

/** Exact hysteresis damping factor chi for the e of impact speed v [m/s]. */
CORLAB_DEM_API double corlab_dem_chi(const corlab_dem_pair* pair, double velocity);

/** Hertz stiffness K = 4/3 E* sqrt(R*) [N/m^1.5]. */
CORLAB_DEM_API double corlab_dem_stiffness(const corlab_dem_pair* pair);

/** Normal force [N] at overlap delta [m] (> 0 in contact) and overlap rate [m/s] (> 0 approaching);
 *  updates *state (sets the impact speed at first touch). 0 when delta <= 0. */
CORLAB_DEM_API double corlab_dem_force(const corlab_dem_pair* pair,
                                       double overlap,
                                       double overlap_rate,
                                       corlab_dem_state* state);

/** Frees a pair (NULL is allowed). */
CORLAB_DEM_API void corlab_dem_pair_free(corlab_dem_pair* pair);

#ifdef __cplusplus
}
#endif

#endif /* CORLAB_DEM_H */
