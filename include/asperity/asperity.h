/* SPDX-License-Identifier: GPL-2.0-or-later */
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
 *            f(nx,ny) and NumPy shape (nx,ny) with order='F', without a copy. It is also the
 *            same memory as a C-order array of shape (ny,nx): one scan line of nx values per
 *            row, which is how image and text files hold a surface.
 * Heights    h: the rigid surface, positive towards the elastic body (highest point touches
 *            first).
 * Penetration delta: rigid-body approach, 0 when max(h) just touches the undeformed body.
 * Displacement u: surface displacement of the elastic body, positive into the body.
 * Gap        g = u - h + max(h) - delta, g >= 0 for a hard wall.
 * Pressure   p: positive is compressive. Mean pressure is force per unit area (2D) or force per
 *            unit length divided by lx (1D).
 * Modulus    E* = E/(1 - nu^2), the contact modulus of the elastic body (E Young's modulus,
 *            nu Poisson's ratio). Two elastic bodies against each other behave as one rigid
 *            and one elastic body of 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2.
 * Elasticity p~(q) = K~(q) u~(q), K~(q) = E*|q|/2. The q = 0 mode uses a finite stiffness
 *            K~(0) (see asp_system_set_k0); it links mean pressure and penetration, and so
 *            sets the force-penetration curve, never the pressure field under mean-pressure
 *            control. An elastic layer on a rigid base has its own K~(q) and K~(0)
 *            (asp_system_create_layer).
 *
 * ---------------------------------------------------------------------------------------------
 * Handles and lifetimes
 * ---------------------------------------------------------------------------------------------
 * asp_grid    the discretisation: sizes, box, FFT plans. Immutable after creation.
 * asp_system  a contact problem on a grid: substrate, topography and the current state
 *             (pressure, gap, displacement). Because the state lives here, a second solve on
 *             the same system warm-starts.
 * asp_solver  an algorithm, its options, and the report and history of its last run.
 *             Independent of any system; one solver can be used on many systems.
 * Handles may be destroyed in any order: a system keeps its grid alive (the library counts
 * references), so asp_grid_destroy only gives up the caller's reference. Every destroy
 * function accepts NULL.
 *
 * ---------------------------------------------------------------------------------------------
 * Errors
 * ---------------------------------------------------------------------------------------------
 * Every call that can fail returns an int status: ASP_OK (0) or one of the ASP_ERR_* codes.
 * On failure, asp_last_error_message() tells which argument was wrong and why; outputs that
 * are handles are set to NULL, and the handles passed in are left as they were and stay
 * usable. The library never prints, never exits or aborts, and no C++ exception crosses
 * this interface. Every number the library returns is finite: a scene whose numbers doubles
 * cannot hold (a modulus or box so extreme that the stiffness, the area or the pressures
 * overflow) is refused with ASP_ERR_INVALID_ARGUMENT naming the argument, before any work.
 *
 * ---------------------------------------------------------------------------------------------
 * Constants
 * ---------------------------------------------------------------------------------------------
 * Constants come in families, each with its own range of values: FFT planning 1xx,
 * normalisations 2xx, scalar results 3xx, fields 4xx, controls 5xx, history columns 6xx,
 * termination reasons 7xx, detrending modes 8xx, solver report keys 9xx. A value of one
 * family passed where another is expected is refused with a message naming both, never
 * misread. Status codes are 0..99.
 *
 * ---------------------------------------------------------------------------------------------
 * Memory
 * ---------------------------------------------------------------------------------------------
 * A system holds 3 fields of nx*ny doubles (heights, pressure, gap): 24 bytes per pixel. A
 * solve adds the work arrays of its algorithm, a few tens to a few hundred bytes per pixel
 * depending on the algorithm, its variable and its options (docs/performance.md gives each
 * one's measured figure); a grid adds FFTW's plans. A request whose arrays cannot be
 * allocated returns ASP_ERR_OUT_OF_MEMORY and changes nothing.
 *
 * ---------------------------------------------------------------------------------------------
 * Threads
 * ---------------------------------------------------------------------------------------------
 * Distinct handles may be used from distinct threads at the same time, and several systems
 * made on one grid may be solved at once from different threads (the grid's plans are shared
 * and FFTW executes them concurrently). One handle must not be used from two threads at once.
 * FFTW planning is serialised inside the library; the library never calls fftw_cleanup(), so
 * it coexists with other FFTW users in the process. How many threads a solve itself uses,
 * and how that behaves on a busy machine or inside a host's own threads, is said in one place:
 * asp_grid_set_threads.
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
#define ASP_ERR_SIZE_MISMATCH 3    /* an array count does not match what the call needs */
#define ASP_ERR_OUT_OF_MEMORY 4
#define ASP_ERR_UNSUPPORTED 5      /* valid request this algorithm or build does not provide */
#define ASP_ERR_INVALID_STATE 6    /* call out of order, e.g. a report before any solve */
#define ASP_ERR_FFT 7              /* FFTW could not make a plan */
#define ASP_ERR_CALLBACK 8         /* a user callback returned non-zero */
#define ASP_ERR_INTERNAL 9         /* a bug in asperity; please report it with the message */
#define ASP_ERR_IO 10              /* a file could not be read or written */

/* A short, static, English description of a status code ("unknown status" for others). */
ASP_EXPORT const char *asp_status_string(int status);

/* The detail of the last failed call made from this thread: function, argument, value, reason.
 * Empty after a call that returned ASP_OK, also when a callback it ran (progress, potential)
 * made a call of its own that failed: that call's message is there to read inside the
 * callback, right after it. The pointer stays valid until the next asperity call from the
 * same thread. */
ASP_EXPORT const char *asp_last_error_message(void);

/* The library's version, e.g. "0.2.0"; compare with ASP_VERSION_STRING to detect a header and
 * library mismatch. */
ASP_EXPORT const char *asp_version_string(void);

/* The ABI number of the library (ASP_ABI_VERSION of the build). */
ASP_EXPORT int asp_abi_version(void);

/* ============================================================================================
 * Grid
 * ========================================================================================== */
typedef struct asp_grid asp_grid;

/* A 1D periodic grid of nx >= 1 pixels on a length lx > 0. Fields are per unit length.
 * nx is at most 1073741823 (FFTW takes int sizes, and padded transforms double them), and
 * the box must be representable as below. */
ASP_EXPORT int asp_grid_create_1d(int64_t nx, double lx, asp_grid **out);

/* A 2D periodic grid of nx x ny pixels (each from 1 to 1073741823, any size: odd and prime
 * sizes work) on a box lx x ly. A 1 x N strip is a valid 2D grid. The box must be
 * representable: the area lx*ly and the pixel sizes must be finite, normal doubles, and every
 * wavevector, from 2 pi/lx to 2 pi nx/lx (likewise in y), must lie within 1e-150 to 1e150 so
 * that its square is one too. Otherwise ASP_ERR_INVALID_ARGUMENT names the length; rescale
 * the units. */
ASP_EXPORT int asp_grid_create_2d(int64_t nx, int64_t ny, double lx, double ly, asp_grid **out);

/* Gives up the caller's reference. The grid lives on while systems made on it exist.
 * Accepts NULL. */
ASP_EXPORT void asp_grid_destroy(asp_grid *grid);

/* Dimension (1 or 2), sizes (ny = 1 in 1D), pixel count nx*ny, box lengths (ly = 1 in 1D,
 * so that the pixel area lx*ly/(nx*ny) is the pixel length). Any output pointer may be NULL. */
ASP_EXPORT int asp_grid_get_shape(const asp_grid *grid, int *dimension, int64_t *nx, int64_t *ny,
                                  int64_t *n_pixels);
ASP_EXPORT int asp_grid_get_box(const asp_grid *grid, double *lx, double *ly);

/* How hard FFTW looks for fast plans.
 *   ASP_FFT_MEASURE   (default) times candidate algorithms the first time a transform shape
 *                     is needed in the process, and keeps the fastest. That first planning
 *                     took 0.3 s at 256^2, 0.5 s at 512^2, 0.7 s at 1024^2 and 1.1 s at
 *                     2048^2 on one core of the machine of docs/performance.md. Later grids
 *                     of the same shape, in the same process, plan at once;
 *                     asp_fft_export_wisdom and asp_fft_import_wisdom carry that knowledge
 *                     across processes.
 *   ASP_FFT_PATIENT   times many more candidates (FFTW_PATIENT): sometimes a faster plan,
 *                     for a planning several times longer; worth it for long runs whose
 *                     wisdom is kept.
 *   ASP_FFT_ESTIMATE  plans at once from heuristics; its transforms are as fast on some
 *                     machines and sizes and up to about 2x slower on others.
 * Planning is bounded in time, so that a busy machine (on which every timed candidate takes
 * longer) cannot make it last: FFTW stops looking after 1 s per transform plan with
 * ASP_FFT_MEASURE and 15 s with ASP_FFT_PATIENT, and keeps the fastest plan found so far
 * (fftw_set_timelimit, put back to FFTW's default of none afterwards; plans of distributed
 * grids, which FFTW-MPI makes together on every process, are not bounded). A grid's shape
 * has up to two plans each way, so its first planning costs at most a few seconds.
 * Plans are made on first use, so set this right after creating the grid; once plans exist
 * the call returns ASP_ERR_INVALID_STATE. */
#define ASP_FFT_ESTIMATE 101
#define ASP_FFT_MEASURE 102
#define ASP_FFT_PATIENT 103
ASP_EXPORT int asp_grid_set_fft_planning(asp_grid *grid, int planning);

/* The threads of the grid's FFTs (FFTW's threads) and of the element-wise passes of every
 * solve on it (the library's own threads), threads >= 1. The default, the one rule of the
 * library:
 *   1. ASPERITY_NUM_THREADS, when it holds a positive whole number (the first of a list);
 *   2. else OMP_NUM_THREADS, read the same way;
 *   3. else, on a grid of asperity_mpi.h, one thread per process (MPI codes run a process per
 *      core); on any other grid, the processors the process may run on (its CPU affinity,
 *      which taskset, cpusets and MPI launchers' binding narrow).
 * The variables are read when the grid is created.
 * Waiting threads sleep: a helper thread spins at most some tens of microseconds after a
 * pass before it sleeps, and a pass never waits for a thread that has not started, because
 * the calling thread takes the work of helpers the operating system has not run yet; when a
 * helper was stopped by the system in the middle of its work (other processes want its
 * core), the passes of the next moments (20 ms, doubling while it recurs, up to 1 s) run on
 * the calling thread alone. FFTW's threaded transforms run on the same threads: the library
 * sets FFTW's thread callback (fftw_threads_set_callback), which is process-wide, so that
 * other users of FFTW's threads in the process run theirs there too. On a
 * machine whose cores are busy with other processes, a solve with the default count therefore
 * takes about the time it takes on one thread (docs/performance.md, "A busy machine"), and on
 * an idle machine it uses every core. A pass started while another thread of the process runs
 * one (several solves at once, a host's own threads or OpenMP region) runs on its calling
 * thread alone, so that concurrent solves never compete for the same helpers; FFTW's
 * threaded transforms have their own sleeping workers. A program that runs asperity inside its
 * own threads or MPI ranks may still keep each grid to one thread with
 * asp_grid_set_threads(grid, 1) (or ASPERITY_NUM_THREADS=1), which spares the helpers' wake-ups.
 * The count is fixed when the plans are made: set it right after creating the grid (once
 * plans exist the call returns ASP_ERR_INVALID_STATE). Results with any count agree with
 * one thread to 1e-12 relative (tested for every solver): sums over the pixels are added in
 * fixed chunks, and the chunks in order, whichever thread did them, so they do not depend on
 * the count; only FFTW's threaded transforms may round differently from its serial ones.
 * The same count and the same FFT plans give the same result run after run: with
 * ASP_FFT_ESTIMATE, or measured plans kept as wisdom (FFTW_MEASURE times candidate plans,
 * so that a new measurement may pick another, which rounds differently; on strongly
 * adhesive scenes the iteration counts then move by a few per cent between runs). Passes
 * and transforms over fewer than 32768 entries run on one thread. A build without threads
 * (ASPERITY_THREADS off) accepts any count and runs on one. */
ASP_EXPORT int asp_grid_set_threads(asp_grid *grid, int threads);
ASP_EXPORT int asp_grid_get_threads(const asp_grid *grid, int *threads);

/* The rows of the grid this process holds: local_ny rows from row_offset on, local_pixels =
 * nx*local_ny pixels. A grid of asperity_mpi.h is shared among the processes of a
 * communicator, each holding a slab of whole rows; every other grid is held whole
 * (local_ny = ny, row_offset = 0, local_pixels = n_pixels). Every array the library reads or
 * fills for a grid (heights, fields) holds this process's rows, x fastest, local_pixels
 * values; a process without rows passes a count of 0 (and any pointer). Sizes, box,
 * n_pixels and every scalar result (means, forces, energies, statistics) are those of the
 * whole grid. Any output pointer may be NULL. */
ASP_EXPORT int asp_grid_get_slab(const asp_grid *grid, int64_t *local_ny, int64_t *row_offset,
                                 int64_t *local_pixels);

/* FFTW "wisdom": what planning with ASP_FFT_MEASURE has learnt in this process, saved to and
 * loaded from a file, so that repeated runs skip the planning: a grid shape whose plans the
 * wisdom holds is planned from it alone, timing nothing. Importing adds to what is known.
 * Returns ASP_ERR_IO, naming the path and the problem, when the file cannot be written or
 * read, and, on import, before reading it, when it is not a regular file (a device, a pipe,
 * a directory) or is larger than 16 MiB (the wisdom of hundreds of shapes is tens of
 * kilobytes), and after reading it, when FFTW does not read it as its own wisdom (damaged, or
 * written by another FFTW version); a refused file changes nothing of what the process knew.
 * Wisdom of another machine with the same FFTW version is accepted: its plans are correct
 * but may be slower there. The asperity command keeps a wisdom file in the user's cache
 * directory (docs/command.md). */
ASP_EXPORT int asp_fft_export_wisdom(const char *path);
ASP_EXPORT int asp_fft_import_wisdom(const char *path);

/* ============================================================================================
 * Topographies: functions that fill a caller's array of n = nx*ny heights on a grid (on a
 * distributed grid, the n = local_pixels heights of this process's rows: asp_grid_get_slab).
 * Caller arrays, inputs and outputs alike, need no particular alignment: NumPy slices (a[1:])
 * and Fortran array sections are fine, because the library copies them into its own buffers
 * before any Fourier transform. Every output is finite: a request whose numbers doubles
 * cannot hold is refused with ASP_ERR_INVALID_ARGUMENT naming the argument, as each function
 * says below. A call that fails writes nothing: the caller's arrays and output variables
 * keep what they held.
 * ========================================================================================== */

/* h = 0 everywhere. */
ASP_EXPORT int asp_topography_flat(const asp_grid *grid, double *heights, int64_t n);

/* A true sphere of radius R centred on the box (at x = lx/2, y = ly/2), apex at h = 0:
 * h = sqrt(R^2 - r^2) - R for r <= R and h = -R outside. In 1D, a cylinder (r = |x - lx/2|).
 * Finite for every radius > 0. */
ASP_EXPORT int asp_topography_sphere(const asp_grid *grid, double radius, double *heights,
                                     int64_t n);

/* The paraboloid h = -r^2/(2R) centred like the sphere: what Hertz theory assumes. Refused
 * ('radius') when the depth at the corners of the box, (lx^2 + ly^2)/(8R) (lx^2/(8R) in 1D),
 * overflows a double. */
ASP_EXPORT int asp_topography_paraboloid(const asp_grid *grid, double radius, double *heights,
                                         int64_t n);

/* h = amplitude * cos(2 pi periods_x x/lx) * cos(2 pi periods_y y/ly). periods_x >= 1 and
 * periods_y >= 0 are whole numbers so that the surface is periodic; periods_y = 0 gives a
 * sinusoid along x only (the only choice on a 1D grid). |h| <= |amplitude| on every grid. */
ASP_EXPORT int asp_topography_sinusoid(const asp_grid *grid, double amplitude, int64_t periods_x,
                                       int64_t periods_y, double *heights, int64_t n);

/* The "double sinewave" used to provoke adhesive instabilities (thesis, Table 5 and Fig. 28):
 * one long wave over the box plus a ripple,
 *   h = amplitude * cos(2 pi x/lx) + ripple_amplitude * cos(2 pi ripple_periods x/lx),
 * constant along y. The thesis's scene is amplitude 1, ripple_amplitude 0.05,
 * ripple_periods 32, lx = 1. Refused ('amplitude' and 'ripple_amplitude') when
 * |amplitude| + |ripple_amplitude|, the bound of |h|, overflows a double. */
ASP_EXPORT int asp_topography_double_sinewave(const asp_grid *grid, double amplitude,
                                              double ripple_amplitude, int64_t ripple_periods,
                                              double *heights, int64_t n);

/* A self-affine Gaussian random surface. Its isotropic power spectrum is, on a 2D grid,
 *   C(q) = 0                        for q < q_l      (q_l = 2 pi/long_cutoff)
 *   C(q) = C0                       for q_l <= q < q_r (q_r = 2 pi/rolloff)
 *   C(q) = C0 (q/q_r)^(-2-2 hurst)   for q_r <= q <= q_s (q_s = 2 pi/short_cutoff)
 *   C(q) = 0                        for q > q_s,
 * and on a 1D grid the profile's spectrum C1D(q) is the same with the exponent -1-2 hurst:
 * C1D(q) ~ q^(-1-2 hurst) against C(q) ~ q^(-2-2 hurst) for a surface. That is the
 * convention of the field (Jacobs, Junge and Pastewka, Surf. Topogr. 2017): a profile cut
 * from a surface of Hurst exponent H has Hurst exponent H, so H means the same roughness in
 * 1D and 2D. The wavelengths are ordered short_cutoff < rolloff <= long_cutoff. C0 is chosen
 * so that the surface has exactly the requested rms height (normalise = ASP_RMS_HEIGHT) or
 * rms slope (ASP_RMS_SLOPE), as asp_topography_statistics measures them; the mean height is
 * 0. A target whose surface would have heights beyond the largest double (a Gaussian surface
 * peaks at several times its rms height) is refused ('target').
 * The surface is white noise from the seed, filtered by sqrt(C): each wavevector's noise is
 * drawn from a stream keyed by the seed and the wavevector. The same seed and grid give the
 * same surface on every platform (to the last bits of the math library's cos and log), in
 * every run whatever was planned before, and on any number of MPI processes, to the bit. */
#define ASP_RMS_HEIGHT 201
#define ASP_RMS_SLOPE 202
ASP_EXPORT int asp_topography_self_affine(const asp_grid *grid, double hurst, double long_cutoff,
                                          double rolloff, double short_cutoff, int normalise,
                                          double target, int64_t seed, double *heights,
                                          int64_t n);

/* Statistics of a topography (thesis eqs. 52-54), computed spectrally:
 *   rms_height^2    = <(h - mean h)^2>,
 *   rms_slope^2     = <|grad h|^2>,
 *   rms_curvature^2 = <|laplacian h|^2>/4 in 2D, <h''^2> in 1D.
 * Any output pointer may be NULL. Any finite heights work, but a slope or curvature can
 * itself exceed the largest double (tall heights on a very fine grid): a requested statistic
 * that would is refused ('heights'); one not requested (NULL) never causes a refusal. */
ASP_EXPORT int asp_topography_statistics(const asp_grid *grid, const double *heights, int64_t n,
                                         double *rms_height, double *rms_slope,
                                         double *rms_curvature);

/* Removes a measured surface's form before it is solved, in place: its mean
 * (ASP_DETREND_MEAN), its tilt (ASP_DETREND_PLANE: the least-squares plane a + b x + c y,
 * in 1D the line a + b x) or its curvature (ASP_DETREND_CURVATURE: the least-squares
 * polynomial of degree 2 in x and y, in 1D in x), fitted over all pixels. A tilt left on a
 * periodic substrate becomes a ridge where the surface wraps around and silently changes the
 * contact (a 3 % tilt took 4.8 % contact to 2.5 %): remove it, or solve on the free
 * substrate. On a grid too small to determine a term (a quadratic along an axis of two
 * pixels) that term is left out of the fit. Refused with ASP_ERR_INVALID_ARGUMENT: a mode of
 * another family ('mode'); heights that are not finite, or whose result would not be
 * ('heights'), which are then left as they were. */
#define ASP_DETREND_MEAN 801
#define ASP_DETREND_PLANE 802
#define ASP_DETREND_CURVATURE 803
ASP_EXPORT int asp_topography_detrend(const asp_grid *grid, int mode, double *heights,
                                      int64_t n);

/* Radially averaged power spectrum C(q), normalised so that rms_height^2 = integral of C over
 * wavevectors (2D: d^2q, C = A/(2 pi)^2 |h^_q|^2; 1D: dq over positive and negative q,
 * C1D = lx/(2 pi) |h^_q|^2; h^ the DFT divided by nx*ny). The range 0 < |q| <= q_max of the
 * grid is cut into n_bins equal bins, 1 <= n_bins <= nx*ny (more bins than pixels would only
 * be empty; a count outside is refused, 'n_bins'). q and c are arrays of n_bins doubles each
 * (their length is n_bins, not nx*ny): q[k] the mean |q| of the modes in bin k and c[k] their
 * mean C; a bin without modes gets q[k] = its centre and c[k] = 0. A C(q) beyond the largest
 * double (very tall heights on a large box) is refused ('heights'). */
ASP_EXPORT int asp_topography_power_spectrum(const asp_grid *grid, const double *heights,
                                             int64_t n, int64_t n_bins, double *q, double *c);

/* ============================================================================================
 * System: substrate + topography + current state
 * ========================================================================================== */
typedef struct asp_system asp_system;

/* A periodic elastic half-space of contact modulus E* = contact_modulus > 0 on the grid, with
 * zero pressure and no topography yet: set one (asp_system_set_topography) before a solve,
 * which is refused until then. The system keeps the grid alive. E* must leave the
 * stiffness of every mode of the grid a finite, normal double. */
ASP_EXPORT int asp_system_create(const asp_grid *grid, double contact_modulus, asp_system **out);

/* A free (non-periodic) elastic half-space of contact modulus E* = contact_modulus > 0 on a 2D
 * grid: pressure acts only inside the grid's box lx x ly, and the surface around it is
 * unloaded and free, as under a measured, non-periodic topography or a single asperity. The
 * displacement is Love's solution for a pressure uniform over each pixel (Johnson, Contact
 * Mechanics, section 3.2, eq. 3.25):
 *   u(x) = 1/(pi E*) * sum over pixels of p times the integral of 1/|x - s| over the pixel,
 * computed exactly (to round-off) by FFTs of the grid zero-padded to 2nx x 2ny. There is no
 * q = 0 ambiguity: u vanishes far away, so the penetration delta is the approach of distant
 * points, as in Hertz's theory, and no K~(0) is involved. Otherwise it is used like a periodic
 * system, with these differences:
 *   - asp_system_set_k0 and asp_system_get with ASP_K0 return ASP_ERR_UNSUPPORTED;
 *   - ASP_ELASTIC_ENERGY is the whole elastic energy (a/2) sum p u, and ASP_MEAN_MODE_ENERGY
 *     is 0;
 *   - the solvers on the pressure serve it under mean-pressure and penetration control
 *     ("pk"; "bugnicourt" and "lbfgsb" with "variable" = "pressure", "lbfgsb" under
 *     penetration control only, as everywhere); the solvers on the gap ("bugnicourt" and
 *     "lbfgsb" with "variable" = "gap", with or without adhesion, "lbfgsb" also with a
 *     user's potential and the hard wall) serve it under ASP_CONTROL_PENETRATION and, but
 *     for a user's potential, ASP_CONTROL_MEAN_PRESSURE: the inverse of the compliance
 *     restricted to the box is not a convolution, so they minimise over the displacement of
 *     the whole padded surface, whose mean is not a free mode, and mean-gap control is
 *     refused with ASP_ERR_UNSUPPORTED; of the unconstrained solvers of soft potentials,
 *     "lbfgs" and "fire" serve it under penetration control, and "lbfgs_fourier",
 *     "fire_mass_weighted" and "gfmd" (periodic only) refuse it;
 *   - in the error measure the stiffness of one pixel is 1/C(0), C(0) the displacement of a
 *     pixel under unit pressure on itself (4 ln(1 + sqrt 2) dx/(pi E*), about 1.12 dx/E*,
 *     for square pixels of width dx); for a surface without slope the scale of a solve
 *     under penetration control is the stiffness under uniform pressure on the box (mean
 *     pressure over the mean displacement it makes) times the penetration.
 * Cost: every transform is of the padded grid, about 4 times that of a periodic one; the
 * system holds 32 bytes per pixel more (a padded work field) and a solve's spectra are 4
 * times larger (see docs/performance.md).
 * A 1D grid is refused with ASP_ERR_UNSUPPORTED naming 'grid': under plane strain the
 * displacement of a loaded free half-space grows like the logarithm of the distance and is
 * defined only relative to a reference point, so there is no unique force-penetration
 * relation. E* must leave the influence coefficients of the grid, their inverses and their
 * sums finite, normal doubles (ASP_ERR_INVALID_ARGUMENT naming 'contact_modulus'). */
ASP_EXPORT int asp_system_create_free(const asp_grid *grid, double contact_modulus,
                                      asp_system **out);

/* A periodic elastic layer of thickness t = thickness > 0, contact modulus
 * E* = contact_modulus > 0 and Poisson's ratio nu = poisson_ratio, 0 <= nu < 1/2, bonded
 * (no slip) to a rigid base and free of shear at its top (Carbone & Mangialardi, J. Mech.
 * Phys. Solids 56 (2008)). Its stiffness, with s = |q| t and kappa = 3 - 4 nu, is
 *   K~(q) = (E*|q|/2) [kappa cosh 2s + 2 s^2 + (1 + kappa^2)/2] / [kappa sinh 2s - 2s]:
 * the half-space's E*|q|/2 for wavelengths much shorter than t (the difference falls as
 * s^2 exp(-2s)), and for wavelengths much longer the stiffness of a column under uniaxial
 * strain, M/t, M = E(1 - nu)/((1 + nu)(1 - 2 nu)), E = E*(1 - nu^2) (a Winkler foundation).
 * That M/t is the layer's own K~(0): a uniform pressure p compresses it by p t/M, so the
 * penetration under a load is physical, not a convention. It is used like a periodic system
 * (every solver that takes asp_system_create takes it, under the same controls), with these
 * differences:
 *   - asp_system_get with ASP_K0 returns M/t, and asp_system_set_k0 returns
 *     ASP_ERR_UNSUPPORTED;
 *   - ASP_ELASTIC_ENERGY is, as on the half-space, that of the q != 0 modes, and
 *     ASP_MEAN_MODE_ENERGY = A pbar^2/(2 M/t) is the layer's physical energy of uniform
 *     compression: their sum is its whole elastic energy.
 * 1D grids take it too (plane strain, E* the plane-strain modulus). Refused with
 * ASP_ERR_INVALID_ARGUMENT naming the argument: E* or t not positive and finite, nu outside
 * [0, 1/2) (at nu = 1/2 the bonded incompressible layer has an infinite K~(0)), M/t not a
 * finite, normal double ('thickness'), or a K~ of some mode of the grid, or its inverse,
 * that is not ('contact_modulus'). */
ASP_EXPORT int asp_system_create_layer(const asp_grid *grid, double contact_modulus,
                                       double poisson_ratio, double thickness,
                                       asp_system **out);
/* Frees the system (NULL is ignored). Called from a callback of a call that is using the
 * system (a solve, or asp_system_get evaluating a potential), it does nothing and says so in
 * asp_last_error_message(). */
ASP_EXPORT void asp_system_destroy(asp_system *system);

/* Copies n = nx*ny finite heights (local_pixels of this process's rows on a distributed grid)
 * whose range max - min is a finite double; a height that is NaN or infinite is refused with
 * ASP_ERR_INVALID_ARGUMENT naming its pixel (x, y) and its index in the array (as are those
 * given to asp_topography_detrend, _statistics and _power_spectrum). Resets the state
 * to zero pressure (a new surface makes the old state meaningless). */
ASP_EXPORT int asp_system_set_topography(asp_system *system, const double *heights, int64_t n);

/* The stiffness K~(0) > 0 of the mean (q = 0) displacement mode. Default: the mean of K~ at the
 * lowest non-zero wavevector along x and along y (E* pi/lx in 1D), as in the thesis. Changing
 * it changes mean displacement and penetration, not the pressure under mean-pressure control,
 * and not ASP_ELASTIC_ENERGY (see ASP_MEAN_MODE_ENERGY). The current state keeps its pressure
 * and gap; its penetration moves by pbar (1/K~(0)new - 1/K~(0)old), so that it stays an
 * equilibrium (refused if that penetration is not a finite double). A free system (see
 * asp_system_create_free) has no K~(0), and a layer's (asp_system_create_layer) is its own,
 * M/t: both ASP_ERR_UNSUPPORTED. */
ASP_EXPORT int asp_system_set_k0(asp_system *system, double k0);

/* The interaction: a hard wall (g >= 0) with exponential adhesion, an energy per unit area
 *     phi(g) = -w exp(-g/rho),  g >= 0    (thesis eq. 11),
 * w = work_of_adhesion >= 0 the work of adhesion (energy per unit area), rho = range > 0 the
 * interaction range (a length). Where the gap is open the equilibrium pressure is
 * -phi'(g) = -(w/rho) exp(-g/rho): tensile, w/rho the largest tensile stress. The default,
 * and work_of_adhesion = 0, is the plain (non-adhesive) hard wall, phi = 0. The adhesion
 * strength of a sphere of radius R is measured by the Tabor parameter
 * (R w^2/(E*^2 rho^3))^(1/3); above about 3 it is strong, and solutions can be several
 * (hysteresis between loading and unloading).
 * Refused with ASP_ERR_INVALID_ARGUMENT, naming the argument: a work_of_adhesion that is
 * negative, NaN or infinite; a range that is not > 0 and finite (also with work 0); a largest
 * tensile stress w/rho that is not a finite, normal double. Nothing else changes: the state is
 * kept as it is (an equilibrium of the old interaction, generally not of the new one) and
 * the next solve starts from it; asp_system_reset starts cold. Solvers that do not handle
 * adhesion refuse a system with it (ASP_ERR_UNSUPPORTED): with adhesion, solve with
 * "bugnicourt" on the gap. */
ASP_EXPORT int asp_system_set_adhesion(asp_system *system, double work_of_adhesion,
                                       double range);

/* Soft interactions. Each replaces the interaction (as asp_system_set_adhesion does): an
 * energy per unit area phi(g) of the gap g, in the units of the system (lengths as the grid's
 * and the heights, pressures as E*, phi an energy per unit area), whose total is
 * a sum phi(g_i) (ASP_INTERACTION_ENERGY) and whose equilibrium pressure is p = -phi'(g).
 * Unlike the hard wall, a soft wall lets the gap become negative: the surfaces interpenetrate
 * as far as the repulsion lets them. Every one is defined for every finite gap, with finite
 * phi, phi' and phi''. A pixel counts as in contact (ASP_CONTACT_FRACTION, ASP_FIELD_CONTACT)
 * where the potential repels, phi'(g) < 0: at equilibrium that is where its pressure is
 * positive, but far from contact the equilibrium pressure is an attraction below rounding,
 * whose sign would be noise, while phi' changes sign once, at the potential's minimum, a gap
 * of the order of its range. With the hard wall (asp_system_set_potential with
 * hard_wall != 0) a pixel is in contact where the gap is 0, as for the other hard walls.
 * Nothing else changes: the state is kept as it is, and the next solve starts from it;
 * asp_system_reset starts cold. asp_system_set_hard_wall returns to the default.
 * The solvers that take a soft wall without the hard wall (asp_system_set_soft_wall,
 * asp_system_set_lennard_jones, asp_system_set_potential with hard_wall = 0) are the
 * unconstrained solvers lbfgs, lbfgs_fourier, gfmd, fire, fire_mass_weighted; the others
 * ("pk", "bugnicourt", "lbfgsb") refuse it before the solve with ASP_ERR_UNSUPPORTED naming
 * the interaction and listing those they handle (as asp_solver_describe does). */

/* The exponential soft wall (thesis eqs. 12-13):
 *     phi(g) = gamma_r exp(-2g/rho_r) - gamma_a exp(-g/rho_a),
 * a repulsion of strength gamma_r (energy per unit area) and range rho_r/2, and an attraction
 * of strength gamma_a and range rho_a (lengths). With one range rho = rho_r = rho_a and
 * gamma_a > 0 its minimum lies at g* = rho ln(2 gamma_r/gamma_a), with depth
 * phi(g*) = -gamma_a^2/(4 gamma_r); with two ranges at
 * g* = ln(2 gamma_r rho_a/(gamma_a rho_r)) / (2/rho_r - 1/rho_a). gamma_a = 0 is a purely
 * repulsive wall. Each exponential is continued below the gap where its exponent reaches 40
 * (g = -20 rho_r for the repulsion, g = -40 rho_a for the attraction) by its quadratic
 * Taylor expansion there, so that deep interpenetration costs a finite, growing energy.
 * Refused with ASP_ERR_INVALID_ARGUMENT, naming the argument: gamma_r, rho_r or rho_a not
 * > 0 and finite; gamma_a negative or not finite; and (naming all four) a repulsion whose
 * curvature 4 gamma_r/rho_r^2 does not exceed the attraction's gamma_a/rho_a^2, which would
 * leave the energy without a lower bound as the surfaces interpenetrate. A refused call
 * changes nothing. */
ASP_EXPORT int asp_system_set_soft_wall(asp_system *system, double gamma_r, double rho_r,
                                        double gamma_a, double rho_a);

/* The Lennard-Jones 9-3 wall (a 12-6 pair potential integrated over a half-space), by its
 * work of adhesion w = work_of_adhesion > 0 (energy per unit area) and its equilibrium
 * distance z0 = equilibrium_distance > 0 (a length):
 *     phi(g) = (w/2) [(z0/g)^9 - 3 (z0/g)^3],   g >= z0/2,
 * whose minimum is phi(z0) = -w. Its largest tensile stress, max phi'(g) over g > z0, is
 * (27/10) (2/5)^(2/3) w/z0, about 1.466 w/z0, at g = z0 (5/2)^(1/6), about 1.165 z0. Below
 * the threshold g = z0/2 (where phi = 244 w) it is continued by its quadratic Taylor
 * expansion there, phi'' = 91584 w/z0^2, so that zero and negative gaps have a finite energy
 * and a repulsion that grows linearly with the interpenetration.
 * Refused with ASP_ERR_INVALID_ARGUMENT, naming the argument: a work_of_adhesion or an
 * equilibrium_distance that is not > 0 and finite; and (naming both) a largest tensile
 * stress or a curvature at the threshold that is not a finite, normal double. A refused call
 * changes nothing. */
ASP_EXPORT int asp_system_set_lennard_jones(asp_system *system, double work_of_adhesion,
                                            double equilibrium_distance);

/* The plain, non-adhesive hard wall g >= 0, phi = 0 (the default): the same as
 * asp_system_set_adhesion with work 0, from any interaction. */
ASP_EXPORT int asp_system_set_hard_wall(asp_system *system);

/* A user's potential, evaluated by a callback over many gaps at once: fn(n, gap, phi, dphi,
 * d2phi, user_data) writes phi(gap[i]), phi'(gap[i]) and (if d2phi is not NULL) phi''(gap[i])
 * for i = 0..n-1 and returns 0; d2phi is NULL when the solver does not need it. The gaps and
 * values are in the system's units (physical, as the grid, heights and E*: a solve's internal
 * scaling is undone around the call). It is called once per evaluation with all pixels (and,
 * with the hard wall, also with the single gap 0, where the solver needs the wall's adhesive
 * stress -phi'(0)), and only from the thread that calls asp_solver_solve (or asp_system_get for
 * ASP_INTERACTION_ENERGY, and without the hard wall for ASP_CONTACT_FRACTION and
 * ASP_COMPRESSIVE_FRACTION, or asp_system_get_field for ASP_FIELD_CONTACT, which ask where
 * phi' < 0); it must not use the system or solver being solved: such calls from it are
 * refused with ASP_ERR_INVALID_STATE (and a destroy does nothing), while other handles and
 * functions work as anywhere. user_data is passed through untouched.
 * A non-zero return, or a value written to phi, dphi or d2phi that is not finite, ends the
 * solve with ASP_ERR_CALLBACK, naming the returned value or the first bad index and its gap;
 * the system then goes back to the state the solve started from.
 * hard_wall = 0: the potential alone, a soft wall; any other value: the hard wall g >= 0 with
 * the potential acting on the open gap, as the exponential adhesion of
 * asp_system_set_adhesion does. As its scales are not known beforehand, a solve takes its
 * scales from the load and the heights only (set a reference pressure with
 * asp_system_set_reference_pressure for a surface without slope). Without the hard wall the
 * unconstrained solvers take it; with it "lbfgsb" on the gap (penetration control). Solvers
 * that do not handle a user potential refuse it before the solve with ASP_ERR_UNSUPPORTED.
 * fn NULL: ASP_ERR_NULL_POINTER naming 'fn', and nothing changes. */
typedef int (*asp_potential_fn)(int64_t n, const double *gap, double *phi, double *dphi,
                                double *d2phi, void *user_data);
ASP_EXPORT int asp_system_set_potential(asp_system *system, asp_potential_fn fn,
                                        void *user_data, int hard_wall);

/* The reference pressure that solver errors are divided by (see asp_solver_solve). Default 0:
 * use E* h'_rms/2, the rms pressure of full contact, the scale of local contact pressures at
 * any load (on a free system, h'_rms from the differences between neighbouring pixels inside
 * the box, so that the step between the opposite edges of a non-periodic surface does not
 * count). For a surface without slope (the flat) a solve uses its own scale instead: the
 * mean pressure, or K~(0) times the penetration (on a free system the stiffness under a
 * uniform pressure), or with adhesion the largest tensile stress w/rho if that is larger
 * (with a soft wall its largest tensile stress, gamma_a^2/(8 gamma_r rho) for one range rho;
 * E* if all are zero). A value > 0 overrides all this. */
ASP_EXPORT int asp_system_set_reference_pressure(asp_system *system, double reference_pressure);

/* Forgets the state (zero pressure), so the next solve starts cold. */
ASP_EXPORT int asp_system_reset(asp_system *system);

/* Scalar results of the current state, chosen by key. In 1D, energies and forces are per unit
 * length. */
#define ASP_CONTACT_FRACTION 301   /* fraction of pixels in contact, the mean of
                                      ASP_FIELD_CONTACT: with the hard wall (with or without
                                      adhesion or a potential) the pixels where the gap is 0,
                                      the solver's active set; with adhesion that is the
                                      JKR/Maugis-Dugdale contact area, tensile edge included
                                      (ASP_COMPRESSIVE_FRACTION is its compressive core); for
                                      a soft wall where it repels, phi'(g) < 0 */
#define ASP_MEAN_PRESSURE 302      /* mean of p over all pixels */
#define ASP_MEAN_GAP 303           /* mean of g over all pixels */
#define ASP_ELASTIC_ENERGY 304     /* (A/2) sum over q != 0 of K~(q)|u^_q|^2: the energy of the
                                      deformation, independent of the K~(0) convention; on
                                      a free system all of it, (a/2) sum p u */
#define ASP_PENETRATION 305        /* delta */
#define ASP_TOTAL_FORCE 306        /* mean pressure times lx*ly (1D: times lx) */
#define ASP_K0 307                 /* the q = 0 stiffness in use (ASP_ERR_UNSUPPORTED on a
                                      free system, which has none; a layer's own M/t) */
#define ASP_REFERENCE_PRESSURE 308 /* the reference pressure of the last solve */
#define ASP_MEAN_MODE_ENERGY 309   /* the q = 0 term A pbar^2/(2 K~(0)), kept apart because it
                                      depends on K~(0); ELASTIC + MEAN_MODE = (a/2) sum p u;
                                      0 on a free system */
#define ASP_ATTRACTIVE_FRACTION 310 /* fraction of pixels with negative (tensile) pressure */
#define ASP_REPULSIVE_FORCE 311    /* a times the sum of the positive pressures (a the pixel
                                      area; 1D: the pixel length) */
#define ASP_ATTRACTIVE_FORCE 312   /* a times the sum of the negative pressures (<= 0);
                                      REPULSIVE + ATTRACTIVE = ASP_TOTAL_FORCE */
#define ASP_INTERACTION_ENERGY 313 /* a sum phi(g_i): 0 for the plain hard wall, <= 0 with
                                      adhesion */
#define ASP_WORK_OF_ADHESION 314   /* w of asp_system_set_adhesion (0: no adhesion, and 0 for
                                      any other interaction, soft walls included) */
