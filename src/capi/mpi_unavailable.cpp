// SPDX-License-Identifier: GPL-2.0-or-later
// asp_grid_create_mpi_f in a build without MPI: the library exports the same functions
// whatever its build, so that the Fortran module and the Python package, which bind it by
// name, load and link against either; a distributed grid is then refused with a reason.
// (asp_grid_create_mpi takes an MPI_Comm, a type of MPI's header, and exists only with MPI.)
#include <cstdint>

#include "asperity/asperity.h"
#include "capi/firewall.hpp"

extern "C" ASP_EXPORT int asp_grid_create_mpi_f(int comm, int64_t nx, int64_t ny, double lx,
                                                double ly, asp_grid **out);

extern "C" int asp_grid_create_mpi_f(int, int64_t, int64_t, double, double, asp_grid **out) {
  if (out != nullptr) *out = nullptr;
  return asp::capi::guarded("asp_grid_create_mpi_f", [] {
    throw asp::Error(asp::Status::unsupported,
                     "this asperity was built without MPI (CMake option ASPERITY_MPI, which "
                     "needs an MPI library and libfftw3-mpi): distributed grids are not "
                     "available");
  });
}
