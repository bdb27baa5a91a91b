/*
 * asperity: normal contact between a linear-elastic half-space and a rigid rough surface,
 * solved with FFT-based boundary elements.
 *
 * This header is the whole public interface. It is plain C99 and reads as the manual.
 *
 * ---------------------------------------------------------------------------------------------
 * Conventions
 * ---------------------------------------------------------------------------------------------
 * Units      Any consistent system; nothing is rescaled behind your back.
 * Grid       1D (nx pixels on a length lx) or 2D (nx x ny pixels on lx x ly), periodic.
 *            Pixel i sits at x_i = i*lx/nx (and y_j = j*ly/ny).
 * Layout     Every field is an array of doubles, x fastest: f[i + nx*j]. That is Fortran
 *            f(nx,ny) and NumPy shape (nx,ny) with order='F', without a copy.
 * Heights    h: the rigid surface, positive towards the elastic body (highest point touches
 *            first).
 * Penetration delta: rigid-body approach, 0 when max(h) just touches the undeformed body.
 * Displacement u: surface displacement of the elastic body, positive into the body.
 * Gap        g = u - h + max(h) - delta, g >= 0 for a hard wall.
 * Pressure   p: positive is compressive. Mean pressure is force per unit area (2D) or force per
 *            unit length divided by lx (1D).
 * Elasticity p~(q) = K~(q) u~(q), K~(q) = E*|q|/2, E* the contact modulus. The q = 0 mode uses
 *            a finite stiffness K~(0) (see asp_system_set_k0); it links mean pressure and
 *            penetration, and so sets the force-penetration curve, never the pressure field
 *            under mean-pressure control.
 *
 * ---------------------------------------------------------------------------------------------
 * Handles and lifetimes
 * ---------------------------------------------------------------------------------------------
 * asp_grid    the discretisation: sizes, box, FFT plans. Immutable after creation.
 * asp_system  a contact problem on a grid: substrate, topography and the current state
 *             (pressure, gap, displacement). It borrows its grid: destroy the system first.
 *             Because the state lives here, a second solve on the same system warm-starts.
 * asp_solver  an algorithm, its options and the report of its last run. Independent of any
 *             system; one solver can be used on many systems.
 *
 * ---------------------------------------------------------------------------------------------
 * Errors
 * ---------------------------------------------------------------------------------------------
 * Every call that can fail returns an int status: ASP_OK (0) or one of the ASP_ERR_* codes.
 * On failure, asp_last_error_message() tells which argument was wrong and why; outputs that
 * are handles are set to NULL, and the handles passed in are left as they were and stay
 * usable. The library never prints, never exits or aborts, and no C++ exception crosses
 * this interface.
 *
 * ---------------------------------------------------------------------------------------------
 * Threads
 * ---------------------------------------------------------------------------------------------
 * Distinct handles may be used from distinct threads at the same time. One handle must not
 * be used from two threads at once. FFTW planning is serialised inside the library; the
 * library never calls fftw_cleanup(), so it coexists with other FFTW users in the process.
 */
#ifndef ASPERITY_ASPERITY_H
#define ASPERITY_ASPERITY_H

#include <stdint.h>

#include "asperity/asperity_export.h"
#include "asperity/asperity_version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ============================================================================================
 * Status codes. Values never change; new codes are only ever appended.
 * ========================================================================================== */
#define ASP_OK 0
#define ASP_ERR_NULL_POINTER 1    /* a required handle or pointer argument was NULL */
#define ASP_ERR_INVALID_ARGUMENT 2 /* a value out of its domain: negative size, NaN, ... */
#define ASP_ERR_SIZE_MISMATCH 3    /* an array count does not match the grid */
#define ASP_ERR_OUT_OF_MEMORY 4
#define ASP_ERR_UNSUPPORTED 5      /* valid request this algorithm or build does not provide */
#define ASP_ERR_INVALID_STATE 6    /* call out of order, e.g. solve before a topography is set */
#define ASP_ERR_FFT 7              /* FFTW could not make a plan */
#define ASP_ERR_CALLBACK 8         /* a user callback returned non-zero */
#define ASP_ERR_INTERNAL 9         /* a bug in asperity; please report it with the message */