#define ASP_ADHESION_RANGE 315     /* rho of asp_system_set_adhesion (0: no adhesion, and 0
                                      for any other interaction, soft walls included) */
#define ASP_COMPRESSIVE_FRACTION 316 /* fraction of pixels in contact (ASP_FIELD_CONTACT) that
                                      carry positive (compressive) pressure; equal to
                                      ASP_CONTACT_FRACTION without adhesion at convergence,
                                      less with it (the tensile edge of the contact) */
ASP_EXPORT int asp_system_get(const asp_system *system, int key, double *value);

/* Fields of the current state, copied into the caller's array of n = nx*ny doubles (this
 * process's local_pixels on a distributed grid). The displacement is the one the pressure
 * makes, K^-1 p (its mean by the q = 0 term), computed from the pressure on each call (one
 * FFT pair), so that it stays exact however large the penetration.
 * The contact map ASP_FIELD_CONTACT is 1.0 on the pixels in contact and 0.0 elsewhere, by the
 * rule of ASP_CONTACT_FRACTION (its mean): with the hard wall where the gap is 0, for a soft
 * wall where phi'(g) < 0 (which calls a user's potential once over all pixels).
 * With the hard wall every solve leaves the gap exactly 0 on its active set and >= 0
 * elsewhere, whatever its ending, so that the contact is never decided by the sign of a
 * rounding residue; the gap therefore differs from the one the pressure makes,
 * K^-1 p - (h - max h) - delta, by the residual of the solver's last iterate:
 *   - pressure-based (dual) solvers store their pressure iterate p >= 0 and the gap it makes,
 *     set to 0 on the active set p > 0, and where that gap is <= 0 off it (a pixel touching
 *     the wall with no pressure, to rounding, or left interpenetrating by the residual) to
 *     the smallest positive double (about 4.9e-324), so that the pixels with g = 0 are the
 *     active set exactly. On each pixel the difference is at most the final error times the
 *     reference pressure over the pixel stiffness (the error measures exactly these
 *     residues); the penetration is the one of the gap the pressure makes;
 *   - gap-based (primal) solvers store their gap iterate (>= 0, 0 on the active set) and the
 *     hard wall's reading of it as the pressure (see asp_solver_solve), which differs from the
 *     elastic pressure K u of that gap's displacement by at most the final error times the
 *     reference pressure on each pixel; the displacement K^-1 p differs from g + (h - max h) +
 *     delta by K^-1 of that difference, which sums it over neighbouring pixels: measured at 2
 *     to 14 times the final error times the reference pressure over the pixel stiffness (an
 *     adhesive sphere on a free 256^2 grid, Tabor parameter 5, adhesive and non-adhesive
 *     rough surfaces on periodic grids, tolerances from 1e-10 to a solve stopped at its
 *     start; for the sphere at 1e-4, 1.8e-4 times the adhesion's range).
 * Soft walls store the pressure of their displacement and the gap it makes, consistent to
 * rounding. */
