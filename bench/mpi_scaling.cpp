// SPDX-License-Identifier: GPL-2.0-or-later
// Strong scaling over MPI processes: the solves of asperity_thread_scaling (pk, bugnicourt and
// lbfgs_fourier on bench/scaling_scene.hpp's scenes) on a grid distributed over the
// processes this program is started with, one thread each. For each solver and size: the
// time per iteration of a fixed number of iterations (the tolerance out of reach, the slowest
// process's time), one FFT pair of the distributed grid in the same run, their ratio, and the
// peak resident memory per pixel of a process (its VmHWM over its pixels: the whole process,
// MPI's buffers included). Run it with 1 and with 2 processes and compare:
//
//   mpirun -np 1 ./build/bench/asperity_mpi_scaling --size 2048 --iterations 20
//   mpirun -np 2 ./build/bench/asperity_mpi_scaling --size 2048 --iterations 20
//
// With --free the substrate is the free half-space (pk and bugnicourt by default): its
// transforms are those of the grid zero-padded to 2N x 2N, and the FFT pair is the padded
// pair the solvers make (the box's rows in, the box's rows out), on the same processes.
//
// usage: asperity_mpi_scaling [--size N]... [--iterations K] [--solver NAME]... [--free]
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "bench/bench_common.hpp"
#include "bench/scaling_scene.hpp"
#include "core/mpi_partition.hpp"

namespace {

int rank = 0, ranks = 1;

// The slowest process's time of `work`, started together.
template <class Work>
double timed(Work &&work) {
  MPI_Barrier(MPI_COMM_WORLD);
  const double start = MPI_Wtime();
  work();
  double seconds = MPI_Wtime() - start;
  MPI_Allreduce(MPI_IN_PLACE, &seconds, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return seconds;
}

template <class Pair>
double best_pair_seconds(const asp::Grid &grid, Pair &&pair) {
  const int repeats = std::max(3, static_cast<int>(2e7 / static_cast<double>(grid.n_pixels())));
  double best = 1e300;
  for (int batch = 0; batch < 5; ++batch)
    best = std::min(best, timed([&] {
                            for (int k = 0; k < repeats; ++k) pair();
                          }) / repeats);
  return best;
}

double fft_pair_seconds(const asp::Grid &grid) {
  asp::Field f = grid.make_field();
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<double>(i % 7);
  asp::Spectrum s = grid.make_spectrum();
  const asp::RealTransform &fft = grid.fft();
  return best_pair_seconds(grid, [&] {
    fft.forward(f.data(), s.data());
    fft.backward(s.data(), f.data());
  });
}

// The free substrate's pair: the box's rows into the padded spectrum and back.
double padded_pair_seconds(const asp::Grid &grid) {
  asp::Field f = grid.make_field();
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = static_cast<double>(i % 7);
  asp::Spectrum s(static_cast<std::size_t>(grid.padded_spectrum().size()));
  asp::Field rows(static_cast<std::size_t>(4 * grid.nx() * grid.local_rows()));
  const asp::PaddedTransform &fft = grid.padded_fft();
  return best_pair_seconds(grid, [&] {
    fft.forward(f.data(), s.data(), rows.data());
    fft.backward(s.data(), f.data(), rows.data());
  });
}

void run(const char *algorithm, std::int64_t n, int iterations, bool free) {
  auto grid = asp::Grid::create_distributed(asp::make_mpi_partition(MPI_COMM_WORLD), n, n,
                                            static_cast<double>(n), static_cast<double>(n));
  grid->set_fft_planning(asp::FftPlanning::estimate);
  grid->set_threads(1);
  bench::ScalingScene scene = bench::scaling_scene(
      grid, algorithm, free ? asp::SubstrateKind::free : asp::SubstrateKind::periodic);
  asp::Solver solver(algorithm);
  bench::warm_up(solver, scene, iterations);
  const double seconds = timed([&] { solver.solve(*scene.system, scene.control, scene.value); });
  const double per_iteration = seconds / static_cast<double>(solver.report().iterations);
  const double pair = free ? padded_pair_seconds(*grid) : fft_pair_seconds(*grid);
  double memory =
      bench::peak_resident_bytes() / static_cast<double>(std::max<std::int64_t>(1, grid->local_pixels()));
  MPI_Allreduce(MPI_IN_PLACE, &memory, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  if (rank == 0)
    std::printf("%-14s %6lld %9d %12.2f %10.2f %10.2f %14.0f\n", algorithm,
                static_cast<long long>(n), ranks, 1e3 * per_iteration, 1e3 * pair,
                per_iteration / pair, memory);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char **argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  std::vector<std::int64_t> sizes;
  std::vector<std::string> solvers;
  int iterations = 20;
  bool free = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--size" && has_value)
      sizes.push_back(std::atoll(argv[++i]));
    else if (arg == "--iterations" && has_value)
      iterations = std::atoi(argv[++i]);
    else if (arg == "--solver" && has_value)
      solvers.push_back(argv[++i]);
    else if (arg == "--free")
      free = true;
    else {
      if (rank == 0)
        std::fprintf(stderr,
                     "usage: %s [--size N]... [--iterations K] [--solver NAME]... [--free]\n",
                     argv[0]);
      MPI_Finalize();
      return 2;
    }
  }
  if (sizes.empty()) sizes = {2048, 4096};
  if (solvers.empty())
    solvers = free ? std::vector<std::string>{"pk", "bugnicourt"}
                   : std::vector<std::string>{"pk", "bugnicourt", "lbfgs_fourier"};
  if (rank == 0)
    std::printf("%-14s %6s %9s %12s %10s %10s %14s\n", "solver", "size", "processes", "ms/iter",
                "pair ms", "pairs/it", "peak B/pixel");
  for (std::int64_t n : sizes)
    for (const std::string &algorithm : solvers) run(algorithm.c_str(), n, iterations, free);
  MPI_Finalize();
  return 0;
}