/* A short, static, English description of a status code ("unknown status" for others). */
ASP_EXPORT const char *asp_status_string(int status);

/* The detail of the last failed call made from this thread: function, argument, value, reason.
 * Empty after a successful call. The pointer stays valid until the next asperity call from
 * the same thread. */
ASP_EXPORT const char *asp_last_error_message(void);

/* The library's version, e.g. "0.1.0"; compare with ASP_VERSION_STRING to detect a header and
 * library mismatch. */
ASP_EXPORT const char *asp_version_string(void);

/* The ABI number of the library (ASP_ABI_VERSION of the build). */
ASP_EXPORT int asp_abi_version(void);

/* ============================================================================================
 * Grid
 * ========================================================================================== */
typedef struct asp_grid asp_grid;

/* A 1D periodic grid of nx >= 1 pixels on a length lx > 0. Fields are per unit length. */
ASP_EXPORT int asp_grid_create_1d(int64_t nx, double lx, asp_grid **out);

/* A 2D periodic grid of nx x ny pixels (each >= 1, any size: odd and prime sizes work) on a box
 * lx x ly. A 1 x N strip is a valid 2D grid. */
ASP_EXPORT int asp_grid_create_2d(int64_t nx, int64_t ny, double lx, double ly, asp_grid **out);

/* Accepts NULL. Destroy every system made on the grid first. */
ASP_EXPORT void asp_grid_destroy(asp_grid *grid);

/* Dimension (1 or 2), sizes (ny = 1 in 1D), pixel count nx*ny, box lengths (ly = 1 in 1D,
 * so that the pixel area lx*ly/(nx*ny) is the pixel length). Any output pointer may be NULL. */
ASP_EXPORT int asp_grid_get_shape(const asp_grid *grid, int *dimension, int64_t *nx, int64_t *ny,
                                  int64_t *n_pixels);
ASP_EXPORT int asp_grid_get_box(const asp_grid *grid, double *lx, double *ly);

/* How hard FFTW looks for fast plans. ASP_FFT_ESTIMATE (default) plans at once;
 * ASP_FFT_MEASURE times candidates when the plans are first needed (a second or more on large
 * grids) and usually runs faster. Plans are made on first use, so set this right after
 * creating the grid; once plans exist the call returns ASP_ERR_INVALID_STATE. */
#define ASP_FFT_ESTIMATE 0
#define ASP_FFT_MEASURE 1
ASP_EXPORT int asp_grid_set_fft_planning(asp_grid *grid, int planning);

/* ============================================================================================
 * Topographies: functions that fill a caller's array of n = nx*ny heights on a grid.
 * ========================================================================================== */

/* h = 0 everywhere. */
ASP_EXPORT int asp_topography_flat(const asp_grid *grid, double *heights, int64_t n);

/* A true sphere of radius R centred on the box (at x = lx/2, y = ly/2), apex at h = 0:
 * h = sqrt(R^2 - r^2) - R for r <= R and h = -R outside. In 1D, a cylinder (r = |x - lx/2|). */
ASP_EXPORT int asp_topography_sphere(const asp_grid *grid, double radius, double *heights,
                                     int64_t n);

/* The paraboloid h = -r^2/(2R) centred like the sphere: what Hertz theory assumes. */
ASP_EXPORT int asp_topography_paraboloid(const asp_grid *grid, double radius, double *heights,
                                         int64_t n);

/* h = amplitude * cos(2 pi periods_x x/lx) * cos(2 pi periods_y y/ly). periods_x >= 1 and
 * periods_y >= 0 are whole numbers so that the surface is periodic; periods_y = 0 gives a
 * sinusoid along x only (the only choice on a 1D grid). */
ASP_EXPORT int asp_topography_sinusoid(const asp_grid *grid, double amplitude, int64_t periods_x,
                                       int64_t periods_y, double *heights, int64_t n);

/* The "double sinewave" used to provoke adhesive instabilities (thesis, Table 5 and Fig. 28):
 * one long wave over the box plus a ripple,
 *   h = amplitude * cos(2 pi x/lx) + ripple_amplitude * cos(2 pi ripple_periods x/lx),
 * constant along y. The thesis's scene is amplitude 1, ripple_amplitude 0.05,
 * ripple_periods 32, lx = 1. */