#define ASP_FIELD_PRESSURE 401
#define ASP_FIELD_GAP 402
#define ASP_FIELD_DISPLACEMENT 403
#define ASP_FIELD_TOPOGRAPHY 404
#define ASP_FIELD_CONTACT 405
ASP_EXPORT int asp_system_get_field(const asp_system *system, int field, double *values,
                                    int64_t n);

/* Whether the grid resolves the system's interaction, asked before any solve (it reads the
 * parameters only: no transform, no callback, no change). An adhesive contact's edge is a
 * crack tip with a cohesive zone, the length over which the adhesive stress acts; in
 * Dugdale's model (Maugis, J. Colloid Interface Sci. 150, 243 (1992)) it is
 *     l = (pi/4) E* w / s^2,   w the work of adhesion (the depth of the well),
 *                              s the largest tensile stress,
 * from the zone's stress intensity s sqrt(8 l/pi) and the energy release rate K^2/(2 E*) of
 * a contact's edge, set to w. When l is below about one pixel (the threshold is 1), the
 * potential's largest curvature, of order s^2/w (w/rho^2 for the exponential adhesion),
 * exceeds the stiffness of a pixel, of order E* over dx: single pixels can rest both on and
 * off the wall, and the discrete problem has many metastable states (lattice trapping:
 * Thomson, Hsieh and Rana, J. Appl. Phys. 42, 3154 (1971)). No solver can then be expected
 * to converge cleanly: a solve may stall, or converge to one of those states, which depends
 * on the grid and the solver. The length l:
 *   exponential adhesion (asp_system_set_adhesion)   l = (pi/4) E* rho^2/w (s = w/rho);
 *   the exponential soft wall                          the depth w of its well and s at its
 *                                                      inflection (with one range rho,
 *                                                      l = 4 pi E* gamma_r rho^2/gamma_a^2);
 *   the Lennard-Jones wall                             s = 1.466 w/z0, l = 0.366 E* z0^2/w;
 *   the plain hard wall, a soft wall without attraction (gamma_a = 0) or whose attraction
 *   fades no slower than its repulsion (rho_a <= rho_r/2): no well, nothing to resolve;
 *   a user's potential: no length the library knows.
 * *ratio = l/dx, dx the smaller pixel size, min(lx/nx, ly/ny) (lx/nx in 1D); 0 when there is
 * no length (nothing to resolve, or a user's potential); finite (a ratio beyond the doubles
 * is given as the largest or the smallest normal double).
 * *resolved = 1 when the ratio is at least 1 or there is nothing to resolve; 0 when the
 * ratio is below 1, and also for a user's potential, of which the library cannot say that
 * the grid resolves it (ratio 0 and resolved 0 mean "unknown").
 * The text is one sentence for a person: which length was compared, its value in pixels and
 * in the system's units, and, when unresolved, what lengthens it (buffer rules as for
 * asp_algorithms). ratio and resolved may be NULL; they are written also when the buffer is
 * too small for the text. The command prints the sentence as a warning before it solves a
 * scene that is not resolved (docs/command.md). Asks nothing of other processes on a
 * distributed grid, and answers the same on each. */
