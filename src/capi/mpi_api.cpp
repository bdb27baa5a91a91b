// SPDX-License-Identifier: GPL-2.0-or-later
// asp_grid_create_mpi*: grids shared among the processes of an MPI communicator.
#include "asperity/asperity_mpi.h"
#include "capi/firewall.hpp"
#include "capi/handles.hpp"
#include "core/checks.hpp"
#include "core/mpi_partition.hpp"

using asp::capi::guarded;

namespace {
int create_distributed(const char *function, MPI_Comm comm, int64_t nx, int64_t ny, double lx,
                       double ly, asp_grid **out) {
  if (out != nullptr) *out = nullptr;
  return guarded(function, [&] {
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (!initialised || finalised)
      throw asp::Error(asp::Status::invalid_state,
                       "MPI is not initialised, or already finalised: call MPI_Init first");
    if (comm == MPI_COMM_NULL)
      throw asp::Error(asp::Status::invalid_argument, "argument 'comm' is MPI_COMM_NULL");
    std::shared_ptr<const asp::Partition> partition = asp::make_mpi_partition(comm);
    // A missing output on one process is reported on all, at the grid's own agreement.
    if (out == nullptr) {
      const asp::Error missing(asp::Status::null_pointer, "argument 'out' is NULL");
      partition->agree(&missing);
    }
    std::unique_ptr<asp_grid> handle(new asp_grid);
    handle->grid = asp::Grid::create_distributed(std::move(partition), nx, ny, lx, ly);
    *out = handle.release();
  });
}
}  // namespace

extern "C" {

int asp_grid_create_mpi(MPI_Comm comm, int64_t nx, int64_t ny, double lx, double ly,
                        asp_grid **out) {
  return create_distributed("asp_grid_create_mpi", comm, nx, ny, lx, ly, out);
}

int asp_grid_create_mpi_f(MPI_Fint comm, int64_t nx, int64_t ny, double lx, double ly,
                          asp_grid **out) {
  return create_distributed("asp_grid_create_mpi_f", MPI_Comm_f2c(comm), nx, ny, lx, ly, out);
}

}  // extern "C"