ASP_EXPORT int asp_topography_double_sinewave(const asp_grid *grid, double amplitude,
                                              double ripple_amplitude, int64_t ripple_periods,
                                              double *heights, int64_t n);

/* A self-affine Gaussian random surface. Its isotropic power spectrum is
 *   C(q) = 0                        for q < q_l      (q_l = 2 pi/long_cutoff)
 *   C(q) = C0                       for q_l <= q < q_r (q_r = 2 pi/rolloff)
 *   C(q) = C0 (q/q_r)^(-2-2 hurst)   for q_r <= q <= q_s (q_s = 2 pi/short_cutoff)
 *   C(q) = 0                        for q > q_s,
 * with the wavelengths ordered short_cutoff < rolloff <= long_cutoff. C0 is chosen so that
 * the surface has exactly the requested rms height (normalise = ASP_RMS_HEIGHT) or rms slope
 * (ASP_RMS_SLOPE), as asp_topography_statistics measures them; the mean height is 0.
 * The surface is white noise from the seed, filtered by sqrt(C): the same seed and grid give
 * the same surface on every platform (to the last bits of the math library's cos and log). */
#define ASP_RMS_HEIGHT 1
#define ASP_RMS_SLOPE 2
ASP_EXPORT int asp_topography_self_affine(const asp_grid *grid, double hurst, double long_cutoff,
                                          double rolloff, double short_cutoff, int normalise,
                                          double target, int64_t seed, double *heights,
                                          int64_t n);

/* Statistics of a topography (thesis eqs. 52-54), computed spectrally:
 *   rms_height^2    = <(h - mean h)^2>,
 *   rms_slope^2     = <|grad h|^2>,
 *   rms_curvature^2 = <|laplacian h|^2>/4 in 2D, <h''^2> in 1D.
 * Any output pointer may be NULL. */
ASP_EXPORT int asp_topography_statistics(const asp_grid *grid, const double *heights, int64_t n,
                                         double *rms_height, double *rms_slope,
                                         double *rms_curvature);

/* Radially averaged power spectrum C(q), normalised so that rms_height^2 = integral of C over
 * wavevectors (2D: d^2q; 1D: dq over positive and negative q). The range 0 < |q| <= q_max of
 * the grid is cut into n_bins equal bins; q[k] is the mean |q| of the modes in bin k and c[k]
 * their mean C; a bin without modes gets q[k] = its centre and c[k] = 0. */
ASP_EXPORT int asp_topography_power_spectrum(const asp_grid *grid, const double *heights,
                                             int64_t n, int64_t n_bins, double *q, double *c);

/* ============================================================================================
 * System: substrate + topography + current state
 * ========================================================================================== */
typedef struct asp_system asp_system;

/* A periodic elastic half-space of contact modulus E* = contact_modulus > 0 on the grid, with a
 * flat topography and zero pressure. The grid must outlive the system. */
ASP_EXPORT int asp_system_create(const asp_grid *grid, double contact_modulus, asp_system **out);
ASP_EXPORT void asp_system_destroy(asp_system *system);

/* Copies n = nx*ny heights. Resets the state to zero pressure (a new surface makes the old
 * state meaningless). */
ASP_EXPORT int asp_system_set_topography(asp_system *system, const double *heights, int64_t n);

/* The stiffness K~(0) > 0 of the mean (q = 0) displacement mode. Default: the mean of K~ at the
 * lowest non-zero wavevector along x and along y (E* pi/lx in 1D), as in the thesis. Changing
 * it changes mean displacement and penetration, not the pressure under mean-pressure control. */
ASP_EXPORT int asp_system_set_k0(asp_system *system, double k0);

/* The reference pressure that solver errors are divided by (see asp_solver_solve). Default 0:
 * use E* h'_rms/2, the rms pressure of full contact, the scale of local contact pressures at
 * any load. For a surface without slope (the flat) a solve uses its own scale instead: the
 * mean pressure, or K~(0) times the penetration (E* if that is zero too). A value > 0
 * overrides all this. */