ASP_EXPORT int asp_system_check_resolution(const asp_system *system, double *ratio,
                                           int *resolved, char *buffer, int64_t size,
                                           int64_t *length);

/* ============================================================================================
 * Algorithms
 * ========================================================================================== */

/* The names of the algorithms of this build, one per line ("pk\n..."), written into buffer
 * as a NUL-terminated string. For this and every other call that fills a string buffer:
 * *length (if length is not NULL) receives the length of the whole text without its NUL;
 * size 0 with buffer NULL and length not NULL asks for the length only and returns ASP_OK;
 * a buffer too small (size <= the length) receives the text cut to size - 1 characters and
 * the call returns ASP_ERR_SIZE_MISMATCH (also for size 0 without a length pointer). */
ASP_EXPORT int asp_algorithms(char *buffer, int64_t size, int64_t *length);

/* ============================================================================================
 * Solver
 * ========================================================================================== */
typedef struct asp_solver asp_solver;

/* An algorithm by name (see asp_algorithms and docs/algorithms.md); a name this build does
 * not provide is refused with ASP_ERR_UNSUPPORTED, listing the names it does:
 *   "pk"          Polonsky & Keer constrained conjugate gradient on the pressure (hard wall,
 *                 no adhesion, periodic or free substrate). Controls:
 *                 ASP_CONTROL_MEAN_PRESSURE, ASP_CONTROL_PENETRATION. Option
 *                 "preconditioner" (string): "auto" (the default; here the same as
 *                 "fourier"), "fourier" or "none". "fourier": the substrate's stiffness
 *                 applied to the gap on the contact set (and on the pixels off it whose gap
 *                 is negative, which enter along the result) before each
 *                 conjugate-gradient update; on both substrates and under both controls it
 *                 reaches the same solution in 2 to 3 times fewer iterations on 512^2 to
 *                 4096^2 grids, each costing one more FFT pair, and 12 more bytes per
 *                 pixel (24 on a free substrate). "none": unpreconditioned, as published.
 *                 Option "restart" (string): "powell" (the default) keeps the conjugate
 *                 direction across changes of the contact set and restarts it where
 *                 Powell's test finds it no longer conjugate; "entry" restarts after every
 *                 step that let pixels enter the contact set, as published. On rough
 *                 surfaces "powell" takes 1.4 to 3 times fewer iterations, whose counts grow
 *                 about 1.25 times per doubling of the grid (docs/performance.md,
 *                 "Iterations against the grid").
 *   "bugnicourt"  Bugnicourt et al.'s constrained conjugate gradient (OUT-LIN, 2018; hard
 *                 wall), on the pressure (option "variable" = "pressure", the default;
 *                 controls as "pk"; no adhesion; periodic or free substrate) or on the gap
 *                 ("gap"; controls ASP_CONTROL_MEAN_PRESSURE, tensile loads included with
 *                 adhesion, ASP_CONTROL_MEAN_GAP and ASP_CONTROL_PENETRATION, on a free
 *                 substrate not mean-gap; with or without adhesion, see
 *                 asp_system_set_adhesion). Option "preconditioner" (string): "fourier"
 *                 (the inverse of the elastic operator of the objective, the compliance on
 *                 the gap or the stiffness on the pressure, applied to the projected
 *                 gradient: the same solution in 2 to 6 times fewer iterations, each costing
 *                 one more FFT pair; 12 more bytes per pixel, 24 on a free substrate),
 *                 "none" (as published), or "auto" (the default): "fourier", with or
 *                 without adhesion (the adhesive problem has several stable states, and
 *                 the two paths can reach different ones; "none" keeps the published path).
 *                 Faster than "pk" near full contact. Stops as stalled also when it has no
 *                 descent direction left.
 *   "lbfgsb"      Byrd, Lu, Nocedal & Zhu's L-BFGS-B (1995; hard wall, periodic or free
 *                 substrate) on the pressure (option "variable" = "pressure", the default;
 *                 no adhesion) or on the gap ("gap"; with or without adhesion, or a user's
 *                 potential with the hard wall), under ASP_CONTROL_PENETRATION, and on the
 *                 gap also under ASP_CONTROL_MEAN_PRESSURE (tensile loads included with
 *                 adhesion; not with a user's potential): it keeps the unknowns in bounds but
 *                 cannot impose a mean, so mean-gap control, and mean-pressure control on the
 *                 pressure, are refused with ASP_ERR_UNSUPPORTED. Option "memory" (integer in
 *                 [1, 100], default 5): the
 *                 correction pairs it keeps. Stops as stalled when even a steepest-descent
 *                 line search finds no decrease (the rounding floor).
 * The unconstrained solvers of soft potentials (the soft wall, the Lennard-Jones wall, a
 * user's potential without the hard wall; they refuse the hard walls) minimise the elastic
 * energy plus the interaction energy over the displacement, without bounds, under
 * ASP_CONTROL_PENETRATION or ASP_CONTROL_MEAN_PRESSURE (the latter on a periodic substrate
 * only; mean-gap control is refused):
 *   "lbfgs"       L-BFGS (Nocedal 1980) with a strong Wolfe line search on the displacement;
 *                 periodic or free substrate. Option "memory" (integer in [1, 100], default
 *                 10).
 *   "lbfgs_fourier"  L-BFGS on the displacement's spectrum scaled by sqrt(K~(q)), so that
 *                 the elastic Hessian is the identity (the thesis's preconditioned L-BFGS),
 *                 1D and 2D; periodic substrate. Option "memory" as "lbfgs". The fastest of
 *                 the five on every scene measured (docs/performance.md).
 *   "fire"        FIRE (Bitzek et al. 2006, with FIRE 2.0's half step back) on the
 *                 displacement, equal masses; periodic or free substrate.
 *   "fire_mass_weighted"  FIRE with masses proportional to K~(q) (Zhou et al. 2019): FIRE on
 *                 the variable of "lbfgs_fourier"; periodic substrate.
 *     Options of both FIREs: "time_step" (0: automatic, 1/sqrt of a bound on the largest
 *     curvature at the start), "max_time_step" (0: automatic), "time_step_growth" (1.1),
 *     "time_step_shrink" (0.5), "mixing" (0.1), "mixing_decay" (0.99), "delay" (5).
 *   "gfmd"        damped Green's function molecular dynamics (mass-weighted; thesis Alg. 5)
 *                 on the variable of "lbfgs_fourier"; periodic substrate. Options
 *                 "time_step" (0: automatic, 1/sqrt of a bound on the largest
 *                 curvature at the iterate, at most 1, taken again every 10 steps; a
 *                 positive value is a fixed step) and "damping" (2: the elastic modes critically damped). A step that
 *                 raises the energy is undone and the motion restarts from rest. Its error
 *                 does not fall monotonically; raise "stall_window" for it on adhesive
 *                 scenes under mean-pressure control. */
