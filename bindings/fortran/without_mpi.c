/* SPDX-License-Identifier: GPL-2.0-or-later */
/* asp_grid_create_mpi_f for a libasperity built without MPI, which does not have it. The
 * module's asp_grid_create_mpi calls it, so without this every program using the module would
 * fail to link against such a library, MPI or not. Distributed grids are not there to make:
 * ASP_ERR_UNSUPPORTED (the library's last error message is left as it was). Part of
 * asperity_fortran only in builds without MPI. */
#include <stddef.h>
#include <stdint.h>

#include "asperity/asperity.h"

int asp_grid_create_mpi_f(int comm, int64_t nx, int64_t ny, double lx, double ly,
                          asp_grid **out);

int asp_grid_create_mpi_f(int comm, int64_t nx, int64_t ny, double lx, double ly,
                          asp_grid **out) {
  (void)comm;
  (void)nx;
  (void)ny;
  (void)lx;
  (void)ly;
  if (out != NULL) *out = NULL;
  return ASP_ERR_UNSUPPORTED;
}