ASP_EXPORT int asp_system_set_reference_pressure(asp_system *system, double reference_pressure);

/* Forgets the state (zero pressure), so the next solve starts cold. */
ASP_EXPORT int asp_system_reset(asp_system *system);

/* Scalar results of the current state, chosen by key. */
#define ASP_CONTACT_FRACTION 1   /* fraction of pixels with positive (repulsive) pressure */
#define ASP_MEAN_PRESSURE 2      /* mean of p over all pixels */
#define ASP_MEAN_GAP 3           /* mean of g over all pixels */
#define ASP_ELASTIC_ENERGY 4     /* (A/2) sum_q K~(q)|u^_q|^2 = (a/2) sum_i p_i u_i; per length in 1D */
#define ASP_PENETRATION 5        /* delta */
#define ASP_TOTAL_FORCE 6        /* mean pressure times lx*ly (per unit length in 1D: times lx) */
#define ASP_K0 7                 /* the q = 0 stiffness in use */
#define ASP_REFERENCE_PRESSURE 8 /* the reference pressure in use */
ASP_EXPORT int asp_system_get(const asp_system *system, int key, double *value);

/* Fields of the current state, copied into the caller's array of n = nx*ny doubles. */
#define ASP_FIELD_PRESSURE 1
#define ASP_FIELD_GAP 2
#define ASP_FIELD_DISPLACEMENT 3
#define ASP_FIELD_TOPOGRAPHY 4
ASP_EXPORT int asp_system_get_field(const asp_system *system, int field, double *values,
                                    int64_t n);

/* ============================================================================================
 * Solver
 * ========================================================================================== */
typedef struct asp_solver asp_solver;

/* An algorithm by name:
 *   "pk"  Polonsky & Keer constrained conjugate gradient on the pressure (hard wall, no
 *         adhesion). Controls: ASP_CONTROL_MEAN_PRESSURE, ASP_CONTROL_PENETRATION. */
ASP_EXPORT int asp_solver_create(const char *algorithm, asp_solver **out);
ASP_EXPORT void asp_solver_destroy(asp_solver *solver);

/* Stop when the error falls to tolerance (> 0, default 1e-8), or after max_iterations (>= 1,
 * default 10000) iterations. */
ASP_EXPORT int asp_solver_set_tolerance(asp_solver *solver, double tolerance);
ASP_EXPORT int asp_solver_set_max_iterations(asp_solver *solver, int64_t max_iterations);

/* Solves the system for the given control, starting from the system's current state, and
 * leaves the solution there.
 *   ASP_CONTROL_MEAN_PRESSURE  value = mean pressure (>= 0 for non-adhesive solvers);
 *                              the penetration is an unknown and is reported.
 *   ASP_CONTROL_PENETRATION    value = delta; the mean pressure is reported.
 *   ASP_CONTROL_MEAN_GAP       value = mean gap (not offered by "pk": ASP_ERR_UNSUPPORTED).
 * The error is the largest force-balance residual over the pixels in pressure units, divided
 * by the reference pressure; for pressure-based (dual) solvers the residual is the gap
 * violation (|g| where p > 0, max(-g, 0) where p = 0) times the stiffness of one pixel,
 * mean over q of K~(q). Reaching max_iterations is not an error: the call returns ASP_OK
 * and asp_solver_converged() reports 0. */
#define ASP_CONTROL_MEAN_PRESSURE 1
#define ASP_CONTROL_PENETRATION 2
#define ASP_CONTROL_MEAN_GAP 3
ASP_EXPORT int asp_solver_solve(asp_solver *solver, asp_system *system, int control,
                                double value);

/* The report of the last solve. */
ASP_EXPORT int asp_solver_iterations(const asp_solver *solver, int64_t *iterations);
ASP_EXPORT int asp_solver_final_error(const asp_solver *solver, double *error);
ASP_EXPORT int asp_solver_converged(const asp_solver *solver, int *converged);
ASP_EXPORT int asp_solver_elapsed_seconds(const asp_solver *solver, double *seconds);

#ifdef __cplusplus
}
#endif

#endif /* ASPERITY_ASPERITY_H */