ASP_EXPORT int asp_solver_create(const char *algorithm, asp_solver **out);
/* Frees the solver (NULL is ignored); from a callback of its own solve it does nothing and
 * says so in asp_last_error_message(). */
ASP_EXPORT void asp_solver_destroy(asp_solver *solver);

/* What the solver's algorithm does, the controls, substrates and interactions it serves, and
 * each option with its type, default, range and meaning, as text (buffer rules as for
 * asp_algorithms). */
ASP_EXPORT int asp_solver_describe(const asp_solver *solver, char *buffer, int64_t size,
                                   int64_t *length);

/* Options by name. Every algorithm has
 *   "tolerance"       real in (0, 1e300], default 1e-8: stop when the error falls to it
 *                     (what the error can resolve: asp_solver_solve);
 *   "max_iterations"  integer in [1, 9.2e18], default 10000;
 *   "stall_window"    integer in [0, 9.2e18], default 1000: stop as stalled when this
 *                     many iterations have passed since the error last fell below 0.99
 *                     times the error of the iteration at which it last did so (the
 *                     starting point at first); 0: never stall;
 *   "levels"          integer in [0, 16], or the string "auto"; default "auto" for "pk",
 *                     "bugnicourt" and "lbfgsb", 0 for the others: nested grids (cascadic coarse-to-fine). A solve whose system state carries no
 *                     pressure (a new system, after asp_system_reset or a new
 *                     topography) first solves the same scene on this many grids coarser
 *                     by 2 per axis (same box, substrate, K~(0) and interaction; the heights'
 *                     spectrum truncated below the coarse grid's Nyquist wavevector), the
 *                     coarsest first, each to the tolerance times 100 per level below the
 *                     system's grid (at most 1e-4, at least the tolerance; with a
 *                     continuation in the range, below, all at its first stage's 1e-2),
 *                     and starts from
 *                     the finest of them, its pressure interpolated linearly and the gap
 *                     the one that pressure makes (docs/algorithms.md); the solve on the
 *                     system's grid then meets the tolerance as without levels. A state
 *                     with pressure (a warm start, a load sweep) is solved from as it is.
 *                     Under penetration control the coarse levels keep the rigid body where
 *                     it is; under mean-pressure or mean-gap control they take the same
 *                     value. "auto" halves while both sides stay at least 64 pixels (none on
 *                     an odd size, and none with a user's potential, which the coarse
 *                     grids would call with their own, fewer pixels: an explicit count
 *                     does that), and reads back as -1 from
 *                     asp_solver_get_option and as "auto" from asp_solver_get_option_string
 *                     (a number reads back only from the former). An explicit count the grid
 *                     cannot take (an odd size on the way, or a side below 8 pixels) is
 *                     refused by asp_solver_solve and
 *                     asp_solver_supports with ASP_ERR_UNSUPPORTED naming the option and
 *                     why. The report and the history count the iterations and evaluations
 *                     of the system's own grid, the seconds of all levels, and the transforms
 *                     of all levels, a coarse one's weighted by its pixels over the system's
 *                     (one transform of a grid halved per axis counts a quarter; the
 *                     history's first row holds the coarse levels' already); the progress
 *                     callback is called on the system's grid only. A distributed grid's
 *                     coarse grids are distributed over the same processes;
 *   "range_continuation"  real in [0, 1e6] (0 or at least 1), or the string "auto";
 *                     default "auto" for "bugnicourt", 0 for the others: with the hard
 *                     wall and exponential adhesion (asp_system_set_adhesion), a solve
 *                     whose state carries no pressure first solves the same scene with the
 *                     range F rho (the work of adhesion kept: a cohesive zone F^2 times
 *                     longer), after the coarse levels and from their state, to the
 *                     tolerance 1e-2 (or the solve's, if looser; the coarse levels too),
 *                     then with rho from that state to the solve's tolerance. On a grid that
 *                     does not resolve the cohesive zone (asp_system_check_resolution) the
 *                     contact lines otherwise settle a pixel at a time: on the
 *                     contact-mechanics challenge's scene this cut the iterations at 4096^2
 *                     by 21 to 56 %, and cost up to 30 % more at 512^2 and 1024^2
 *                     (docs/performance.md). Adhesive contact has many stable states, and
 *                     the one reached may differ from a plain solve's (lower in energy on
 *                     that scene; 1.5e-3 higher, relative, on one test scene with F = 1.75).
 *                     "auto" takes F = sqrt(2 / zone), the factor that makes the zone 2
 *                     pixels long, where the zone is at most half a pixel, and none
 *                     otherwise or with any other interaction; it reads back as -1 and
 *                     "auto" as "levels" does. 0 and 1 are none, and so is any value under
 *                     a mean pressure <= 0 (a load the longer range's weaker tension might
 *                     not hold). The system's interaction is its own again when the solve
 *                     returns, however it ends. An explicit F with another interaction is refused by
 *                     asp_solver_solve and asp_solver_supports with ASP_ERR_UNSUPPORTED, a
 *                     value in (0, 1) with ASP_ERR_INVALID_ARGUMENT, naming the option.
 *                     The report, the history and the progress callback count the
 *                     iterations, evaluations and transforms of both stages: the history's
 *                     row at the first stage's last iteration is the second stage's
 *                     starting point, measured with rho (the callback saw that iteration
 *                     once, with the first stage's error), and max_iterations bounds both
 *                     stages together. A solve that ends in the first stage (cancelled, or
 *                     at the iteration limit) leaves that stage's state, and its error is
 *                     that of the range F rho; a cancel there ends the solve even at an
 *                     iteration that met the stage's tolerance. A first stage that breaks
 *                     down leaves the state reset, and the second stage starts cold;
 * and its own options (asp_solver_describe lists them). Integer options take whole numbers
 * given as doubles. An unknown name or a value outside the range is refused with
 * ASP_ERR_INVALID_ARGUMENT, naming the option and listing the valid names or the range;
 * a string option set as a number or the other way round likewise. */
