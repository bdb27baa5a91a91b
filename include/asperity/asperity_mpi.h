/* SPDX-License-Identifier: GPL-2.0-or-later */
/* asperity over MPI: one 2D grid shared among the processes of a communicator.
 *
 * Installed only by a build with MPI (CMake option ASPERITY_MPI, on where an MPI library and
 * FFTW's MPI transforms, libfftw3-mpi, are found). Include it after MPI's own header; the
 * program initialises MPI before the first call and finalises it after destroying every
 * grid, system and solver.
 *
 * The grid is split into slabs of whole rows (y), one per process, as FFTW-MPI splits it
 * (a process may hold none when there are fewer rows than processes). asp_grid_get_slab
 * tells each process its rows; every array it passes or receives (heights, fields) holds
 * those rows only, x fastest, and every count is local. Scalars (means, forces, energies,
 * statistics, the solver's error and iterations) are those of the whole grid, the same bits
 * on every process.
 *
 * Every function of asperity.h works on such a grid and on the systems and solvers made on
 * it, with these rules:
 *   - Calls on them are collective: every process makes the same calls in the same order,
 *     with the same scalar arguments and solver options, from one thread. Scalars and options
 *     that differ between processes are refused on every process (ASP_ERR_INVALID_ARGUMENT,
 *     naming the first differing process) before anything is computed.
 *   - A call that fails on one process fails on all, with the same status and the message of
 *     the first failing process, which names it ("on process 1 of 3: array 'heights' ...").
 *     Arrays are checked on each process before the processes wait for each other, so that a
 *     bad array on one of them is reported on every one, without a hang. Handles must be
 *     valid (not NULL) on every process. What no process can foresee, running out of memory
 *     on one process in the middle of a solve, is reported on that process only, while the
 *     others wait for it: a program that cannot tolerate that calls MPI_Abort on such an
 *     error (ASP_ERR_OUT_OF_MEMORY).
 *   - Every solver runs distributed, on the periodic and on the free (non-periodic)
 *     substrate (asp_system_create_free: its grid zero-padded to 2nx x 2ny is shared among
 *     the processes with the grid, each holding the padded rows of its own rows).
 *   - Generators give the same global surface for any number of processes, to the bit:
 *     asp_topography_self_affine draws each wavevector's noise from a stream keyed by the
 *     seed and the wavevector.
 *   - A potential callback runs on each process for its pixels; if it fails on one, the
 *     solve fails on all (ASP_ERR_CALLBACK). A progress callback that asks to stop on one
 *     process stops the solve on all.
 *   - The grid's thread count defaults to one per process (one process per core is the
 *     usual layout of MPI codes), unless ASPERITY_NUM_THREADS or OMP_NUM_THREADS asks for
 *     another (the rule of asp_grid_set_threads in asperity.h); asp_grid_set_threads sets it
 *     as for any grid.
 *   - Results agree with one process to about 1e-10 relative and better: the sums over the
 *     processes are added in process order, and FFTW-MPI's transforms round differently from
 *     the serial ones.
 */
#ifndef ASPERITY_MPI_H
#define ASPERITY_MPI_H

#include <mpi.h>

#include "asperity/asperity.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A 2D periodic grid of nx x ny pixels on a box lx x ly (as asp_grid_create_2d) shared among
 * the processes of comm. Collective; the library works on a duplicate of comm, so that its
 * messages never meet the caller's. Every process must pass the same sizes and box:
 * otherwise every process gets ASP_ERR_INVALID_ARGUMENT. MPI must be initialised
 * (ASP_ERR_INVALID_STATE otherwise); comm must not be MPI_COMM_NULL. */
ASP_EXPORT int asp_grid_create_mpi(MPI_Comm comm, int64_t nx, int64_t ny, double lx, double ly,
                                   asp_grid **out);

/* The same, taking a Fortran communicator handle (MPI_Fint, the integer of mpi_f08's
 * MPI_Comm%MPI_VAL or of the mpi module); for the Fortran module and other languages whose
 * MPI bindings hold Fortran handles. A library built without MPI exports it too (with an
 * int communicator), returning ASP_ERR_UNSUPPORTED, so that bindings link either way. */
ASP_EXPORT int asp_grid_create_mpi_f(MPI_Fint comm, int64_t nx, int64_t ny, double lx,
                                     double ly, asp_grid **out);

#ifdef __cplusplus
}
#endif

#endif /* ASPERITY_MPI_H */
