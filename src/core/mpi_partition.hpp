// SPDX-License-Identifier: GPL-2.0-or-later
// The partition of a grid over the processes of an MPI communicator: FFTW-MPI's slabs of
// rows and transforms, and collectives that give every process the same bits. Built only
// with ASPERITY_MPI; the C API's asperity_mpi.h is its one user.
#pragma once

#include <mpi.h>

#include <memory>

#include "core/partition.hpp"

namespace asp {

// A partition over a duplicate of `communicator` (so that the library's messages never meet
// the caller's). Collective. The caller has initialised MPI; the partition must be destroyed
// (its grids and systems too) before MPI_Finalize.
std::shared_ptr<const Partition> make_mpi_partition(MPI_Comm communicator);

}  // namespace asp