ASP_EXPORT int asp_solver_set_option(asp_solver *solver, const char *name, double value);
ASP_EXPORT int asp_solver_set_option_string(asp_solver *solver, const char *name,
                                            const char *value);
ASP_EXPORT int asp_solver_get_option(const asp_solver *solver, const char *name, double *value);
ASP_EXPORT int asp_solver_get_option_string(const asp_solver *solver, const char *name,
                                            char *buffer, int64_t size, int64_t *length);

/* Shorthands for asp_solver_set_option(solver, "tolerance", ...) and "max_iterations"; the
 * latter takes any count >= 1, and counts above 9.2e18 set 9.2e18. */
ASP_EXPORT int asp_solver_set_tolerance(asp_solver *solver, double tolerance);
ASP_EXPORT int asp_solver_set_max_iterations(asp_solver *solver, int64_t max_iterations);

/* Called once per iteration of every solve, after the error of that iteration is known, with
 * the iteration number (0 is the starting point), the wall-clock seconds since the solve
 * started and the error. Return 0 to go on; any other value stops the solve cleanly: the
 * system holds the valid state of that iteration (see asp_solver_solve) and the termination
 * reason is ASP_TERMINATION_CANCELLED (unless that iteration's error already met the tolerance: a
 * converged state is reported as converged; but see "range_continuation" for a first stage).
 * With "range_continuation" the iterations of both stages are numbered on, and the one that
 * ends the first is reported once. The callback runs on the thread that called
 * asp_solver_solve and must not use the solver or system being solved (such calls from it are
 * refused with ASP_ERR_INVALID_STATE, and a destroy does nothing). NULL removes it.
 * user_data is passed through untouched. */
typedef int (*asp_progress_fn)(int64_t iteration, double seconds, double error, void *user_data);
ASP_EXPORT int asp_solver_set_progress(asp_solver *solver, asp_progress_fn progress,
                                       void *user_data);

/* Records one row per iteration of the next solves (on != 0) or not (0, the default; then
 * recording costs nothing). Each solve starts a new history. */
ASP_EXPORT int asp_solver_set_history(asp_solver *solver, int on);

/* Solves the system for the given control, starting from the system's current state, and
 * leaves the solution there.
 *   ASP_CONTROL_MEAN_PRESSURE  value = mean pressure (>= 0 without adhesion; with it a
 *                              negative, tensile load is taken); the penetration is an
 *                              unknown and is reported. Gap-based solvers find a minimum of
 *                              the energy less the work of the load, F delta (F the total
 *                              force): a stable state (one whose force grows with the
 *                              penetration). An unstable equilibrium is never returned: from
 *                              one, the solve follows the jump into or out of contact to the
 *                              stable state it leads to, and under a tensile load beyond the
 *                              pull-off force, where the surfaces have no stable state, it
 *                              ends as ASP_TERMINATION_SEPARATED.
 *   ASP_CONTROL_PENETRATION    value = delta; the mean pressure is reported.
 *   ASP_CONTROL_MEAN_GAP       value = mean gap (>= 0); mean pressure and penetration are
 *                              reported. Offered by gap-based (primal) solvers only.
 * A request the algorithm cannot serve (control, substrate, interaction, or a control that
 * the chosen options do not offer) is refused with ASP_ERR_UNSUPPORTED before anything
 * changes. A system whose topography was never set (asp_system_set_topography) is refused
 * with ASP_ERR_INVALID_STATE naming it: the zeros it holds until then would be solved as a
 * flat surface, and a forgotten topography reported as converged. A flat surface is an
 * array of zeros set like any other (asp_topography_flat).
 *
 * The error is the largest force-balance residual over the pixels in pressure units, divided
 * by the reference pressure; for pressure-based (dual) solvers the residual is the gap
 * violation (|g| where p > 0, max(-g, 0) where p = 0) times the stiffness of one pixel,
 * mean over q of K~(q); for gap-based (primal) solvers it is the pressure of the iterate's
 * displacement (|p| where g > 0, max(-p, 0) where g = 0), under mean-gap control relative
 * to the mean pressure, the constraint's multiplier; with adhesion the pressure counted is
 * the elastic pressure less the interaction's, K u + phi'(g). A primal solve stores its gap
 * iterate and the hard wall's reading of it as the pressure: where the gap is open no
 * pressure (with adhesion the interaction's, -phi'(g), tensile), on the wall the elastic
 * pressure, none below 0 (with adhesion below -w/rho). A dual solve stores its pressure
 * iterate and the gap it makes, projected onto the wall (asp_system_get_field says how the
 * two then differ).
 *
 * What the error can resolve: it is computed in doubles from the pressures of the iterate,
 * so a residual below their rounding, about 1e-16 times the largest of them (elastic,
 * interaction or load) over the reference pressure, is not seen ("lbfgs" and "fire" under
 * mean-pressure control carry the penetration in their displacement, and see no better
 * than 1e-16 of it times the largest K~(q)). An error of exactly 0 means that the terms
 * cancelled in floating point (a uniform or symmetric state, say), not that the state is
 * exact: it is exact to round-off. A tolerance below that floor is met only by such a
 * cancellation; otherwise the solve ends stalled or at the iteration limit. The error
 * reported is that of the iterate written back into the system (of which the state is the
 * reading above), so that "converged" says that the state left met the tolerance.
 *
 * Every way a solve ends returns ASP_OK with a finite state in the system, made from the
 * solver's last iterate as described above (the gap within the residual of the one the
 * pressure produces, exactly 0 on the active set). With the hard wall no ending leaves the
 * surfaces interpenetrating (gap >= 0 everywhere): a solve that stops short of the tolerance
 * (iteration limit, cancelled, stalled) leaves its last iterate projected onto g >= 0 (the
 * pressure solvers' gap raised to above 0 off the active set, as asp_system_get_field says;
 * the gap solvers' iterate, feasible by construction), not its best one. The contact fraction
 * of that state is the last row of the history's ASP_HISTORY_CONTACT_FRACTION.
 * asp_solver_get with ASP_REPORT_TERMINATION says which way it ended:
 *   ASP_TERMINATION_CONVERGED        the error met the tolerance (the only case in which
 *                                    ASP_REPORT_CONVERGED is 1);
 *   ASP_TERMINATION_ITERATION_LIMIT  max_iterations iterations ran;
 *   ASP_TERMINATION_CANCELLED        the progress callback returned non-zero;
 *   ASP_TERMINATION_STALLED          no progress within stall_window iterations;
 *   ASP_TERMINATION_BREAKDOWN        the arithmetic broke down (a non-finite value appeared);
 *                                    the system is reset to the zero-pressure state (the
 *                                    undeformed body touching the highest point), and the
 *                                    final error is the last finite one
 *                                    (DBL_MAX if not even the starting point was finite);
 *   ASP_TERMINATION_SEPARATED        no stable state under this load: the surfaces separate
 *                                    (ASP_CONTROL_MEAN_PRESSURE with adhesion, a tensile load
 *                                    beyond the pull-off force). Said of an iterate with no
 *                                    pixel on the wall along whose uniform separation the
 *                                    energy less the load's work falls (and then falls without
 *                                    bound, the adhesive energy being concave); the system
 *                                    holds that iterate's consistent, finite state, out of
 *                                    contact. The most tensile load that still converges
 *                                    bounds the pull-off force (the asperity command's sweep
 *                                    brackets it, docs/command.md).
 * Errors (a status other than ASP_OK) mean the solve did not run or its result could not be
 * stored; the system keeps the state it had before the call, and the solver has no report.
 * One exception: when memory runs out after the solve has begun to work on the state in place
 * (ASP_ERR_OUT_OF_MEMORY from a work array made during the iterations, as the correction pairs
 * of "lbfgsb" are), the system is reset to the zero-pressure state, as after a breakdown. */
#define ASP_CONTROL_MEAN_PRESSURE 501
#define ASP_CONTROL_PENETRATION 502
#define ASP_CONTROL_MEAN_GAP 503
ASP_EXPORT int asp_solver_solve(asp_solver *solver, asp_system *system, int control,
                                double value);

/* Whether the solver, with its current options, serves the system under the control, asked
 * without solving and without changing anything: ASP_OK if it does, ASP_ERR_UNSUPPORTED with
 * the message asp_solver_solve would give if it does not (ASP_ERR_INVALID_ARGUMENT for an
 * unknown control, and for a "range_continuation" in (0, 1)). Programs that offer every algorithm able to solve a scene ask this of
 * each one (asp_algorithms lists them). */
ASP_EXPORT int asp_solver_supports(const asp_solver *solver, const asp_system *system,
                                   int control);

/* The report of the last solve, one figure per key:
 *   ASP_REPORT_TERMINATION       how the solve ended, an ASP_TERMINATION_* code (below)
 *   ASP_REPORT_CONVERGED         1 if it ended ASP_TERMINATION_CONVERGED, else 0
 *   ASP_REPORT_ITERATIONS        the steps taken
 *   ASP_REPORT_EVALUATIONS       objective or gradient evaluations
 *   ASP_REPORT_TRANSFORMS        FFTs (one forward or one backward transform each)
 *   ASP_REPORT_FINAL_ERROR       the error of the state left in the system
 *   ASP_REPORT_ELAPSED_SECONDS   wall-clock seconds of the whole call, including the FFT
 *                                planning a first solve on a grid may do
 *   ASP_REPORT_HISTORY_LENGTH    rows of the history (0 when it was not recorded)
 * Evaluations and transforms are counted up to the last iteration, as in the history, so that
 * solvers can be compared by their work as well as by their time.
 *
 * asp_solver_get is the one way to read the report: a figure added later is a new key of
 * this family. Counts, codes and flags come as doubles that hold them exactly (every integer
 * up to 2^53, about 9.0e15, is a double; no count of a solve comes near it), so
 * (int64_t)value and (int)value give them back unchanged. A key of another family, or none,
 * is refused with ASP_ERR_INVALID_ARGUMENT naming it and listing the keys; a NULL solver or
 * value with ASP_ERR_NULL_POINTER naming it; a solver without a report with
 * ASP_ERR_INVALID_STATE: before the first solve, or after a solve that returned an error
 * (the report then describes nothing). */
#define ASP_REPORT_TERMINATION 901
#define ASP_REPORT_CONVERGED 902
#define ASP_REPORT_ITERATIONS 903
#define ASP_REPORT_EVALUATIONS 904
#define ASP_REPORT_TRANSFORMS 905
#define ASP_REPORT_FINAL_ERROR 906
#define ASP_REPORT_ELAPSED_SECONDS 907
#define ASP_REPORT_HISTORY_LENGTH 908
ASP_EXPORT int asp_solver_get(const asp_solver *solver, int key, double *value);

/* Termination reasons (ASP_REPORT_TERMINATION). */
#define ASP_TERMINATION_CONVERGED 701
#define ASP_TERMINATION_ITERATION_LIMIT 702
#define ASP_TERMINATION_CANCELLED 703
#define ASP_TERMINATION_STALLED 704
#define ASP_TERMINATION_BREAKDOWN 705
#define ASP_TERMINATION_SEPARATED 706

/* The same figures by getters of their own, kept while the ABI is 0.x for the programs that
 * use them: each gives what asp_solver_get gives for its key, in its own type, and refuses
 * what it refuses. New code uses asp_solver_get. */
ASP_EXPORT int asp_solver_termination(const asp_solver *solver, int *reason);
ASP_EXPORT int asp_solver_iterations(const asp_solver *solver, int64_t *iterations);
ASP_EXPORT int asp_solver_evaluations(const asp_solver *solver, int64_t *evaluations);
ASP_EXPORT int asp_solver_transforms(const asp_solver *solver, int64_t *transforms);
ASP_EXPORT int asp_solver_final_error(const asp_solver *solver, double *error);
ASP_EXPORT int asp_solver_converged(const asp_solver *solver, int *converged);
ASP_EXPORT int asp_solver_elapsed_seconds(const asp_solver *solver, double *seconds);

/* The history of the last solve, when asp_solver_set_history was on: one row per iteration,
 * starting with iteration 0 (the starting point). asp_solver_get_history copies one column
 * into values, n = the history length (ASP_REPORT_HISTORY_LENGTH, or
 * asp_solver_history_length, kept as the getters above; values may be NULL when n is 0);
 * another n is
 * refused with ASP_ERR_SIZE_MISMATCH.
 *   ASP_HISTORY_ITERATION         iteration number
 *   ASP_HISTORY_EVALUATIONS       objective or gradient evaluations so far
 *   ASP_HISTORY_TRANSFORMS        FFTs so far (one forward or one backward transform each)
 *   ASP_HISTORY_SECONDS           wall-clock seconds since the solve started
 *   ASP_HISTORY_ERROR             the error (as compared with the tolerance)
 *   ASP_HISTORY_OBJECTIVE         the algorithm's objective (docs/algorithms.md says which)
 *   ASP_HISTORY_CONTACT_FRACTION  fraction of pixels in contact at that iterate, by the rule
 *                                 of ASP_CONTACT_FRACTION applied to the state the iterate
 *                                 would leave: the last row equals ASP_CONTACT_FRACTION
 *                                 after the solve, however it ended (but a breakdown) */
#define ASP_HISTORY_ITERATION 601
#define ASP_HISTORY_EVALUATIONS 602
#define ASP_HISTORY_TRANSFORMS 603
#define ASP_HISTORY_SECONDS 604
#define ASP_HISTORY_ERROR 605
#define ASP_HISTORY_OBJECTIVE 606
#define ASP_HISTORY_CONTACT_FRACTION 607
ASP_EXPORT int asp_solver_history_length(const asp_solver *solver, int64_t *length);
ASP_EXPORT int asp_solver_get_history(const asp_solver *solver, int column, double *values,
                                      int64_t n);

/* The normal contact stiffness of the state the solver's last solve left in the system:
 * *stiffness = d(mean pressure)/d(penetration), the derivative of the mean pressure with
 * respect to delta along the equilibria through that state, in units of pressure per length
 * (times the box's area, dF/d(delta), force per length; in 1D per unit length of the
 * other direction). It is the consistent tangent of a Newton iteration on delta (a finite-
 * element code's contact element), and, by Barber's analogy, proportional to the electrical
 * and thermal conductance of the contact (docs/guide.md).
 *
 * What is differentiated: the equilibrium linearised about the state, with the set of pixels
 * on the hard wall held (the pixels with gap 0, and for the plain hard wall also those that
 * carry pressure). So it is the derivative with that contact set, which is the derivative
 * itself wherever the set does not change within a small change of delta, and between the
 * one-sided derivatives of a step where a pixel comes into or leaves contact.
 *   plain hard wall: the pressure increment dp on the contact set C that moves the surface
 *     by 1 there, (K^-1 dp) = 1 on C and dp = 0 off C; stiffness = mean(dp). A state without
 *     contact has stiffness 0; so has a touching state without pressure (zero load or
 *     penetration) left by a pressure solver, which has no contact set there (ASP_CONTACT_
 *     FRACTION 0), while a gap solver holds the touching pixels on the wall and gives the
 *     stiffness of increasing delta from there.
 *   with a potential (exponential adhesion, a soft wall, Lennard-Jones, a user's potential
 *     with or without the wall, whose phi'' the callback is asked for once): the Hessian
 *     K + phi''(g) of the energy on the points off C, the displacement held at +1 on C.
 * On a periodic substrate the mean pressure follows the system's K~(0) convention (full
 * contact gives K~(0)); on a free substrate the padded (non-periodic) operator is used.
 *
 * Cost: conjugate gradients on the contact set (plain hard wall) or on the free points of
 * the surface (with a potential: all of it for a soft wall, the zero-padded surface on a free
 * substrate), one forward and one backward transform per step, to a relative residual of
 * 1e-12: a few tens to a few hundred steps, about the cost of one solve warm-started after a
 * small change of delta (half a solve from rest), where a central difference costs two.
 * Work memory of a few fields over the grid (over the padded surface on a free substrate with
 * a potential). The result is accurate to about 1e-10 relative. Collective on a distributed
 * grid.
 *
 * Refused with ASP_ERR_INVALID_STATE (the message says which): when the solver has not
 * solved, or its last solve failed, did not converge, or was of another system; when the
 * system has changed since that solve (topography, interaction, K~(0), reference pressure,
 * asp_system_reset); and when the state is not a stable equilibrium: the Hessian restricted
 * to the free points is not positive definite (an adhesive state at or past an instability,
 * where the contact jumps), detected as a non-positive diagonal entry or a direction of
 * non-positive curvature met by the conjugate gradients. ASP_ERR_CALLBACK if a user's
 * potential fails; ASP_ERR_NULL_POINTER for a NULL argument. Nothing changes in the system or
 * in the solver's report. */
ASP_EXPORT int asp_solver_normal_stiffness(asp_solver *solver, asp_system *system,
                                           double *stiffness);

#ifdef __cplusplus
}
#endif

#endif /* ASPERITY_ASPERITY_H */
